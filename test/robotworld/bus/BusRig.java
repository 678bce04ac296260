package robotworld.bus;

import java.io.IOException;
import java.time.Duration;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;

/**
 * A simulated robot and a bus master connected to it, over {@code tcp://} or through a socat pty pair (simulator
 * on one end, master on the other, both through jSerialComm).
 */
final class BusRig implements AutoCloseable {

    /**
     * Motor (1), bumper (2), servo (3), IR distance (4) in a 2 m x 1 m arena; the robot at (500, 500) facing the
     * wall at x = 2000; ten times real time, so a drive to the wall takes about half a second.
     */
    static final String FOUR_MODULES = """
            <SimulatedRobot name="TestBot">
              <Bus baud="115200" timing="fast"/>
              <World width="2000" height="1000" timeScale="10"/>
              <Body x="500" y="500" heading="0" radius="150" wheelBase="260" maxSpeed="300"/>
              <Motor address="1" left="1" right="2" ramp="4000"/>
              <Bumper address="2">
                <Mount number="4" angle="20" span="50"/>
                <Mount number="6" angle="-20" span="50"/>
                <Mount number="1" angle="180" span="90"/>
              </Bumper>
              <Servo address="3" speed="90"/>
              <IRDistance address="4" range="800">
                <Sensor number="1" angle="0"/>
                <Sensor number="2" angle="90"/>
                <Sensor number="3" angle="-90"/>
              </IRDistance>
            </SimulatedRobot>""";

    /**
     * Master timing for tests: a reply timeout a busy machine does not eat (a module in fast timing answers at
     * once, but the simulator's thread was seen starved for over 250 ms with two CPU hogs per core beside the
     * suite), yet failure tests stay short.
     */
    static final BusTiming TIMING = BusTiming.defaults().withResponseTimeout(Duration.ofMillis(1000))
            .withServoMoveTimeout(Duration.ofSeconds(5));

    private final SimulatedRobot robot;
    private final RS485Bus bus;
    private final SocatPty pty;

    private BusRig(SimulatedRobot robot, RS485Bus bus, SocatPty pty) {
        this.robot = robot;
        this.bus = bus;
        this.pty = pty;
    }

    /** The robot served on a free loopback port, the master connected through {@code tcp://}. */
    static BusRig tcp(String configXml, BusTiming timing) throws IOException {
        SimulatedRobot robot = SimulatedRobot.create(SimRobotConfigReader.parse(configXml, "test robot"));
        try {
            String port = robot.serve("tcp://127.0.0.1:0");
            return new BusRig(robot, new RS485Bus(port, SerialSettings.eightNoneOne(115_200), timing), null);
        } catch (IOException | RuntimeException e) {
            robot.close();
            throw e;
        }
    }

    /** The robot on one end of a socat pty pair, the master on the other. */
    static BusRig pty(String configXml, BusTiming timing) throws IOException, InterruptedException {
        SocatPty pty = SocatPty.start();
        SimulatedRobot robot = SimulatedRobot.create(SimRobotConfigReader.parse(configXml, "test robot"));
        try {
            robot.serve(pty.a().toString());
            return new BusRig(robot, new RS485Bus(pty.b().toString(), SerialSettings.eightNoneOne(115_200), timing),
                    pty);
        } catch (IOException | RuntimeException e) {
            robot.close();
            pty.close();
            throw e;
        }
    }

    SimulatedRobot robot() {
        return robot;
    }

    RS485Bus bus() {
        return bus;
    }

    @Override
    public void close() throws IOException {
        try {
            bus.close();
        } finally {
            robot.close();
            if (pty != null) {
                pty.close();
            }
        }
    }
}
