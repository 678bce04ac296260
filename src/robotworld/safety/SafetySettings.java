package robotworld.safety;

import java.time.Duration;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Properties;

/**
 * The safety layer's settings and where they come from. For each value, the first that is set wins:
 * <ol>
 *   <li>the setting for the module: system property {@code <key>.<Participant>.<Module>}, else environment
 *       variable {@code <KEY>_<PARTICIPANT>_<MODULE>} (upper case, dots and dashes as underscores);</li>
 *   <li>the module's {@code <Safety>} element in the description ({@link ModuleSafety});</li>
 *   <li>the setting for every module: system property {@code <key>}, else environment variable {@code <KEY>};</li>
 *   <li>the default.</li>
 * </ol>
 * <table>
 *   <caption>safety settings</caption>
 *   <tr><th>value</th><th>key</th><th>default</th></tr>
 *   <tr><td>command timeout (ms)</td><td>{@code rwe.command.timeout.ms}</td><td>500</td></tr>
 *   <tr><td>bus watchdog of a motor module (ms, 0 = off)</td><td>{@code rwe.watchdog.ms}</td><td>500</td></tr>
 *   <tr><td>bus watchdog of a servo module (ms, 0 = off)</td><td>{@code rwe.watchdog.ms}</td><td>0: a servo's
 *       safe state is to hold, which it does without one</td></tr>
 *   <tr><td>X10 safe state</td><td>{@code rwe.x10.safe.state}</td><td>unchanged</td></tr>
 *   <tr><td>heartbeat period (ms, 0 = none; only for the whole program)</td><td>{@code rwe.heartbeat.ms}</td>
 *       <td>100</td></tr>
 *   <tr><td>what losing the space stops: {@code all}, or {@code remote} (only what programs elsewhere commanded
 *       through the space)</td><td>{@code rwe.space.loss.stops}</td><td>all</td></tr>
 * </table>
 * Immutable.
 */
public final class SafetySettings {

    /** Default command timeout: a remote commander silent this long has its actuators stopped. */
    public static final Duration DEFAULT_COMMAND_TIMEOUT = Duration.ofMillis(500);
    /** Default bus watchdog of a motor module. */
    public static final int DEFAULT_MOTOR_WATCHDOG_MILLIS = 500;
    /** Default heartbeat period. */
    public static final Duration DEFAULT_HEARTBEAT = Duration.ofMillis(100);
    /** The shortest command timeout accepted: shorter ones stop actuators for a busy network alone. */
    public static final Duration SHORTEST_COMMAND_TIMEOUT = Duration.ofMillis(50);

    static final String COMMAND_TIMEOUT = "rwe.command.timeout.ms";
    static final String WATCHDOG = "rwe.watchdog.ms";
    static final String X10_SAFE_STATE = "rwe.x10.safe.state";
    static final String HEARTBEAT = "rwe.heartbeat.ms";
    static final String SPACE_LOSS_STOPS = "rwe.space.loss.stops";

    private final Properties properties;
    private final Map<String, String> environment;

    private SafetySettings(Properties properties, Map<String, String> environment) {
        this.properties = properties;
        this.environment = environment;
    }

    /** From this JVM's system properties and environment. */
    public static SafetySettings fromSystem() {
        return new SafetySettings(System.getProperties(), System.getenv());
    }

    /** From the given sources (tests, embedding). */
    public static SafetySettings of(Properties properties, Map<String, String> environment) {
        return new SafetySettings(Objects.requireNonNull(properties), Objects.requireNonNull(environment));
    }

    /** The command timeout of a module. */
    public Duration commandTimeout(String participant, String module, ModuleSafety described,
                                   Duration programDefault) {
        String perModule = lookup(COMMAND_TIMEOUT + "." + participant + "." + module);
        if (perModule != null) {
            return checkCommandTimeout(millis(COMMAND_TIMEOUT + "." + participant + "." + module, perModule));
        }
        if (described.commandTimeoutMillis() != null) {
            return Duration.ofMillis(described.commandTimeoutMillis());
        }
        return programDefault;
    }

    /** The command timeout for modules without their own: {@code rwe.command.timeout.ms}, else 500 ms. */
    public Duration defaultCommandTimeout() {
        String value = lookup(COMMAND_TIMEOUT);
        return value == null ? DEFAULT_COMMAND_TIMEOUT : checkCommandTimeout(millis(COMMAND_TIMEOUT, value));
    }

