package robotworld.bus;

import java.time.Duration;

/**
 * How patient the bus master is. All reply timeouts count from the moment the request has left the wire (its
 * wire time at the baud rate is added automatically).
 *
 * @param responseTimeout how long a module may take to start its reply in normal calls
 * @param attempts how often a call is sent in all (1 = no retry); timeouts, CRC errors and malformed replies
 *        are retried, exception responses are not
 * @param interByteTimeout the longest pause inside one reply; longer means the reply was cut short
 * @param scanAllowance in bus exploration, how long an address may take to start answering beyond the 3.5
 *        character silence; an absent address costs this much, so it is short (see {@code docs/bus.md})
 * @param frameGap silence kept before each request (Modbus asks for 3.5 characters; {@link Duration#ZERO} for
 *        links without a real line, e.g. a simulator in fast timing)
 * @param servoMoveTimeout how long {@code setServo} waits for a servo to report it reached its target
 */
public record BusTiming(Duration responseTimeout, int attempts, Duration interByteTimeout, Duration scanAllowance,
        Duration frameGap, Duration servoMoveTimeout) {

    /** The 3.5-character silence of the baud rate; resolved by the bus. */
    public static final Duration AUTO_FRAME_GAP = Duration.ofNanos(-1);

    public BusTiming {
        positive(responseTimeout, "response timeout");
        positive(interByteTimeout, "inter-byte timeout");
        positive(scanAllowance, "scan allowance");
        positive(servoMoveTimeout, "servo move timeout");
        if (attempts < 1 || attempts > 10) {
            throw new IllegalArgumentException("attempts must be 1..10, was " + attempts);
        }
        if (frameGap == null || (frameGap.isNegative() && !frameGap.equals(AUTO_FRAME_GAP))) {
            throw new IllegalArgumentException("frame gap must be zero, positive or AUTO_FRAME_GAP");
        }
    }

    /** The setting that changes the default response timeout, in milliseconds. */
    public static final String RESPONSE_TIMEOUT_PROPERTY = "rwe.bus.timeout.ms";

    /** The environment variable that does the same when the property is not given. */
    public static final String RESPONSE_TIMEOUT_VARIABLE = "RWE_BUS_TIMEOUT_MS";

    /**
     * Defaults for real modules: 100 ms to start a reply (or {@value #RESPONSE_TIMEOUT_PROPERTY} /
     * {@value #RESPONSE_TIMEOUT_VARIABLE}, for modules
     * reached through something slower than a serial line, such as a simulator on a busy machine), 3 attempts,
     * 20 ms inside a reply (a fifth of a longer response timeout), 8 ms scan allowance, the 3.5-character frame gap, 5 s for a servo move.
     *
     * @throws IllegalArgumentException when {@value #RESPONSE_TIMEOUT_PROPERTY} is set but not a positive number
     */
    public static BusTiming defaults() {
        Duration response = defaultResponseTimeout();
        // a link slow to start a reply (a gateway, a simulator on a busy machine) also pauses inside one: a fifth of
        // the response timeout, never less than the 20 ms a serial line needs
        Duration interByte = Duration.ofMillis(Math.max(20, response.toMillis() / 5));
        return new BusTiming(response, 3, interByte, Duration.ofMillis(8), AUTO_FRAME_GAP, Duration.ofSeconds(5));
    }

    private static Duration defaultResponseTimeout() {
        String value = System.getProperty(RESPONSE_TIMEOUT_PROPERTY);
        if (value == null || value.isBlank()) {
            // like the other run-time settings, also from the environment: it reaches programs started by others
            value = System.getenv(RESPONSE_TIMEOUT_VARIABLE);
        }
        if (value == null || value.isBlank()) {
            return Duration.ofMillis(100);
        }
        try {
            long millis = Long.parseLong(value.strip());
            if (millis >= 1) {
                return Duration.ofMillis(millis);
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException(RESPONSE_TIMEOUT_PROPERTY + " must be a number of milliseconds of at "
                + "least 1, was '" + value + "'");
    }

    public BusTiming withResponseTimeout(Duration timeout) {
        return new BusTiming(timeout, attempts, interByteTimeout, scanAllowance, frameGap, servoMoveTimeout);
    }

    public BusTiming withAttempts(int count) {
        return new BusTiming(responseTimeout, count, interByteTimeout, scanAllowance, frameGap, servoMoveTimeout);
    }

    public BusTiming withScanAllowance(Duration allowance) {
        return new BusTiming(responseTimeout, attempts, interByteTimeout, allowance, frameGap, servoMoveTimeout);
    }

    public BusTiming withFrameGap(Duration gap) {
        return new BusTiming(responseTimeout, attempts, interByteTimeout, scanAllowance, gap, servoMoveTimeout);
    }

    public BusTiming withServoMoveTimeout(Duration timeout) {
        return new BusTiming(responseTimeout, attempts, interByteTimeout, scanAllowance, frameGap, timeout);
    }

    private static void positive(Duration duration, String what) {
        if (duration == null || duration.isNegative() || duration.isZero()) {
            throw new IllegalArgumentException(what + " must be positive, was " + duration);
        }
    }
}
