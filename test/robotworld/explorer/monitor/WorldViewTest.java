package robotworld.explorer.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.explorer.gui.GuiTesting.eventually;
import static robotworld.explorer.gui.GuiTesting.onEdt;
import static robotworld.explorer.gui.GuiTesting.screenshot;

import java.awt.Color;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.time.Duration;
import java.time.Instant;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.bus.BumperModuleProxy;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.core.BumperModule;
import robotworld.core.MotorModule;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.gui.GuiTesting;
import robotworld.explorer.monitor.gui.LayoutMemory;
import robotworld.explorer.monitor.gui.MonitorWindow;
import robotworld.explorer.monitor.gui.WorldView;
import robotworld.observe.GroundTruth;
import robotworld.observe.ModuleRef;
import robotworld.sim.robot.GroundTruthFeed;
import robotworld.sim.robot.LineTiming;
import robotworld.sim.robot.SimRobotConfigReader;
import robotworld.sim.robot.SimulatedRobot;
import robotworld.testsupport.ProjectFiles;
import robotworld.bus.IRDistanceModuleProxy;
import robotworld.bus.ServoModuleProxy;
import robotworld.core.IRDistanceModule;
import robotworld.core.ServoModule;
import robotworld.explorer.monitor.gui.BumperModulePanel;
import robotworld.explorer.monitor.gui.IRDistanceModulePanel;
import robotworld.xvsm.XVSMIRDistanceModuleLocal;
import robotworld.xvsm.XVSMIRDistanceModuleRemote;
import robotworld.xvsm.XVSMServoModuleLocal;
import robotworld.xvsm.XVSMServoModuleRemote;
import robotworld.xvsm.XVSMX10ApplianceModuleLocal;
import robotworld.xvsm.XVSMX10ApplianceModuleRemote;
import robotworld.xvsm.XVSMX10LampModuleLocal;
import robotworld.xvsm.XVSMX10LampModuleRemote;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMBumperModuleRemote;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * The monitor window with a simulated robot behind it, as a user runs it: the robot's program serves its motor and
 * bumper modules on the simulated bus, a laptop drives it through the space into the crate, the simulator publishes
 * its ground truth, and the pixels of the world view must show the robot where it stopped, touching with its front
 * bumpers; the plots must gain the values.
 *
 * <p>It also takes the user guide's pictures of the monitor: {@code build/screenshots/docs-NAME.png} is
 * {@code docs/images/NAME.png}; copy them over when the monitor's looks change.
 */
class WorldViewTest {

    private static final String ROBOT = "CaterpillarRobot";
    /** The crate of the example robot's arena begins at x = 2000; the body's radius is 150. */
    private static final double STOP_X = 2000 - 150;

    @TempDir
    Path folder;

    private MonitoredSpace space;
    private SimulatedRobot robot;
    private RS485Bus bus;
    private GroundTruthFeed feed;
    private WorldMonitor monitor;

