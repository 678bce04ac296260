package robotworld.xvsm;

import java.time.Duration;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;

/**
 * The runtime's tuning knobs with their run-time overrides (system property first, then environment variable),
 * in the manner of {@link robotworld.core.RuntimeSettings}:
 * <table>
 *   <caption>runtime defaults</caption>
 *   <tr><th>value</th><th>system property</th><th>environment variable</th><th>default</th></tr>
 *   <tr><td>remote call timeout</td><td>{@code rwe.call.timeout.ms}</td><td>{@code RWE_CALL_TIMEOUT_MS}</td>
 *       <td>10000</td></tr>
 *   <tr><td>publish local calls</td><td>{@code rwe.publish.local}</td><td>{@code RWE_PUBLISH_LOCAL}</td>
 *       <td>true</td></tr>
 *   <tr><td>adaptive batching of sensor requests</td><td>{@code rwe.sensor.batching}</td>
 *       <td>{@code RWE_SENSOR_BATCHING}</td><td>false</td></tr>
 * </table>
 *
 * @param callTimeout       how long a remote call waits for its answer
 * @param publishLocalCalls whether local calls publish their results under the own host name
 * @param sensorBatching    whether sensor modules answer all waiting requests from one hardware read
 */
record RuntimeDefaults(Duration callTimeout, boolean publishLocalCalls, boolean sensorBatching) {

    /** Ten seconds: longer than a servo move (5 s) and a queue of X10 commands at real power-line speed. */
    static final Duration DEFAULT_CALL_TIMEOUT = Duration.ofSeconds(10);

    RuntimeDefaults {
        checkTimeout(callTimeout);
    }

    /** From this JVM's system properties and environment. */
    static RuntimeDefaults fromSystem() {
        return of(System.getProperties(), System.getenv());
    }

    /** From the given sources. */
    static RuntimeDefaults of(Properties properties, Map<String, String> environment) {
        String timeout = lookup(properties, environment, "rwe.call.timeout.ms");
        String publish = lookup(properties, environment, "rwe.publish.local");
        String batching = lookup(properties, environment, "rwe.sensor.batching");
        return new RuntimeDefaults(timeout == null ? DEFAULT_CALL_TIMEOUT : parseMillis(timeout),
                publish == null || parseBoolean("rwe.publish.local", publish),
                batching != null && parseBoolean("rwe.sensor.batching", batching));
    }

    static Duration checkTimeout(Duration timeout) {
        if (timeout == null || timeout.isNegative() || timeout.isZero()) {
            throw new IllegalArgumentException("a call timeout must be positive, was " + timeout);
        }
        return timeout;
    }

    private static String lookup(Properties properties, Map<String, String> environment, String property) {
        String value = properties.getProperty(property);
        if (value == null || value.isBlank()) {
            value = environment.get(property.toUpperCase(Locale.ROOT).replace('.', '_'));
        }
        return value == null || value.isBlank() ? null : value.strip();
    }

    private static Duration parseMillis(String text) {
        try {
            return checkTimeout(Duration.ofMillis(Long.parseLong(text)));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("rwe.call.timeout.ms must be a number of milliseconds, was '" + text
                    + "'");
        }
    }

    private static boolean parseBoolean(String property, String text) {
        return switch (text.toLowerCase(Locale.ROOT)) {
            case "true", "yes", "on", "1" -> true;
            case "false", "no", "off", "0" -> false;
            default -> throw new IllegalArgumentException(property + " must be true or false, was '" + text + "'");
        };
    }
}
