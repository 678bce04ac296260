package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.safety.SafetyRig.eventually;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.explorer.monitor.ConsoleMonitor;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMRuntime;

/** Rule 6 without a display: the console monitor prints every stop of the world's actuators, with who and why. */
class ConsoleMonitorStopsTest {

    @TempDir
    Path temp;

    @Test
    void theConsoleMonitorPrintsWhoStoppedWhatAndWhy() throws Exception {
        try (SafetyRig rig = SafetyRig.start();
             Capi monitorSpace = RemoteSpace.open(rig.space.uri());
             XVSMRuntime robot = XVSMRuntime.connect(rig.spaceUrl, "robot-pc")) {
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(
                    rig.writeWorld(temp.resolve("world.xml")), DescriptionSchemas.configured()));
            SafetyRig.relax(robot);
            RS485Bus bus = robot.own(new RS485Bus(rig.busPort, SerialSettings.eightNoneOne(115_200),
                    BusTiming.defaults().withFrameGap(Duration.ZERO)));
            XVSMMotorModuleLocal motor = robot.own(new XVSMMotorModuleLocal(robot, SafetyRig.ROBOT, SafetyRig.MOTOR,
                    new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
            StringWriter text = new StringWriter();
            try (ConsoleMonitor console = new ConsoleMonitor(world, monitorSpace, new PrintWriter(text, true))) {
                motor.setMotor(1, 0.5);
                WorldStop.stop(monitorSpace, "ops", "lunch", List.of(
                        new WorldStop.Target(SafetyRig.ROBOT, SafetyRig.MOTOR, true)), Duration.ofSeconds(30));
                eventually("the stop line", () -> text.toString().contains("STOPPED by"));
            }
            String output = text.toString();
            assertTrue(output.lines().anyMatch(line -> line.contains("SafetyBot") && line.contains("Motor")
                    && line.contains("STOPPED by " + robot.programId() + " (stop-request: asked by ops: lunch): "
                    + "motors 1-8 set to 0")), output);
        }
    }
}
