package robotworld.explorer.monitor;

import java.util.Locale;
import java.util.Objects;
import org.apache.xmlbeans.XmlObject;

/**
 * One module of a RobotWorld as a monitor needs it: where it lives and what it is, plus its description element
 * ({@code Module} or {@code X10Module}) for anything type-specific.
 *
 * @param communicationType the world's communication type, e.g. {@code xvsm}
 * @param participant       the robot or environment the module belongs to
 * @param moduleName        the module's {@code <Name>}
 * @param moduleClass       the module's {@code <Class>}, e.g. {@code BumperModule}
 * @param description       the module's element in the world description (may be null in tests)
 */
public record MonitoredModule(String communicationType, String participant, String moduleName, String moduleClass,
                              XmlObject description) {

    /** The package that holds the monitors of every communication type, one sub-package per type. */
    public static final String LOGIC_PACKAGE = "robotworld.explorer.monitor.logic";

    /** Checks the names. */
    public MonitoredModule {
        Objects.requireNonNull(communicationType, "communicationType");
        Objects.requireNonNull(participant, "participant");
        Objects.requireNonNull(moduleName, "moduleName");
        Objects.requireNonNull(moduleClass, "moduleClass");
    }

    /**
     * The monitor class the naming convention asks for:
     * {@code robotworld.explorer.monitor.logic.<type>.<TYPE><Class>Monitor}.
     */
    public String monitorClassName() {
        return LOGIC_PACKAGE + "." + communicationType.toLowerCase(Locale.ROOT) + "."
                + communicationType.toUpperCase(Locale.ROOT) + moduleClass + "Monitor";
    }

    /** The module as the tap names it. */
    public robotworld.observe.ModuleRef ref() {
        return new robotworld.observe.ModuleRef(participant, moduleName, moduleClass);
    }

    /** {@code Participant/Module}, for messages and log lines. */
    public String label() {
        return participant + "/" + moduleName;
    }
}
