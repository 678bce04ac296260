package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.xvsm.Conditions.async;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.core.BumperModule;
import robotworld.core.IRDistanceModule;
import robotworld.core.MotorModule;
import robotworld.core.ServoModule;
import robotworld.core.X10ApplianceModule;
import robotworld.core.X10LampModule;
import robotworld.space.Capi;
import robotworld.space.ContainerInfo;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/**
 * The tuples on the wire, exactly as {@code docs/runtime.md} documents them (thesis tables 4-8), written and read
 * by hand, so another implementation could take part: what a Remote proxy writes, what a Local proxy answers.
 * On an embedded space with recording fakes for the hardware.
 */
class TupleLayoutTest {

    private Capi space;
    private XVSMRuntime host;
    private final List<String> hardwareCalls = new ArrayList<>();

    @BeforeEach
    void open() {
        space = EmbeddedSpace.open();
        host = XVSMRuntime.using(space, "robot-pc");
    }

    @AfterEach
    void close() {
        host.close();
        space.close();
    }

    @Test
    void containersAreNamedAndShapedAsTheThesisSays() {
        XVSMMotorModuleLocal motor = new XVSMMotorModuleLocal(host, "Robot1", "Motor-Controller", recordingMotor());
        assertEquals("Robot1Motor-ControllerREQUEST", motor.requestName());
        assertEquals("Robot1Motor-ControllerANSWER", motor.answerName());
        ContainerInfo requests = space.describeContainer(space.lookupContainer("Robot1Motor-ControllerREQUEST"));
        ContainerInfo answers = space.describeContainer(space.lookupContainer("Robot1Motor-ControllerANSWER"));
        assertEquals(ContainerSpec.of(Order.FIFO).named("Robot1Motor-ControllerREQUEST"), requests.spec());
        assertEquals(ContainerSpec.of(Order.LIFO).withKeyView().named("Robot1Motor-ControllerANSWER"), answers.spec());
    }

    @Test
    void motorAndServo() {
        new XVSMMotorModuleLocal(host, "R", "M", recordingMotor());
        assertEquals(Tuple.of("x#1", 2, -300, "setMotor"), serve("RM", Tuple.of("x#1", 2, -300, "setMotor")));
        assertEquals(Tuple.of("x#2", 1, 1000, "setMotorQuiet"),
                serve("RM", Tuple.of("x#2", 1, 1000, "setMotorQuiet")));
        new XVSMServoModuleLocal(host, "R", "S", recordingServo());
        assertEquals(Tuple.of("x#3", 4, 90, "setServo"), serve("RS", Tuple.of("x#3", 4, 90, "setServo")));
        assertEquals(List.of("setMotor(2, -0.3)", "setMotorQuiet(1, 1.0)", "setServo(4, 90)"), hardwareCalls);
    }

    @Test
    void bumper() {
        new XVSMBumperModuleLocal(host, "R", "B", fixedBumper(0b101000));
        assertEquals(Tuple.of("x#1", 40, "getAllBumper"), serve("RB", Tuple.of("x#1", 0, "getAllBumper")));
        assertEquals(Tuple.of("x#2", Tuple.of(4, 1), "getSingleBumper"),
                serve("RB", Tuple.of("x#2", 4, "getSingleBumper")));
        assertEquals(Tuple.of("x#3", Tuple.of(5, 0), "getSingleBumper"),
                serve("RB", Tuple.of("x#3", 5, "getSingleBumper")));
    }

    @Test
    void irDistance() {
        new XVSMIRDistanceModuleLocal(host, "R", "I", fixedIr());
        assertEquals(Tuple.of("x#1", "10 20 30 40 50 60 70", "getAllSensors"),
                serve("RI", Tuple.of("x#1", 0, "getAllSensors")));
        assertEquals(Tuple.of("x#2", Tuple.of(1, 2, 3, 4, 5, 6, 7), "getAllSensors_ByteRep"),
                serve("RI", Tuple.of("x#2", 0, "getAllSensors_ByteRep")));
        assertEquals(Tuple.of("x#3", Tuple.of(3, 30), "getSingleSensor"),
                serve("RI", Tuple.of("x#3", 3, "getSingleSensor")));
        assertEquals(Tuple.of("x#4", Tuple.of(6, 60), "getSingleSensor_Cached"),
                serve("RI", Tuple.of("x#4", 6, "getSingleSensor_Cached")));
    }

    @Test
    void x10Modules() {
        new XVSMX10ApplianceModuleLocal(host, "Env", "Fan", recordingAppliance());
        assertEquals(Tuple.of("x#1", 1), serve("EnvFan", Tuple.of("x#1", 1)));
        assertEquals(Tuple.of("x#2", -1), serve("EnvFan", Tuple.of("x#2", -1)));
        assertEquals(Tuple.of("x#3", 0), serve("EnvFan", Tuple.of("x#3", 0)), "0 is not below 0: on");
        new XVSMX10LampModuleLocal(host, "Env", "Lamp", recordingLamp());
        assertEquals(Tuple.of("x#4", 40, "dim"), serve("EnvLamp", Tuple.of("x#4", 40, "dim")));
        assertEquals(Tuple.of("x#5", 0, "on"), serve("EnvLamp", Tuple.of("x#5", 0, "on")));
        assertEquals(List.of("on", "off", "on", "dim(40)", "on"), hardwareCalls);
    }

