package robotworld.sim.robot;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.w3c.dom.Element;
import org.w3c.dom.NamedNodeMap;
import org.w3c.dom.Node;
import org.xml.sax.SAXException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * Reads a simulated-robot configuration: a small XML file, documented in {@code docs/bus.md} with an example in
 * {@code docs/examples/simulated-robot.sim}. Unknown elements and attributes are errors (a typo must not pass
 * silently); all problems are reported together. DOCTYPEs are refused.
 */
public final class SimRobotConfigReader {

    /** NodeIDs of the reference modules in {@code ModuleDescriptions/}, used when a module names none. */
    public static final Map<String, String> DEFAULT_NODE_IDS = Map.of("Motor", "15B63A4", "Servo", "15B63A1",
            "Bumper", "15B63B2", "IRDistance", "15B63C7");
    private static final String DEFAULT_VENDOR = "RobotWorld reference modules";
    private static final Set<String> COMMON = Set.of("address", "nodeId", "version", "vendor", "serverId", "silent",
            "crcErrorRate", "replyDelay", "refuseWith", "stopped");

    private final String source;
    private final List<String> problems = new ArrayList<>();

    private SimRobotConfigReader(String source) {
        this.source = source;
    }

    /** Reads a configuration file. */
    public static SimRobotConfig read(Path file) throws IOException {
        return parse(Files.readString(file, StandardCharsets.UTF_8), file.toString());
    }

    /** Reads a configuration from text; {@code sourceName} prefixes the problems. */
    public static SimRobotConfig parse(String xml, String sourceName) throws SimRobotConfigException {
        SimRobotConfigReader reader = new SimRobotConfigReader(sourceName);
        SimRobotConfig config = reader.readDocument(xml);
        if (!reader.problems.isEmpty()) {
            throw new SimRobotConfigException(reader.problems);
        }
        return config;
    }

