package robotworld.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.testsupport.ProjectFiles;

class SimRobotConfigReaderTest {

    @Test
    void theShippedExampleReads() throws Exception {
        SimRobotConfig config = SimRobotConfigReader.read(ProjectFiles.resolve("docs/examples/simulated-robot.sim"));
        assertEquals("CaterpillarRobot", config.name());
        assertEquals(115_200, config.baud());
        assertEquals(LineTiming.REAL, config.timing());
        assertEquals(4, config.modules().size());
        ModuleSpec.Motor motor = assertInstanceOf(ModuleSpec.Motor.class, config.modules().get(0));
        assertEquals(1, motor.common().address());
        assertEquals("15B63A4", motor.common().identity().nodeId());
        ModuleSpec.Bumper bumper = assertInstanceOf(ModuleSpec.Bumper.class, config.modules().get(1));
        assertEquals(20, bumper.mounts().get(4).angle());
        assertEquals(List.of(1, 2, 3, 4, 5, 6, 7),
                List.copyOf(assertInstanceOf(ModuleSpec.IRDistance.class, config.modules().get(3)).angles().keySet()));
    }

    @Test
    void faultsAndIdentityCanBeConfigured() throws Exception {
        SimRobotConfig config = SimRobotConfigReader.parse("""
                <SimulatedRobot>
                  <World width="1000" height="1000"/>
                  <Body x="500" y="500"/>
                  <Bumper address="9" nodeId="DEADBEEF" version="2.1" silent="true" crcErrorRate="0.5"
                          replyDelay="30" refuseWith="4" stopped="true"/>
                </SimulatedRobot>""", "inline.xml");
        ModuleSpec.Common common = config.modules().get(0).common();
        assertEquals(new ModuleIdentity("RobotWorld reference modules", "DEADBEEF", "2.1"), common.identity());
        assertEquals(new ModuleSpec.Common(9, common.identity(), true, 0.5, 30, 4, true), common);
        assertEquals(LineTiming.FAST, config.timing(), "fast timing by default");
    }

    @Test
    void everyProblemIsReportedWithItsPlace() {
        SimRobotConfigException e = assertThrows(SimRobotConfigException.class, () -> SimRobotConfigReader.parse("""
                <SimulatedRobot nmae="x">
                  <Bus baud="115200" timing="slow"/>
                  <World width="1000"/>
                  <Body x="500" y="500" radius="150"/>
                  <Motor address="300" left="9"/>
                  <Bumper address="2"><Mount number="9" angle="0"/><Sensor number="1"/></Bumper>
                  <IRDistance address="2"/>
                  <Wheel/>
                </SimulatedRobot>""", "bad.xml"));
        List<String> problems = e.problems();
        String all = String.join("\n", problems);
        assertTrue(all.contains("bad.xml: <SimulatedRobot>: unknown attribute 'nmae'"), all);
        assertTrue(all.contains("bad.xml: <Bus>: timing 'slow' is neither fast nor real"), all);
        assertTrue(all.contains("bad.xml: <World>: attribute 'height' is required"), all);
        assertTrue(all.contains("<Motor address=\"300\">: address 300 is outside 1..247"), all);
        assertTrue(all.contains("<Motor address=\"300\">: left 9 is outside 0..8"), all);
        assertTrue(all.contains("<Bumper address=\"2\"> <Mount>: number 9 is outside 1..8"), all);
        assertTrue(all.contains("<Bumper address=\"2\">: unknown element <Sensor> (expected Mount)"), all);
        assertTrue(all.contains("address 2 is used by two modules (Bumper and IRDistance)"), all);
        assertTrue(all.contains("unknown element <Wheel>"), all);
        assertTrue(problems.stream().allMatch(p -> p.startsWith("bad.xml: ")), all);
    }

    @Test
    void aRobotThatDoesNotFitItsArenaIsReported() {
        SimRobotConfigException e = assertThrows(SimRobotConfigException.class, () -> SimRobotConfigReader.parse("""
                <SimulatedRobot>
                  <World width="1000" height="1000"><Obstacle x="400" y="400" width="200" height="200"/></World>
                  <Body x="500" y="500"/>
                </SimulatedRobot>""", "crowded.xml"));
        assertTrue(e.getMessage().contains("does not fit"), e.getMessage());
    }

    @Test
    void doctypesAreRefused() {
        SimRobotConfigException e = assertThrows(SimRobotConfigException.class, () -> SimRobotConfigReader.parse("""
                <?xml version="1.0"?>
                <!DOCTYPE SimulatedRobot [<!ENTITY x SYSTEM "file:///etc/passwd">]>
                <SimulatedRobot name="&x;"/>""", "evil.xml"));
        assertTrue(e.getMessage().contains("evil.xml: not well-formed XML"), e.getMessage());
        assertTrue(e.getMessage().contains("DOCTYPE"), e.getMessage());
    }
}
