package robotworld.explorer.monitor;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.explorer.monitor.gui.WorldView;
import robotworld.observe.AnswerSeen;
import robotworld.observe.ModuleRef;
import robotworld.observe.WorldLayout;
import robotworld.xvsm.CallTuple;

/**
 * Real hardware, no simulator: the world view draws the robot in its own frame (heading up) from what its modules
 * last reported. Checked on the pixels: each IR ray points where its sensor is mounted and has the colour of its
 * distance, a touching bumper's arc is red and a free one grey.
 */
class RobotFrameViewTest {

    private static final String ROBOT = "Rover";
    private static final ModuleRef IR = new ModuleRef(ROBOT, "IR", "IRDistanceModule");
    private static final ModuleRef BUMPER = new ModuleRef(ROBOT, "Bumper", "BumperModule");
    private static final ModuleRef MOTOR = new ModuleRef(ROBOT, "Motor", "MotorModule");
    private static final int WIDTH = 640;
    private static final int HEIGHT = 480;

    @Test
    void raysAndBumpersAreDrawnFromTheModulesLastReadingsInTheRobotsOwnFrame() {
        RobotReadings readings = new RobotReadings(new WorldLayout("HardwareWorld",
                List.of(new WorldLayout.Participant(ROBOT, "robot", List.of(IR, BUMPER, MOTOR)))));
        // sensor 1 ahead 200 mm (near), 4 on the left 500 mm (middle), 5 on the right 700 mm (far), others nothing
        report(readings, IR, CallTuple.of("laptop#a.1", "getAllSensors", "200 800 800 500 700 800 800"));
        report(readings, BUMPER, CallTuple.of("laptop#a.2", "getAllBumper", 1 << 4)); // bumper 5: the front
        report(readings, MOTOR, CallTuple.of("laptop#a.3", "setMotor", 1, 500));

        BufferedImage image = paint(new WorldView(readings));

        // the geometry the view uses for the robot's own frame: fit the longest reading (800 mm) and the body
        double available = Math.min(WIDTH - 2 * 28, HEIGHT - 2 * 28 - 40) / 2.0;
        double scale = available / (WorldView.ASSUMED_RANGE + 150);
        double cx = WIDTH / 2.0;
        double cy = 40 + (HEIGHT - 40) / 2.0;
        double radius = 150 * scale;
        double ring = radius + Math.max(3, radius * 0.12);

        assertColourNear(image, cx, cy - radius - 150 * scale, WorldView.NEAR, "ray 1, straight ahead (up), 200 mm");
        assertColourNear(image, cx - radius - 300 * scale, cy, WorldView.MIDDLE, "ray 4, to the left, 500 mm");
        assertColourNear(image, cx + radius + 450 * scale, cy, WorldView.FAR, "ray 5, to the right, 700 mm");
        assertColourNear(image, cx, cy - ring, WorldView.CONTACT, "bumper 5, at the front, touching");
        assertColourNear(image, cx, cy + ring, WorldView.FREE, "bumper 1, at the back, free");
        assertColourNear(image, cx, cy, WorldView.BODY, "the body at the centre");
        assertTrue(!colourNear(image, cx, cy - radius - 150 * scale, WorldView.MIDDLE),
                "ray 1 is not drawn in another colour");
    }

    @Test
    void withoutReadingsItSaysWhatItWaitsFor() {
        RobotReadings readings = new RobotReadings(new WorldLayout("HardwareWorld",
                List.of(new WorldLayout.Participant(ROBOT, "robot", List.of(IR)))));
        BufferedImage image = paint(new WorldView(readings));
        assertTrue(!colourNear(image, WIDTH / 2.0, 40 + (HEIGHT - 40) / 2.0, WorldView.BODY),
                "no robot is drawn before anything was reported");
    }

    private static void report(RobotReadings readings, ModuleRef module, CallTuple answer) {
        readings.answerSeen(new AnswerSeen(module, answer, Instant.now(), false, Duration.ofMillis(2), 0));
    }

    /** Paints the view off screen, as Swing would at this size. */
    private static BufferedImage paint(WorldView view) {
        view.setFont(new Font(Font.DIALOG, Font.PLAIN, 12));
        view.setSize(WIDTH, HEIGHT);
        BufferedImage image = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            view.paint(g);
        } finally {
            g.dispose();
        }
        return image;
    }

    private static void assertColourNear(BufferedImage image, double x, double y, Color colour, String what) {
        assertTrue(colourNear(image, x, y, colour), what + ": no pixel of " + colour + " within 2 px of ("
                + Math.round(x) + ", " + Math.round(y) + "), found " + new Color(image.getRGB((int) Math.round(x),
                (int) Math.round(y))));
    }

    /** Antialiased edges blend: the exact colour somewhere within 2 px. */
    private static boolean colourNear(BufferedImage image, double x, double y, Color colour) {
        for (int dx = -2; dx <= 2; dx++) {
            for (int dy = -2; dy <= 2; dy++) {
                int px = (int) Math.round(x) + dx;
                int py = (int) Math.round(y) + dy;
                if (px >= 0 && py >= 0 && px < image.getWidth() && py < image.getHeight()
                        && image.getRGB(px, py) == colour.getRGB()) {
                    return true;
                }
            }
        }
        return false;
    }
}
