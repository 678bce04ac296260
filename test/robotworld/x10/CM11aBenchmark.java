package robotworld.x10;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;
import robotworld.x10.Cm11aRig.Transport;

/**
 * How long CM11A commands take end to end against the simulated interface at real timing, compared with the
 * protocol minimum: every character at 4800 baud 8N1, the configured power-line time per frame, and the quiet the
 * controller keeps after each 0x55 before the next frame (80 ms by default, as the reference client). The
 * difference is what the driver, the simulator, the operating system and the transport add; target ≤ 5 ms.
 *
 * <p>Run with {@code ./antw bench-x10}. System properties: {@code bench.powerLineMs} (default 100),
 * {@code bench.runs} (5), {@code bench.commands} (10 per run). Exits 1 when a median overhead misses the target.
 */
public final class CM11aBenchmark {

    private static final double TARGET_OVERHEAD_MS = 5.0;
    private static final double CHARACTER_MS = X10Constants.CM11A_SERIAL.characterTimeNanos() / 1e6;
    private static final X10Address LAMP = X10Address.of('A', 1);
    private static final X10Address APPLIANCE = X10Address.of('A', 3);

    private interface Command {
        void run(CM11aController controller);
    }

    private record Case(String name, int characters, int frames, Command command) {
    }

    private CM11aBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        long powerLineMs = Long.getLong("bench.powerLineMs", 100);
        int runs = Integer.getInteger("bench.runs", 5);
        int perRun = Integer.getInteger("bench.commands", 10);
        List<Case> cases = List.of(
                // address + function: (2 out, 1 checksum, 1 ack, 1 ready) per frame
                new Case("on A3", 10, 2, controller -> controller.on(APPLIANCE)),
                new Case("dim A1 by 2/22", 10, 2, controller -> controller.dim(LAMP, 2)),
                // 0x8B and 14 bytes back, no power line
                new Case("status request", 15, 0, CM11aController::requestStatus));

        System.out.printf(Locale.ROOT, "CM11A command timing against the protocol minimum%n");
        long pauseMs = CM11aConfig.defaults().pauseAfterReady().toMillis();
        System.out.printf(Locale.ROOT, "serial: 4800 baud 8N1 = %.3f ms per character; power line: %d ms per frame; "
                + "%d ms quiet after each 0x55 (commands back to back, so every frame follows one)%n", CHARACTER_MS,
                powerLineMs, pauseMs);
        System.out.printf(Locale.ROOT, "%d runs x %d commands per case; median per run, then median of the runs%n%n",
                runs, perRun);
        System.out.printf(Locale.ROOT, "%-9s %-16s %5s %6s %11s %10s %12s %7s  %s%n", "transport", "command",
                "chars", "frames", "minimum ms", "median ms", "overhead ms", "ratio", "run medians (ms)");
        boolean met = true;
        for (Transport transport : Transport.values()) {
            SimulatedCm11a sim = SimulatedCm11a.withDevices(Cm11aTiming.real(Duration.ofMillis(powerLineMs)),
                    "A1=lamp,A3=appliance");
            try (Cm11aRig rig = Cm11aRig.connect(transport, sim, CM11aConfig.defaults())) {
                for (Case c : cases) {
                    met &= measure(transport, c, rig.controller, powerLineMs + pauseMs, runs, perRun);
                }
            }
        }
        System.out.printf(Locale.ROOT, "%ntarget: median overhead <= %.1f ms: %s%n", TARGET_OVERHEAD_MS,
                met ? "met" : "MISSED");
        System.exit(met ? 0 : 1);
    }

    /** @param frameMs power-line time plus the quiet after 0x55, per frame */
    private static boolean measure(Transport transport, Case c, CM11aController controller, long frameMs,
            int runs, int perRun) {
        for (int i = 0; i < 3; i++) {
            c.command().run(controller); // warm up the JIT and the connection
        }
        List<Double> runMedians = new ArrayList<>();
        for (int run = 0; run < runs; run++) {
            List<Double> times = new ArrayList<>();
            for (int i = 0; i < perRun; i++) {
                long start = System.nanoTime();
                c.command().run(controller);
                times.add((System.nanoTime() - start) / 1e6);
            }
            runMedians.add(median(times));
        }
        double minimum = c.characters() * CHARACTER_MS + c.frames() * frameMs;
        double median = median(runMedians);
        double overhead = median - minimum;
        StringBuilder perRunText = new StringBuilder();
        for (double value : runMedians) {
            perRunText.append(String.format(Locale.ROOT, "%.2f ", value));
        }
        System.out.printf(Locale.ROOT, "%-9s %-16s %5d %6d %11.2f %10.2f %12.2f %7.4f  %s%n",
                transport.name().toLowerCase(Locale.ROOT), c.name(), c.characters(), c.frames(), minimum, median,
                overhead, median / minimum, perRunText.toString().trim());
        return overhead <= TARGET_OVERHEAD_MS;
    }

    private static double median(List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        Collections.sort(sorted);
        int n = sorted.size();
        return n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2;
    }
}
