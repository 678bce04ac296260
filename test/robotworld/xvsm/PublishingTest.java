package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.xvsm.XVSMWorld.BUMPER;
import static robotworld.xvsm.XVSMWorld.MOTOR;
import static robotworld.xvsm.XVSMWorld.PROVIDER_HOST;
import static robotworld.xvsm.XVSMWorld.ROBOT;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.bus.ModuleRefusedException;
import robotworld.space.Capi;
import robotworld.space.Entry;
import robotworld.space.Notification;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/**
 * What a monitor on a third computer sees when it subscribes to a module's ANSWER container: every local call
 * (unless publishing is switched off) and every answered remote call, as a shift carrying function and value.
 */
class PublishingTest {

    private XVSMWorld world;
    private Capi monitor;

    @BeforeEach
    void start() throws Exception {
        world = XVSMWorld.start();
        monitor = world.host("monitor").space();
    }

    @AfterEach
    void stop() throws Exception {
        world.close();
    }

    @Test
    void localCallsArePublishedUnderTheOwnHostName() throws Exception {
        BlockingQueue<Notification> seen = watch(world.bumper.answerContainer());
        BlockingQueue<Notification> motorSeen = watch(world.motor.answerContainer());

        world.bumper.getAllBumper();
        world.bumper.getSingleBumper(6);
        world.motor.setMotor(2, -0.25);

        assertShift(Tuple.of(PROVIDER_HOST, XVSMWorld.CONTACT_MASK, "getAllBumper"), seen);
        assertShift(Tuple.of(PROVIDER_HOST, Tuple.of(6, 1), "getSingleBumper"), seen);
        assertShift(Tuple.of(PROVIDER_HOST, 2, -250, "setMotor"), motorSeen);
        assertEquals(List.of(Tuple.of(PROVIDER_HOST, Tuple.of(6, 1), "getSingleBumper")),
                monitor.read(world.bumper.answerContainer(), Timeout.TRY_ONCE, Selector.key(PROVIDER_HOST)),
                "the host's entry holds its latest call");
    }

    @Test
    void publishingCanBeSwitchedOff() throws Exception {
        world.bumper.setPublishLocalCalls(false);
        world.bumper.getAllBumper();
        assertTrue(world.provider().awaitPublished(Duration.ofSeconds(5)));
        assertEquals(0, monitor.describeContainer(world.bumper.answerContainer()).size());

        world.provider().setPublishLocalCallsByDefault(false);
        XVSMMotorModuleLocal quiet = new XVSMMotorModuleLocal(world.provider(), ROBOT, "Other", world.motorHardware);
        quiet.setMotor(1, 0.1);
        assertTrue(world.provider().awaitPublished(Duration.ofSeconds(5)));
        assertEquals(0, monitor.describeContainer(quiet.answerContainer()).size());
    }

    @Test
    void aFailedLocalCallIsPublishedAsAnErrorAnswer() throws Exception {
        BlockingQueue<Notification> seen = watch(world.bumper.answerContainer());
        world.robot.faults(XVSMWorld.BUMPER_ADDRESS).refuseWith(4);
        try {
            world.bumper.getAllBumper();
        } catch (ModuleRefusedException expected) {
            // published before it was thrown
        }
        Tuple published = (Tuple) next(seen).entries().get(0);
        assertEquals(Entry.of("ERROR"), published.get(3));
        assertEquals(Entry.of("getAllBumper"), published.get(1));
        assertEquals(Entry.of(ModuleRefusedException.class.getName()), published.tupleAt(2).get(1));
    }

    @Test
    void answeredRemoteCallsAreShiftsWithFunctionAndValue() throws Exception {
        BlockingQueue<Notification> seen = watch(world.bumper.answerContainer());
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host("laptop"), ROBOT, BUMPER);
        assertTrue(remote.getSingleBumper(4));

        Notification shift = next(seen);
        assertEquals(Operation.SHIFT, shift.operation());
        Tuple answer = (Tuple) shift.entries().get(0);
        assertTrue(answer.stringAt(0).startsWith("laptop#"), answer.toString());
        assertEquals(Tuple.of(4, 1), answer.get(1));
        assertEquals(Entry.of("getSingleBumper"), answer.get(2));
    }

    @Test
    void quietRemoteCallsAreAnsweredUnderTheProgramsId() throws Exception {
        BlockingQueue<Notification> seen = watch(world.motor.answerContainer());
        XVSMRuntime laptop = world.host("laptop");
        XVSMMotorModuleRemote remote = new XVSMMotorModuleRemote(laptop, ROBOT, MOTOR);
        remote.setMotorQuiet(3, 0.5);
        remote.setMotorQuiet(3, 0.75);
        assertTrue(laptop.programId().startsWith("laptop#"), laptop.programId());
        assertShift(Tuple.of(laptop.programId(), 3, 500, "setMotorQuiet"), seen);
        assertShift(Tuple.of(laptop.programId(), 3, 750, "setMotorQuiet"), seen);
        assertEquals(1, monitor.describeContainer(world.motor.answerContainer()).size(), "nothing piles up");
    }

    private BlockingQueue<Notification> watch(robotworld.space.ContainerRef answers) {
        BlockingQueue<Notification> seen = new LinkedBlockingQueue<>();
        monitor.subscribe(answers, java.util.Set.of(Operation.WRITE, Operation.SHIFT), NotificationMode.INFINITE,
                Timeout.INFINITE, seen::add);
        return seen;
    }

    private static Notification next(BlockingQueue<Notification> seen) throws InterruptedException {
        Notification notification = seen.poll(5, TimeUnit.SECONDS);
        if (notification == null) {
            throw new AssertionError("no notification within 5 s");
        }
        return notification;
    }

    private static void assertShift(Tuple expected, BlockingQueue<Notification> seen) throws InterruptedException {
        Notification notification = next(seen);
        assertEquals(Operation.SHIFT, notification.operation());
        assertEquals(List.of(expected), notification.entries());
    }
}
