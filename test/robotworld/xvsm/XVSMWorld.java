package robotworld.xvsm;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import robotworld.bus.BumperModuleProxy;
import robotworld.bus.BusTiming;
import robotworld.bus.IRDistanceModuleProxy;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.ServoModuleProxy;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.x10.CM11aConfig;
import robotworld.x10.CM11aController;
import robotworld.x10.X10Address;
import robotworld.x10.X10ApplianceModuleLocal;
import robotworld.x10.X10LampModuleLocal;

/**
 * A whole small RobotWorld on loopback: a space server; a simulated robot "TestBot" (motor 1, bumper 2, servo 3,
 * IR 4, fast timing, parked against the wall so bumpers 4 and 6 touch it) and a simulated CM11A with a lamp at
 * A1 and an appliance at A3 for the environment "Room"; the hardware proxies on them; and a provider runtime on
 * host {@value #PROVIDER_HOST} with its own connection to the space that serves every module with its Local
 * proxy. {@link #host(String)} adds computers with their own connections and host names.
 */
final class XVSMWorld implements AutoCloseable {

    static final String ROBOT = "TestBot";
    static final String ENVIRONMENT = "Room";
    static final String MOTOR = "Motor";
    static final String BUMPER = "Bumper";
    static final String SERVO = "Servo";
    static final String IR = "IR";
    static final String LAMP = "Lamp";
    static final String FAN = "Fan";
    static final String PROVIDER_HOST = "robot-pc";
    static final int BUMPER_ADDRESS = 2;
    static final X10Address LAMP_ADDRESS = X10Address.of('A', 1);
    static final X10Address FAN_ADDRESS = X10Address.of('A', 3);
    /** Bumpers 4 and 6 touch the wall: bits 3 and 5. */
    static final int CONTACT_MASK = 1 << 3 | 1 << 5;

    /** Motor, bumper, servo, IR; the robot's front touches the wall at x = 2000; ten times real time. */
    static final String ROBOT_CONFIG = """
            <SimulatedRobot name="TestBot">
              <Bus baud="115200" timing="fast"/>
              <World width="2000" height="1000" timeScale="10"/>
              <Body x="1850" y="500" heading="0" radius="150" wheelBase="260" maxSpeed="300"/>
              <Motor address="1" left="1" right="2" ramp="4000"/>
              <Bumper address="2">
                <Mount number="4" angle="20" span="50"/>
                <Mount number="6" angle="-20" span="50"/>
                <Mount number="1" angle="180" span="90"/>
              </Bumper>
              <Servo address="3" speed="900"/>
              <IRDistance address="4" range="800">
                <Sensor number="1" angle="0"/>
                <Sensor number="2" angle="90"/>
                <Sensor number="3" angle="-90"/>
              </IRDistance>
            </SimulatedRobot>""";

    /**
     * No frame gap on a simulator link. The reply timeout is generous: with 80 busy threads on 2 cores the
     * simulator can be slow to answer, and every timeout makes the next call to that module wait out the
     * master's late-reply window (RtuMaster discards replies that come after their request timed out).
     */
    static final BusTiming BUS_TIMING = BusTiming.defaults().withResponseTimeout(Duration.ofMillis(250))
            .withAttempts(2).withFrameGap(Duration.ZERO).withServoMoveTimeout(Duration.ofSeconds(3));

    SpaceServer server;
    private EmbeddedSpace spaceData = EmbeddedSpace.open();
    final SimulatedRobot robot;
    final SimulatedCm11a cm11a;
    final RS485Bus bus;
    final CM11aController x10;
    final MotorModuleProxy motorHardware;
    final BumperModuleProxy bumperHardware;
    final ServoModuleProxy servoHardware;
    final IRDistanceModuleProxy irHardware;
    final X10LampModuleLocal lampHardware;
    final X10ApplianceModuleLocal fanHardware;
    private final List<XVSMRuntime> runtimes = new ArrayList<>();
    private XVSMRuntime provider;
    XVSMMotorModuleLocal motor;
    XVSMBumperModuleLocal bumper;
    XVSMServoModuleLocal servo;
    XVSMIRDistanceModuleLocal ir;
    XVSMX10LampModuleLocal lamp;
    XVSMX10ApplianceModuleLocal fan;

