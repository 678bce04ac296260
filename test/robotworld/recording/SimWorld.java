package robotworld.recording;

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
import robotworld.observe.ModuleRef;
import robotworld.observe.WorldLayout;
import robotworld.sim.robot.GroundTruthFeed;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMIRDistanceModuleLocal;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMRuntime;

/**
 * A running simulated world on loopback, for the recording and Foxglove tests: a space server; the simulated
 * robot "SimBot" (motor 1, bumper 2, IR 4 with three sensors, fast bus timing) publishing its ground truth to the
 * space; a provider on host "robot-pc" serving its modules with the Local proxies over the Modbus bus. Others
 * reach it with {@link #host(String)}.
 */
public final class SimWorld implements AutoCloseable {

    public static final String ROBOT = "SimBot";
    public static final ModuleRef MOTOR = new ModuleRef(ROBOT, "Motor", "MotorModule");
    public static final ModuleRef BUMPER = new ModuleRef(ROBOT, "Bumper", "BumperModule");
    public static final ModuleRef IR = new ModuleRef(ROBOT, "IR", "IRDistanceModule");
    public static final WorldLayout LAYOUT = new WorldLayout("SimWorld",
            List.of(new WorldLayout.Participant(ROBOT, "robot", List.of(MOTOR, BUMPER, IR))));

    private static final String CONFIG = """
            <SimulatedRobot name="SimBot">
              <Bus baud="115200" timing="fast"/>
              <World width="2000" height="1000" timeScale="4">
                <Obstacle x="1500" y="300" width="200" height="400"/>
              </World>
              <Body x="500" y="500" heading="0" radius="150" wheelBase="260" maxSpeed="300"/>
              <Motor address="1" left="1" right="2" ramp="2000"/>
              <Bumper address="2">
                <Mount number="4" angle="20" span="50"/>
                <Mount number="6" angle="-20" span="50"/>
              </Bumper>
              <IRDistance address="4" range="800">
                <Sensor number="1" angle="0"/>
                <Sensor number="2" angle="90"/>
                <Sensor number="3" angle="-90"/>
              </IRDistance>
            </SimulatedRobot>""";

    private final SpaceServer server;
    private final SimulatedRobot robot;
    private final RS485Bus bus;
    private final GroundTruthFeed feed;
    private final List<AutoCloseable> opened = new ArrayList<>();

    private SimWorld() throws IOException {
        server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
        robot = SimulatedRobot.create(SimRobotConfigReader.parse(CONFIG, "recording test robot"));
        bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withResponseTimeout(Duration.ofMillis(1000)).withAttempts(2)
                        .withFrameGap(Duration.ZERO));
        feed = GroundTruthFeed.start(robot, ROBOT, space(), Duration.ofMillis(50));
        XVSMRuntime provider = host("robot-pc");
        new XVSMMotorModuleLocal(provider, ROBOT, MOTOR.name(), new MotorModuleProxy(bus, 1, MOTOR.name()));
        new XVSMBumperModuleLocal(provider, ROBOT, BUMPER.name(), new BumperModuleProxy(bus, 2, BUMPER.name()));
        new XVSMIRDistanceModuleLocal(provider, ROBOT, IR.name(), new IRDistanceModuleProxy(bus, 4, IR.name()));
    }

    /** Starts it all. */
    /**
     * Clients with 30 s of network allowance: a test JVM starved of CPU on a busy machine may not see its first
     * answer within the default 3 s, and these tests are about what the world shows, not about network bounds.
     */
    private static final RemoteSpace.Options PATIENT = RemoteSpace.Options.defaults().networkAllowanceMillis(30_000);

    public static SimWorld start() throws IOException {
        return new SimWorld();
    }

    /** The space's URL. */
    public String url() {
        return server.uri().toString();
    }

    /** A new connection to the space, closed with the world. */
    public Capi space() {
        return keep(RemoteSpace.open(server.uri(), PATIENT));
    }

    /** Another computer: its own connection and host name, closed with the world. */
    public XVSMRuntime host(String name) {
        return keep(XVSMRuntime.using(RemoteSpace.open(server.uri(), PATIENT), name, true));
    }

    /** The simulated robot. */
    public SimulatedRobot robot() {
        return robot;
    }

    private <T extends AutoCloseable> T keep(T closeable) {
        opened.add(closeable);
        return closeable;
    }

    @Override
    public void close() {
        feed.close();
        for (int i = opened.size() - 1; i >= 0; i--) {
            try {
                opened.get(i).close();
            } catch (Exception e) {
                throw new IllegalStateException("closing the simulated world: " + e, e);
            }
        }
        try {
            bus.close();
        } catch (IOException e) {
            throw new IllegalStateException("closing the bus: " + e, e);
        }
        robot.close();
        server.stop();
    }
}
