package robotworld.explorer.generator;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.StandardLocation;
import javax.tools.ToolProvider;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.FrameworkGenerator;

/**
 * The generator's promise, checked for one world: a RobotWorld either fails validation, every error with
 * {@code file:line:column} and a message in the author's words, or generates for every viewpoint a project that
 * compiles (with a control program in its main class that uses {@code java.lang} as programs do). Compiles with
 * the JDK's compiler in this JVM, against the framework jars every project gets.
 *
 * <p>Used by {@code GeneratorPropertyTest} (a sample, in the unit suite) and {@code GeneratorPropertySoak}
 * ({@code ./antw soak-generator}: every name of every pool in every slot).
 */
final class GeneratorProperty implements AutoCloseable {

    /** The places in the world where a name goes. */
    enum Slot { WORLD, PACKAGE, ENVIRONMENT, ROBOT, SECOND_ROBOT, BUS_CLASS, ENV_BUS_CLASS, MODULE, HOST, DETAILS,
        TYPE }

    static final String SOURCE_NAME = "property-world.xml";

    /** Put into the main class of every project: a control program sees java.lang and the participant's NAME. */
    static final String CONTROL_SNIPPET = """
            Thread.sleep(0);
            System.out.println(Math.max(1, 2) + String.valueOf(NAME) + Integer.valueOf(3) + Long.MAX_VALUE);
            Object nothing = null;
            if (nothing instanceof Exception) { throw new IllegalStateException(); }
            """;

    private final FrameworkGenerator generator = new FrameworkGenerator();
    private final JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
    private final StandardJavaFileManager files;
    private final Path work;
    private int compiled;

    GeneratorProperty(Path work) throws IOException, GenerationException {
        this.work = work;
        this.files = javac.getStandardFileManager(null, Locale.ROOT, StandardCharsets.UTF_8);
        List<java.io.File> classPath = new ArrayList<>();
        for (Path jar : FrameworkLibraries.classPath(FrameworkLibraries.defaultDirectory())) {
            classPath.add(jar.toFile());
        }
        files.setLocation(StandardLocation.CLASS_PATH, classPath);
    }

    /** How many projects have been compiled so far. */
    int compiled() {
        return compiled;
    }

    /** The world with the given slots filled, the others as in a plain, valid lab world. */
    static String world(Map<Slot, String> values) {
        Map<Slot, String> v = new EnumMap<>(Slot.class);
        v.put(Slot.WORLD, "Lab");
        v.put(Slot.TYPE, "xvsm");
        v.put(Slot.ENVIRONMENT, "Hall");
        v.put(Slot.ROBOT, "Robot");
        v.put(Slot.SECOND_ROBOT, "Crawler");
        v.put(Slot.BUS_CLASS, "RS485Bus");
        v.put(Slot.ENV_BUS_CLASS, "robotworld.bus.RS485Bus");
        v.put(Slot.MODULE, "Lamp");
        v.put(Slot.HOST, "hall-pc");
        v.put(Slot.DETAILS, "dimmable floor lamp");
        v.putAll(values);
        String packageElement = v.containsKey(Slot.PACKAGE)
                ? "\n  <PackageName>" + xml(v.get(Slot.PACKAGE)) + "</PackageName>" : "";
        return """
                <?xml version="1.0" encoding="UTF-8"?>
                <RobotWorld xmlns="urn:robotworld:description">
                  <WorldName>%s</WorldName>
                  <CommunicationType>%s</CommunicationType>%s
                  <SpaceURL>http://localhost:9876/space</SpaceURL>
                  <Environment>
                    <EnvironmentName>%s</EnvironmentName>
                    <Host>%s</Host>
                    <COMPort>/dev/ttyS0</COMPort>
                    <BusPort>tcp://127.0.0.1:4001</BusPort>
                    <TalkToBusClass>%s</TalkToBusClass>
                    <X10Module>
                      <Name>%s</Name><HouseCode>A</HouseCode><UnitCode>ONE</UnitCode>
                      <Class>X10LampModule</Class><Version>1.0</Version>
                      <Details>%s</Details>
                      <DocRef>docs/modules/x10-lamp.md</DocRef>
                      <Safety><CommandTimeout>2000</CommandTimeout><SafeState>off</SafeState></Safety>
                    </X10Module>
                    <X10Module>
                      <Name>Fan</Name><HouseCode>P</HouseCode><UnitCode>SIXTEEN</UnitCode>
                      <Class>X10ApplianceModule</Class><Version>1.0</Version>
                    </X10Module>
                    <Module>
                      <Name>Door</Name><NodeID>15B63A1</NodeID><NodeNumber>3</NodeNumber>
                      <Class>ServoModule</Class><Version>1.0</Version>
                    </Module>
                  </Environment>
                  <RobotDescription>
                    <RobotName>%s</RobotName>
                    <Host>robot-laptop</Host>
                    <COMPort>/dev/ttyUSB0</COMPort>
                    <TalkToBusClass>%s</TalkToBusClass>
                    <Module>
                      <Name>Motor-Controller</Name><NodeID>15B63A4</NodeID><NodeNumber>1</NodeNumber>
                      <Class>MotorModule</Class><Version>1.0</Version>
                      <Safety><CommandTimeout>800</CommandTimeout><Watchdog>300</Watchdog></Safety>
                    </Module>
                    <Module>
                      <Name>Bumper-Sensor</Name><NodeID>15B63B2</NodeID><NodeNumber>2</NodeNumber>
                      <Class>BumperModule</Class><Version>1.0</Version>
                    </Module>
                  </RobotDescription>
                  <RobotDescription>
                    <RobotName>%s</RobotName>
                    <Host>crawler</Host>
                    <TalkToBusClass>RS485Bus</TalkToBusClass>
                    <Module>
                      <Name>Servo</Name><NodeID>15B63A1</NodeID><NodeNumber>1</NodeNumber>
                      <Class>ServoModule</Class><Version>1.0</Version>
                    </Module>
                    <Module>
                      <Name>Distance</Name><NodeID>15B63C7</NodeID><NodeNumber>2</NodeNumber>
                      <Class>IRDistanceModule</Class><Version>1.0</Version>
                    </Module>
                  </RobotDescription>
                </RobotWorld>
                """.formatted(xml(v.get(Slot.WORLD)), xml(v.get(Slot.TYPE)), packageElement,
                xml(v.get(Slot.ENVIRONMENT)), xml(v.get(Slot.HOST)), xml(v.get(Slot.ENV_BUS_CLASS)),
                xml(v.get(Slot.MODULE)), xml(v.get(Slot.DETAILS)), xml(v.get(Slot.ROBOT)), xml(v.get(Slot.BUS_CLASS)),
                xml(v.get(Slot.SECOND_ROBOT)));
    }

