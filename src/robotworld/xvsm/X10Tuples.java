package robotworld.xvsm;

import robotworld.space.Entry;
import robotworld.space.IntEntry;

/**
 * Tuples of the X10 modules. Appliance (thesis table 4): {@code <key, functionCode>} with an integer code, below 0
 * off, else on ({@link #OFF_CODE} -1, {@link #ON_CODE} 1); the answer repeats the code, which is the new state.
 * Lamp (table 5): {@code <key, level, function>} with {@code function} one of {@code on off brighten dim} and the
 * level (the change in percent of the full range, 0..100) 0 for on and off; the answer repeats level and function.
 */
final class X10Tuples {

    static final int ON_CODE = 1;
    static final int OFF_CODE = -1;

    static final String ON = "on";
    static final String OFF = "off";
    static final String BRIGHTEN = "brighten";
    static final String DIM = "dim";
    /** The level of an on or off request. */
    static final int NO_LEVEL = 0;

    private X10Tuples() {
    }

    /** Whether an appliance function code means on. */
    static boolean isOn(Entry code) {
        if (!(code instanceof IntEntry number)) {
            throw new MalformedCallException("an X10 appliance function code is an integer, was " + code);
        }
        return number.value() >= 0;
    }

    /** Checks a brightness change, as the lamp module does. */
    static int level(int percent) {
        if (percent < 0 || percent > 100) {
            throw new IllegalArgumentException("a brightness amount is 0..100 percent, was " + percent);
        }
        return percent;
    }
}
