package robotworld.core;

/**
 * An X10 lamp module: a dimmable lamp in the environment, addressed by house code and unit code.
 * X10 lamp modules only understand relative changes of brightness, in 22 steps over the full range, and report
 * nothing back; so {@code brighten} and {@code dim} take the amount of the change, in percent of the full range,
 * and it is rounded to the nearest step (one step is about 4.5 %). Implementations signal a failed command with
 * an unchecked exception.
 */
public interface X10LampModule {

    /**
     * Makes the lamp brighter.
     *
     * @param level the change, 0..100 percent of the full range (0 does nothing)
     * @throws IllegalArgumentException when level is outside 0..100
     */
    void brighten(int level);

    /**
     * Makes the lamp darker.
     *
     * @param level the change, 0..100 percent of the full range (0 does nothing)
     * @throws IllegalArgumentException when level is outside 0..100
     */
    void dim(int level);

    /** Switches the lamp on. */
    void on();

    /** Switches the lamp off. */
    void off();
}
