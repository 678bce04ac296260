package robotworld.explorer.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.generator.GeneratorProperty.Outcome;
import robotworld.explorer.generator.GeneratorProperty.Slot;

/**
 * Every description that validates generates and compiles for every viewpoint; every other one is rejected with
 * {@code file:line:column} in the author's words. Here: the names that used to break that promise, a sample of
 * every pool's names in every slot through validation, and a random sample of worlds all the way through javac. The whole
 * cross product, compiled, is {@code ./antw soak-generator}. A failing sample names its seed:
 * {@code -Drwe.test.property.seed=N} repeats it, {@code -Drwe.test.property.samples=N} takes more.
 */
class GeneratorPropertyTest {

    @TempDir
    static Path temp;

    private static GeneratorProperty property;

    @BeforeAll
    static void open() throws Exception {
        property = new GeneratorProperty(temp);
    }

    @AfterAll
    static void close() throws Exception {
        property.close();
    }

    static Stream<Arguments> namesThatValidatedButDidNotBuild() {
        return Stream.of(
                Arguments.of(Slot.ROBOT, "runtime", "'runtime'"),
                Arguments.of(Slot.ROBOT, "robotworld", "'robotworld'"),
                Arguments.of(Slot.ENVIRONMENT, "x10", "'x10'"),
                Arguments.of(Slot.ROBOT, "bus", "'bus'"),
                Arguments.of(Slot.SECOND_ROBOT, "XVSMRuntime", "'XVSMRuntime'"),
                Arguments.of(Slot.ROBOT, "external", "external viewpoint"),
                Arguments.of(Slot.BUS_CLASS, "new", "'new'"),
                Arguments.of(Slot.BUS_CLASS, "FooBus", "'FooBus'"),
                Arguments.of(Slot.ENV_BUS_CLASS, "robotworld.bus.TcpSerialLink", "not a bus class"),
                Arguments.of(Slot.WORLD, "Int", "'int'"),
                Arguments.of(Slot.PACKAGE, "java.util", "'java.util'"),
                Arguments.of(Slot.PACKAGE, "javax.swing", "module java.desktop"),
                Arguments.of(Slot.PACKAGE, "robotworld.lab", "robotworld"),
                Arguments.of(Slot.SECOND_ROBOT, "robot", "differs only in case"),
                Arguments.of(Slot.ROBOT, "Thread", "java.lang.Thread"),
                Arguments.of(Slot.ROBOT, "CON", "Windows"),
                Arguments.of(Slot.DETAILS, "lamp \u202E evil \u202C", "U+202E"),
                Arguments.of(Slot.DETAILS, "\u2066isolate\u2069", "U+2066"));
    }

