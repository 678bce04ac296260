package robotworld.explorer.generator;

import java.io.IOException;
import java.net.URI;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import java.util.stream.Stream;
import robotworld.testsupport.ProjectFiles;

/**
 * Names that are hard on a code generator, for {@link GeneratorProperty}: Java keywords and restricted
 * identifiers, the types of {@code java.lang} (read from the running JDK, not from our own list), this project's
 * own package and class names (read from the compiled classes), the names generated code uses for itself, and
 * other identifiers the schema accepts.
 */
final class NamePool {

    /** Keywords, literals, restricted and contextual identifiers of Java 17 to 25. */
    static final List<String> KEYWORDS = List.of(
            "abstract", "assert", "boolean", "break", "byte", "case", "catch", "char", "class", "const",
            "continue", "default", "do", "double", "else", "enum", "extends", "final", "finally", "float", "for",
            "goto", "if", "implements", "import", "instanceof", "int", "interface", "long", "native", "new",
            "package", "private", "protected", "public", "return", "short", "static", "strictfp", "super",
            "switch", "synchronized", "this", "throw", "throws", "transient", "try", "void", "volatile", "while",
            "true", "false", "null", "_", "var", "yield", "record", "sealed", "permits", "module", "open",
            "opens", "requires", "exports", "to", "uses", "provides", "with", "transitive", "when");

    /** What generated code calls its own variables, constants, methods and viewpoints, in several spellings. */
    static final List<String> GENERATED = List.of("runtime", "Runtime", "bus", "Bus", "x10", "X10", "program",
            "args", "settings", "NAME", "HOST", "SPACE_URL", "external", "External", "EXTERNAL", "control", "main",
            "close", "serveUntilStopped", "port", "own", "MotorModule1", "BumperModule2", "X10LampModule1",
            "ParticipantMain", "RuntimeSettings", "CM11aController", "RS485Bus", "XVSMRuntime");

    /** Other identifiers the schema accepts, chosen to be awkward. */
    static final List<String> OTHER = List.of("a", "A", "_a", "__", "_0", "a_", "Z9", "chapter5", "Chapter5",
            "CHAPTER5", "CON", "con", "Nul", "COM1", "LPT9", "aux", "Robot", "robot", "ROBOT", "Crawler", "Hall",
            "hall", "MyModule", "Module", "module1", "Module1", "Lamp", "Fan", "Door", "DimRoom", "dimroom",
            "WorldExternal", "HallExternal", "Value", "Entry", "Item", "Tuple", "Template", "Selector", "Space",
            "space", "Capi", "core", "xvsm", "sim", "com", "org", "javafx", "jdk", "sun", "lib", "src", "build",
            "docs", "bin", "Test", "Main", "App", "Override", "Deprecated", "SuppressWarnings",
            "x".repeat(64), "X" + "y".repeat(63), "\u0061b");

    private NamePool() {
    }

    /** The public top-level types of java.lang in the JDK running the test. */
    static List<String> javaLangTypes() throws IOException {
        FileSystem jrt = FileSystems.getFileSystem(URI.create("jrt:/"));
        TreeSet<String> names = new TreeSet<>();
        try (Stream<Path> classes = Files.list(jrt.getPath("/modules/java.base/java/lang"))) {
            classes.map(p -> p.getFileName().toString())
                    .filter(n -> n.endsWith(".class") && !n.contains("$") && !n.equals("package-info.class"))
                    .map(n -> n.substring(0, n.length() - ".class".length()))
                    .filter(NamePool::isPublicJavaLang)
                    .forEach(names::add);
        }
        return List.copyOf(names);
    }

    private static boolean isPublicJavaLang(String simpleName) {
        try {
            return java.lang.reflect.Modifier.isPublic(Class.forName("java.lang." + simpleName, false, null)
                    .getModifiers());
        } catch (ReflectiveOperationException | LinkageError e) {
            return false;
        }
    }

    /** Package segments and top-level class names of this project's compiled classes. */
    static List<String> ownNames() throws IOException {
        Path classes = Path.of(System.getProperty("rwe.build.dir", ProjectFiles.resolve("build").toString()))
                .resolve("classes/robotworld");
        TreeSet<String> names = new TreeSet<>(List.of("robotworld"));
        try (Stream<Path> files = Files.walk(classes)) {
            files.forEach(file -> {
                String name = file.getFileName().toString();
                if (Files.isDirectory(file)) {
                    names.add(name);
                } else if (name.endsWith(".class") && !name.contains("$")) {
                    names.add(name.substring(0, name.length() - ".class".length()));
                }
            });
        }
        names.removeIf(n -> !n.matches("[A-Za-z_][A-Za-z0-9_]*") || n.length() > 64);
        return List.copyOf(names);
    }

