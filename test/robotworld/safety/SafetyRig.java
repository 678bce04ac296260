package robotworld.safety;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.time.Duration;
import java.util.function.BooleanSupplier;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;
import robotworld.sim.robot.SimMotorModule;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.server.SpaceServer;

/**
 * A small world on loopback for the safety tests and benchmarks: a space server, a simulated robot "SafetyBot" (a
 * motor module at address 1 driving the wheels, a bumper at 2, a servo at 3, a second motor module "Winch" at 4 that
 * drives no wheel, fast timing) and a simulated CM11A
 * with a lamp at A1. Programs under test run in this JVM or as {@link ChildProgram}s.
 */
final class SafetyRig implements AutoCloseable {

    static final String ROBOT = "SafetyBot";
    static final String MOTOR = "Motor";
    static final String BUMPER = "Bumper";
    static final String SERVO = "Servo";
    /** A second motor module (address 4, no wheels), for tests that need two actuators. */
    static final String WINCH = "Winch";
    static final String ROOM = "SafetyRoom";
    static final String LAMP = "Lamp";

    static final String ROBOT_CONFIG = """
            <SimulatedRobot name="SafetyBot">
              <Bus baud="115200" timing="fast"/>
              <World width="4000" height="4000" timeScale="1"/>
              <Body x="2000" y="2000" heading="0" radius="150" wheelBase="260" maxSpeed="300"/>
              <Motor address="1" left="1" right="2" ramp="0"/>
              <Bumper address="2">
                <Mount number="4" angle="20" span="50"/>
              </Bumper>
              <Servo address="3" speed="90"/>
              <Motor address="4" left="0" right="0" ramp="0"/>
            </SimulatedRobot>""";

    /**
     * For a child program whose test is not about the bus watchdog nor the command timeout: long ones, so that a
     * machine too busy to feed a watchdog in time does not stop the robot in the middle of another test.
     */
    static final java.util.List<String> RELAXED = java.util.List.of("-Drwe.watchdog.ms.SafetyBot.Motor=10000",
            "-Drwe.command.timeout.ms=60000");

    /** {@link #RELAXED} for a program in this JVM: call before the motor is served. */
    static void relax(robotworld.xvsm.XVSMRuntime runtime) {
        runtime.safety().describe(ROBOT, MOTOR, new ModuleSafety(60_000, 10_000, null));
    }

    final SpaceServer space;
    final SimulatedRobot robot;
    final SimulatedCm11a cm11a;
    final String spaceUrl;
    final String busPort;
    final String x10Port;

    private SafetyRig() throws IOException {
        SpaceServer server = null;
        SimulatedRobot simulated = null;
        SimulatedCm11a controller = null;
        try {
            server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
            simulated = SimulatedRobot.create(SimRobotConfigReader.parse(ROBOT_CONFIG, "safety test robot"));
            controller = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp");
            this.busPort = simulated.serve("tcp://127.0.0.1:0");
            this.x10Port = controller.listen(0);
        } catch (IOException | RuntimeException e) {
            if (server != null) {
                server.close();
            }
            if (simulated != null) {
                simulated.close();
            }
            if (controller != null) {
                controller.close();
            }
            throw e;
        }
        this.space = server;
        this.robot = simulated;
        this.cm11a = controller;
        this.spaceUrl = server.uri().toString();
    }

    static SafetyRig start() throws IOException {
        return new SafetyRig();
    }

    /** The speed motor {@code motor} is set to at the simulated module, in per-mille. */
    int motorSpeed(int motor) {
        return ((SimMotorModule) robot.module(1)).setSpeed(motor);
    }

    /** The speed motor {@code motor} of the winch (address 4) is set to at the simulated module, in per-mille. */
    int winchSpeed(int motor) {
        return ((SimMotorModule) robot.module(4)).setSpeed(motor);
    }

    /** Whether both wheel motors are set to 0 at the simulated module. */
    boolean motorsStopped() {
        return motorSpeed(1) == 0 && motorSpeed(2) == 0;
    }

    @Override
    public void close() {
        robot.close();
        cm11a.close();
        space.close();
    }

    /** Writes the rig's RobotWorld (SafetyRoom with the lamp, SafetyBot with motor and bumper) to {@code file}. */
    java.nio.file.Path writeWorld(java.nio.file.Path file) throws IOException {
        java.nio.file.Files.writeString(file, """
                <?xml version="1.0" encoding="UTF-8"?>
                <RobotWorld xmlns="urn:robotworld:description">
                  <WorldName>SafetyWorld</WorldName>
                  <CommunicationType>xvsm</CommunicationType>
                  <SpaceURL>%s</SpaceURL>
                  <Environment>
                    <EnvironmentName>SafetyRoom</EnvironmentName>
                    <Host>room-pc</Host>
                    <COMPort>%s</COMPort>
                    <X10Module>
                      <Name>Lamp</Name>
                      <HouseCode>A</HouseCode>
                      <UnitCode>ONE</UnitCode>
                      <Class>X10LampModule</Class>
                      <Version>1.0</Version>
                    </X10Module>
                  </Environment>
                  <RobotDescription>
                    <RobotName>SafetyBot</RobotName>
                    <Host>robot-pc</Host>
                    <COMPort>%s</COMPort>
                    <TalkToBusClass>RS485Bus</TalkToBusClass>
                    <Module>
                      <Name>Motor</Name>
                      <NodeID>15B63A4</NodeID>
                      <NodeNumber>1</NodeNumber>
                      <Class>MotorModule</Class>
                      <Version>1.0</Version>
                    </Module>
                    <Module>
                      <Name>Bumper</Name>
                      <NodeID>15B63B2</NodeID>
                      <NodeNumber>2</NodeNumber>
                      <Class>BumperModule</Class>
                      <Version>1.0</Version>
                    </Module>
                  </RobotDescription>
                </RobotWorld>
                """.formatted(spaceUrl, x10Port, busPort));
        return file;
    }

    /** Polls until {@code condition} holds; fails naming {@code what} after {@code limit}. */
    static void eventually(String what, Duration limit, BooleanSupplier condition) {
        long deadline = System.nanoTime() + limit.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() - deadline > 0) {
                fail("not within " + limit.toMillis() + " ms: " + what);
            }
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("interrupted while waiting for: " + what);
            }
        }
    }

    /** {@link #eventually(String, Duration, BooleanSupplier)} with a limit no load can reach. */
    static void eventually(String what, BooleanSupplier condition) {
        eventually(what, Duration.ofSeconds(30), condition);
    }
}
