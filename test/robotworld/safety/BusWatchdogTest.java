package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.safety.SafetyRig.eventually;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.BusTiming;
import robotworld.bus.BusWatchdog;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.sim.robot.SimModule;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;
import robotworld.xvsm.ActuatorStoppedException;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMRuntime;

/**
 * Rule 2: the program that serves a motor module arms the module's communication watchdog and keeps it fed; when
 * the program dies hard (SIGKILL) the module stops by itself; a trip the program lives to see is recorded, and
 * its commanders are told.
 */
class BusWatchdogTest {

    @TempDir
    Path temp;

    private SafetyRig rig;

    @BeforeEach
    void startRig() throws Exception {
        rig = SafetyRig.start();
    }

    @AfterEach
    void stopRig() {
        rig.close();
    }

    /** The test JVM sets long safety timeouts for the tests that are not about them: back to the defaults here. */
    @BeforeEach
    void defaults() {
        watchdogSetting = System.getProperty("rwe.watchdog.ms");
        System.clearProperty("rwe.watchdog.ms");
    }

    @AfterEach
    void restore() {
        if (watchdogSetting != null) {
            System.setProperty("rwe.watchdog.ms", watchdogSetting);
        }
    }

    private String watchdogSetting;

    @Test
    void aMotorModuleIsArmedWithTheDefaultAndKeptFedWhileTheProgramLives() throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc")) {
            RS485Bus bus = runtime.own(bus());
            XVSMMotorModuleLocal motor = runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT,
                    SafetyRig.MOTOR, new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
            SimModule module = rig.robot.module(1);
            assertEquals(SafetySettings.DEFAULT_MOTOR_WATCHDOG_MILLIS, module.watchdogMillis());
            assertEquals(SafetySettings.DEFAULT_MOTOR_WATCHDOG_MILLIS, bus.watchdog().armedMillis(1));
            motor.setMotor(1, 0.3);
            // idle for several timeouts: only the watchdog's heartbeats talk to the module
            eventually("heartbeats", () -> bus.watchdog().heartbeats() >= 6);
            assertFalse(module.watchdogTripped(), "fed by heartbeats");
            assertEquals(300, rig.motorSpeed(1));
        }
    }

    @Test
    void aModuleWithoutAWatchdogIsServedAnyway() throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc")) {
            RS485Bus bus = runtime.own(bus());
            rig.robot.faults(1).refuseWith(2); // a module that knows no register 0x0100 (nor any other)
            runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT, SafetyRig.MOTOR,
                    new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
            assertEquals(0, bus.watchdog().armedMillis(1), "not armed, logged");
            rig.robot.faults(1).refuseWith(0);
        }
    }

    @Test
    void aModuleSilentWhenItIsArmedIsArmedWhenItAnswersAgain() throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc")) {
            RS485Bus bus = runtime.own(bus());
            rig.robot.faults(1).silent(true);
            runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT, SafetyRig.MOTOR,
                    new MotorModuleProxy(bus, 1, SafetyRig.MOTOR))); // the program starts anyway
            assertEquals(0, rig.robot.module(1).watchdogMillis());
            rig.robot.faults(1).silent(false);
            eventually("armed once it answers", () -> rig.robot.module(1).watchdogMillis()
                    == SafetySettings.DEFAULT_MOTOR_WATCHDOG_MILLIS);
            eventually("and fed", () -> bus.watchdog().armedMillis(1) == SafetySettings.DEFAULT_MOTOR_WATCHDOG_MILLIS);
        }
    }

    @Test
    void aProgramKilledWithSigkillLeavesItsMotorsToTheWatchdog() throws Exception {
        // only the watchdog: a command timeout (for a lost space) no busy machine reaches
        try (ChildProgram child = ChildProgram.start(temp, List.of("-Drwe.command.timeout.ms=60000"), SafetyChild.class,
                "serve", "wait",
                rig.spaceUrl, rig.busPort)) {
            child.awaitLine("READY", Duration.ofSeconds(60));
            assertEquals(450, rig.motorSpeed(1));
            child.kill();
            child.awaitExit(Duration.ofSeconds(30));
            eventually("the module stops by itself", rig::motorsStopped);
            assertTrue(rig.robot.module(1).watchdogTripped());
        }
    }

    @Test
    void aHardDeathIsRecordedByTheNextProgramThatArmsTheModuleSoMonitorsShowIt() throws Exception {
        try (ChildProgram child = ChildProgram.start(temp, List.of("-Drwe.command.timeout.ms=60000"), SafetyChild.class,
                "serve", "wait", rig.spaceUrl, rig.busPort)) {
            child.awaitLine("READY", Duration.ofSeconds(60));
            child.kill(); // nobody is left to read the tripped bit
            child.awaitExit(Duration.ofSeconds(30));
            eventually("the module stops by itself", () -> rig.robot.module(1).watchdogTripped());
        }
        List<StopRecord> shown = new java.util.concurrent.CopyOnWriteArrayList<>();
        try (Capi monitorSpace = RemoteSpace.open(rig.space.uri());
             StopWatcher monitor = StopWatcher.start(monitorSpace, shown::add);
             XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc")) {
            RS485Bus bus = runtime.own(bus());
            XVSMMotorModuleLocal motor = runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT,
                    SafetyRig.MOTOR, new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
            eventually("a monitor is shown the stop", () -> shown.stream()
                    .anyMatch(stop -> stop.cause() == StopCause.WATCHDOG && stop.where().equals("SafetyBot/Motor")));
            StopRecord stop = shown.stream().filter(s -> s.cause() == StopCause.WATCHDOG).findFirst().orElseThrow();
            assertTrue(stop.reason().startsWith("stopped by its watchdog while no program fed it"), stop.toString());
            assertTrue(stop.reason().contains(runtime.programId()), "who found it: " + stop);
            assertEquals("its watchdog", stop.stoppedBy());
            assertTrue(runtime.safety().recentStops().stream().anyMatch(s -> s.reason().equals(stop.reason())),
                    "recorded by the program that found it: " + runtime.safety().recentStops());
            assertFalse(rig.robot.module(1).watchdogTripped(), "armed again");
            motor.setMotor(1, 0.3); // nobody is owed a notice: this program had commanded nothing
            assertEquals(300, rig.motorSpeed(1));
        }
    }

    @Test
    void aTripTheProgramLivesToSeeIsRecordedAndItsCommandersAreTold() throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(rig.spaceUrl, "robot-pc")) {
            RS485Bus bus = runtime.own(bus());
            runtime.safety().describe(SafetyRig.ROBOT, SafetyRig.MOTOR, new ModuleSafety(null, 100, null));
            XVSMMotorModuleLocal motor = runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT,
                    SafetyRig.MOTOR, new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
            assertEquals(100, rig.robot.module(1).watchdogMillis());
            motor.setMotor(1, 0.3);
            // the line to the module breaks for a while (as if this program froze): it hears nothing, stops
            rig.robot.faults(1).silent(true);
            eventually("tripped", () -> rig.robot.module(1).watchdogTripped());
            assertEquals(0, rig.motorSpeed(1));
            rig.robot.faults(1).silent(false);
            eventually("the program hears of the trip", () -> runtime.safety().recentStops().stream()
                    .anyMatch(stop -> stop.cause() == StopCause.WATCHDOG));
            eventually("armed again", () -> !rig.robot.module(1).watchdogTripped());
            StopRecord stop = runtime.safety().recentStops().stream()
                    .filter(s -> s.cause() == StopCause.WATCHDOG).findFirst().orElseThrow();
            assertTrue(stop.reason().contains("watchdog tripped"), stop.toString());
            ActuatorStoppedException told = assertThrows(ActuatorStoppedException.class,
                    () -> motor.setMotor(1, 0.3));
            assertTrue(told.getMessage().contains("watchdog"), told.getMessage());
            motor.setMotor(1, 0.3);
            assertEquals(300, rig.motorSpeed(1), "commanded again, it moves");
        }
    }

    @Test
    void theRegisterMapIsTheDocumentedOne() throws Exception {
        try (RS485Bus bus = bus()) {
            bus.writeRegister(1, BusWatchdog.TIMEOUT_REGISTER, 1234);
            assertEquals(1234, bus.readHoldingRegisters(1, 0x0100, 1)[0]);
            assertFalse(bus.readDiscreteInputs(1, 0x0100, 1)[0]);
            bus.writeRegister(1, BusWatchdog.TIMEOUT_REGISTER, 0);
        }
    }

    private RS485Bus bus() throws Exception {
        return new RS485Bus(rig.busPort, SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withFrameGap(Duration.ZERO));
    }
}
