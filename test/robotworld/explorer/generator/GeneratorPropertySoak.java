package robotworld.explorer.generator;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import robotworld.explorer.generator.GeneratorProperty.Outcome;
import robotworld.explorer.generator.GeneratorProperty.Slot;

/**
 * {@code ./antw soak-generator}: the generator property for every name of every pool in every slot, each world
 * that validates generated for every viewpoint and compiled. Too slow for the unit suite (thousands of javac
 * runs); {@code GeneratorPropertyTest} runs a random sample of the same. Exit code 1 if any world breaks the
 * promise; {@code -Drwe.soak.slots=ROBOT,PACKAGE} limits the slots.
 */
public final class GeneratorPropertySoak {

    public static void main(String[] args) throws Exception {
        Map<Slot, List<String>> pools = GeneratorPropertyTest.pools(new Random(1));
        String only = System.getProperty("rwe.soak.slots", "");
        Path work = Files.createTempDirectory("rwe-generator-soak");
        List<String> broken = new ArrayList<>();
        int worlds = 0;
        int valid = 0;
        long started = System.nanoTime();
        try (GeneratorProperty property = new GeneratorProperty(work)) {
            for (Map.Entry<Slot, List<String>> pool : pools.entrySet()) {
                if (!only.isBlank() && !List.of(only.split(",")).contains(pool.getKey().name())) {
                    continue;
                }
                int slotValid = 0;
                for (String value : pool.getValue()) {
                    Outcome outcome = property.check(Map.of(pool.getKey(), value));
                    worlds++;
                    valid += outcome.valid() ? 1 : 0;
                    slotValid += outcome.valid() ? 1 : 0;
                    if (outcome.broken() != null) {
                        broken.add(outcome.broken());
                        System.out.println("BROKEN " + outcome.broken());
                    }
                }
                System.out.printf("%-14s %5d names, %5d valid; %6d projects compiled so far, %.0f s%n",
                        pool.getKey(), pool.getValue().size(), slotValid, property.compiled(),
                        (System.nanoTime() - started) / 1e9);
            }
            System.out.printf("generator soak: %d worlds, %d valid, %d projects compiled, %d broken, %.0f s%n",
                    worlds, valid, property.compiled(), broken.size(), (System.nanoTime() - started) / 1e9);
        } finally {
            GeneratorProperty.delete(work);
        }
        System.exit(broken.isEmpty() ? 0 : 1);
    }
}
