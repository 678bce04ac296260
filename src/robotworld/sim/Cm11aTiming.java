package robotworld.sim;

import java.time.Duration;
import robotworld.x10.X10Constants;

/**
 * How fast the simulated CM11A answers.
 *
 * @param characterTime time of one character on the serial line (4800 baud 8N1: about 2.08 ms); zero = no pacing
 * @param powerLineTime time one frame takes on the power line, between the host's 0x00 and the 0x55
 * @param pollInterval time between two polls (0x5A, 0xA5); the real interface polls once a second
 * @param hostTimeout how long the interface waits for the rest of a frame and for the host's 0x00
 */
public record Cm11aTiming(Duration characterTime, Duration powerLineTime, Duration pollInterval,
        Duration hostTimeout) {

    /**
     * Power-line time of one X10 frame at 50 Hz mains: the frame is sent twice (22 cycles) plus the 3 silent
     * cycles that end it, 25 cycles = 500 ms. (At 60 Hz it would be about 417 ms.)
     */
    public static final Duration DEFAULT_POWER_LINE_TIME = Duration.ofMillis(500);

    public Cm11aTiming {
        for (Duration d : new Duration[] {characterTime, powerLineTime, pollInterval, hostTimeout}) {
            if (d == null || d.isNegative()) {
                throw new IllegalArgumentException("timings must be zero or positive");
            }
        }
        if (pollInterval.isZero() || hostTimeout.isZero()) {
            throw new IllegalArgumentException("poll interval and host timeout must be positive");
        }
    }

    /** The real device: 4800 baud pacing, 500 ms per power-line frame, a poll per second. */
    public static Cm11aTiming real() {
        return real(DEFAULT_POWER_LINE_TIME);
    }

    /** The real device with another power-line time per frame. */
    public static Cm11aTiming real(Duration powerLineTime) {
        return new Cm11aTiming(Duration.ofNanos(X10Constants.CM11A_SERIAL.characterTimeNanos()), powerLineTime,
                Duration.ofSeconds(1), Duration.ofSeconds(1));
    }

    /**
     * As fast as the machine allows: no pacing, no power-line time, a poll every 20 ms. For tests. The interface
     * waits up to {@value #FAST_HOST_TIMEOUT_SECONDS} s for the host's 0x00: a busy machine can hold the host back
     * for longer than a real interface would wait, and a simulator that gave up then would make the host's next
     * command fail for no fault of its own. (A host that resends a frame in place of the 0x00 is served at once.)
     */
    public static Cm11aTiming fast() {
        return new Cm11aTiming(Duration.ZERO, Duration.ZERO, Duration.ofMillis(20),
                Duration.ofSeconds(FAST_HOST_TIMEOUT_SECONDS));
    }

    /** How long a simulator in {@link #fast()} timing waits for the rest of a frame and for the 0x00. */
    public static final int FAST_HOST_TIMEOUT_SECONDS = 10;

    /** Whether characters are paced at the baud rate. */
    public boolean isPaced() {
        return !characterTime.isZero();
    }

    /** This timing with another {@code powerLineTime}. */
    public Cm11aTiming withPowerLineTime(Duration value) {
        return new Cm11aTiming(characterTime, value, pollInterval, hostTimeout);
    }

    /** This timing with another {@code pollInterval}. */
    public Cm11aTiming withPollInterval(Duration value) {
        return new Cm11aTiming(characterTime, powerLineTime, value, hostTimeout);
    }

    /** This timing with another {@code hostTimeout}. */
    public Cm11aTiming withHostTimeout(Duration value) {
        return new Cm11aTiming(characterTime, powerLineTime, pollInterval, value);
    }
}
