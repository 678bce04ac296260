package robotworld.description;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import javax.xml.namespace.QName;
import org.apache.xmlbeans.XmlAnySimpleType;
import org.apache.xmlbeans.XmlCursor;
import org.apache.xmlbeans.XmlError;
import org.apache.xmlbeans.XmlObject;
import org.apache.xmlbeans.XmlValidationError;

/**
 * Turns XMLBeans' and the parser's wording into messages a description author can act on: which element, what
 * it may hold, and what it held ("RobotName: names may contain only letters, digits and _ ...; got 'my robot'").
 */
final class ErrorMessages {

    /** What each restricted type accepts, in words. */
    private static final Map<String, String> ALLOWED = Map.ofEntries(
            Map.entry("IdentifierType", "names may contain only letters, digits and _, and may not start with a"
                    + " digit"),
            Map.entry("QualifiedNameType", "a Java package or class name is made of letters, digits and _, in"
                    + " parts joined by dots (like my.robots)"),
            Map.entry("ModuleNameType", "module names may contain only letters, digits, _ and -, and start with a"
                    + " letter"),
            Map.entry("NodeIdType", "a NodeID may contain only letters, digits, _ and -"),
            Map.entry("NodeNumberType", "a bus address is a number from 1 to 247"),
            Map.entry("HostType", "a host is a computer's name or IP address (robot-laptop, 192.168.1.20) or a URL"
                    + " (http://robot-laptop:8080/)"),
            Map.entry("PortType", "a port is a serial device (/dev/ttyUSB0, COM4) or tcp://host:port"),
            Map.entry("SpaceUrlType", "the space URL is http://host:port/path (like http://localhost:9876/space),"
                    + " or several servers' URLs separated by commas"),
            Map.entry("HouseCodeType", "an X10 house code is one capital letter from A to P"),
            Map.entry("UnitCodeType", "an X10 unit code is a number word from ONE to SIXTEEN"),
            Map.entry("CommunicationTypeType", "the communication type is xvsm or none"),
            Map.entry("BusModuleClassType", "a bus module's class is one of the bus module classes (MotorModule,"
                    + " ServoModule, ...)"),
            Map.entry("X10ModuleClassType", "an X10 module's class is X10LampModule or X10ApplianceModule"),
            Map.entry("AnyModuleClassType", "a module's class is one of the module classes (MotorModule,"
                    + " X10LampModule, ...)"),
            Map.entry("VersionType", "a version may contain only letters, digits, '.', '_' and '-'"),
            Map.entry("DocRefType", "a DocRef is a relative path or URL without spaces or quotes"),
            Map.entry("DetailsType", "details are at most 1000 characters of text"),
            Map.entry("CommandTimeoutType", "a command timeout is a number of milliseconds from 50 to 3600000"),
            Map.entry("WatchdogType", "a watchdog time is 0 (off) or a number of milliseconds from 10 to 65535"),
            Map.entry("X10SafeStateType", "an X10 module's safe state is unchanged, off or on"));

    /** Types whose message lists the values of the schema in use, after these words. */
    private static final Map<String, String> ENUMERATED = Map.of(
            "BusModuleClassType", "a bus module's class is ",
            "X10ModuleClassType", "an X10 module's class is ");

    private static final String NAMESPACE_SUFFIX = " in namespace " + DescriptionKind.NAMESPACE;

    private static final Pattern FOR_TYPE = Pattern.compile(" for (\\w+)$");

    private ErrorMessages() {
    }

    /** One schema error in words, with what tells a cascade of the same mistake. */
    record Described(String message, String cascadeKey) {
    }

