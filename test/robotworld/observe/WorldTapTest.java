package robotworld.observe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.core.BumperModule;
import robotworld.core.MotorModule;
import robotworld.space.Capi;
import robotworld.space.ContainerRef;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Item;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * The tap over a real loopback space server: Local proxies on the robot's "computer", remote calls from a laptop,
 * the tap on a connection of its own; what observers hear, in which order, and the gap signal.
 */
class WorldTapTest {

    static final String ROBOT = "Robot1";
    static final ModuleRef MOTOR = new ModuleRef(ROBOT, "Motor", "MotorModule");
    static final ModuleRef BUMPER = new ModuleRef(ROBOT, "Bumper", "BumperModule");
    static final WorldLayout LAYOUT = new WorldLayout("TestWorld",
            List.of(new WorldLayout.Participant(ROBOT, "robot", List.of(MOTOR, BUMPER))));

    private final EmbeddedSpace data = EmbeddedSpace.open();
    private SpaceServer server;
    private final List<AutoCloseable> opened = new ArrayList<>();
    private final Recorder events = new Recorder();
    private volatile int mask = 0b1000;

    @BeforeEach
    void startServer() {
        server = SpaceServer.start(data, SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
    }

    @AfterEach
    void stop() throws Exception {
        for (int i = opened.size() - 1; i >= 0; i--) {
            opened.get(i).close();
        }
        server.stop();
        data.close();
    }

    private <T extends AutoCloseable> T open(T closeable) {
        opened.add(closeable);
        return closeable;
    }

    private XVSMRuntime host(String name) {
        return open(XVSMRuntime.using(RemoteSpace.open(server.uri()), name, true));
    }

    private WorldTap tap(Duration livenessWindow) {
        WorldTap tap = open(new WorldTap(open(RemoteSpace.open(server.uri())), LAYOUT, livenessWindow));
        tap.add(events);
        return tap;
    }

    private void serveRobot(XVSMRuntime robot) {
        new XVSMMotorModuleLocal(robot, ROBOT, "Motor", new MotorModule() {
            @Override
            public void setMotor(int motor, double speed) {
            }

            @Override
            public void setMotorQuiet(int motor, double speed) {
            }
        });
        new XVSMBumperModuleLocal(robot, ROBOT, "Bumper", new BumperModule() {
            @Override
            public int getAllBumper() {
                if (mask < 0) {
                    throw new IllegalStateException("bumper module does not answer");
                }
                return mask;
            }

            @Override
            public boolean getSingleBumper(int bumperNumber) {
                return (getAllBumper() & 1 << bumperNumber - 1) != 0;
            }
        });
    }

    @Test
    void aRemoteCallIsSeenAsRequestThenAnswerWithItsLatency() throws Exception {
        serveRobot(host("robot-pc"));
        WorldTap tap = tap(WorldTap.DEFAULT_LIVENESS_WINDOW).start();
        assertTrue(tap.awaitWatching(Duration.ofSeconds(30)));
        XVSMRuntime laptop = host("laptop");
        BumperModule bumper = new XVSMBumperModuleRemote(laptop, ROBOT, "Bumper");
        for (int i = 0; i < 10; i++) {
            assertTrue(bumper.getSingleBumper(4));
        }

        waitFor(() -> events.answers.size() == 10);
        RequestSeen request = events.requests.get(0);
        AnswerSeen answer = events.answers.get(0);
        assertEquals(BUMPER, request.module());
        assertEquals("getSingleBumper", request.request().functionText());
        assertEquals(1, request.queued());
        assertTrue(events.answers.stream().anyMatch(a -> a.answer().key().equals(request.request().key())));
        assertTrue(answer.isRemoteCall() && !answer.isError() && !answer.earlier());
        assertEquals("laptop", answer.host());
        List<Duration> latencies = events.answers.stream().map(AnswerSeen::latency).filter(l -> l != null).toList();
        assertFalse(latencies.isEmpty(), "where the tap saw the request first, it knows the latency");
        assertTrue(latencies.stream().allMatch(l -> !l.isNegative() && l.compareTo(Duration.ofSeconds(5)) < 0));
        waitFor(() -> !events.queues.isEmpty() && events.queues.get(events.queues.size() - 1).queued() == 0);
        assertTrue(events.queues.stream().anyMatch(q -> q.queued() == 1 && q.module().equals(BUMPER)),
                "the request waited, then the Local side took it: " + events.queues);
        waitFor(() -> events.last(ROBOT) == Liveness.State.ALIVE);
    }

    @Test
    void errorAnswersLocalCallsAndEarlierAnswersAreTold() throws Exception {
        XVSMRuntime robot = host("robot-pc");
        serveRobot(robot);
        XVSMMotorModuleLocal local = new XVSMMotorModuleLocal(robot, ROBOT, "Motor", new MotorModule() {
            @Override
            public void setMotor(int motor, double speed) {
            }

            @Override
            public void setMotorQuiet(int motor, double speed) {
            }
        });
        local.setMotor(1, 0.25); // published under the host's name before the tap starts
        waitFor(() -> !data.read(data.lookupContainer(MOTOR.answerContainer()), Timeout.TRY_ONCE,
                robotworld.space.Selector.fifo(robotworld.space.Selector.ALL)).isEmpty());
        tap(WorldTap.DEFAULT_LIVENESS_WINDOW).start();
        waitFor(() -> !events.answers.isEmpty());
        AnswerSeen earlier = events.answers.get(0);
        assertTrue(earlier.earlier());
        assertNull(earlier.latency());
        assertEquals("robot-pc", earlier.host());
        assertEquals("1 250", earlier.answer().fields().get(0) + " " + earlier.answer().fields().get(1));

        mask = -1;
        try {
            new XVSMBumperModuleRemote(host("laptop"), ROBOT, "Bumper").getAllBumper();
        } catch (RuntimeException expected) {
            // the caller gets the failure, observers the error answer
        }
        waitFor(() -> events.answers.stream().anyMatch(AnswerSeen::isError));
        AnswerSeen error = events.answers.stream().filter(AnswerSeen::isError).findFirst().orElseThrow();
        assertEquals(BUMPER, error.module());
        assertEquals("laptop", error.host());
    }

    @Test
    void aRequestNobodyServesMakesTheParticipantNotAnswering() throws Exception {
        tap(Duration.ofMillis(300)).start();
        waitFor(() -> events.last(ROBOT) == Liveness.State.UNKNOWN);
        new XVSMMotorModuleRemote(host("laptop"), ROBOT, "Motor").setMotorQuiet(1, 0.5); // queued, never taken
        waitFor(() -> events.last(ROBOT) == Liveness.State.NOT_ANSWERING);
        assertEquals(1, events.requests.get(0).queued());
        int before = events.liveness.size();
        serveRobot(host("robot-pc")); // the Local side starts, takes and answers it
        waitFor(() -> events.seenSince(before, ROBOT, Liveness.State.ALIVE));
        // its program's heartbeats keep it alive while nothing calls it (HeartbeatLivenessTest has more)
        Thread.sleep(900);
        assertEquals(Liveness.State.ALIVE, events.last(ROBOT));
    }

    @Test
    void aMotorModuleWhoseLastMovingChannelStopsIsReported() throws Exception {
        serveRobot(host("robot-pc"));
        tap(WorldTap.DEFAULT_LIVENESS_WINDOW).start();
        MotorModule motor = new XVSMMotorModuleRemote(host("laptop"), ROBOT, "Motor");
        motor.setMotor(1, 0.5);
        motor.setMotor(2, -0.5);
        motor.setMotor(1, 0);
        motor.setMotor(2, 0);
        waitFor(() -> events.answers.size() == 4);
        waitFor(() -> !events.stops.isEmpty());
        assertEquals(1, events.stops.size());
        assertEquals(MOTOR, events.stops.get(0).module());
        assertEquals("laptop", events.stops.get(0).by());
    }

    @Test
    void groundTruthFramesArriveDecodedAndTheNewestIsReadAtStart() throws Exception {
        Capi publisher = open(RemoteSpace.open(server.uri()));
        ContainerRef frames = publisher.lookupOrCreateContainer(GroundTruthTuples.containerSpec(ROBOT));
        publisher.shift(frames, Timeout.ofMillis(5_000),
                List.of(Item.keyed(GroundTruthTuples.KEY, GroundTruthTuples.encode(GroundTruthTuplesTest.frame(1)))));
        tap(WorldTap.DEFAULT_LIVENESS_WINDOW).start();
        waitFor(() -> events.frames.size() == 1);
        publisher.shift(frames, Timeout.ofMillis(5_000),
                List.of(Item.keyed(GroundTruthTuples.KEY, GroundTruthTuples.encode(GroundTruthTuplesTest.frame(2)))));
        waitFor(() -> events.frames.size() == 2);
        assertEquals(GroundTruthTuplesTest.frame(2), events.frames.get(1));
    }

    @Test
    void observersThatFallBehindGetAGapWithTheNumberOfEventsMissed() throws Exception {
        serveRobot(host("robot-pc"));
        CountDownLatch release = new CountDownLatch(1);
        List<Gap> gaps = new CopyOnWriteArrayList<>();
        WorldTap tap = open(new WorldTap(open(RemoteSpace.open(server.uri())), LAYOUT,
                WorldTap.DEFAULT_LIVENESS_WINDOW, 4));
        tap.add(new WorldObserver() {
            @Override
            public void answerSeen(AnswerSeen event) {
                try {
                    release.await(); // a stuck observer
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }

            @Override
            public void gap(Gap gap) {
                gaps.add(gap);
            }
        });
        tap.start();
        BumperModule bumper = new XVSMBumperModuleRemote(host("laptop"), ROBOT, "Bumper");
        for (int i = 0; i < 20; i++) {
            bumper.getAllBumper();
        }
        release.countDown();
        waitFor(() -> !gaps.isEmpty());
        assertTrue(gaps.get(0).missed() > 0 && gaps.get(0).module() == null && !gaps.get(0).ended(),
                gaps.toString());
    }

    @Test
    void aClosedConnectionEndsWatchingWithAGap() throws Exception {
        Capi connection = RemoteSpace.open(server.uri());
        WorldTap tap = open(new WorldTap(connection, LAYOUT));
        tap.add(events);
        tap.start();
        connection.close();
        waitFor(() -> events.gaps.stream().filter(Gap::ended).count() >= 4); // two containers of two modules
        assertTrue(events.gaps.stream().allMatch(gap -> gap.why().contains("closed")), events.gaps.toString());

        Capi closed = RemoteSpace.open(server.uri());
        closed.close();
        WorldTap failing = open(new WorldTap(closed, LAYOUT));
        Recorder told = new Recorder();
        failing.add(told);
        failing.startInBackground();
        assertFalse(failing.awaitWatching(Duration.ofSeconds(5)));
        waitFor(() -> told.gaps.size() >= 2);
        assertTrue(told.gaps.get(0).why().startsWith("cannot watch Robot1MotorANSWER: "), told.gaps.toString());
    }

    static void waitFor(BooleanSupplier condition) throws InterruptedException {
        // only a failure runs this out: room for a busy machine
        long deadline = System.nanoTime() + Duration.ofSeconds(30).toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("condition not met within 30 s");
            }
            Thread.sleep(10);
        }
    }