    /** The result of checking one world: whether it validated, and what broke the promise (null: nothing). */
    record Outcome(boolean valid, String broken) {
    }

    /** Checks the promise for one world. */
    Outcome check(Map<Slot, String> values) throws IOException {
        String xml = world(values);
        RobotWorldDocument world;
        try {
            world = DescriptionLoader.loadWorldFromString(xml, SOURCE_NAME);
        } catch (DescriptionException e) {
            return new Outcome(false, checkErrors(e, values));
        }
        List<String> viewpoints = new ArrayList<>();
        for (var environment : world.getRobotWorld().getEnvironmentArray()) {
            viewpoints.add(environment.getEnvironmentName());
        }
        for (var robot : world.getRobotWorld().getRobotDescriptionArray()) {
            viewpoints.add(robot.getRobotName());
        }
        if (world.getRobotWorld().getCommunicationType().toString().equals("xvsm")) {
            viewpoints.add(FrameworkGenerator.EXTERNAL);
        }
        for (String viewpoint : viewpoints) {
            String broken = generateAndCompile(world, viewpoint);
            if (broken != null) {
                return new Outcome(true, values + " validates, but viewpoint " + viewpoint + ": " + broken);
            }
        }
        return new Outcome(true, null);
    }

    /** Every error at a position, in words: no schema type names, no exception names. */
    private static String checkErrors(DescriptionException e, Map<Slot, String> values) {
        for (DescriptionError error : e.errors()) {
            String shown = error.toString();
            if (!SOURCE_NAME.equals(error.source()) || error.line() < 1 || error.column() < 1) {
                return values + " is rejected without file:line:column: " + shown;
            }
            String words = error.message();
            for (String value : values.values()) {
                words = words.replace(value, "");  // the author's own names may say anything
            }
            if (words.isBlank() || words.matches("(?s).*\\b[A-Z]\\w*Type\\b.*") || words.contains("cvc-")
                    || words.contains("Exception") || words.contains("@urn:")) {
                return values + " is rejected in schema or Java words: " + shown;
            }
        }
        return null;
    }

    private String generateAndCompile(RobotWorldDocument world, String viewpoint) throws IOException {
        Path project = work.resolve("p" + compiled);
        Path classes = work.resolve("c" + compiled);
        compiled++;
        try {
            GenerationResult result;
            try {
                result = generator.generate(world, viewpoint, null, project, false, GenerationListener.SILENT);
            } catch (GenerationException e) {
                return "generation failed: " + e.getMessage();
            }
            GeneratedProject generated = new GeneratedProject(result.destination());
            generated.insertControlLogic("src/" + result.mainClass().replace('.', '/') + ".java", CONTROL_SNIPPET);
            Files.createDirectories(classes);
            DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
            Iterable<? extends JavaFileObject> units = files.getJavaFileObjectsFromPaths(generated.sources());
            StringWriter output = new StringWriter();
            boolean ok = javac.getTask(output, files, diagnostics,
                    List.of("-d", classes.toString(), "-encoding", "UTF-8", "-Xlint:none", "-proc:none",
                            "--release", "17"), null, units).call();
            if (!ok) {
                StringBuilder report = new StringBuilder("does not compile:");
                diagnostics.getDiagnostics().forEach(d -> report.append("\n  ").append(d));
                return report.toString();
            }
            return null;
        } finally {
            delete(project);
            delete(classes);
        }
    }

    private static String xml(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    static void delete(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        try (Stream<Path> paths = Files.walk(root)) {
            for (Path path : paths.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(path);
            }
        }
    }

    @Override
    public void close() throws IOException {
        files.close();
    }
}
