package robotworld.explorer.monitor;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import javax.swing.SwingUtilities;
import robotworld.core.BumperModule;
import robotworld.core.IRDistanceModule;
import robotworld.core.MotorModule;
import robotworld.core.ServoModule;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMIRDistanceModuleLocal;
import robotworld.xvsm.XVSMIRDistanceModuleRemote;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMServoModuleLocal;
import robotworld.xvsm.XVSMServoModuleRemote;

/**
 * {@code ./antw bench-monitor-soak}: the monitor window open for {@code bench.monitor.minutes} (10) minutes while
 * the robot's IR, bumper, motor and servo modules each report 50 times a second through a loopback space server
 * (IR: 7 distances, bumper: 8 contacts, motors 1 and 2, servo 1: 18 channels at 50 Hz, plus each module's call
 * latency: 22 series). Every 30 s, after a
 * garbage collection, it prints the points the plots hold, the heap in use and the answers seen. The verdict: the
 * points held never exceed the fixed bound (series × ring size) and the heap at the end is within 10 % (or 8 MB)
 * of the heap after the first full minute.
 */
public final class MonitorSoak {

    private static final int MINUTES = Integer.getInteger("bench.monitor.minutes", 10);
    private static final long TICK_NANOS = 20_000_000L;

    private MonitorSoak() {
    }

    public static void main(String[] args) throws Exception {
        Path folder = Files.createTempDirectory("monitor-soak");
        try (MonitoredSpace space = new MonitoredSpace()) {
            XVSMRuntime robot = space.host("robot-laptop");
            new XVSMMotorModuleLocal(robot, "CaterpillarRobot", "Motor-Controller", new FakeHardware.Motor());
            new XVSMBumperModuleLocal(robot, "CaterpillarRobot", "Bumper-Sensor", new FakeHardware.Bumper());
            new XVSMServoModuleLocal(robot, "CaterpillarRobot", "Head-Servo", new FakeHardware.Servo());
            new XVSMIRDistanceModuleLocal(robot, "CaterpillarRobot", "IR-Sensors", new FakeHardware.IR());
            XVSMRuntime laptop = space.host("laptop");
            MotorModule motor = new XVSMMotorModuleRemote(laptop, "CaterpillarRobot", "Motor-Controller");
            BumperModule bumper = new XVSMBumperModuleRemote(laptop, "CaterpillarRobot", "Bumper-Sensor");
            ServoModule servo = new XVSMServoModuleRemote(laptop, "CaterpillarRobot", "Head-Servo");
            IRDistanceModule ir = new XVSMIRDistanceModuleRemote(laptop, "CaterpillarRobot", "IR-Sensors");
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(
                    MonitorTestWorlds.everyModuleType(folder)));
            WorldMonitor[] monitor = new WorldMonitor[1];
            SwingUtilities.invokeAndWait(() -> {
                monitor[0] = new WorldMonitor(world, space.connection(), new MonitorLoader(), WorldMonitor.Windows.ONE,
                        LayoutMemory.none());
                monitor[0].window().setBounds(0, 0, 1360, 900);
                monitor[0].show();
            });
            if (!monitor[0].awaitWatching(Duration.ofSeconds(30))) {
                throw new IllegalStateException("the monitor does not watch");
            }
            int series = 0;
            for (MonitoredParticipant p : world.participants()) {
                series += p.modules().size() * (PlotModel.MAX_CHANNEL + 2);
            }
            long bound = (long) series * PlotModel.CAPACITY;
            System.out.printf(Locale.ROOT, "Monitor soak: %d min, 4 modules x 50 reports/s (18 channels), window open;"
                    + " bound on points held: %d%n", MINUTES, bound);
            System.out.printf(Locale.ROOT, "  %6s %12s %14s %12s %10s%n", "time", "answers", "points held",
                    "heap MB", "gaps");
            long start = System.nanoTime();
            long end = start + Duration.ofMinutes(MINUTES).toNanos();
            long nextReport = start + 30_000_000_000L;
            long next = start;
            long ticks = 0;
            double heapAfterFirstMinute = -1;
            double heap = 0;
            long maxPoints = 0;
            while (System.nanoTime() < end) {
                double phase = ticks++ * 0.05;
                motor.setMotor(1, Math.round(Math.sin(phase) * 1000) / 1000.0);
                motor.setMotor(2, Math.round(Math.cos(phase) * 1000) / 1000.0);
                servo.setServo(1, (int) (90 + 80 * Math.sin(phase / 3)));
                bumper.getAllBumper();
                ir.getAllSensors();
                maxPoints = Math.max(maxPoints, monitor[0].plotModel().pointsHeld());
                next += TICK_NANOS;
                long now = System.nanoTime();
                if (now >= nextReport) {
                    nextReport += 30_000_000_000L;
                    heap = usedHeapMb();
                    double minutes = (now - start) / 60e9;
                    if (heapAfterFirstMinute < 0 && minutes >= 1) {
                        heapAfterFirstMinute = heap;
                    }
                    long answers = monitor[0].statistics().snapshot().modules().stream()
                            .mapToLong(TrafficStatistics.ModuleFigures::calls).sum();
                    System.out.printf(Locale.ROOT, "  %5.1fm %12d %14d %12.1f %10d%n", minutes, answers,
                            monitor[0].plotModel().pointsHeld(), heap, monitor[0].statistics().snapshot().gaps());
                    next = Math.max(next, System.nanoTime());
                }
                LockSupport.parkNanos(next - System.nanoTime());
            }
            heap = usedHeapMb();
            boolean pointsBounded = maxPoints <= bound;
            boolean heapFlat = heapAfterFirstMinute < 0 || heap <= Math.max(heapAfterFirstMinute * 1.10,
                    heapAfterFirstMinute + 8);
            System.out.printf(Locale.ROOT, "  most points held: %d (bound %d); heap after the first minute %.1f MB, "
                    + "at the end %.1f MB%n", maxPoints, bound, heapAfterFirstMinute, heap);
            System.out.println("  verdict: " + (pointsBounded && heapFlat ? "BOUNDED" : "GROWING"));
            SwingUtilities.invokeAndWait(() -> monitor[0].close());
            if (!(pointsBounded && heapFlat)) {
                System.exit(1);
            }
        }
        System.exit(0);
    }

    private static double usedHeapMb() throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(100);
        }
        Runtime runtime = Runtime.getRuntime();
        return (runtime.totalMemory() - runtime.freeMemory()) / 1048576.0;
    }
}