    private XVSMWorld() throws IOException {
        server = SpaceServer.start(spaceData, serverOptions(0));
        robot = SimulatedRobot.create(SimRobotConfigReader.parse(ROBOT_CONFIG, "xvsm test robot"));
        cm11a = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp,A3=appliance");
        bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200), BUS_TIMING);
        x10 = CM11aController.open(cm11a.listen(0), CM11aConfig.defaults()
                .withChecksumTimeout(Duration.ofMillis(200)).withReadyTimeout(Duration.ofMillis(500))
                .withMaxAttempts(2).withIdlePollInterval(Duration.ofMillis(5)).withPauseAfterReady(Duration.ZERO)
                .withResendDelay(Duration.ZERO).withDeadInterfaceTimeout(Duration.ofMillis(400)));
        motorHardware = new MotorModuleProxy(bus, 1, MOTOR);
        bumperHardware = new BumperModuleProxy(bus, BUMPER_ADDRESS, BUMPER);
        servoHardware = new ServoModuleProxy(bus, 3, SERVO);
        irHardware = new IRDistanceModuleProxy(bus, 4, IR);
        lampHardware = new X10LampModuleLocal(x10, LAMP_ADDRESS);
        fanHardware = new X10ApplianceModuleLocal(x10, FAN_ADDRESS);
    }

    /** The world with the provider serving every module. */
    static XVSMWorld start() throws IOException {
        XVSMWorld world = new XVSMWorld();
        try {
            world.startProvider();
        } catch (RuntimeException e) {
            world.close();
            throw e;
        }
        return world;
    }

    /** The world without anyone serving its modules yet. */
    static XVSMWorld startWithoutProvider() throws IOException {
        return new XVSMWorld();
    }

    /** Starts (or restarts) the provider program: a new runtime and connection, a Local proxy per module. */
    XVSMRuntime startProvider() {
        provider = host(PROVIDER_HOST);
        motor = new XVSMMotorModuleLocal(provider, ROBOT, MOTOR, motorHardware);
        bumper = new XVSMBumperModuleLocal(provider, ROBOT, BUMPER, bumperHardware);
        servo = new XVSMServoModuleLocal(provider, ROBOT, SERVO, servoHardware);
        ir = new XVSMIRDistanceModuleLocal(provider, ROBOT, IR, irHardware);
        lamp = new XVSMX10LampModuleLocal(provider, ENVIRONMENT, LAMP, lampHardware);
        fan = new XVSMX10ApplianceModuleLocal(provider, ENVIRONMENT, FAN, fanHardware);
        return provider;
    }

    /** A provider program on host {@value #PROVIDER_HOST} serving nothing yet: tests add their own Local proxies. */
    XVSMRuntime startEmptyProvider() {
        provider = host(PROVIDER_HOST);
        return provider;
    }

    /** Stops the provider program (its runtime closes its Local proxies and its connection). */
    void stopProvider() {
        provider.close();
    }

    XVSMRuntime provider() {
        return provider;
    }

    /** Another computer: its own connection to the space, its own host name. Closed with the world. */
    XVSMRuntime host(String hostName) {
        XVSMRuntime runtime = XVSMRuntime.using(RemoteSpace.open(server.uri()), hostName, true);
        synchronized (runtimes) {
            runtimes.add(runtime);
        }
        return runtime;
    }

    /** Stops the space server and starts a new one on the same port in front of the same space. */
    void restartServer() {
        int port = server.port();
        server.stop();
        server = SpaceServer.start(spaceData, serverOptions(port));
    }

    /** Stops the space server and starts a new one on the same port with an empty space (all containers gone). */
    void restartServerEmpty() {
        int port = server.port();
        server.stop();
        spaceData.close();
        spaceData = EmbeddedSpace.open();
        server = SpaceServer.start(spaceData, serverOptions(port));
    }

    private static SpaceServer.Options serverOptions(int port) {
        return SpaceServer.Options.defaults().port(port).stopGraceMillis(200);
    }

    @Override
    public void close() throws IOException {
        List<XVSMRuntime> all;
        synchronized (runtimes) {
            all = new ArrayList<>(runtimes);
        }
        all.forEach(XVSMRuntime::close);
        try {
            bus.close();
            x10.close();
        } finally {
            robot.close();
            cm11a.close();
            server.stop();
            spaceData.close();
        }
    }
}
