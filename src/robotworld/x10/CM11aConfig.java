package robotworld.x10;

import java.time.Clock;
import java.time.Duration;

/**
 * Timeouts, pauses and retry limits of the host side of the CM11A protocol. The defaults are those of the reference
 * client (heyu, a long-standing CM11A client): 1 s for the checksum, 10 s for the "ready" byte after the
 * power-line transmission, 80 ms of quiet after each "ready" before the next frame, 1 s before a frame is sent
 * again after a wrong checksum, 3 attempts, an interface that says nothing for 6 s declared dead, and the clock
 * set in standard time.
 *
 * @param checksumTimeout how long to wait for the checksum echo of a frame (and for each byte the interface
 *        sends on its own, such as the upload after 0xC3)
 * @param readyTimeout how long to wait for 0x55 after the 0x00 acknowledge; covers the power-line transmission,
 *        which takes seconds for long dims
 * @param maxAttempts how often one frame is sent before giving up on wrong checksums (at least 1)
 * @param maxPollsPerCommand how many interface polls one command may answer before it is abandoned, so a device
 *        that polls forever cannot keep a caller waiting forever
 * @param idlePollInterval how often an idle controller looks for polls (uploads, power fail)
 * @param pauseAfterReady quiet kept after each 0x55 before the next frame goes out (the interface is still busy
 *        with the power line just after it)
 * @param resendDelay pause before a frame is sent again after a wrong checksum, so the interface has given up
 *        waiting for the 0x00 of the first try
 * @param deadInterfaceTimeout how long an interface may stay completely silent (the frame is sent again each
 *        {@code checksumTimeout}) before a command fails with {@link X10TimeoutException}
 * @param clock where the time sent to the interface comes from (after a power failure, or by {@code setClock})
 * @param clockTime whether that time is sent as standard time or as the legal (summer) time of the clock's zone
 * @param monitoredHouse the house code sent with the clock; the interface keeps status for this house
 */