    /**
     * The bus watchdog of a module in ms, 0 for none.
     *
     * @param typeDefault the module type's default ({@link #DEFAULT_MOTOR_WATCHDOG_MILLIS} for motors, 0 for
     *                    modules whose safe state needs no watchdog)
     */
    public int watchdogMillis(String participant, String module, ModuleSafety described, int typeDefault) {
        String perModule = lookup(WATCHDOG + "." + participant + "." + module);
        if (perModule != null) {
            return checkWatchdog(millis(WATCHDOG + "." + participant + "." + module, perModule).toMillis());
        }
        if (described.watchdogMillis() != null) {
            return described.watchdogMillis();
        }
        String everyModule = lookup(WATCHDOG);
        if (everyModule != null && typeDefault > 0) {
            return checkWatchdog(millis(WATCHDOG, everyModule).toMillis());
        }
        return typeDefault;
    }

    /** What stopping does to an X10 module. */
    public X10SafeState x10SafeState(String participant, String module, ModuleSafety described) {
        String perModule = lookup(X10_SAFE_STATE + "." + participant + "." + module);
        if (perModule != null) {
            return X10SafeState.parse(perModule);
        }
        if (described.safeState() != null) {
            return X10SafeState.parse(described.safeState());
        }
        String everyModule = lookup(X10_SAFE_STATE);
        return everyModule == null ? X10SafeState.UNCHANGED : X10SafeState.parse(everyModule);
    }

    /**
     * Whether losing the space stops (and holds) a module's actuator even when only its own serving program commands
     * it ({@code all}, the default: without its space nobody elsewhere could stop it), or only when a program
     * elsewhere commanded it through the space ({@code remote}).
     */
    public boolean spaceLossStopsAll(String participant, String module) {
        String key = SPACE_LOSS_STOPS + "." + participant + "." + module;
        String value = lookup(key);
        if (value == null) {
            key = SPACE_LOSS_STOPS;
            value = lookup(key);
        }
        if (value == null) {
            return true;
        }
        return switch (value.toLowerCase(Locale.ROOT)) {
            case "all" -> true;
            case "remote" -> false;
            default -> throw new IllegalArgumentException(key + " is 'all' or 'remote', was '" + value + "'");
        };
    }

    /** How often the program sends a heartbeat; zero for none. */
    public Duration heartbeatPeriod() {
        String value = lookup(HEARTBEAT);
        if (value == null) {
            return DEFAULT_HEARTBEAT;
        }
        Duration period = millis(HEARTBEAT, value);
        if (period.isNegative()) {
            throw new IllegalArgumentException(HEARTBEAT + " must not be negative, was " + value);
        }
        return period;
    }

    /**
     * Checks a command timeout.
     *
     * @throws IllegalArgumentException when it is null or shorter than {@link #SHORTEST_COMMAND_TIMEOUT}
     */
    public static Duration checkCommandTimeout(Duration timeout) {
        if (timeout == null || timeout.compareTo(SHORTEST_COMMAND_TIMEOUT) < 0) {
            throw new IllegalArgumentException("a command timeout must be at least "
                    + SHORTEST_COMMAND_TIMEOUT.toMillis() + " ms, was " + (timeout == null ? null
                    : timeout.toMillis() + " ms"));
        }
        return timeout;
    }

    /**
     * Checks a watchdog timeout: 0 (off) or 10..65535 ms (one holding register).
     *
     * @throws IllegalArgumentException otherwise
     */
    public static int checkWatchdog(long millis) {
        if (millis != 0 && (millis < 10 || millis > 65_535)) {
            throw new IllegalArgumentException("a watchdog timeout is 0 (off) or 10..65535 ms, was " + millis);
        }
        return (int) millis;
    }

    private String lookup(String key) {
        String value = properties.getProperty(key);
        if (value == null || value.isBlank()) {
            value = environment.get(key.toUpperCase(Locale.ROOT).replace('.', '_').replace('-', '_'));
        }
        return value == null || value.isBlank() ? null : value.strip();
    }

    private static Duration millis(String key, String text) {
        try {
            return Duration.ofMillis(Long.parseLong(text));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(key + " must be a number of milliseconds, was '" + text + "'");
        }
    }
}