    static Described schemaError(XmlError error) {
        if (error instanceof XmlValidationError validation && validation.getExpectedQNames() != null
                && !validation.getExpectedQNames().isEmpty() && validation.getFieldQName() != null) {
            return structure(validation);
        }
        String raw = plain(error.getMessage());
        Matcher type = FOR_TYPE.matcher(raw);
        ElementValue at = elementValue(error);
        if (type.find() && ENUMERATED.containsKey(type.group(1)) && at != null && !at.choices().isEmpty()) {
            // the choices of the schemas in use, which may list module classes added at run time
            return new Described(prefix(at) + ENUMERATED.get(type.group(1)) + oneOf(at.choices()) + got(at), null);
        }
        if (type.find(0) && ALLOWED.containsKey(type.group(1))) {
            return new Described(prefix(at) + ALLOWED.get(type.group(1)) + got(at), null);
        }
        if (raw.startsWith("Invalid decimal value") || raw.startsWith("Invalid int value")) {
            String expected = at == null ? "a number is expected" : switch (at.element()) {
                case "NodeNumber" -> ALLOWED.get("NodeNumberType");
                case "CommandTimeout" -> ALLOWED.get("CommandTimeoutType");
                case "Watchdog" -> ALLOWED.get("WatchdogType");
                default -> "a number is expected";
            };
            return new Described(prefix(at) + expected + got(at), null);
        }
        return new Described(prefix(at) + raw, null);
    }

    /** Errors of the element structure: a missing, misplaced or unknown element. */
    private static Described structure(XmlValidationError error) {
        String parent = "<" + error.getFieldQName().getLocalPart() + ">";
        List<QName> expectedNames = error.getExpectedQNames();
        String expected = expectedNames.stream().map(q -> "<" + q.getLocalPart() + ">")
                .collect(Collectors.joining(" or "));
        String key = expected + " in " + parent;
        QName offending = error.getOffendingQName();
        if (offending != null) {
            return new Described(parent + ": expected " + expected + " here, found <" + offending.getLocalPart()
                    + ">", key);
        }
        return new Described(parent + ": " + expected + " is missing (before the end of " + parent + ")", key);
    }

    /** Which element held which value, and the values its type allows if it lists them, where XMLBeans tells. */
    private record ElementValue(String element, String value, List<String> choices) {
    }

    private static String oneOf(List<String> choices) {
        if (choices.size() == 1) {
            return choices.get(0);
        }
        return String.join(", ", choices.subList(0, choices.size() - 1)) + " or " + choices.get(choices.size() - 1);
    }

    private static ElementValue elementValue(XmlError error) {
        XmlCursor location = error.getCursorLocation();
        if (location == null) {
            return null;
        }
        try (XmlCursor cursor = location.newCursor()) {
            if (!cursor.currentTokenType().isStart() && !cursor.toParent()) {
                return null;
            }
            QName name = cursor.getName();
            if (name == null) {
                return null;
            }
            List<String> choices = new ArrayList<>();
            XmlObject element = cursor.getObject();
            XmlAnySimpleType[] values = element == null ? null : element.schemaType().getEnumerationValues();
            if (values != null) {
                for (XmlAnySimpleType value : values) {
                    choices.add(value.getStringValue());
                }
            }
            return new ElementValue(name.getLocalPart(), cursor.getTextValue(), choices);
        } catch (RuntimeException e) {
            return null; // the position is only decoration: never fail a report because of it
        }
    }

    private static String prefix(ElementValue at) {
        return at == null ? "" : at.element() + ": ";
    }

    private static String got(ElementValue at) {
        if (at == null) {
            return "";
        }
        String value = at.value().strip();
        return "; got '" + (value.length() > 60 ? value.substring(0, 57) + "..." : value) + "'";
    }

    private static String plain(String raw) {
        return raw == null ? "invalid" : raw.replace("@" + DescriptionKind.NAMESPACE, "").replace(NAMESPACE_SUFFIX, "");
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
    static List<DescriptionError> withoutCascades(List<DescriptionError> errors, List<String> cascadeKeys) {
        List<DescriptionError> kept = new ArrayList<>(errors.size());
        String previousRun = null;
        for (int i = 0; i < errors.size(); i++) {
            String run = cascadeKeys.get(i);
            if (run == null || !run.equals(previousRun)) {
                kept.add(errors.get(i));
            }
            previousRun = run;
        }
        return kept;
    }
}