public record CM11aConfig(Duration checksumTimeout, Duration readyTimeout, int maxAttempts, int maxPollsPerCommand,
        Duration idlePollInterval, Duration pauseAfterReady, Duration resendDelay, Duration deadInterfaceTimeout,
        Clock clock, ClockTime clockTime, HouseCode monitoredHouse) {

    /** Which time of day the interface's clock is set to. */
    public enum ClockTime {
        /**
         * The zone's standard time all year, as the reference client sends it: timers uploaded to the interface
         * are written in standard time, so a clock in summer time would run them an hour off.
         */
        STANDARD,
        /** The zone's legal time (summer time in summer). */
        LEGAL
    }

    public CM11aConfig {
        requirePositive("checksumTimeout", checksumTimeout);
        requirePositive("readyTimeout", readyTimeout);
        requirePositive("idlePollInterval", idlePollInterval);
        requirePositive("deadInterfaceTimeout", deadInterfaceTimeout);
        requireNotNegative("pauseAfterReady", pauseAfterReady);
        requireNotNegative("resendDelay", resendDelay);
        if (maxAttempts < 1) {
            throw new IllegalArgumentException("maxAttempts must be at least 1, was " + maxAttempts);
        }
        if (maxPollsPerCommand < 1) {
            throw new IllegalArgumentException("maxPollsPerCommand must be at least 1, was " + maxPollsPerCommand);
        }
        if (clock == null || clockTime == null || monitoredHouse == null) {
            throw new IllegalArgumentException("clock, clockTime and monitoredHouse are required");
        }
    }

    private static void requirePositive(String name, Duration value) {
        if (value == null || value.isZero() || value.isNegative()) {
            throw new IllegalArgumentException(name + " must be positive, was " + value);
        }
    }

    private static void requireNotNegative(String name, Duration value) {
        if (value == null || value.isNegative()) {
            throw new IllegalArgumentException(name + " must be zero or positive, was " + value);
        }
    }

    /**
     * The reference client's timing: 1 s checksum, 10 s ready, 80 ms after each ready, 1 s before a resend, 3
     * attempts, dead after 6 s of silence; idle check every 20 ms; the system clock in standard time; house A.
     */
    public static CM11aConfig defaults() {
        return new CM11aConfig(Duration.ofSeconds(1), Duration.ofSeconds(10), 3, 10, Duration.ofMillis(20),
                Duration.ofMillis(80), Duration.ofSeconds(1), Duration.ofSeconds(6), Clock.systemDefaultZone(),
                ClockTime.STANDARD, HouseCode.A);
    }

    /** How often a frame is sent to an interface that never answers: one send per checksum timeout. */
    public int sendsToASilentInterface() {
        return (int) Math.max(1, deadInterfaceTimeout.toNanos() / checksumTimeout.toNanos());
    }

    /**
     * The longest a command waits on an interface that never answers before it throws
     * {@link X10TimeoutException}: {@link #sendsToASilentInterface()} × {@code checksumTimeout}, which is
     * {@code deadInterfaceTimeout} rounded down to whole checksum timeouts (6 s by default).
     */
    public Duration deadDeviceTimeout() {
        return checksumTimeout.multipliedBy(sendsToASilentInterface());
    }

    /** This configuration with another {@code checksumTimeout}. */
    public CM11aConfig withChecksumTimeout(Duration value) {
        return new CM11aConfig(value, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                pauseAfterReady, resendDelay, deadInterfaceTimeout, clock, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code readyTimeout}. */
    public CM11aConfig withReadyTimeout(Duration value) {
        return new CM11aConfig(checksumTimeout, value, maxAttempts, maxPollsPerCommand, idlePollInterval,
                pauseAfterReady, resendDelay, deadInterfaceTimeout, clock, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code maxAttempts}. */
    public CM11aConfig withMaxAttempts(int value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, value, maxPollsPerCommand, idlePollInterval,
                pauseAfterReady, resendDelay, deadInterfaceTimeout, clock, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code maxPollsPerCommand}. */
    public CM11aConfig withMaxPollsPerCommand(int value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, value, idlePollInterval,
                pauseAfterReady, resendDelay, deadInterfaceTimeout, clock, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code idlePollInterval}. */
    public CM11aConfig withIdlePollInterval(Duration value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, value,
                pauseAfterReady, resendDelay, deadInterfaceTimeout, clock, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code pauseAfterReady}. */
    public CM11aConfig withPauseAfterReady(Duration value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                value, resendDelay, deadInterfaceTimeout, clock, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code resendDelay}. */
    public CM11aConfig withResendDelay(Duration value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                pauseAfterReady, value, deadInterfaceTimeout, clock, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code deadInterfaceTimeout}. */
    public CM11aConfig withDeadInterfaceTimeout(Duration value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                pauseAfterReady, resendDelay, value, clock, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code clock}. */
    public CM11aConfig withClock(Clock value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                pauseAfterReady, resendDelay, deadInterfaceTimeout, value, clockTime, monitoredHouse);
    }

    /** This configuration with another {@code clockTime}. */
    public CM11aConfig withClockTime(ClockTime value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                pauseAfterReady, resendDelay, deadInterfaceTimeout, clock, value, monitoredHouse);
    }

    /** This configuration with another {@code monitoredHouse}. */
    public CM11aConfig withMonitoredHouse(HouseCode value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                pauseAfterReady, resendDelay, deadInterfaceTimeout, clock, clockTime, value);
    }

    /**
     * No pauses, for simulators in fast timing and tests, never for a real interface. The timeouts are generous
     * (5 s for a checksum, 10 s for the ready byte, dead after 10 s): they only run out when something is wrong,
     * and short ones would run out on a busy machine where nothing is. Tests of the timeouts themselves set their
     * own.
     */
    public CM11aConfig forFastSimulator() {
        return withChecksumTimeout(Duration.ofSeconds(5)).withReadyTimeout(Duration.ofSeconds(10))
                .withDeadInterfaceTimeout(Duration.ofSeconds(10)).withIdlePollInterval(Duration.ofMillis(5))
                .withPauseAfterReady(Duration.ZERO).withResendDelay(Duration.ZERO);
    }
}
