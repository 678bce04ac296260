package robotworld.safety;

import java.util.Locale;

/**
 * What stopping does to an X10 module (lamp or appliance). The default is {@link #UNCHANGED}: switching a lamp or
 * appliance off can itself be unsafe (lights in a lab, a pump), so it is left as it is unless the description
 * ({@code <SafeState>} in the module's {@code <Safety>}) or the setting {@code rwe.x10.safe.state} says otherwise.
 */
public enum X10SafeState {
    /** Left as it is. */
    UNCHANGED,
    /** Switched off. */
    OFF,
    /** Switched on. */
    ON;

    /** {@code unchanged}, {@code off}, {@code on}. */
    public String wireName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * Reads {@code unchanged}, {@code off} or {@code on} (any case).
     *
     * @throws IllegalArgumentException for anything else
     */
    public static X10SafeState parse(String text) {
        for (X10SafeState state : values()) {
            if (state.wireName().equalsIgnoreCase(text.strip())) {
                return state;
            }
        }
        throw new IllegalArgumentException("an X10 safe state is unchanged, off or on, was '" + text + "'");
    }
}
