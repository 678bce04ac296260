package robotworld.safety;

/**
 * The safety values a description gives one module, in its optional {@code <Safety>} element; generated code
 * passes them to {@link SafetySupervisor#describe}. Each value is null when the description does not set it.
 * Run-time settings for the module override them ({@link SafetySettings}).
 *
 * @param commandTimeoutMillis {@code <CommandTimeout>}: how long a remote commander may be silent, in ms
 * @param watchdogMillis       {@code <Watchdog>}: the bus module's communication watchdog, in ms (0 = off)
 * @param safeState            {@code <SafeState>}: for X10 modules, {@code unchanged}, {@code off} or {@code on}
 */
public record ModuleSafety(Integer commandTimeoutMillis, Integer watchdogMillis, String safeState) {

    /** Nothing set. */
    public static final ModuleSafety NONE = new ModuleSafety(null, null, null);

    /** Checks the values. */
    public ModuleSafety {
        if (commandTimeoutMillis != null) {
            SafetySettings.checkCommandTimeout(java.time.Duration.ofMillis(commandTimeoutMillis));
        }
        if (watchdogMillis != null) {
            SafetySettings.checkWatchdog(watchdogMillis);
        }
        if (safeState != null) {
            X10SafeState.parse(safeState);
        }
    }
}
