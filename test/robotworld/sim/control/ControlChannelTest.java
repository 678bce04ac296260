package robotworld.sim.control;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import robotworld.bus.BusTimeoutException;
import robotworld.bus.BusTiming;
import robotworld.bus.IRDistanceModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.FoundModule;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.testsupport.ProjectFiles;
import robotworld.x10.CM11aConfig;
import robotworld.x10.CM11aController;
import robotworld.x10.X10Address;
import robotworld.x10.X10Event;
import robotworld.x10.X10Function;
import robotworld.x10.X10TimeoutException;

/** Both simulators driven through their control channel over loopback TCP, as a test or a person would. */
class ControlChannelTest {

    private static final String ROBOT = """
            <SimulatedRobot name="Driven">
              <Bus baud="115200" timing="fast"/>
              <World width="2000" height="1000"/>
              <Body x="500" y="500" heading="0"/>
              <Motor address="1" left="1" right="2"/>
              <Bumper address="2"/>
              <IRDistance address="4" range="800"><Sensor number="1" angle="0"/></IRDistance>
            </SimulatedRobot>""";

    /** One control connection: a line out, a line back. */
    private static final class Client implements AutoCloseable {
        private final Socket socket;
        private final PrintWriter out;
        private final BufferedReader in;

        Client(String portName) throws IOException {
            URI uri = URI.create(portName);
            socket = new Socket(uri.getHost(), uri.getPort());
            socket.setSoTimeout(10_000);
            out = new PrintWriter(socket.getOutputStream(), true, StandardCharsets.UTF_8);
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        }

        String ask(String line) throws IOException {
            out.println(line);
            return in.readLine();
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }

    @Test
    void theCm11aSimulatorTakesPowerLineTrafficAndFaultsFromOutside() throws Exception {
        BlockingQueue<X10Event> events = new LinkedBlockingQueue<>();
        CM11aConfig config = CM11aConfig.defaults().forFastSimulator().withChecksumTimeout(Duration.ofMillis(200))
                .withDeadInterfaceTimeout(Duration.ofMillis(400));
        try (SimulatedCm11a sim = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp,A3=appliance");
                ControlChannel channel = new ControlChannel(new Cm11aControl(sim));
                CM11aController controller = CM11aController.open(sim.listen(0), config);
                Client client = new Client(channel.listen(0))) {
            controller.addListener(events::add);
            assertEquals("ok A5 On", client.ask("remote A5 on"));
            X10Event event = events.poll(10, TimeUnit.SECONDS);
            assertEquals("A5 On", String.valueOf(event));

            assertEquals("ok A1 dim 11", client.ask("dim a1 11"));
            assertEquals(11, sim.lamp(X10Address.of('A', 1)).level());
            assertEquals("ok A All Lights Off", client.ask("house A all-lights-off"));
            assertFalse(sim.lamp(X10Address.of('A', 1)).isOn());

            assertEquals("ok the next 1 checksums are wrong", client.ask("bad-checksums 1"));
            controller.on(X10Address.of('A', 3)); // sent again after the wrong checksum
            assertTrue(sim.appliance(X10Address.of('A', 3)).isOn());

            assertEquals("ok the interface answers nothing", client.ask("power-off"));
            assertThrows(X10TimeoutException.class, () -> controller.off(X10Address.of('A', 3)));
            assertTrue(client.ask("power-on").startsWith("ok back"));
            controller.off(X10Address.of('A', 3)); // after the clock the interface asked for
            assertFalse(sim.appliance(X10Address.of('A', 3)).isOn());

            assertTrue(client.ask("status").startsWith("ok A1 lamp off, A3 appliance off"));
            assertTrue(client.ask("help").contains("remote A5 on|off"));
            assertTrue(client.ask("remote Z9 on").startsWith("error 'Z9' is not an X10 address"));
            assertTrue(client.ask("remote A5 sing").startsWith("error 'sing' is not an X10 function"));
            assertTrue(client.ask("explode").startsWith("error unknown command 'explode'"));
            assertEquals("ok bye", client.ask("quit"));
        }
    }

    @Test
    void theRobotSimulatorIsMovedGivenObstaclesAndFaultsFromOutside() throws Exception {
        try (SimulatedRobot robot = SimulatedRobot.create(SimRobotConfigReader.parse(ROBOT, "driven"));
                ControlChannel channel = new ControlChannel(new RobotControl(robot));
                RS485Bus bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                        BusTiming.defaults().withResponseTimeout(Duration.ofMillis(100)));
                Client client = new Client(channel.listen(0))) {
            IRDistanceModuleProxy ir = new IRDistanceModuleProxy(bus, 4, "IR");
            assertEquals("ok 1000.0 500.0 0.0", client.ask("place 1000 500 0"));
            assertEquals(800, ir.getSingleSensor(1), "nothing within range ahead");
            assertEquals("ok 1 obstacles", client.ask("obstacle 1400 400 100 200"));
            assertEquals(250, ir.getSingleSensor(1), 2, "the box 250 mm ahead of the body");
            assertTrue(client.ask("obstacle 900 400 200 200").startsWith("error the obstacle"), "not onto the robot");
            assertEquals("ok 0 obstacles", client.ask("remove-obstacle 1400 400 100 200"));
            assertEquals(800, ir.getSingleSensor(1));

            assertEquals("ok address 2: silent", client.ask("fail 2 silent"));
            assertThrows(BusTimeoutException.class, () -> bus.identify(2));
            assertEquals("ok address 2: none", client.ask("fail 2 none"));
            assertEquals("ok address 4 replies 40 ms late", client.ask("slow 4 40"));
            ExplorationResult result = new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve(
                    "ModuleDescriptions"))).addresses(1, 6).explore("Driven", new ExplorationListener() { });
            assertEquals(List.of(1, 2, 4), result.modules().stream().map(FoundModule::address).toList(),
                    "the slow module found through its late reply: " + result.problems());

            assertEquals("ok the line echoes requests", client.ask("echo on"));
            bus.identify(1);
            assertTrue(bus.echoDetected());
            assertTrue(client.ask("fail 9 silent").startsWith("error no simulated module at address 9"));
            assertTrue(client.ask("fail 2 crc 2").startsWith("error CRC error rate must be 0..1"));
            assertTrue(client.ask("pose").startsWith("ok 1000.0 500.0"));
        }
    }
}
