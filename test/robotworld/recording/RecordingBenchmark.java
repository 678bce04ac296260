package robotworld.recording;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import robotworld.core.BumperModule;
import robotworld.core.MotorModule;
import robotworld.observe.ModuleRef;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldTap;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.telemetry.TelemetryMessage;
import robotworld.telemetry.Topics;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMRuntime;

/**
 * Recording benchmark ({@code ./antw bench-recording}).
 * <ol>
 * <li><b>Overhead</b>: p50/p99 of a remote {@code getAllBumper} through a loopback space server, with and without
 *     a recorder (tap + recorder writing MCAP) attached, in the same run, and with a tap alone (what any monitor
 *     costs the space): the phases alternate (without, tap alone, with recorder, without, ...) {@code bench.runs} times with {@code bench.calls} calls each, after a warm-up; medians of the
 *     phases' p50 and p99, and their ratio.</li>
 * <li><b>Throughput</b>: a producer offers module-traffic messages (about 300 bytes of JSON) to a recorder at a
 *     paced rate for {@code bench.seconds} per step, doubling the rate from 5 000/s; for each step it reports
 *     whether the recorder said it fell behind (queue over half full, or drops). The last rate before that is
 *     its sustained throughput. Then the raw drain rate: one million messages into a queue big enough for all.</li>
 * </ol>
 */
public final class RecordingBenchmark {

    private static final int RUNS = Integer.getInteger("bench.runs", 5);
    private static final int CALLS = Integer.getInteger("bench.calls", 2000);
    private static final int WARMUP = Integer.getInteger("bench.warmupCalls", 10_000);
    private static final double SECONDS = Double.parseDouble(System.getProperty("bench.seconds", "2"));