    /** Every identifier of every pool, in a fixed order. */
    static List<String> identifiers() throws IOException {
        List<String> all = new ArrayList<>(KEYWORDS);
        all.addAll(javaLangTypes());
        all.addAll(GENERATED);
        all.addAll(OTHER);
        all.addAll(ownNames());
        return List.copyOf(new java.util.LinkedHashSet<>(all));
    }

    /** Package names: the dangerous ones, and dotted combinations of identifiers. */
    static List<String> packageNames(List<String> identifiers, Random random, int combinations) {
        List<String> names = new ArrayList<>(List.of("java.util", "java", "java.foo", "javax.swing", "javax.foo",
                "javax.xml.parsers", "org.w3c.dom", "org.xml.sax", "jdk.internal.misc", "sun.misc", "com.sun.net",
                "robotworld", "robotworld.core", "robotworld.xvsm", "robotworld.lab", "com.example.robots",
                "my.class.app", "a.b.c", "chapter5", "Chapter5", "lab.Robot", "lab.robot", "x10.lab", "bus",
                "runtime", "external", "String", "lab.String", "org.eclipse.jetty.server", "picocli", "_"));
        for (int i = 0; i < combinations; i++) {
            int parts = 1 + random.nextInt(3);
            StringBuilder name = new StringBuilder();
            for (int p = 0; p < parts; p++) {
                name.append(p == 0 ? "" : ".").append(identifiers.get(random.nextInt(identifiers.size())));
            }
            names.add(name.toString());
        }
        return names;
    }

    /** Bus class names as a robot description may give them. */
    static List<String> busClasses(List<String> identifiers) {
        List<String> names = new ArrayList<>(List.of("RS485Bus", "robotworld.bus.RS485Bus", "FooBus",
                "com.acme.FooBus", "new", "robotworld.bus.new", "rs485bus", "RS485BUS", "TcpSerialLink",
                "robotworld.bus.TcpSerialLink", "SerialLink", "robotworld.bus.SerialLink", "java.lang.String",
                "java.io.FileInputStream", "robotworld.bus.MotorModuleProxy", "BusException", "RtuMaster",
                "robotworld.space.server.SpaceServer", "java.util.Scanner"));
        names.addAll(identifiers);
        return names;
    }

    /** Host values: names, addresses and URLs. */
    static final List<String> HOSTS = List.of("localhost", "robot-laptop", "a", "192.168.1.20", "[::1]",
            "[fe80::1]", "http://robot-laptop:8080/", "http://robot-laptop", "tcp://[::1]:5020", "HTTP://X:1/a/b",
            "https://lab.example.org/robots/1", "x".repeat(253), "ROBOT-PC", "robot.lab.example.org");

    /** Module names: only string literals and container names in generated code, but still names. */
    static List<String> moduleNames(List<String> identifiers) {
        List<String> names = new ArrayList<>(List.of("Motor-Controller", "a-b", "A-", "x--y", "Lamp", "Z",
                "a".repeat(64)));
        identifiers.stream().filter(n -> n.matches("[A-Za-z][A-Za-z0-9_\\-]*")).forEach(names::add);
        return names;
    }

    /** Free text for Details: every kind of character that is hard on generated comments. */
    static final List<String> DETAILS = List.of(
            "plain details", "x */ static { System.exit(1); } /*", "\\u000a class Evil {} \\u002a/",
            "line one\nline two\r\n\tthree", "-- an XML comment -- ends --> here", "<b>bold</b> & \"quoted\"",
            "Stoßstange vorn, ½ Meter", "مصباح الأرضية", "lamp \u202E evil \u202C", "\u2066isolate\u2069",
            "zero\u200Bwidth", "\u200Fmark", "soft\u00ADhyphen", "\uFEFFbom", "emoji \uD83E\uDD16 robot",
            "family \uD83D\uDC68\u200D\uD83D\uDC69", "line\u2028separator", "c1 \u0085 next line",
            "private \uE000 use", "${injection} #{x} %s %n", "@Override @interface */");

    /** A random pick. */
    static String pick(List<String> pool, Random random) {
        return pool.get(random.nextInt(pool.size()));
    }
}