    /** Keeps everything it hears; checks it is called on one thread only. */
    static final class Recorder implements WorldObserver {
        final List<RequestSeen> requests = new CopyOnWriteArrayList<>();
        final List<AnswerSeen> answers = new CopyOnWriteArrayList<>();
        final List<Liveness> liveness = new CopyOnWriteArrayList<>();
        final List<ActuatorStopped> stops = new CopyOnWriteArrayList<>();
        final List<GroundTruth> frames = new CopyOnWriteArrayList<>();
        final List<Gap> gaps = new CopyOnWriteArrayList<>();
        final List<QueueLength> queues = new CopyOnWriteArrayList<>();
        final List<String> order = new CopyOnWriteArrayList<>();
        private volatile Thread thread;

        private void onOneThread() {
            if (thread == null) {
                thread = Thread.currentThread();
            }
            assertEquals(thread, Thread.currentThread(), "observers are called on the tap's one thread");
        }

        boolean seenSince(int index, String participant, Liveness.State state) {
            return liveness.subList(index, liveness.size()).stream()
                    .anyMatch(each -> each.participant().equals(participant) && each.state() == state);
        }

        Liveness.State last(String participant) {
            Liveness.State state = null;
            for (Liveness each : liveness) {
                if (each.participant().equals(participant)) {
                    state = each.state();
                }
            }
            return state;
        }

        @Override
        public void requestSeen(RequestSeen event) {
            onOneThread();
            requests.add(event);
            order.add("request");
        }

        @Override
        public void answerSeen(AnswerSeen event) {
            onOneThread();
            answers.add(event);
            order.add("answer");
        }

        @Override
        public void queueLength(QueueLength event) {
            onOneThread();
            queues.add(event);
        }

        @Override
        public void liveness(Liveness event) {
            onOneThread();
            liveness.add(event);
        }

        @Override
        public void actuatorStopped(ActuatorStopped event) {
            stops.add(event);
        }

        @Override
        public void groundTruth(GroundTruth frame) {
            frames.add(frame);
        }

        @Override
        public void gap(Gap gap) {
            gaps.add(gap);
        }
    }

}
