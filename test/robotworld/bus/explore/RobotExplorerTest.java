package robotworld.bus.explore;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.modbus.FunctionCodes;
import robotworld.description.DescriptionException;
import robotworld.description.ModuleType;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.testsupport.ProjectFiles;

/** Exploration of a bus with troubled modules: each problem is reported for its address and skipped. */
class RobotExplorerTest {

    private static final String TROUBLED = """
            <SimulatedRobot name="Troubled">
              <World width="2000" height="1000"/>
              <Body x="500" y="500"/>
              <Motor address="1" left="1" right="2"/>
              <Bumper address="2"/>
              <Bumper address="3"/>
              <Bumper address="5" nodeId="DEADBEEF"/>
              <Servo address="6" refuseWith="4"/>
              <IRDistance address="7" crcErrorRate="1"/>
              <Motor address="8" stopped="true"/>
              <Servo address="9" silent="true"/>
              <IRDistance address="10" replyDelay="40"/>
              <Bumper address="11" nodeId="X10-LM465"/>
              <Bumper address="12"/>
              <Servo address="13" nodeId="../../etc/passwd"/>
            </SimulatedRobot>""";

    private SimulatedRobot robot;
    private RS485Bus bus;

    @BeforeEach
    void start() throws Exception {
        robot = SimulatedRobot.create(SimRobotConfigReader.parse(TROUBLED, "troubled robot"));
        robot.faults(12).mute(FunctionCodes.REPORT_SERVER_ID); // identifies itself, then fails its status
        bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withResponseTimeout(Duration.ofMillis(100)));
    }

    @AfterEach
    void stop() throws Exception {
        bus.close();
        robot.close();
    }

    private RobotExplorer explorer() {
        return new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve("ModuleDescriptions"))).addresses(1, 16);
    }

    @Test
    void everyProblemIsReportedPerAddressAndTheGoodModulesAreDescribed() throws Exception {
        // a scan timeout that a busy machine cannot beat: a reply that comes late is not what this test is about
        // (a corrupted one, as from address 7, cannot even be recognised late), every address must answer its probe
        bus.close();
        bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withResponseTimeout(Duration.ofMillis(100))
                        .withScanAllowance(Duration.ofMillis(500)));
        List<String> heard = new ArrayList<>();
        List<Integer> progress = new ArrayList<>();
        ExplorationResult result = explorer().explore("Troubled", new ExplorationListener() {
            @Override
            public void progress(int address, int done, int total) {
                progress.add(done);
                assertEquals(16, total);
            }

            @Override
            public void moduleFound(FoundModule module) {
                heard.add("found " + module.address());
            }

            @Override
            public void problem(AddressProblem problem) {
                heard.add("problem " + problem.address());
            }
        });

        Map<Integer, AddressProblem.Kind> kinds = new TreeMap<>();
        result.problems().forEach(p -> kinds.put(p.address(), p.kind()));
        assertEquals(Map.of(
                5, AddressProblem.Kind.UNKNOWN_NODE_ID,
                6, AddressProblem.Kind.EXCEPTION_RESPONSE,
                7, AddressProblem.Kind.CRC_ERROR,
                8, AddressProblem.Kind.NOT_RUNNING,
                11, AddressProblem.Kind.UNKNOWN_NODE_ID,
                12, AddressProblem.Kind.TIMEOUT,
                13, AddressProblem.Kind.UNKNOWN_NODE_ID), kinds);
        String messages = result.problems().stream().map(AddressProblem::toString).collect(Collectors.joining("\n"));
        assertTrue(messages.contains("address 5: unknown node id: NodeID 'DEADBEEF' has no description"), messages);
        assertTrue(messages.contains("Modbus exception 4 (server device failure)"), messages);
        assertTrue(messages.contains("address 11: unknown node id: NodeID 'X10-LM465' describes a X10LampModule, "
                + "which is not a bus module"), messages);
        assertTrue(messages.contains("'../../etc/passwd' is not a valid NodeID"), messages);
        assertTrue(messages.contains("no reply to report server ID (0x11)"), messages);

        assertEquals(List.of("1 MotorModule Motor-Controller", "2 BumperModule Bumper-Sensor",
                "3 BumperModule Bumper-Sensor-3", "10 IRDistanceModule IR-Distance-Sensor"),
                result.modules().stream().map(m -> m.address() + " " + m.moduleClass() + " " + m.name()).toList());
        List<String> described = new ArrayList<>();
        for (ModuleType module : result.description().orElseThrow().getRobotDescription().getModuleList()) {
            described.add(module.getNodeNumber() + " " + module.getName());
        }
        assertEquals(List.of("1 Motor-Controller", "2 Bumper-Sensor", "3 Bumper-Sensor-3", "10 IR-Distance-Sensor"),
                described);

        assertEquals(16, progress.size());
        assertEquals(16, progress.get(15));
        assertEquals(11, heard.size(), "every module and problem was heard: " + heard);
        assertTrue(result.summary(16).startsWith("4 modules found, 7 addresses skipped, 16 addresses in "),
                result.summary(16));
    }

    @Test
    void aModuleSlowerThanTheScanTimeoutIsFoundThroughItsLateReply() throws Exception {
        // a late-reply window far longer than the module's delay: a busy machine cannot make the reply miss it
        RS485Bus patient = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults().withResponseTimeout(Duration.ofSeconds(3)));
        bus.close();
        bus = patient;
        assertTrue(bus.scanReplyTimeout().toMillis() < 40, "the slow module is slower than the scan timeout");
        ExplorationResult result = new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve("ModuleDescriptions")))
                .addresses(10, 10).explore("Slow", new ExplorationListener() { });
        assertEquals(List.of(10), result.modules().stream().map(FoundModule::address).toList());
        assertTrue(result.statistics().strayFrames() >= 1, "found late: " + result.statistics());
    }

    @Test
    void aModuleAnsweringUnderAnotherAddressIsReportedWhereItListens() throws Exception {
        robot.faults(3).answerAs(14);
        ExplorationResult result = explorer().explore("Troubled", new ExplorationListener() { });
        AddressProblem at3 = result.problems().stream().filter(p -> p.address() == 3).findFirst().orElseThrow();
        assertEquals(AddressProblem.Kind.PROTOCOL_ERROR, at3.kind());
        assertTrue(at3.message().contains("came from address 14"), at3.message());
        assertTrue(result.problems().stream().noneMatch(p -> p.address() == 14), "no phantom at 14: "
                + result.problems());
    }

    @Test
    void aModuleWithAMultiByteServerIdIsExplored() throws Exception {
        String config = """
                <SimulatedRobot name="Ids">
                  <World width="2000" height="1000"/>
                  <Body x="500" y="500"/>
                  <Bumper address="20" serverId="ACME bumper rev 7"/>
                  <Motor address="21" serverId="M" stopped="true"/>
                </SimulatedRobot>""";
        try (SimulatedRobot ids = SimulatedRobot.create(SimRobotConfigReader.parse(config, "ids"));
                RS485Bus idBus = new RS485Bus(ids.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                        BusTiming.defaults())) {
            assertEquals("ACME bumper rev 7", idBus.reportServerId(20).serverIdText());
            ExplorationResult result = new RobotExplorer(idBus, new ModuleCatalog(ProjectFiles.resolve(
                    "ModuleDescriptions"))).addresses(19, 22).explore("Ids", new ExplorationListener() { });
            assertEquals(List.of(20), result.modules().stream().map(FoundModule::address).toList());
            assertEquals(List.of("address 21: NOT_RUNNING"), result.problems().stream()
                    .map(p -> "address " + p.address() + ": " + p.kind()).toList());
        }
    }

    @Test
    void noModuleMeansNoDescription() throws Exception {
        ExplorationResult result = new RobotExplorer(bus, new ModuleCatalog(ProjectFiles.resolve("ModuleDescriptions")))
                .addresses(20, 30).explore("Empty", new ExplorationListener() { });
        assertTrue(result.description().isEmpty());
        assertEquals(List.of(), result.problems());
    }

    @Test
    void aBadRobotNameFailsBeforeTheScan() {
        long before = bus.statistics().transactions();
        DescriptionException e = assertThrows(DescriptionException.class,
                () -> explorer().explore("class", new ExplorationListener() { }));
        assertTrue(e.getMessage().contains("class"), e.getMessage());
        assertThrows(DescriptionException.class, () -> explorer().explore("My Robot", new ExplorationListener() { }));
        assertEquals(before, bus.statistics().transactions());
    }

    @Test
    void addressRangesAreChecked() {
        assertThrows(IllegalArgumentException.class, () -> explorer().addresses(0, 10));
        assertThrows(IllegalArgumentException.class, () -> explorer().addresses(10, 248));
        assertThrows(IllegalArgumentException.class, () -> explorer().addresses(10, 9));
    }
}
