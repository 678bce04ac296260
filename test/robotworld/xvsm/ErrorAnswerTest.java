package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.xvsm.Conditions.eventually;
import static robotworld.xvsm.XVSMWorld.BUMPER;
import static robotworld.xvsm.XVSMWorld.BUMPER_ADDRESS;
import static robotworld.xvsm.XVSMWorld.ENVIRONMENT;
import static robotworld.xvsm.XVSMWorld.LAMP;
import static robotworld.xvsm.XVSMWorld.MOTOR;
import static robotworld.xvsm.XVSMWorld.PROVIDER_HOST;
import static robotworld.xvsm.XVSMWorld.ROBOT;
import static robotworld.xvsm.XVSMWorld.SERVO;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.bus.ModuleRefusedException;
import robotworld.space.Entry;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/**
 * Failures: a hardware error travels back as an error answer and is raised at the caller naming participant,
 * module and function, and the Local side goes on serving; silent hardware and a missing Local side give
 * timeouts naming module and host, never a hang.
 */
class ErrorAnswerTest {

    private XVSMWorld world;

    @BeforeEach
    void start() throws Exception {
        world = XVSMWorld.start();
    }

    @AfterEach
    void stop() throws Exception {
        world.close();
    }

    @Test
    void hardwareFailureIsRaisedAtTheCallerAndTheLocalSideKeepsServing() {
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host("laptop"), ROBOT, BUMPER);
        world.robot.faults(BUMPER_ADDRESS).refuseWith(4); // Modbus "server device failure"

        XVSMRemoteException failure = assertThrows(XVSMRemoteException.class, () -> remote.getSingleBumper(4));
        assertEquals(ROBOT, failure.participant());
        assertEquals(BUMPER, failure.module());
        assertEquals("getSingleBumper", failure.function());
        assertEquals(PROVIDER_HOST, failure.remoteHost());
        assertEquals(ModuleRefusedException.class.getName(), failure.remoteType());
        assertTrue(failure.getMessage().startsWith("TestBot/Bumper getSingleBumper failed on host robot-pc: "),
                failure.getMessage());

