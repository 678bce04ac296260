package robotworld.observe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.core.MotorModule;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMRuntime;

/**
 * Liveness from the programs' heartbeats, over a real loopback space server with real runtimes (each sends a
 * heartbeat every 100 ms): a program that serves a module nobody calls is alive; one killed with SIGKILL (in a JVM
 * of its own) is silent within two seconds, and alive again once a new program serves its module; one that closes
 * cleanly has ended, though it released its actuator before its last heartbeat. No module is ever called, so the
 * traffic alone would call them all quiet.
 */
class HeartbeatLivenessTest {

    private static final String IDLE = "IdleBot";
    private static final String KILLED = "KilledBot";
    private static final String CLOSED = "ClosedRoom";
    private static final ModuleRef FAN = new ModuleRef(CLOSED, "Fan", "MotorModule");
    private static final WorldLayout LAYOUT = new WorldLayout("HeartbeatWorld", List.of(
            participant(IDLE, "robot"), participant(KILLED, "robot"), new WorldLayout.Participant(CLOSED,
                    "environment", List.of(FAN))));
    /** About a second without heartbeats, a tick of the tap, and room for a busy machine. */
    private static final Duration SILENT_WITHIN = Duration.ofMillis(2_500);

    @TempDir
    Path folder;

    private final EmbeddedSpace data = EmbeddedSpace.open();
    private SpaceServer server;
    private final List<AutoCloseable> opened = new ArrayList<>();
    private final Heard heard = new Heard();
    private Process child;

    @BeforeEach
    void startServer() {
        server = SpaceServer.start(data, SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
    }

    @AfterEach
    void stop() throws Exception {
        if (child != null) {
            child.destroyForcibly();
            child.waitFor(10, TimeUnit.SECONDS);
        }
        for (int i = opened.size() - 1; i >= 0; i--) {
            opened.get(i).close();
        }
        server.stop();
        data.close();
    }

    @Test
    void anIdleProgramIsAliveAKilledOneFallsSilentAndOneThatClosedHasEnded() throws Exception {
        serve(host("idle-pc"), IDLE);
        XVSMRuntime room = host("room-pc");
        serveFan(room); // an actuator: closing, the program releases it before its last heartbeat
        startChild(KILLED);
        WorldTap tap = open(new WorldTap(open(RemoteSpace.open(server.uri())), LAYOUT));
        tap.add(heard);
        tap.start();

        for (String participant : List.of(IDLE, KILLED, CLOSED)) {
            waitFor(participant + " alive", () -> heard.last(participant) == Liveness.State.ALIVE);
            assertTrue(heard.lastOf(participant).basis().startsWith("heartbeats of "), heard.lastOf(participant)
                    .toString());
        }

        long killed = System.nanoTime();
        child.destroyForcibly(); // SIGKILL: no last heartbeat, nothing cleaned up
        waitFor(KILLED + " silent", () -> heard.last(KILLED) == Liveness.State.SILENT);
        long after = heard.lastNanos(KILLED) - killed;
        assertTrue(after < SILENT_WITHIN.toNanos(), "silent " + after / 1_000_000 + " ms after the kill");
        assertTrue(heard.lastOf(KILLED).basis().startsWith("no heartbeat from killed-pc#"), heard.lastOf(KILLED)
                .toString());

        room.close(); // its last heartbeat says so
        waitFor(CLOSED + " ended", () -> heard.last(CLOSED) == Liveness.State.ENDED);

        serve(host("spare-pc"), KILLED); // a new program takes over the killed one's module
        waitFor(KILLED + " alive again", () -> heard.last(KILLED) == Liveness.State.ALIVE);
        assertTrue(heard.lastOf(KILLED).basis().startsWith("heartbeats of spare-pc#"), heard.lastOf(KILLED)
                .toString());

        List<Liveness.State> idle = heard.states(IDLE);
        assertEquals(List.of(Liveness.State.ALIVE), idle.subList(idle.indexOf(Liveness.State.ALIVE), idle.size())
                .stream().distinct().toList(), "once alive, the idle program stayed alive: " + idle);
    }

    private static WorldLayout.Participant participant(String name, String kind) {
        return new WorldLayout.Participant(name, kind, List.of(bumper(name)));
    }

    private static ModuleRef bumper(String participant) {
        return new ModuleRef(participant, "Bumper", "BumperModule");
    }

    private <T extends AutoCloseable> T open(T closeable) {
        opened.add(closeable);
        return closeable;
    }

    private XVSMRuntime host(String name) {
        return open(XVSMRuntime.using(RemoteSpace.open(server.uri()), name, true));
    }

    private static void serve(XVSMRuntime runtime, String participant) {
        ServingChild.serveIdleBumper(runtime, participant, "Bumper");
    }

    private static void serveFan(XVSMRuntime runtime) {
        runtime.own(new XVSMMotorModuleLocal(runtime, CLOSED, FAN.name(), new MotorModule() {
            @Override
            public void setMotor(int motor, double speed) {
            }

            @Override
            public void setMotorQuiet(int motor, double speed) {
            }
        }));
    }

    /** {@link ServingChild} in a JVM of its own, serving {@code participant}'s bumper module; waits until it does. */
    private void startChild(String participant) throws IOException, InterruptedException {
        Path log = Files.createTempFile(folder, "serving-child", ".log");
        child = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx128m",
                "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), ServingChild.class.getName(),
                server.uri().toString(), "killed-pc", participant, "Bumper")
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        waitFor("the child serves (its output: " + log + ")", () -> {
            try {
                return Files.readString(log).lines().anyMatch(line -> line.startsWith("READY "));
            } catch (IOException e) {
                return false;
            }
        });
    }

    private static void waitFor(String what, BooleanSupplier condition) throws InterruptedException {
        // only a failure runs this out: room for a busy machine starting a JVM
        long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("not within 60 s: " + what);
            }
            Thread.sleep(10);
        }
    }

    /** The liveness events, each with when it was heard. */
    private static final class Heard implements WorldObserver {
        private final List<Liveness> events = new CopyOnWriteArrayList<>();
        private final List<Long> nanos = new CopyOnWriteArrayList<>();

        @Override
        public synchronized void liveness(Liveness event) {
            events.add(event);
            nanos.add(System.nanoTime());
        }

        synchronized Liveness lastOf(String participant) {
            for (int i = events.size() - 1; i >= 0; i--) {
                if (events.get(i).participant().equals(participant)) {
                    return events.get(i);
                }
            }
            return null;
        }

        synchronized long lastNanos(String participant) {
            for (int i = events.size() - 1; i >= 0; i--) {
                if (events.get(i).participant().equals(participant)) {
                    return nanos.get(i);
                }
            }
            throw new AssertionError("nothing heard of " + participant);
        }

        Liveness.State last(String participant) {
            Liveness last = lastOf(participant);
            return last == null ? null : last.state();
        }

        List<Liveness.State> states(String participant) {
            return events.stream().filter(each -> each.participant().equals(participant)).map(Liveness::state)
                    .toList();
        }
    }
}