    @BeforeEach
    void start() throws Exception {
        GuiTesting.assumeDisplay();
        space = new MonitoredSpace();
        robot = SimulatedRobot.create(SimRobotConfigReader.read(ProjectFiles.resolve(
                "docs/examples/simulated-robot.sim")).withTiming(LineTiming.FAST).withTimeScale(4));
        bus = new RS485Bus(robot.serve("tcp://127.0.0.1:0"), SerialSettings.eightNoneOne(115_200),
                BusTiming.defaults());
        XVSMRuntime robotLaptop = space.host("robot-laptop");
        new XVSMMotorModuleLocal(robotLaptop, ROBOT, "Motor-Controller", new MotorModuleProxy(bus, 1));
        new XVSMBumperModuleLocal(robotLaptop, ROBOT, "Bumper-Sensor", new BumperModuleProxy(bus, 2));
        new XVSMServoModuleLocal(robotLaptop, ROBOT, "Head-Servo", new ServoModuleProxy(bus, 3));
        new XVSMIRDistanceModuleLocal(robotLaptop, ROBOT, "IR-Sensors", new IRDistanceModuleProxy(bus, 4));
        new XVSMX10ApplianceModuleLocal(space.host("room-pc"), "DimRoom", "Lamp", new FakeHardware.Appliance());
        new XVSMX10LampModuleLocal(space.host("room-pc"), "DimRoom", "Ceiling", new FakeHardware.Lamp());
        feed = GroundTruthFeed.start(robot, ROBOT, space.connection(), Duration.ofMillis(20));
        MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorld(MonitorTestWorlds.everyModuleType(folder)));
        monitor = onEdt(() -> {
            WorldMonitor opened = new WorldMonitor(world, space.connection(), new MonitorLoader(),
                    WorldMonitor.Windows.ONE, LayoutMemory.none());
            opened.show(); // at its default size: the docs screenshots show what a user sees the first time
            return opened;
        });
        assertTrue(monitor.awaitWatching(Duration.ofSeconds(10)));
    }

    @AfterEach
    void stop() throws Exception {
        if (monitor != null) {
            onEdt(monitor::close);
        }
        if (feed != null) {
            feed.close();
        }
        if (bus != null) {
            bus.close();
        }
        if (robot != null) {
            robot.close();
        }
        if (space != null) {
            space.close();
        }
    }

    @Test
    void theRobotDrivenIntoTheCrateIsDrawnWhereItStoppedWithItsFrontBumpersTouching() throws Exception {
        MonitorWindow window = monitor.window();
        WorldView view = window.worldView();
        eventually("the first frame is shown", Duration.ofSeconds(10), view::showsGroundTruth);

        XVSMRuntime laptop = space.host("laptop");
        MotorModule motor = new XVSMMotorModuleRemote(laptop, ROBOT, "Motor-Controller");
        BumperModule bumper = new XVSMBumperModuleRemote(laptop, ROBOT, "Bumper-Sensor");
        long deadline = System.nanoTime() + Duration.ofSeconds(20).toNanos();
        do { // as a control program does: command the tracks on every round, which also feeds the watchdog
            assertTrue(System.nanoTime() < deadline, "the robot reached the crate, at " + robot.pose());
            // steer along the line through the middle of the crate's face, aiming far beyond it so the robot
            // arrives square to the face: the two tracks start one call apart (longer on a busy machine), which
            // turns the robot, and unsteered it may reach a wall instead
            double error = steeringError(robot.pose(), 4000, 1000);
            // and slow down for the last 200 mm, as a careful program does: the two stop commands below are one
            // call apart too, and a track still running at full speed against the crate turns the robot in place
            double speed = Math.max(0.1, Math.min(1, (STOP_X - robot.pose().x()) / 200));
            command(() -> motor.setMotor(1, Math.max(-1, Math.min(1, speed * (1.0 - error / 20)))));
            command(() -> motor.setMotor(2, Math.max(-1, Math.min(1, speed * (1.0 + error / 20)))));
            Thread.sleep(20);
        } while (bumper.getAllBumper() == 0); // 1250 mm at up to 300 mm/s, four times as fast: a second or two
        command(() -> motor.setMotor(1, 0));
        command(() -> motor.setMotor(2, 0));
        assertEquals(STOP_X, robot.pose().x(), 5, "stopped against the crate's face at " + robot.pose());
        assertEquals(1000, robot.pose().y(), 200 - 20, "in front of the crate, at " + robot.pose());

        eventually("the view has the frame at the crate", Duration.ofSeconds(10), () -> {
            GroundTruth frame = view.frameOf(ROBOT);
            return Math.abs(frame.body().x() - robot.pose().x()) <= 1 && frame.anyContact();
        });
        Thread.sleep(900); // let the contact flash fade: the ring itself is what is checked
        onEdt(() -> view.repaint());
        BufferedImage image = ImageIO.read(screenshot(view, "docs-monitor-world-view-bump").toFile());
        GroundTruth frame = onEdt(() -> view.frameOf(ROBOT));

        Point2D centre = onEdt(() -> view.toScreen(frame.body().x(), frame.body().y()));
        assertColour(WorldView.BODY, image, centre, "the robot's centre, where it stopped");
        Point2D start = onEdt(() -> view.toScreen(600, 1000));
        assertNotEquals(WorldView.BODY.getRGB(), pixel(image, start).getRGB(), "no robot left at the start");
        Point2D crate = onEdt(() -> view.toScreen(2200, 1000));
        assertColour(WorldView.OBSTACLE, image, crate, "the crate");

        // every mounted bumper on the ring around the body: red where the frame says it touches, grey where not
        double pixelsPerMm = onEdt(() -> view.toScreen(1, 0).getX() - view.toScreen(0, 0).getX());
        double ring = 150 * pixelsPerMm + Math.max(3, 150 * pixelsPerMm * 0.12);
        assertEquals(List.of(4, 6), frame.bumpers().stream().filter(GroundTruth.Bumper::contact)
                .map(GroundTruth.Bumper::number).toList(), "head-on, both front bumpers touch the crate (the user"
                + " guide says so): " + frame.bumpers());
        for (GroundTruth.Bumper b : frame.bumpers()) {
            assertColour(b.contact() ? WorldView.CONTACT : WorldView.FREE, image,
                    onRing(centre, ring, frame.body().heading() + b.angle()), "bumper " + b.number());
        }

        // the bumper panel of that moment, for the user guide: the front bumpers in contact, the others free
        assertEquals(1 << 3 | 1 << 5, bumper.getAllBumper());
        BumperModulePanel bumperPanel = monitor.monitors().stream().map(Monitor::getPanel)
                .filter(BumperModulePanel.class::isInstance).map(BumperModulePanel.class::cast).findFirst()
                .orElseThrow();
        eventually("the bumper panel shows 4 and 6 in contact", () -> bumperPanel.colourOf(4)
                .equals(BumperModulePanel.CONTACT) && bumperPanel.colourOf(6).equals(BumperModulePanel.CONTACT)
                && bumperPanel.colourOf(1).equals(BumperModulePanel.FREE));
        onEdt(() -> showTabOf(bumperPanel, window));
        screenshot(bumperPanel, "docs-panel-BumperModule");

        // the plots gained the motor commands and the bumper readings
        ModuleRef motorModule = new ModuleRef(ROBOT, "Motor-Controller", "MotorModule");
        eventually("the motor plot has the four commands", () -> {
            window.plots().reveal(motorModule);
            window.plots().refresh();
            return window.plots().pointsShown(motorModule) >= 4;
        });
        int before = onEdt(() -> window.plots().pointsShown(motorModule));
        command(() -> motor.setMotor(1, -0.5));
        command(() -> motor.setMotor(1, 0));
        eventually("it gains the next ones", () -> {
            window.plots().reveal(motorModule);
            window.plots().refresh();
            return window.plots().pointsShown(motorModule) >= before + 2;
        });
        eventually("latencies of the remote calls", () -> {
            window.plots().revealLatency();
            window.plots().refresh();
            return window.plots().latencyPointsShown() > 0;
        });
        screenshot(window, "monitor-window-simulated-robot");
    }

    @Test
    void theIrPanelAgreesWithTheRaysAndARunningRobotLooksLikeThis() throws Exception {
        MonitorWindow window = monitor.window();
        WorldView view = window.worldView();
        eventually("the first frame is shown", Duration.ofSeconds(10), view::showsGroundTruth);
        XVSMRuntime laptop = space.host("laptop");
        MotorModule motor = new XVSMMotorModuleRemote(laptop, ROBOT, "Motor-Controller");
        IRDistanceModule ir = new XVSMIRDistanceModuleRemote(laptop, ROBOT, "IR-Sensors");
        ServoModule head = new XVSMServoModuleRemote(laptop, ROBOT, "Head-Servo");
        new XVSMX10ApplianceModuleRemote(laptop, "DimRoom", "Lamp").on();
        new XVSMX10LampModuleRemote(laptop, "DimRoom", "Ceiling").on();
        BumperModule bumper = new XVSMBumperModuleRemote(laptop, ROBOT, "Bumper-Sensor");
        // a small IR-avoidance program: forward, turn left when something is close ahead or a bumper touches
        long until = System.nanoTime() + Duration.ofSeconds(5).toNanos();
        int step = 0;
        while (System.nanoTime() < until) {
            String[] distances = ir.getAllSensors().split(" ");
            boolean close = Integer.parseInt(distances[0]) < 250 || Integer.parseInt(distances[2]) < 200
                    || bumper.getAllBumper() != 0;
            command(() -> motor.setMotor(1, close ? -0.3 : 0.5));
            command(() -> motor.setMotor(2, close ? 0.6 : 0.5));
            head.setServo(1, 90 + (step++ % 20 - 10) * 4);
            Thread.sleep(40);
        }
        IRDistanceModulePanel panel = monitor.monitors().stream().map(Monitor::getPanel)
                .filter(IRDistanceModulePanel.class::isInstance).map(IRDistanceModulePanel.class::cast).findFirst()
                .orElseThrow();
        // A photograph of the robot on its way. The IR panel shows the last reading the program took, the world
        // view where the robot is now: a robot that drives on after that reading (as it does while a window is
        // painted) has both disagree by what it travelled meanwhile. So the simulated clock stops: the world stands
        // still while the program reads its sensors once more and the window is painted, and both show one
        // instant. The motors keep their speeds, so the track arrows show.
        robot.simulation().close();
        double frozen = robot.simulation().simulatedSeconds();
        Instant asked = Instant.now();
        String frozenReading = ir.getAllSensors();
        bumper.getAllBumper();
        eventually("the IR panel shows the reading, the world view a frame, of the frozen instant", () -> {
            Instant reported = panel.freshness().lastReport();
            return reported != null && !reported.isBefore(asked) && shownReading(panel).equals(frozenReading)
                    && Math.abs(view.frameOf(ROBOT).simulatedSeconds() - frozen) < 1e-5;
        });
        onEdt(() -> {
            window.plots().refresh();
            window.statusStrip().refresh();
            window.tabs().setSelectedIndex(1);
            window.validate();
            return null;
        });
        screenshot(view, "docs-monitor-world-view");
        BufferedImage photograph = ImageIO.read(screenshot(window, "docs-monitor-window").toFile());
        assertIrPanelAgreesWithTheRays(photograph, window, panel);
        for (Monitor each : monitor.monitors()) { // the panels of that instant too: motors and sensors in use
            if (each.getPanel() instanceof robotworld.explorer.monitor.gui.ModulePanel modulePanel
                    && !(modulePanel instanceof BumperModulePanel)) { // the bumpers' picture is taken at the crate
                onEdt(() -> showTabOf(modulePanel, window)); // a panel in a hidden tab paints black
                screenshot(modulePanel, "docs-panel-" + modulePanel.moduleClass());
            }
        }
        robot.simulation().start();

        command(() -> motor.setMotor(1, 0));
        command(() -> motor.setMotor(2, 0));
        Thread.sleep(300); // the robot comes to rest (ramps)
        String reading = ir.getAllSensors();
        GroundTruth frame = robotworld.observe.GroundTruthTuples.decode(space.connection().read(
                space.connection().lookupContainer("CaterpillarRobotGROUNDTRUTH"), robotworld.space.Timeout.TRY_ONCE)
                .get(0));
        eventually("the IR panel shows the last reading", () -> panel.valueText(1).equals(
                reading.split(" ")[0] + " mm"));
        for (GroundTruth.Ray ray : frame.rays()) {
            int shown = Integer.parseInt(onEdt(() -> panel.valueText(ray.sensor())).replace(" mm", ""));
            assertEquals(ray.length(), shown, 3.0, "sensor " + ray.sensor() + ": the panel and the world view agree");
        }
        eventually("the plots have the IR distances", () -> {
            window.plots().reveal(new ModuleRef(ROBOT, "IR-Sensors", "IRDistanceModule"));
            window.plots().refresh();
            return window.plots().pointsShown(new ModuleRef(ROBOT, "IR-Sensors", "IRDistanceModule")) >= 7 * 10;
        });
        Thread.sleep(600);
        onEdt(() -> {
            window.plots().reveal(new ModuleRef(ROBOT, "Motor-Controller", "MotorModule")); // the first charts
            window.plots().refresh();
            window.statusStrip().refresh();
            window.tabs().setSelectedIndex(1);
            window.validate();
            return null;
        });
        screenshot(window, "monitor-window-at-rest");
        // at the default size, what a researcher looks at is in view without scrolling or dragging a divider
        onEdt(() -> {
            javax.swing.JTable table = window.statusStrip().table();
            assertEquals(6, table.getRowCount());
            assertTrue(table.getVisibleRect().height >= table.getRowCount() * table.getRowHeight(),
                    "every row of the status strip: " + table.getVisibleRect());
            assertEquals(panel.getHeight(), panel.getVisibleRect().height, "the whole IR panel, all 7 sensors");
            assertTrue(window.plots().chartsInView() >= 4, window.plots().chartsInView() + " charts in view");
            assertTrue(view.getHeight() >= 300, "the world view is " + view.getHeight() + " px high");
            return null;
        });
        screenshot(view, "world-view-at-rest");
    }

    /**
     * A motor command, given again if the motor module's watchdog stopped it meanwhile (a loaded machine can delay
     * the program's frames past the watchdog's 500 ms; the first command after such a stop is refused by design).
     */
    private static void command(Runnable call) {
        try {
            call.run();
        } catch (robotworld.xvsm.ActuatorStoppedException stopped) {
            call.run();
        }
    }

    /** The seven distances the IR panel shows, as {@code getAllSensors} gives them. */
    private static String shownReading(IRDistanceModulePanel panel) {
        List<String> distances = new java.util.ArrayList<>();
        for (int sensor = 1; sensor <= IRDistanceModule.SENSORS; sensor++) {
            distances.add(panel.valueText(sensor).replace(" mm", ""));
        }
        return String.join(" ", distances);
    }

    /**
     * Sensor by sensor, in one picture of the window: the IR panel's distance is the one the world view's ray
     * measures, its bar has the ray's colour, and a ray that meets something ends, in the world view, where the
     * panel's distance says.
     */
    private static void assertIrPanelAgreesWithTheRays(BufferedImage photograph, MonitorWindow window,
            IRDistanceModulePanel panel) {
        onEdt(() -> {
            WorldView view = window.worldView();
            GroundTruth frame = view.frameOf(ROBOT);
            Point2D centre = view.toScreen(frame.body().x(), frame.body().y());
            double scale = view.toScreen(1, 0).getX() - view.toScreen(0, 0).getX();
            double radius = frame.body().radius() * scale;
            double ring = radius + Math.max(3, radius * 0.12) + 4;
            assertEquals(IRDistanceModule.SENSORS, frame.rays().size());
            for (GroundTruth.Ray ray : frame.rays()) {
                int sensor = ray.sensor();
                String what = "sensor " + sensor + " (ray " + ray + ")";
                assertEquals(Math.round(ray.length()) + " mm", panel.valueText(sensor), what + ": the same distance");
                double distance = panel.bar(sensor).value();
                assertEquals(ray.length(), distance, 0.5, what + ": the bar's length");
                Color colour = WorldView.rayColour(ray.length(), ray.range());
                ValueBarPixels bar = new ValueBarPixels(panel.bar(sensor), window);
                if (bar.filledWidth(distance) >= 4) {
                    assertTrue(colourNear(photograph, bar.middleOfFill(distance), colour), what + ": the bar is "
                            + colour + " as the ray");
                }
                double direction = Math.toRadians(frame.body().heading() + ray.angle());
                double reach = radius + distance * scale;
                if (ray.hits() && reach > ring + 6) {
                    Point2D end = SwingUtilities.convertPoint(view, new java.awt.Point(
                            (int) Math.round(centre.getX() + reach * Math.cos(direction)),
                            (int) Math.round(centre.getY() - reach * Math.sin(direction))), window.getRootPane());
                    assertTrue(colourNear(photograph, end, colour), what + ": the ray ends, in "
                            + colour + ", " + distance + " mm from the body, at " + end);
                }
            }
            return null;
        });
    }

    /** Where a panel's bar is in a picture of the window, and what it looks like there. */
    private record ValueBarPixels(robotworld.explorer.monitor.gui.ValueBar bar, MonitorWindow window) {

        /** Pixels of the bar filled for {@code distance} of the panel's 800 mm. */
        double filledWidth(double distance) {
            return Math.min(distance, WorldView.ASSUMED_RANGE) / WorldView.ASSUMED_RANGE * (bar.getWidth() - 1);
        }

        Point2D middleOfFill(double distance) {
            return SwingUtilities.convertPoint(bar, new java.awt.Point((int) Math.round(filledWidth(distance) / 2),
                    bar.getHeight() / 2), window.getRootPane());
        }
    }

    /** Whether a pixel of {@code colour} is at {@code point} or next to it (antialiased edges blend). */
    private static boolean colourNear(BufferedImage image, Point2D point, Color colour) {
        for (int dx = -1; dx <= 1; dx++) {
            for (int dy = -1; dy <= 1; dy++) {
                int x = (int) Math.round(point.getX()) + dx;
                int y = (int) Math.round(point.getY()) + dy;
                if (x >= 0 && y >= 0 && x < image.getWidth() && y < image.getHeight()
                        && image.getRGB(x, y) == colour.getRGB()) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Degrees to turn left to head for {@code (x, y)} from {@code pose}, in (-180, 180]. */
    private static double steeringError(robotworld.sim.robot.Pose pose, double x, double y) {
        double bearing = Math.toDegrees(Math.atan2(y - pose.y(), x - pose.x()));
        double error = (bearing - pose.heading()) % 360;
        return error > 180 ? error - 360 : error <= -180 ? error + 360 : error;
    }

    /** Selects, in every tabbed pane above {@code component}, the tab it is on, and lays the window out again. */
    private static Void showTabOf(java.awt.Component component, java.awt.Window window) {
        for (java.awt.Component child = component; child.getParent() != null; child = child.getParent()) {
            if (child.getParent() instanceof javax.swing.JTabbedPane tabs) {
                tabs.setSelectedComponent(child);
            }
        }
        window.validate();
        return null;
    }

    private static Point2D onRing(Point2D centre, double radius, double degrees) {
        double angle = Math.toRadians(degrees);
        return new Point2D.Double(centre.getX() + radius * Math.cos(angle), centre.getY() - radius * Math.sin(angle));
    }

    private static Color pixel(BufferedImage image, Point2D point) {
        return new Color(image.getRGB((int) Math.round(point.getX()), (int) Math.round(point.getY())));
    }

    private static void assertColour(Color expected, BufferedImage image, Point2D point, String what) {
        Color actual = pixel(image, point);
        assertEquals(expected.getRGB(), actual.getRGB(), what + " at " + point + ": expected " + expected + ", was "
                + actual);
    }

}
