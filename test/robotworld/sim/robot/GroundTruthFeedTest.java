package robotworld.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.observe.GroundTruth;
import robotworld.observe.GroundTruthTuples;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.testsupport.ProjectFiles;

/** The simulator's ground truth: what it publishes matches what the modules report, and reaches the space. */
class GroundTruthFeedTest {

    @Test
    void framesShowPoseRaysContactsAndSpeedsAsTheModulesSeeThem() throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.load(ProjectFiles.resolve("docs/examples/simulated-robot.sim"));
             EmbeddedSpace space = EmbeddedSpace.open()) {
            // against the crate (x 2000..2400, y 800..1200), facing it: front bumpers touch, IR 1 reads 0
            robot.simulation().inspect(world -> {
                world.place(new Pose(2000 - 150, 1000, 0));
                return null;
            });
            String port = robot.serve("tcp://127.0.0.1:0");
            try (RS485Bus bus = new RS485Bus(port, SerialSettings.eightNoneOne(115_200), BusTiming.defaults())) {
                new MotorModuleProxy(bus, 1, "Motor").setMotor(3, -0.5); // a channel that drives no wheel
            }
            try (GroundTruthFeed feed = GroundTruthFeed.start(robot, "CaterpillarRobot", space,
                    Duration.ofMillis(20))) {
                long deadline = System.nanoTime() + Duration.ofSeconds(10).toNanos();
                while (feed.published() < 3) {
                    assertTrue(System.nanoTime() < deadline, "published: " + feed.published() + ", " + feed.problem());
                    Thread.sleep(10);
                }
                List<Entry> held = space.read(space.lookupContainer("CaterpillarRobotGROUNDTRUTH"), Timeout.TRY_ONCE,
                        Selector.fifo(Selector.ALL));
                assertEquals(1, held.size(), "only the newest frame is kept");
                GroundTruth frame = GroundTruthTuples.decode(held.get(0));
                assertEquals("CaterpillarRobot", frame.robot());
                assertEquals(1850, frame.body().x(), 0.5);
                assertEquals(1000, frame.body().y(), 0.5);
                assertEquals(150, frame.body().radius());
                assertEquals(3000, frame.arena().width());
                assertEquals(List.of(new GroundTruth.Obstacle(2000, 800, 400, 400)), frame.arena().obstacles());
                assertEquals(7, frame.rays().size());
                SimIRDistanceModule ir = (SimIRDistanceModule) robot.module(4);
                for (GroundTruth.Ray ray : frame.rays()) {
                    assertEquals(ir.distance(ray.sensor()), ray.length(), 1.0, "ray " + ray.sensor());
                }
                assertEquals(0, frame.rays().get(0).length(), 1.0, "straight ahead: the crate");
                assertTrue(frame.bumpers().stream().filter(b -> b.number() == 4 || b.number() == 6)
                        .allMatch(GroundTruth.Bumper::contact), frame.bumpers().toString());
                assertFalse(frame.bumpers().stream().filter(b -> b.number() == 1).findFirst().orElseThrow().contact());
                GroundTruth.Motor third = frame.motors().stream().filter(m -> m.channel() == 3).findFirst()
                        .orElseThrow();
                assertEquals(-0.5, third.setPoint(), 1e-9, "set-points as -1..1");
                assertEquals("", third.wheel());
                assertEquals(List.of("left", "right"), frame.motors().stream().map(GroundTruth.Motor::wheel)
                        .filter(w -> !w.isEmpty()).toList());
                assertEquals(1, feed.bumps(), "touching from the start counts as one bump");
                assertNotNull(feed.latest());
            }
        }
    }

    @Test
    void aSpaceThatIsGoneCostsFramesNotTheSimulation() throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.load(ProjectFiles.resolve("docs/examples/simulated-robot.sim"))) {
            EmbeddedSpace space = EmbeddedSpace.open();
            space.close();
            try (GroundTruthFeed feed = GroundTruthFeed.start(robot, "CaterpillarRobot", space,
                    Duration.ofMillis(20))) {
                long deadline = System.nanoTime() + Duration.ofSeconds(10).toNanos();
                while (feed.problem() == null) {
                    assertTrue(System.nanoTime() < deadline);
                    Thread.sleep(10);
                }
                long first = feed.latest().sequence();
                while (feed.latest().sequence() < first + 3) {
                    assertTrue(System.nanoTime() < deadline, "frames go on being taken");
                    Thread.sleep(10);
                }
                assertEquals(0, feed.published());
            }
        }
    }
}