    /** Each of them is now refused when it is read, at its line and column, in words. */
    @ParameterizedTest(name = "{0} = {1}")
    @MethodSource("namesThatValidatedButDidNotBuild")
    void refusedWhereTheyStandInWords(Slot slot, String value, String mentioned) throws Exception {
        String xml = GeneratorProperty.world(Map.of(slot, value));
        DescriptionException thrown = org.junit.jupiter.api.Assertions.assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorldFromString(xml, GeneratorProperty.SOURCE_NAME));
        String first = thrown.errors().get(0).toString();
        assertTrue(first.matches(GeneratorProperty.SOURCE_NAME.replace(".", "\\.") + ":[1-9][0-9]*:[1-9][0-9]*: .*"),
                first);
        assertTrue(first.contains(mentioned), first);
        int line = thrown.errors().get(0).line();
        String atLine = xml.lines().skip(line - 1).findFirst().orElseThrow();
        String shown = slot == Slot.WORLD ? "Int" : slot == Slot.DETAILS ? "<Details>" : value;
        assertTrue(atLine.contains(shown) || slot == Slot.DETAILS, "line " + line + " is '" + atLine + "'");
        assertNull(property.check(Map.of(slot, value)).broken());
    }

    /** The same names where they do no harm build fine: the rules refuse what breaks, not what looks odd. */
    @Test
    void harmlessPlacesOfTheSameNamesBuild() throws Exception {
        for (Map<Slot, String> harmless : List.of(
                Map.of(Slot.MODULE, "runtime"),
                Map.of(Slot.MODULE, "XVSMRuntime"),
                Map.of(Slot.WORLD, "Int", Slot.PACKAGE, "lab.ints"),
                Map.of(Slot.HOST, "http://robot-laptop:8080/"),
                Map.of(Slot.DETAILS, "x */ static { System.exit(1); } /* \\u000a -- Stoßstange"),
                Map.of(Slot.TYPE, "none", Slot.ROBOT, "Lab"))) {
            Outcome outcome = property.check(harmless);
            assertTrue(outcome.valid(), harmless + " should validate");
            assertNull(outcome.broken());
        }
    }

    /**
     * Validation alone, for a random sample of every pool's names in every slot: refused ones always at a position,
     * in words. (The soak validates and compiles all of them.)
     */
    @Test
    void poolNamesInEverySlotAreAcceptedOrRefusedWithAPosition() throws Exception {
        long seed = Long.getLong("rwe.test.property.seed", System.nanoTime());
        Random random = new Random(seed);
        Map<Slot, List<String>> pools = pools(random);
        List<String> broken = new ArrayList<>();
        int checked = 0;
        for (Map.Entry<Slot, List<String>> pool : pools.entrySet()) {
            List<String> names = new ArrayList<>(pool.getValue());
            java.util.Collections.shuffle(names, random);
            for (String value : names.subList(0, Math.min(names.size(), 40))) {
                String xml = GeneratorProperty.world(Map.of(pool.getKey(), value));
                checked++;
                try {
                    DescriptionLoader.loadWorldFromString(xml, GeneratorProperty.SOURCE_NAME);
                } catch (DescriptionException e) {
                    e.errors().stream().filter(error -> error.line() < 1 || error.column() < 1)
                            .forEach(error -> broken.add(pool.getKey() + "=" + value + ": " + error));
                }
            }
        }
        assertTrue(checked > 300, "only " + checked + " names checked");
        assertEquals(List.of(), broken, "seed " + seed);
    }

    /** Random worlds with one to three odd names each, through validation, generation and javac. */
    @Test
    void sampledWorldsValidateOnlyIfEveryViewpointCompiles() throws Exception {
        long seed = Long.getLong("rwe.test.property.seed", System.nanoTime());
        int samples = Integer.getInteger("rwe.test.property.samples", 15);
        Random random = new Random(seed);
        Map<Slot, List<String>> pools = pools(random);
        List<Slot> slots = List.copyOf(pools.keySet());
        int valid = 0;
        for (int i = 0; i < samples; i++) {
            Map<Slot, String> values = new EnumMap<>(Slot.class);
            int odd = 1 + random.nextInt(3);
            for (int n = 0; n < odd; n++) {
                Slot slot = slots.get(random.nextInt(slots.size()));
                values.put(slot, NamePool.pick(pools.get(slot), random));
            }
            Outcome outcome = property.check(values);
            assertNull(outcome.broken(), "seed " + seed + " (-Drwe.test.property.seed=" + seed + "): "
                    + outcome.broken());
            valid += outcome.valid() ? 1 : 0;
        }
        System.out.println("generator property: " + samples + " sampled worlds (seed " + seed + "), " + valid
                + " valid, " + property.compiled() + " projects compiled");
        assertFalse(samples > 5 && property.compiled() == 0, "no sampled world was valid: the sample proves nothing");
    }

    /** What each slot is filled from. */
    static Map<Slot, List<String>> pools(Random random) throws Exception {
        List<String> identifiers = NamePool.identifiers();
        Map<Slot, List<String>> pools = new EnumMap<>(Slot.class);
        pools.put(Slot.WORLD, identifiers);
        pools.put(Slot.PACKAGE, NamePool.packageNames(identifiers, random, 200));
        pools.put(Slot.ENVIRONMENT, identifiers);
        pools.put(Slot.ROBOT, identifiers);
        pools.put(Slot.SECOND_ROBOT, identifiers);
        pools.put(Slot.BUS_CLASS, NamePool.busClasses(identifiers));
        pools.put(Slot.ENV_BUS_CLASS, NamePool.busClasses(List.of()));
        pools.put(Slot.MODULE, NamePool.moduleNames(identifiers));
        pools.put(Slot.HOST, NamePool.HOSTS);
        pools.put(Slot.DETAILS, NamePool.DETAILS);
        pools.put(Slot.TYPE, List.of("xvsm", "none"));
        return pools;
    }
}