    @Test
    void errorAnswer() {
        new XVSMServoModuleLocal(host, "R", "S", recordingServo());
        assertEquals(Tuple.of("x#1", Entry.of("setServo"), Tuple.of("argument", "java.lang.IllegalArgumentException",
                "servo position 200 is outside 0..180", "robot-pc"), "ERROR"),
                serve("RS", Tuple.of("x#1", 1, 200, "setServo")));
    }

    @Test
    void whatARemoteProxyWrites() throws Exception {
        XVSMRuntime laptop = XVSMRuntime.using(space, "laptop");
        XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(laptop, "R", "B");
        CompletableFuture<Boolean> call = async(() -> remote.getSingleBumper(3));
        Tuple request = (Tuple) space.take(remote.requestContainer(), Timeout.ofMillis(5_000)).get(0);

        assertEquals(3, request.arity());
        assertTrue(request.stringAt(0).matches("laptop#[0-9a-z]+\\.1"), request.toString());
        assertEquals(Entry.of(3), request.get(1));
        assertEquals(Entry.of("getSingleBumper"), request.get(2));
        space.shift(remote.answerContainer(), Timeout.TRY_ONCE,
                List.of(Item.keyed(request.stringAt(0), Tuple.of(request.get(0), Tuple.of(3, 1), "getSingleBumper"))));
        assertTrue(call.get(5, TimeUnit.SECONDS));
        laptop.close();
    }

    @Test
    void localCallsAreAnsweredAndPublishedAlike() throws Exception {
        XVSMIRDistanceModuleLocal ir = new XVSMIRDistanceModuleLocal(host, "R", "I", fixedIr());
        assertArrayEquals(new int[] {1, 2, 3, 4, 5, 6, 7}, ir.getAllSensors_ByteRep());
        assertTrue(host.awaitPublished(java.time.Duration.ofSeconds(5)));
        assertEquals(List.of(Tuple.of("robot-pc", Tuple.of(1, 2, 3, 4, 5, 6, 7), "getAllSensors_ByteRep")),
                space.read(ir.answerContainer(), Timeout.TRY_ONCE, Selector.key("robot-pc")));
    }

    /** Writes a request by hand and takes the answer under its key. */
    private Tuple serve(String module, Tuple request) {
        ContainerRef requests = space.lookupContainer(module + "REQUEST");
        ContainerRef answers = space.lookupContainer(module + "ANSWER");
        space.write(requests, Timeout.TRY_ONCE, request);
        return (Tuple) space.take(answers, Timeout.ofMillis(5_000), Selector.key(request.stringAt(0))).get(0);
    }

    private MotorModule recordingMotor() {
        return new MotorModule() {
            @Override
            public void setMotor(int motor, double speed) {
                hardwareCalls.add("setMotor(" + motor + ", " + speed + ")");
            }

            @Override
            public void setMotorQuiet(int motor, double speed) {
                hardwareCalls.add("setMotorQuiet(" + motor + ", " + speed + ")");
            }
        };
    }

    private ServoModule recordingServo() {
        return new ServoModule() {
            @Override
            public void setServo(int servoNr, int position) {
                robotworld.core.ModuleArguments.servoPosition(position);
                hardwareCalls.add("setServo(" + servoNr + ", " + position + ")");
            }

            @Override
            public void setServoQuiet(int servoNr, int position) {
                hardwareCalls.add("setServoQuiet(" + servoNr + ", " + position + ")");
            }
        };
    }

    private X10ApplianceModule recordingAppliance() {
        return new X10ApplianceModule() {
            @Override
            public void on() {
                hardwareCalls.add("on");
            }

            @Override
            public void off() {
                hardwareCalls.add("off");
            }
        };
    }

    private X10LampModule recordingLamp() {
        return new X10LampModule() {
            @Override
            public void brighten(int level) {
                hardwareCalls.add("brighten(" + level + ")");
            }

            @Override
            public void dim(int level) {
                hardwareCalls.add("dim(" + level + ")");
            }

            @Override
            public void on() {
                hardwareCalls.add("on");
            }

            @Override
            public void off() {
                hardwareCalls.add("off");
            }
        };
    }

    private static BumperModule fixedBumper(int mask) {
        return new BumperModule() {
            @Override
            public int getAllBumper() {
                return mask;
            }

            @Override
            public boolean getSingleBumper(int bumperNumber) {
                return (mask & 1 << bumperNumber - 1) != 0;
            }
        };
    }

    private static IRDistanceModule fixedIr() {
        return new IRDistanceModule() {
            @Override
            public String getAllSensors() {
                return "10 20 30 40 50 60 70";
            }

            @Override
            public int[] getAllSensors_ByteRep() {
                return new int[] {1, 2, 3, 4, 5, 6, 7};
            }

            @Override
            public int getSingleSensor_Cached(int sensorNr) {
                return sensorNr * 10;
            }

            @Override
            public int getSingleSensor(int sensorNr) {
                return sensorNr * 10;
            }
        };
    }
}