        world.robot.faults(BUMPER_ADDRESS).refuseWith(0);
        assertEquals(XVSMWorld.CONTACT_MASK, remote.getAllBumper());
        assertTrue(world.bumper.isServing());
    }

    @Test
    void aLocalCallFailsAsTheHardwareDoes() {
        world.robot.faults(BUMPER_ADDRESS).refuseWith(4);
        assertThrows(ModuleRefusedException.class, world.bumper::getAllBumper);
    }

    @Test
    void silentBusModuleGivesATimeoutNamingModuleAndHost() {
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(world.host("laptop"), ROBOT, BUMPER);
        world.robot.faults(BUMPER_ADDRESS).silent(true);

        long start = System.nanoTime();
        ModuleCallTimeoutException timeout = assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper);
        long millis = (System.nanoTime() - start) / 1_000_000;

        assertTrue(timeout.hardwareTimedOut());
        assertTrue(timeout.getMessage().contains("TestBot/Bumper getAllBumper"), timeout.getMessage());
        assertTrue(timeout.getMessage().contains("host robot-pc"), timeout.getMessage());
        // the bus gives up after 2 x 250 ms; the bound only tells that apart from the 10 s call timeout, with room
        // for a busy machine
        assertTrue(millis < 6_000, "the bus gives up after 2 x 250 ms, the call took " + millis + " ms");

        world.robot.faults(BUMPER_ADDRESS).silent(false);
        assertEquals(XVSMWorld.CONTACT_MASK, remote.getAllBumper());
    }

    @Test
    void silentCm11aGivesATimeoutNotAHang() {
        XVSMX10LampModuleRemote remote = new XVSMX10LampModuleRemote(world.host("laptop"), ENVIRONMENT, LAMP);
        // far longer than the interface's 2 x 200 ms, so that the hardware's timeout answers first even on a busy
        // machine
        remote.setCallTimeout(Duration.ofSeconds(20));
        world.cm11a.powerOff();
        long start = System.nanoTime();
        ModuleCallTimeoutException timeout = assertThrows(ModuleCallTimeoutException.class, remote::on);
        assertTrue(timeout.hardwareTimedOut(), timeout.getMessage());
        assertTrue(timeout.getMessage().contains("Room/Lamp on"), timeout.getMessage());
        assertTrue(System.nanoTime() - start < Duration.ofSeconds(10).toNanos(), "not a hang");
    }

    @Test
    void noLocalSideGivesATimeoutAndTheRequestIsWithdrawn() {
        world.stopProvider();
        XVSMRuntime laptop = world.host("laptop");
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, ROBOT, BUMPER);
        remote.setCallTimeout(Duration.ofMillis(200));

        long start = System.nanoTime();
        ModuleCallTimeoutException timeout = assertThrows(ModuleCallTimeoutException.class, remote::getAllBumper);
        long millis = (System.nanoTime() - start) / 1_000_000;

        assertFalse(timeout.hardwareTimedOut());
        assertEquals(200, timeout.timeoutMillis());
        assertTrue(timeout.getMessage().startsWith("TestBot/Bumper getAllBumper: no answer within 200 ms"),
                timeout.getMessage());
        assertTrue(timeout.getMessage().contains("asked from host laptop"), timeout.getMessage());
        assertTrue(timeout.getMessage().contains("withdrawn"), timeout.getMessage());
        assertTrue(millis >= 190 && millis < 5_000, "took " + millis + " ms"); // generous: the machine may be busy
        assertEquals(0, laptop.space().describeContainer(remote.requestContainer()).size(),
                "a request nobody served is not left for a later Local side to carry out");
    }

    @Test
    void malformedRequestsGetErrorAnswersAndTheLocalSideKeepsServing() {
        XVSMRuntime tool = world.host("tool");
        var space = tool.space();
        var requests = space.lookupContainer(XVSMModule.requestContainerName(ROBOT, MOTOR));
        var answers = space.lookupContainer(XVSMModule.answerContainerName(ROBOT, MOTOR));

        space.write(requests, Timeout.TRY_ONCE, Tuple.of("tool#1", 1, 200, "fly"));
        space.write(requests, Timeout.TRY_ONCE, Tuple.of("tool#2", "fast", "setMotor"));
        space.write(requests, Timeout.TRY_ONCE, Tuple.of("tool#3", 1, 5000, "setMotor"));
        space.write(requests, Timeout.TRY_ONCE, Tuple.of(42)); // no key: nobody to answer, dropped
        space.write(requests, Timeout.TRY_ONCE, Tuple.of("tool#4", 1, 200, "setMotor"));

        assertEquals(Tuple.of("tool#1", Entry.of("fly"), Tuple.of("request", MalformedCallException.class.getName(),
                "unknown function \"fly\" in <\"tool#1\", 1, 200, \"fly\">", PROVIDER_HOST), "ERROR"),
                take(space, answers, "tool#1"));
        Tuple wrongType = take(space, answers, "tool#2");
        assertEquals("request", wrongType.tupleAt(2).stringAt(0));
        Tuple outOfRange = take(space, answers, "tool#3");
        assertEquals(Tuple.of("argument", IllegalArgumentException.class.getName(), "speed 5.0 is outside -1.0..1.0",
                PROVIDER_HOST), outOfRange.tupleAt(2));
        assertEquals(Tuple.of("tool#4", 1, 200, "setMotor"), take(space, answers, "tool#4"));
        assertEquals(0.2, world.motorHardware.getMotor(1));
        eventually("nothing is left in the queue", () -> space.describeContainer(requests).size() == 0);
    }

    @Test
    void anArgumentRefusedByTheHostIsAnIllegalArgumentAtTheCaller() {
        // a caller that skipped the checks: the host refuses, the caller sees the same kind of exception
        XVSMServoModuleRemote remote = new XVSMServoModuleRemote(world.host("laptop"), ROBOT, SERVO);
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> remote.call("setServo", 1, 200));
        assertEquals("TestBot/Servo setServo: servo position 200 is outside 0..180", refused.getMessage());
    }

    private static Tuple take(robotworld.space.Capi space, robotworld.space.ContainerRef answers, String key) {
        List<Entry> taken = space.take(answers, Timeout.ofMillis(5_000), Selector.key(key));
        return (Tuple) taken.get(0);
    }
}
