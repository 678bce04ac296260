package robotworld.description;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** Turns XMLBeans' and the parser's wording into messages a description author can act on. */
final class ErrorMessages {

    /** What each restricted type accepts, appended to "does not match" / "not a valid enumeration" errors. */
    private static final Map<String, String> ALLOWED = Map.ofEntries(
            Map.entry("IdentifierType", "letters, digits and _, not starting with a digit"),
            Map.entry("QualifiedNameType", "dot-separated Java identifiers"),
            Map.entry("ModuleNameType", "letters, digits, _ and -, starting with a letter"),
            Map.entry("NodeIdType", "letters, digits, _ and -"),
            Map.entry("NodeNumberType", "a bus address 1..247"),
            Map.entry("HostType", "a host name or IP address"),
            Map.entry("PortType", "a device such as /dev/ttyUSB0 or COM4, or tcp://host:port"),
            Map.entry("SpaceUrlType", "http://host:port/path"),
            Map.entry("HouseCodeType", "one letter A..P"),
            Map.entry("UnitCodeType", "ONE..SIXTEEN"),
            Map.entry("CommunicationTypeType", "xvsm or none"),
            Map.entry("BusModuleClassType", "ServoModule, BumperModule, IRDistanceModule or MotorModule"),
            Map.entry("X10ModuleClassType", "X10LampModule or X10ApplianceModule"),
            Map.entry("VersionType", "letters, digits, '.', '_' and '-'"),
            Map.entry("DocRefType", "a relative path or URL without blanks or quotes"));

    private static final String NAMESPACE_SUFFIX = " in namespace " + DescriptionKind.NAMESPACE;

    private ErrorMessages() {
    }

    static String schemaMessage(String raw) {
        String message = raw.replace("@" + DescriptionKind.NAMESPACE, "").replace(NAMESPACE_SUFFIX, "");
        for (Map.Entry<String, String> allowed : ALLOWED.entrySet()) {
            if (message.endsWith(" for " + allowed.getKey())) {
                return message + " (expected " + allowed.getValue() + ")";
            }
        }
        return message;
    }

    static String parserMessage(String raw) {
        if (raw == null || raw.isBlank()) {
            return "not well-formed XML";
        }
        if (raw.contains("DOCTYPE is disallowed")) {
            return "DOCTYPE declarations are not allowed in descriptions (no DTDs, no entities)";
        }
        if (raw.contains("Premature end of file")) {
            return "not well-formed XML: the document is empty or ends too early";
        }
        return "not well-formed XML: " + raw;
    }

    /**
     * XMLBeans reports a missing or misplaced element once for every following sibling. Keep only the first
     * of such a run: one mistake, one message.
     */
    static List<DescriptionError> withoutCascades(List<DescriptionError> errors) {
        List<DescriptionError> kept = new ArrayList<>(errors.size());
        String previousRun = null;
        for (DescriptionError error : errors) {
            String run = cascadeKey(error.message());
            if (run == null || !run.equals(previousRun)) {
                kept.add(error);
            }
            previousRun = run;
        }
        return kept;
    }

    /** "Expected element 'X' ... in element P" errors of one run share the expected element and the parent. */
    private static String cascadeKey(String message) {
        if (!message.startsWith("Expected element")) {
            return null;
        }
        int expectedEnd = message.indexOf('\'', message.indexOf('\'') + 1);
        int parent = message.lastIndexOf(" in element ");
        if (expectedEnd < 0 || parent < 0) {
            return null;
        }
        return message.substring(0, expectedEnd + 1) + message.substring(parent);
    }
}
