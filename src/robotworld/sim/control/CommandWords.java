package robotworld.sim.control;

import java.util.List;

/** Checks and reads the words of a control command, with messages that say what would be right. */
final class CommandWords {

    private CommandWords() {
    }

    /** Fails unless the command has exactly {@code count} arguments; {@code form} shows the right form. */
    static void arguments(List<String> words, int count, String form) {
        if (words.size() != count + 1) {
            throw new IllegalArgumentException("'" + words.get(0) + "' takes " + count + (count == 1 ? " argument"
                    : " arguments") + ": " + form);
        }
    }

    /** A whole number within {@code min..max}. */
    static int number(String text, int min, int max, String what) {
        try {
            int value = Integer.parseInt(text);
            if (value >= min && value <= max) {
                return value;
            }
        } catch (NumberFormatException e) {
            // below
        }
        throw new IllegalArgumentException(what + " must be a whole number " + min + ".." + max + ", not '" + text
                + "'");
    }

    /** A finite decimal number. */
    static double decimal(String text, String what) {
        try {
            double value = Double.parseDouble(text);
            if (Double.isFinite(value)) {
                return value;
            }
        } catch (NumberFormatException e) {
            // below
        }
        throw new IllegalArgumentException(what + " must be a number, not '" + text + "'");
    }
}
