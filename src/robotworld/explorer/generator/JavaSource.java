package robotworld.explorer.generator;

import robotworld.description.JavaNames;

/**
 * Turns description values into Java source text safely. Every value a stylesheet writes into generated code
 * goes through one of these: a checked identifier, an escaped string literal, or text that cannot end or
 * escape from a comment.
 */
public final class JavaSource {

    private JavaSource() {
    }

    /** The name itself if it is a Java identifier (not a keyword); otherwise an {@link IllegalArgumentException}. */
    public static String identifier(String name) {
        if (!JavaNames.isIdentifier(name)) {
            throw new IllegalArgumentException("'" + name + "' is not a Java identifier");
        }
        return name;
    }

    /** The name itself if it is a dotted Java name (package or class); otherwise an exception. */
    public static String qualifiedName(String name) {
        if (!JavaNames.isQualifiedName(name)) {
            throw new IllegalArgumentException("'" + name + "' is not a Java package or class name");
        }
        return name;
    }

    /**
     * A Java string literal, quotes included. Everything outside printable ASCII is written as a
     * {@code \\uXXXX} escape, so the literal survives any source encoding and cannot contain a line break.
     */
    public static String stringLiteral(String value) {
        StringBuilder literal = new StringBuilder(value.length() + 2).append('"');
        for (int i = 0; i < value.length(); i++) {
            char c = value.charAt(i);
            switch (c) {
                case '"' -> literal.append("\\\"");
                case '\\' -> literal.append("\\\\");
                default -> {
                    if (c >= 0x20 && c < 0x7f) {
                        literal.append(c);
                    } else {
                        literal.append(String.format("\\u%04x", (int) c));
                    }
                }
            }
        }
        return literal.append('"').toString();
    }

    /**
     * Text for a {@code //} or {@code /* *}{@code /} comment (or an XML comment): on one line, without anything
     * that ends the comment or that javac would read as a unicode escape (javac translates {@code \\u000a} even
     * inside comments), and without invisible characters: control characters become blanks, and bidirectional
     * overrides and other formatting characters are written out as {@code [U+202E]}, so that a comment can
     * never make the code around it display differently from how it compiles ("Trojan source").
     */
    public static String commentText(String value) {
        StringBuilder text = new StringBuilder(value.length());
        for (int i = 0; i < value.length(); ) {
            int c = value.codePointAt(i);
            int next = i + Character.charCount(c);
            if (c == '\\') {
                text.append('/');
            } else if (c == '*' && next < value.length() && value.charAt(next) == '/') {
                text.append("* ");
            } else if (c == '-' && next < value.length() && value.charAt(next) == '-') {
                text.append("- "); // "--" may not appear in an XML comment
            } else if (c < 0x20 || c == 0x7f || (c >= 0x80 && c <= 0x9f)) {
                text.append(' ');
            } else if (isInvisible(c)) {
                text.append(String.format("[U+%04X]", c));
            } else {
                text.appendCodePoint(c);
            }
            i = next;
        }
        return text.toString().strip();
    }

    /** Formatting, separator, private-use, unassigned and lone surrogate characters: nothing a reader can see. */
    static boolean isInvisible(int c) {
        return switch (Character.getType(c)) {
            case Character.FORMAT, Character.LINE_SEPARATOR, Character.PARAGRAPH_SEPARATOR, Character.SURROGATE,
                 Character.PRIVATE_USE, Character.UNASSIGNED, Character.CONTROL -> true;
            default -> false;
        };
    }

    /** An X10 house code A..P as it stands in a char literal. */
    public static String houseCode(String code) {
        if (code == null || code.length() != 1 || code.charAt(0) < 'A' || code.charAt(0) > 'P') {
            throw new IllegalArgumentException("'" + code + "' is not an X10 house code A..P");
        }
        return code;
    }
}
