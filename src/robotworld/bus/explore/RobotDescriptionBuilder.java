package robotworld.bus.explore;

import java.util.List;
import java.util.regex.Pattern;
import robotworld.description.BusModuleClassType;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.ModuleListType;
import robotworld.description.ModuleType;
import robotworld.description.RobotDescriptionDocument;

/** Writes explored modules into a robot description and validates it with the description loader's rules. */
public final class RobotDescriptionBuilder {

    /** The bus class of robots whose modules speak Modbus RTU on RS-485. */
    public static final String BUS_CLASS = "RS485Bus";

    /** PortType of the schema: only such port names can go into {@code <COMPort>}. */
    private static final Pattern PORT = Pattern.compile(
            "tcp://([A-Za-z0-9]([A-Za-z0-9.\\-]*[A-Za-z0-9])?|\\[[0-9A-Fa-f:.]+\\]):[0-9]{1,5}"
                    + "|/[A-Za-z0-9._\\-]+(/[A-Za-z0-9._\\-]+)*|[A-Za-z][A-Za-z0-9._\\-]*");

    private RobotDescriptionBuilder() {
    }

    /** Whether a port name fits {@code <COMPort>}. */
    public static boolean isDescribablePort(String port) {
        return port != null && port.length() <= 200 && PORT.matcher(port).matches();
    }

    /**
     * A validated robot description.
     *
     * @param port goes into {@code <COMPort>}; null to leave it out
     * @param details per module (same order), or null entries for none: the catalogue's details
     * @param docRefs per module (same order), or null entries
     * @throws DescriptionException when the result breaks a rule (e.g. a robot name that is a Java keyword)
     */
    public static RobotDescriptionDocument build(String robotName, String host, String port, List<FoundModule> modules,
            List<String> details, List<String> docRefs) throws DescriptionException {
        RobotDescriptionDocument document = RobotDescriptionDocument.Factory.newInstance();
        ModuleListType robot = document.addNewRobotDescription();
        robot.setRobotName(robotName);
        robot.setHost(host);
        if (port != null) {
            robot.setCOMPort(port);
        }
        robot.setTalkToBusClass(BUS_CLASS);
        for (int i = 0; i < modules.size(); i++) {
            FoundModule found = modules.get(i);
            ModuleType module = robot.addNewModule();
            module.setName(found.name());
            module.setNodeID(found.nodeId());
            module.setNodeNumber(found.address());
            module.setClass1(BusModuleClassType.Enum.forString(found.moduleClass()));
            module.setVersion(found.version());
            if (details.get(i) != null) {
                module.setDetails(details.get(i));
            }
            if (docRefs.get(i) != null) {
                module.setDocRef(docRefs.get(i));
            }
        }
        DescriptionLoader.validate(document, "explored robot '" + robotName + "'");
        return document;
    }

    /**
     * Checks a robot name and host before a scan, so a bad name fails at once and not after the scan.
     *
     * @throws DescriptionException listing what is wrong with them
     */
    public static void checkNames(String robotName, String host) throws DescriptionException {
        FoundModule sample = new FoundModule(1, "Sample", "Sample", "MotorModule", "1.0", "");
        build(robotName, host, null, List.of(sample), java.util.Collections.singletonList(null),
                java.util.Collections.singletonList(null));
    }
}
