package robotworld.x10;

import java.time.Clock;
import java.time.Duration;

/**
 * Timeouts and retry limits of the host side of the CM11A protocol. The defaults follow heyu, a long-standing
 * CM11A client: 1 s for the checksum, 10 s for the "ready" byte after the power-line transmission, 3 attempts.
 *
 * @param checksumTimeout how long to wait for the checksum echo of a frame (and for each byte the interface
 *        sends on its own, such as the upload after 0xC3)
 * @param readyTimeout how long to wait for 0x55 after the 0x00 acknowledge; covers the power-line transmission,
 *        which takes seconds for long dims
 * @param maxAttempts how often one frame is sent before giving up on a missing or wrong checksum (at least 1)
 * @param maxPollsPerCommand how many interface polls one command may answer before it is abandoned, so a device
 *        that polls forever cannot keep a caller waiting forever
 * @param idlePollInterval how often an idle controller looks for polls (uploads, power fail)
 * @param interFrameGap pause before each frame; zero by default (heyu waits about 80 ms, which some old
 *        interfaces may need)
 * @param clock the time sent when the interface asks for it after a power failure
 * @param monitoredHouse the house code sent with the clock; the interface keeps status for this house
 */
public record CM11aConfig(Duration checksumTimeout, Duration readyTimeout, int maxAttempts, int maxPollsPerCommand,
        Duration idlePollInterval, Duration interFrameGap, Clock clock, HouseCode monitoredHouse) {

    public CM11aConfig {
        requirePositive("checksumTimeout", checksumTimeout);
        requirePositive("readyTimeout", readyTimeout);
        requirePositive("idlePollInterval", idlePollInterval);
        if (interFrameGap == null || interFrameGap.isNegative()) {
            throw new IllegalArgumentException("interFrameGap must be zero or positive");
        }
        if (maxAttempts < 1) {
            throw new IllegalArgumentException("maxAttempts must be at least 1, was " + maxAttempts);
        }
        if (maxPollsPerCommand < 1) {
            throw new IllegalArgumentException("maxPollsPerCommand must be at least 1, was " + maxPollsPerCommand);
        }
        if (clock == null || monitoredHouse == null) {
            throw new IllegalArgumentException("clock and monitoredHouse are required");
        }
    }

    private static void requirePositive(String name, Duration value) {
        if (value == null || value.isZero() || value.isNegative()) {
            throw new IllegalArgumentException(name + " must be positive, was " + value);
        }
    }

    /** heyu's timing: 1 s checksum, 10 s ready, 3 attempts; idle check every 20 ms; no gap; system clock; A. */
    public static CM11aConfig defaults() {
        return new CM11aConfig(Duration.ofSeconds(1), Duration.ofSeconds(10), 3, 10, Duration.ofMillis(20),
                Duration.ZERO, Clock.systemDefaultZone(), HouseCode.A);
    }

    /**
     * The longest a command waits on an interface that never answers before it throws
     * {@link X10TimeoutException}: {@code maxAttempts × checksumTimeout} (3 s by default).
     */
    public Duration deadDeviceTimeout() {
        return checksumTimeout.multipliedBy(maxAttempts);
    }

    /** This configuration with another {@code checksumTimeout}. */
    public CM11aConfig withChecksumTimeout(Duration value) {
        return new CM11aConfig(value, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                interFrameGap, clock, monitoredHouse);
    }

    /** This configuration with another {@code readyTimeout}. */
    public CM11aConfig withReadyTimeout(Duration value) {
        return new CM11aConfig(checksumTimeout, value, maxAttempts, maxPollsPerCommand, idlePollInterval,
                interFrameGap, clock, monitoredHouse);
    }

    /** This configuration with another {@code maxAttempts}. */
    public CM11aConfig withMaxAttempts(int value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, value, maxPollsPerCommand, idlePollInterval,
                interFrameGap, clock, monitoredHouse);
    }

    /** This configuration with another {@code maxPollsPerCommand}. */
    public CM11aConfig withMaxPollsPerCommand(int value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, value, idlePollInterval,
                interFrameGap, clock, monitoredHouse);
    }

    /** This configuration with another {@code idlePollInterval}. */
    public CM11aConfig withIdlePollInterval(Duration value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, value,
                interFrameGap, clock, monitoredHouse);
    }

    /** This configuration with another {@code interFrameGap}. */
    public CM11aConfig withInterFrameGap(Duration value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                value, clock, monitoredHouse);
    }

    /** This configuration with another {@code clock}. */
    public CM11aConfig withClock(Clock value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                interFrameGap, value, monitoredHouse);
    }

    /** This configuration with another {@code monitoredHouse}. */
    public CM11aConfig withMonitoredHouse(HouseCode value) {
        return new CM11aConfig(checksumTimeout, readyTimeout, maxAttempts, maxPollsPerCommand, idlePollInterval,
                interFrameGap, clock, value);
    }
}
