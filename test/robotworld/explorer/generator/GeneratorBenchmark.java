package robotworld.explorer.generator;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import robotworld.description.DescriptionLoader;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.FrameworkGenerator;

/**
 * {@code ./antw bench-generator}: how long one viewpoint of a large world takes to generate (warm), and how that
 * grows with the world. Baseline, measured in the same run: copying the framework jars alone, which every
 * generation has to do.
 */
public final class GeneratorBenchmark {

    private static final int RUNS = 7;
    private static final String[] CLASSES = {"MotorModule", "ServoModule", "BumperModule", "IRDistanceModule"};

    public static void main(String[] args) throws Exception {
        Path work = Files.createTempDirectory("rwe-generator-bench");
        FrameworkGenerator generator = new FrameworkGenerator();
        Path frameworkDir = FrameworkLibraries.defaultDirectory();
        System.out.printf("generator benchmark: medians of %d warm runs, one robot viewpoint, 8 modules a robot%n",
                RUNS);
        double copyMs = median(() -> copyJars(frameworkDir, work.resolve("copy")));
        System.out.printf("baseline: copying the %d framework jars alone: %.1f ms%n",
                FrameworkLibraries.in(frameworkDir).size(), copyMs);
        System.out.printf("%8s %8s %12s %12s %12s %10s%n", "robots", "modules", "load ms", "generate ms",
                "total ms", "x copy");
        for (int robots : new int[] {10, 30, 100, 300}) {
            Path world = Files.writeString(work.resolve("world" + robots + ".xml"), world(robots));
            RobotWorldDocument[] loaded = new RobotWorldDocument[1];
            double loadMs = median(() -> loaded[0] = DescriptionLoader.loadWorld(world));
            Path out = work.resolve("out");
            double generateMs = median(() -> generator.generate(loaded[0], "Robot1", null, out, true,
                    GenerationListener.SILENT));
            System.out.printf("%8d %8d %12.1f %12.1f %12.1f %10.1f%n", robots, robots * 8, loadMs, generateMs,
                    loadMs + generateMs, (loadMs + generateMs) / copyMs);
        }
        delete(work);
    }

    /** A world of {@code robots} robots with 8 bus modules each, and one environment with two X10 modules. */
    static String world(int robots) {
        StringBuilder xml = new StringBuilder("""
                <RobotWorld xmlns="urn:robotworld:description">
                  <WorldName>Big</WorldName><CommunicationType>xvsm</CommunicationType>
                  <SpaceURL>http://localhost:9876/space</SpaceURL>
                  <Environment><EnvironmentName>Hall</EnvironmentName><Host>hall</Host><COMPort>/dev/ttyS0</COMPort>
                    <X10Module><Name>Lamp</Name><HouseCode>A</HouseCode><UnitCode>ONE</UnitCode>
                      <Class>X10LampModule</Class><Version>1.0</Version></X10Module>
                    <X10Module><Name>Fan</Name><HouseCode>A</HouseCode><UnitCode>TWO</UnitCode>
                      <Class>X10ApplianceModule</Class><Version>1.0</Version></X10Module>
                  </Environment>
                """);
        for (int r = 1; r <= robots; r++) {
            xml.append("  <RobotDescription><RobotName>Robot").append(r).append("</RobotName><Host>robot").append(r)
                    .append("</Host><COMPort>/dev/ttyUSB0</COMPort><TalkToBusClass>RS485Bus</TalkToBusClass>\n");
            for (int m = 1; m <= 8; m++) {
                xml.append("    <Module><Name>M").append(m).append("</Name><NodeID>15B63A4</NodeID><NodeNumber>")
                        .append(m).append("</NodeNumber><Class>").append(CLASSES[m % CLASSES.length])
                        .append("</Class><Version>1.0</Version></Module>\n");
            }
            xml.append("  </RobotDescription>\n");
        }
        return xml.append("</RobotWorld>\n").toString();
    }

    private interface Work {
        void run() throws Exception;
    }

    private static double median(Work work) throws Exception {
        for (int i = 0; i < 3; i++) {
            work.run(); // warm-up: stylesheet compilation, JIT
        }
        double[] millis = new double[RUNS];
        for (int i = 0; i < RUNS; i++) {
            long start = System.nanoTime();
            work.run();
            millis[i] = (System.nanoTime() - start) / 1e6;
        }
        Arrays.sort(millis);
        return millis[RUNS / 2];
    }

    private static void copyJars(Path from, Path to) throws IOException, GenerationException {
        delete(to);
        Files.createDirectories(to);
        for (Path jar : FrameworkLibraries.in(from)) {
            Files.copy(jar, to.resolve(jar.getFileName()));
        }
    }

    private static void delete(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        List<Path> paths = new ArrayList<>();
        try (Stream<Path> walk = Files.walk(root)) {
            walk.sorted(Comparator.reverseOrder()).forEach(paths::add);
        }
        for (Path path : paths) {
            Files.delete(path);
        }
    }
}
