package robotworld.core;

/**
 * A bumper sensor module: {@value #BUMPERS} micro-switch bumpers, numbered 1..{@value #BUMPERS}, that close while the
 * robot touches something.
 */
public interface BumperModule {

    /** Number of bumpers. */
    int BUMPERS = 8;

    /**
     * Reads all bumpers at once.
     *
     * @return a bit mask: bit {@code n-1} is set while bumper {@code n} has contact (0 = nothing touched)
     */
    int getAllBumper();

    /**
     * Reads one bumper.
     *
     * @param bumperNumber 1..{@value #BUMPERS}
     * @return {@code true} while the bumper has contact
     */
    boolean getSingleBumper(int bumperNumber);
}
