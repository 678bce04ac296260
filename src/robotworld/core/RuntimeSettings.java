package robotworld.core;

import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Properties;

/**
 * Where a participant program finds its space, its own host name and its serial ports. Each value has a default
 * from the RobotWorld description (baked into generated code) and can be overridden at run time, so the same
 * generated project runs against real hardware, simulators, or another space without regenerating:
 *
 * <table>
 *   <caption>overrides, system property first, then environment variable</caption>
 *   <tr><th>value</th><th>system property</th><th>environment variable</th></tr>
 *   <tr><td>space URL</td><td>{@code rwe.space.url}</td><td>{@code RWE_SPACE_URL}</td></tr>
 *   <tr><td>access token</td><td>{@code rwe.space.token}</td><td>{@code RWE_SPACE_TOKEN}</td></tr>
 *   <tr><td>a file holding the access token</td><td>{@code rwe.space.tokenFile}</td>
 *       <td>{@code RWE_SPACE_TOKEN_FILE}</td></tr>
 *   <tr><td>host name</td><td>{@code rwe.host}</td><td>{@code RWE_HOST}</td></tr>
 *   <tr><td>a participant's port</td><td>{@code rwe.port.<Participant>.<kind>}</td>
 *       <td>{@code RWE_PORT_<PARTICIPANT>_<KIND>}</td></tr>
 * </table>
 *
 * Port kinds: {@code bus} (a robot's or environment's module bus) and {@code x10} (an environment's CM11A).
 */
public final class RuntimeSettings {

    private final Properties properties;
    private final Map<String, String> environment;

    private RuntimeSettings(Properties properties, Map<String, String> environment) {
        this.properties = properties;
        this.environment = environment;
    }

    /** Settings from this JVM's system properties and environment. */
    public static RuntimeSettings fromSystem() {
        return new RuntimeSettings(System.getProperties(), System.getenv());
    }

    /** Settings from the given sources (for tests and embedding). */
    public static RuntimeSettings of(Properties properties, Map<String, String> environment) {
        return new RuntimeSettings(Objects.requireNonNull(properties), Objects.requireNonNull(environment));
    }

    /** The space URL: the override, or {@code fromDescription}; fails when neither is set. */
    public String spaceUrl(String fromDescription) {
        return required(lookup("rwe.space.url", "RWE_SPACE_URL", fromDescription),
                "no space URL: set <SpaceURL> in the world, -Drwe.space.url=... or RWE_SPACE_URL");
    }

    /**
     * The access token for the space, or null when none is configured: the token itself, else the contents of
     * the token file. A token on the command line ({@code -Drwe.space.token=...}) is visible to every user of the
     * computer in the process list, so it is warned about once; the environment variable and the file are not.
     *
     * @throws IllegalStateException when a token file is named but cannot be read or is empty
     */
    public String spaceToken() {
        String token = lookup("rwe.space.token", "RWE_SPACE_TOKEN", null);
        if (token != null) {
            TokenOnCommandLine.warnIfSo();
            return token;
        }
        String file = lookup("rwe.space.tokenFile", "RWE_SPACE_TOKEN_FILE", null);
        return file == null ? null : TokenFile.read(Path.of(file));
    }

    /** This program's host name: the override, or {@code fromDescription}. */
    public String hostName(String fromDescription) {
        return required(lookup("rwe.host", "RWE_HOST", fromDescription),
                "no host name: set <Host> in the description, -Drwe.host=... or RWE_HOST");
    }

    /**
     * A participant's serial port of the given kind ({@code bus} or {@code x10}): the override, or
     * {@code fromDescription}; fails with a message naming both override keys when neither is set.
     */
    public String port(String participant, String kind, String fromDescription) {
        String property = "rwe.port." + participant + "." + kind;
        String variable = ("RWE_PORT_" + participant + "_" + kind).toUpperCase(Locale.ROOT).replace('-', '_');
        return required(lookup(property, variable, fromDescription), "no " + kind + " port for " + participant
                + ": set it in the description, -D" + property + "=... or " + variable);
    }

    private String lookup(String property, String variable, String fallback) {
        String value = properties.getProperty(property);
        if (isBlank(value)) {
            value = environment.get(variable);
        }
        return isBlank(value) ? (isBlank(fallback) ? null : fallback) : value.strip();
    }

    private static String required(String value, String message) {
        if (value == null) {
            throw new IllegalStateException(message);
        }
        return value;
    }

    private static boolean isBlank(String value) {
        return value == null || value.isBlank();
    }
}