    private SimRobotConfig readDocument(String xml) {
        Element root;
        try {
            root = secureBuilder().parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)))
                    .getDocumentElement();
        } catch (SAXException | IOException e) {
            problem("not well-formed XML: " + e.getMessage());
            return null;
        }
        if (!root.getTagName().equals("SimulatedRobot")) {
            problem("the root element is <" + root.getTagName() + ">, expected <SimulatedRobot>");
            return null;
        }
        Attributes robot = new Attributes(root, "<SimulatedRobot>", Set.of("name", "seed"));
        String name = robot.text("name", "SimulatedRobot");
        long seed = robot.integer("seed", 1, 0, Integer.MAX_VALUE);

        int baud = 115_200;
        LineTiming timing = LineTiming.FAST;
        double width = 0;
        double height = 0;
        double timeScale = 1;
        List<Rect> obstacles = new ArrayList<>();
        Pose start = null;
        double radius = 150;
        double wheelBase = 260;
        double maxSpeed = 300;
        List<ModuleSpec> modules = new ArrayList<>();
        boolean sawWorld = false;
        for (Element child : children(root)) {
            switch (child.getTagName()) {
                case "Bus" -> {
                    Attributes bus = new Attributes(child, "<Bus>", Set.of("baud", "timing"));
                    baud = (int) bus.integer("baud", baud, 300, 4_000_000);
                    String timingText = bus.text("timing", "fast");
                    try {
                        timing = LineTiming.parse(timingText);
                    } catch (IllegalArgumentException e) {
                        problem("<Bus>: " + e.getMessage());
                    }
                    noChildren(child, "<Bus>");
                }
                case "World" -> {
                    sawWorld = true;
                    Attributes world = new Attributes(child, "<World>", Set.of("width", "height", "timeScale"));
                    width = world.number("width", Double.NaN, 1, 1e6);
                    height = world.number("height", Double.NaN, 1, 1e6);
                    timeScale = world.number("timeScale", 1, 0.001, 1000);
                    for (Element obstacle : children(child)) {
                        readObstacle(obstacle, obstacles);
                    }
                }
                case "Body" -> {
                    Attributes body = new Attributes(child, "<Body>",
                            Set.of("x", "y", "heading", "radius", "wheelBase", "maxSpeed"));
                    start = new Pose(body.number("x", Double.NaN, -1e6, 1e6), body.number("y", Double.NaN, -1e6, 1e6),
                            body.number("heading", 0, -360, 360));
                    radius = body.number("radius", radius, 1, 1e5);
                    wheelBase = body.number("wheelBase", wheelBase, 1, 1e5);
                    maxSpeed = body.number("maxSpeed", maxSpeed, 1, 1e5);
                    noChildren(child, "<Body>");
                }
                case "Motor", "Servo", "Bumper", "IRDistance" -> {
                    ModuleSpec spec = readModule(child);
                    if (spec != null) {
                        modules.add(spec);
                    }
                }
                default -> problem("unknown element <" + child.getTagName() + "> in <SimulatedRobot> (expected Bus, "
                        + "World, Body, Motor, Servo, Bumper, IRDistance)");
            }
        }
        if (!sawWorld) {
            problem("<World width=... height=...> is missing");
        }
        if (start == null) {
            problem("<Body x=... y=...> is missing");
        }
        checkUniqueAddresses(modules);
        if (!problems.isEmpty()) {
            return null;
        }
        SimRobotConfig config = new SimRobotConfig(name, baud, timing, timeScale, seed, width, height, obstacles,
                start, radius, wheelBase, maxSpeed, modules);
        try {
            config.build(); // the world checks that the robot fits where it starts
        } catch (IllegalArgumentException e) {
            problem(e.getMessage());
        }
        return config;
    }

    private void readObstacle(Element element, List<Rect> obstacles) {
        if (!element.getTagName().equals("Obstacle")) {
            problem("unknown element <" + element.getTagName() + "> in <World> (expected Obstacle)");
            return;
        }
        Attributes a = new Attributes(element, "<Obstacle>", Set.of("x", "y", "width", "height"));
        double x = a.number("x", Double.NaN, -1e6, 1e6);
        double y = a.number("y", Double.NaN, -1e6, 1e6);
        double w = a.number("width", Double.NaN, 0.001, 1e6);
        double h = a.number("height", Double.NaN, 0.001, 1e6);
        if (!Double.isNaN(x + y + w + h)) {
            obstacles.add(new Rect(x, y, w, h));
        }
        noChildren(element, "<Obstacle>");
    }

    private ModuleSpec readModule(Element element) {
        String type = element.getTagName();
        Set<String> specific = switch (type) {
            case "Motor" -> Set.of("left", "right", "ramp");
            case "Servo" -> Set.of("speed");
            case "IRDistance" -> Set.of("range");
            default -> Set.of();
        };
        String where = "<" + type + " address=\"" + element.getAttribute("address") + "\">";
        Set<String> allowed = new java.util.HashSet<>(COMMON);
        allowed.addAll(specific);
        Attributes a = new Attributes(element, where, allowed);
        int address = (int) a.integer("address", -1, 1, 247);
        ModuleIdentity identity = new ModuleIdentity(a.text("vendor", DEFAULT_VENDOR),
                a.text("nodeId", DEFAULT_NODE_IDS.get(type)), a.text("version", "1.0"), a.text("serverId", ""));
        ModuleSpec.Common common = new ModuleSpec.Common(address, identity, a.bool("silent"),
                a.number("crcErrorRate", 0, 0, 1), (int) a.integer("replyDelay", 0, 0, 60_000),
                (int) a.integer("refuseWith", 0, 0, 255), a.bool("stopped"));
        return switch (type) {
            case "Motor" -> {
                noChildren(element, where);
                yield new ModuleSpec.Motor(common, (int) a.integer("left", 0, 0, 8), (int) a.integer("right", 0, 0, 8),
                        a.number("ramp", 2000, 0, 1e6));
            }
            case "Servo" -> {
                noChildren(element, where);
                yield new ModuleSpec.Servo(common, a.number("speed", 180, 0, 1e5));
            }
            case "Bumper" -> new ModuleSpec.Bumper(common, readMounts(element, where));
            default -> new ModuleSpec.IRDistance(common, readSensors(element, where),
                    (int) a.integer("range", 800, 1, 0xFFFF));
        };
    }

    private Map<Integer, SimBumperModule.Mount> readMounts(Element bumper, String where) {
        Map<Integer, SimBumperModule.Mount> mounts = new TreeMap<>();
        for (Element child : children(bumper)) {
            if (!child.getTagName().equals("Mount")) {
                problem(where + ": unknown element <" + child.getTagName() + "> (expected Mount)");
                continue;
            }
            Attributes a = new Attributes(child, where + " <Mount>", Set.of("number", "angle", "span"));
            int number = (int) a.integer("number", -1, 1, 8);
            double angle = a.number("angle", Double.NaN, -360, 360);
            double span = a.number("span", 40, 0.001, 360);
            if (mounts.put(number, new SimBumperModule.Mount(angle, span)) != null) {
                problem(where + ": bumper " + number + " is mounted twice");
            }
        }
        return mounts;
    }

    private Map<Integer, Double> readSensors(Element ir, String where) {
        Map<Integer, Double> sensors = new TreeMap<>();
        for (Element child : children(ir)) {
            if (!child.getTagName().equals("Sensor")) {
                problem(where + ": unknown element <" + child.getTagName() + "> (expected Sensor)");
                continue;
            }
            Attributes a = new Attributes(child, where + " <Sensor>", Set.of("number", "angle"));
            int number = (int) a.integer("number", -1, 1, 7);
            if (sensors.put(number, a.number("angle", Double.NaN, -360, 360)) != null) {
                problem(where + ": sensor " + number + " is mounted twice");
            }
        }
        return sensors;
    }

    private void checkUniqueAddresses(List<ModuleSpec> modules) {
        Map<Integer, String> seen = new LinkedHashMap<>();
        for (ModuleSpec spec : modules) {
            int address = spec.common().address();
            String type = spec.getClass().getSimpleName();
            String before = seen.putIfAbsent(address, type);
            if (before != null && address > 0) {
                problem("address " + address + " is used by two modules (" + before + " and " + type + ")");
            }
        }
    }

    private void noChildren(Element element, String where) {
        for (Element child : children(element)) {
            problem(where + ": unexpected element <" + child.getTagName() + ">");
        }
    }

    private void problem(String message) {
        problems.add(source + ": " + message);
    }

    private static List<Element> children(Element parent) {
        List<Element> elements = new ArrayList<>();
        for (Node node = parent.getFirstChild(); node != null; node = node.getNextSibling()) {
            if (node instanceof Element element) {
                elements.add(element);
            }
        }
        return elements;
    }

    private static DocumentBuilder secureBuilder() {
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            factory.setXIncludeAware(false);
            factory.setExpandEntityReferences(false);
            DocumentBuilder builder = factory.newDocumentBuilder();
            builder.setErrorHandler(new DefaultHandler()); // no "[Fatal Error]" lines on stderr
            return builder;
        } catch (ParserConfigurationException e) {
            throw new IllegalStateException("the XML parser cannot be configured securely", e);
        }
    }

    /** Typed access to an element's attributes; problems are collected, never thrown. */
    private final class Attributes {

        private final Element element;
        private final String where;

        Attributes(Element element, String where, Set<String> allowed) {
            this.element = element;
            this.where = where;
            NamedNodeMap all = element.getAttributes();
            for (int i = 0; i < all.getLength(); i++) {
                String name = all.item(i).getNodeName();
                if (!allowed.contains(name)) {
                    problem(where + ": unknown attribute '" + name + "' (allowed: " + String.join(", ",
                            new java.util.TreeSet<>(allowed)) + ")");
                }
            }
        }

        String text(String name, String fallback) {
            String value = element.getAttribute(name).trim();
            return value.isEmpty() ? fallback : value;
        }

        /** A number in [min, max]; a NaN fallback makes the attribute required. */
        double number(String name, double fallback, double min, double max) {
            String value = element.getAttribute(name).trim();
            if (value.isEmpty()) {
                if (Double.isNaN(fallback)) {
                    problem(where + ": attribute '" + name + "' is required");
                }
                return fallback;
            }
            try {
                double number = Double.parseDouble(value);
                if (!(number >= min && number <= max)) {
                    problem(where + ": " + name + " " + value + " is outside " + plain(min) + ".." + plain(max));
                }
                return number;
            } catch (NumberFormatException e) {
                problem(where + ": " + name + " '" + value + "' is not a number");
                return Double.isNaN(fallback) ? 0 : fallback;
            }
        }

        /** A whole number in [min, max]; a negative fallback (below min) makes the attribute required. */
        long integer(String name, long fallback, long min, long max) {
            String value = element.getAttribute(name).trim();
            if (value.isEmpty()) {
                if (fallback < min) {
                    problem(where + ": attribute '" + name + "' is required");
                }
                return fallback;
            }
            try {
                long number = Long.parseLong(value);
                if (number < min || number > max) {
                    problem(where + ": " + name + " " + value + " is outside " + min + ".." + max);
                }
                return number;
            } catch (NumberFormatException e) {
                problem(where + ": " + name + " '" + value + "' is not a whole number");
                return fallback;
            }
        }

        boolean bool(String name) {
            String value = element.getAttribute(name).trim();
            if (value.isEmpty() || value.equals("false")) {
                return false;
            }
            if (value.equals("true")) {
                return true;
            }
            problem(where + ": " + name + " '" + value + "' is neither true nor false");
            return false;
        }

        private String plain(double value) {
            return value == Math.rint(value) ? Long.toString((long) value) : Double.toString(value);
        }
    }
}