    private RecordingBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        Path folder = Files.createTempDirectory("rwe-bench-recording");
        try {
            overhead(folder);
            throughput(folder);
        } finally {
            try (var files = Files.list(folder)) {
                for (Path file : files.toList()) {
                    Files.deleteIfExists(file);
                }
            }
            Files.deleteIfExists(folder);
        }
    }

    private static void overhead(Path folder) throws Exception {
        ModuleRef bumperRef = new ModuleRef("Bot", "Bumper", "BumperModule");
        ModuleRef motorRef = new ModuleRef("Bot", "Motor", "MotorModule");
        WorldLayout layout = new WorldLayout("BenchWorld", List.of(new WorldLayout.Participant("Bot", "robot",
                List.of(bumperRef, motorRef))));
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
             XVSMRuntime robot = XVSMRuntime.using(RemoteSpace.open(server.uri()), "robot-pc", true);
             XVSMRuntime laptop = XVSMRuntime.using(RemoteSpace.open(server.uri()), "laptop", true)) {
            new XVSMBumperModuleLocal(robot, "Bot", "Bumper", new BumperModule() {
                @Override
                public int getAllBumper() {
                    return 0b101000;
                }

                @Override
                public boolean getSingleBumper(int bumperNumber) {
                    return bumperNumber == 4 || bumperNumber == 6;
                }
            });
            new XVSMMotorModuleLocal(robot, "Bot", "Motor", new MotorModule() {
                @Override
                public void setMotor(int motor, double speed) {
                }

                @Override
                public void setMotorQuiet(int motor, double speed) {
                }
            });
            XVSMBumperModuleRemote bumper = new XVSMBumperModuleRemote(laptop, "Bot", "Bumper");
            System.out.printf(Locale.ROOT, "warming up: %d calls%n", WARMUP);
            for (int i = 0; i < WARMUP; i++) {
                bumper.getAllBumper();
            }
            List<long[]> without = new ArrayList<>();
            List<long[]> tapOnly = new ArrayList<>();
            List<long[]> with = new ArrayList<>();
            long recorded = 0;
            long dropped = 0;
            for (int run = 0; run < RUNS; run++) {
                without.add(phase(bumper));
                WorldTap quiet = new WorldTap(RemoteSpace.open(server.uri()), layout)
                        .add(new robotworld.observe.WorldObserver() { }).start();
                tapOnly.add(phase(bumper));
                quiet.close();
                Path file = folder.resolve("overhead-" + run + ".mcap");
                Recorder recorder = Recorder.start(file, new Recorder.Start(layout, server.uri().toString(), null),
                        Recorder.Options.defaults());
                WorldTap tap = new WorldTap(RemoteSpace.open(server.uri()), layout).add(recorder.observer()).start();
                with.add(phase(bumper));
                Thread.sleep(200);
                tap.close();
                recorder.close();
                recorded += recorder.status().messages();
                dropped += recorder.status().dropped();
                System.out.printf(Locale.ROOT, "run %d: without p50 %.3f ms p99 %.3f ms | tap only p50 %.3f ms p99"
                        + " %.3f ms | with recorder p50 %.3f ms p99 %.3f ms%n", run + 1, without.get(run)[0] / 1e6,
                        without.get(run)[1] / 1e6, tapOnly.get(run)[0] / 1e6, tapOnly.get(run)[1] / 1e6,
                        with.get(run)[0] / 1e6, with.get(run)[1] / 1e6);
            }
            double p50Without = median(without, 0);
            double p99Without = median(without, 1);
            double p50With = median(with, 0);
            double p99With = median(with, 1);
            double p50Tap = median(tapOnly, 0);
            double p99Tap = median(tapOnly, 1);
            System.out.printf(Locale.ROOT, "RESULT overhead: remote getAllBumper, %d runs x %d calls; without recorder"
                    + " p50 %.3f ms p99 %.3f ms; a tap alone (what any monitor costs) p50 %.3f ms (x%.2f) p99 %.3f ms"
                    + " (x%.2f); with recorder p50 %.3f ms (x%.2f) p99 %.3f ms (x%.2f); %d messages recorded, %d"
                    + " dropped%n", RUNS, CALLS, p50Without / 1e6, p99Without / 1e6, p50Tap / 1e6,
                    p50Tap / p50Without, p99Tap / 1e6, p99Tap / p99Without, p50With / 1e6, p50With / p50Without,
                    p99With / 1e6, p99With / p99Without, recorded, dropped);
        }
    }

    /** p50 and p99 in ns of CALLS calls. */
    private static long[] phase(XVSMBumperModuleRemote bumper) {
        long[] nanos = new long[CALLS];
        for (int i = 0; i < CALLS; i++) {
            long start = System.nanoTime();
            bumper.getAllBumper();
            nanos[i] = System.nanoTime() - start;
        }
        Arrays.sort(nanos);
        return new long[] {nanos[CALLS / 2], nanos[(int) (CALLS * 0.99)]};
    }

    private static double median(List<long[]> phases, int index) {
        double[] values = phases.stream().mapToDouble(p -> p[index]).sorted().toArray();
        return values[values.length / 2];
    }

    private static void throughput(Path folder) throws Exception {
        byte[] json = ("{\"kind\":\"answer\",\"participant\":\"CaterpillarRobot\",\"module\":\"Bumper-Sensor\","
                + "\"module_class\":\"BumperModule\",\"key\":\"robot-laptop#k3x9a.1234\",\"host\":\"robot-laptop\","
                + "\"function\":\"getSingleBumper\",\"fields\":[4,1],\"queued\":0,\"latency_ms\":1.234,"
                + "\"earlier\":false,\"remote\":true}").getBytes();
        var topic = Topics.module(new ModuleRef("CaterpillarRobot", "Bumper-Sensor", "BumperModule"));
        WorldLayout layout = new WorldLayout("BenchWorld", List.of());
        long sustained = 0;
        for (long rate = 5_000; rate <= 5_120_000; rate *= 2) {
            Path file = folder.resolve("rate-" + rate + ".mcap");
            Recorder recorder = Recorder.start(file, new Recorder.Start(layout, "bench", null),
                    Recorder.Options.defaults());
            long total = (long) (rate * SECONDS);
            long start = System.nanoTime();
            boolean behind = false;
            for (long i = 0; i < total; i++) {
                long due = start + (long) (i * 1e9 / rate);
                while (System.nanoTime() < due) {
                    Thread.onSpinWait();
                }
                recorder.offer(new TelemetryMessage(topic, System.currentTimeMillis() * 1_000_000L, json));
                if ((i & 1023) == 0 && recorder.status().behind()) {
                    behind = true;
                }
            }
            double achieved = total / ((System.nanoTime() - start) / 1e9);
            Recorder.Status status = recorder.status();
            behind |= status.behind();
            recorder.close();
            System.out.printf(Locale.ROOT, "offered %,d msg/s for %.0f s (achieved %,.0f/s): %s, %d dropped, %s%n",
                    rate, SECONDS, achieved, behind ? "FELL BEHIND" : "kept up", recorder.status().dropped(),
                    mib(Files.size(file)));
            if (behind) {
                break;
            }
            sustained = rate;
            Files.deleteIfExists(file);
        }
        Path file = folder.resolve("drain.mcap");
        int count = 1_000_000;
        Recorder recorder = Recorder.start(file, new Recorder.Start(layout, "bench", null),
                Recorder.Options.defaults().queueCapacity(count + 16));
        for (int i = 0; i < count; i++) {
            recorder.offer(new TelemetryMessage(topic, i, json));
        }
        long start = System.nanoTime();
        recorder.close();
        double seconds = (System.nanoTime() - start) / 1e9;
        System.out.printf(Locale.ROOT, "RESULT throughput: kept up with %,d msg/s offered (the next doubling fell"
                + " behind); drains %,.0f msg/s (%s/s) from a full queue into %s%n", sustained, count / seconds,
                mib(Files.size(file) / seconds), mib(Files.size(file)));
    }

    private static String mib(double bytes) {
        return String.format(Locale.ROOT, "%.1f MiB", bytes / (1024 * 1024));
    }
}
