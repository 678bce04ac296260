package robotworld.explorer.monitor.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.Stroke;
import java.awt.geom.Arc2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.swing.JComponent;
import javax.swing.Timer;
import robotworld.explorer.monitor.RobotReadings;
import robotworld.observe.GroundTruth;

/**
 * The world seen from above: each simulated robot in its arena as its simulator publishes it (obstacles, the body
 * with its heading and its name on a plate placed where it hides the least, a trail of the last
 * {@value #TRAIL_SECONDS} s, IR rays coloured by the distance they measure and numbered by sensor, the bumper ring with touching bumpers in red and a flash when contact begins, track speeds as arrows), scaled to
 * fit. Without ground truth (real hardware), it draws the first robot in its own frame, heading up, from what its
 * modules report: rays from the IR distances at the assumed sensor angles, the bumper ring from the bumper
 * answers, arrows from motors 1 and 2.
 *
 * <p>Frames and readings arrive on any thread ({@link #show(GroundTruth)}); painting happens on the Swing thread,
 * at most {@value #FRAMES_PER_SECOND} times a second and only when something changed.
 */
public final class WorldView extends JComponent {

    /** The body's fill: a pixel at the robot's centre has this colour. */
    public static final Color BODY = new Color(0x2F, 0x6F, 0xD6);
    /** A bumper touching something. */
    public static final Color CONTACT = new Color(0xE8, 0x1D, 0x1D);
    /** A bumper that touches nothing. */
    public static final Color FREE = new Color(0x8C, 0x96, 0xA3);
    /** Obstacles and walls. */
    public static final Color OBSTACLE = new Color(0x70, 0x76, 0x80);
    /** A ray measuring something close (under a third of its range). */
    public static final Color NEAR = new Color(0xE0, 0x3A, 0x3E);
    /** A ray measuring something in the middle third. */
    public static final Color MIDDLE = new Color(0xF0, 0x9A, 0x1A);
    /** A ray measuring something far (the last third). */
    public static final Color FAR = new Color(0x2E, 0xA8, 0x5A);
    /** A ray that meets nothing within its range. */
    public static final Color NO_HIT = new Color(0xB4, 0xBA, 0xC4);

    /** Mounting angles assumed for IR sensors 1..7 without a simulator (as in the example robot). */
    public static final double[] ASSUMED_SENSOR_ANGLES = {0, 30, -30, 90, -90, 150, -150};
    /** Mounting angles assumed for bumpers 1..8 without a simulator: 4 and 6 front left and right, 1 at the back. */
    public static final double[] ASSUMED_BUMPER_ANGLES = {180, 135, 90, 30, 0, -30, -135, -90};
    /** The range assumed for IR sensors without a simulator, in mm. */
    public static final double ASSUMED_RANGE = 800;

    static final int TRAIL_SECONDS = 10;
    static final int FRAMES_PER_SECOND = 25;
    private static final long FLASH_NANOS = 700_000_000L;
    private static final int MARGIN = 28;
    /** Above the arena: the caption. */
    private static final int CAPTION = 18;
    /** Below it: the legend, which no ray's number may cover. */
    private static final int LEGEND = 16;
    private static final double NUMBER_RADIUS = 7;
    private static final Color BACKGROUND = new Color(0xEE, 0xF0, 0xF3);
    private static final Color FLOOR = Color.WHITE;
    private static final Color GRID = new Color(0xE4, 0xE7, 0xEB);
    private static final Color TEXT = new Color(0x2B, 0x2F, 0x36);
    private static final Color TRAIL = new Color(0x2F, 0x6F, 0xD6, 0x70);

    private final Map<String, RobotState> robots = new LinkedHashMap<>();
    private final RobotReadings readings;
    private final Timer repaint;
    private volatile boolean changed = true;
    private long paints;

    /** A view fed by {@link #show(GroundTruth)}, falling back to {@code readings} (may be null) without frames. */
    public WorldView(RobotReadings readings) {
        this.readings = readings;
        setOpaque(true);
        setName("world view");
        setPreferredSize(new Dimension(640, 440));
        setMinimumSize(new Dimension(200, 150));
        repaint = new Timer(1000 / FRAMES_PER_SECOND, event -> {
            if (changed || flashing()) {
                changed = false;
                repaint();
            }
        });
    }

    /** A robot's newest frame and its recent past. */
    private static final class RobotState {
        GroundTruth frame;
        final Deque<double[]> trail = new ArrayDeque<>();
        final Map<Integer, Long> contactSince = new LinkedHashMap<>();
    }

    /** Shows a new frame (any thread). */
    public void show(GroundTruth frame) {
        long now = System.nanoTime();
        synchronized (robots) {
            RobotState state = robots.computeIfAbsent(frame.robot(), name -> new RobotState());
            state.frame = frame;
            state.trail.addLast(new double[] {now, frame.body().x(), frame.body().y()});
            while (state.trail.size() > TRAIL_SECONDS * 100
                    || now - (long) state.trail.peekFirst()[0] > TRAIL_SECONDS * 1_000_000_000L) {
                state.trail.removeFirst();
            }
            for (GroundTruth.Bumper bumper : frame.bumpers()) {
                int key = bumper.address() * 16 + bumper.number();
                if (!bumper.contact()) {
                    state.contactSince.remove(key);
                } else {
                    state.contactSince.putIfAbsent(key, now);
                }
            }
        }
        changed = true;
    }

    /** Readings changed (any thread): repaint if they are what is shown. */
    public void readingsChanged() {
        changed = true;
    }

    /** Whether ground truth is shown (else the robot's frame from its readings, if any). */
    public boolean showsGroundTruth() {
        synchronized (robots) {
            return !robots.isEmpty();
        }
    }

    /** The newest frame of {@code robot}, or null. */
    public GroundTruth frameOf(String robot) {
        synchronized (robots) {
            RobotState state = robots.get(robot);
            return state == null ? null : state.frame;
        }
    }

    /** How often the view has painted (for the rendering-cost benchmark). */
    public long paints() {
        return paints;
    }

    @Override
    public void addNotify() {
        super.addNotify();
        repaint.start();
    }

    @Override
    public void removeNotify() {
        repaint.stop();
        super.removeNotify();
    }

    private boolean flashing() {
        long now = System.nanoTime();
        synchronized (robots) {
            for (RobotState state : robots.values()) {
                for (long since : state.contactSince.values()) {
                    if (now - since < FLASH_NANOS) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    // ---- the arena's mapping to the screen ----

    /** Where world point {@code (x, y)} (mm) is drawn, for the current size and arenas; null without frames. */
    public Point2D toScreen(double x, double y) {
        Mapping mapping;
        synchronized (robots) {
            mapping = mapping(frames());
        }
        return mapping == null ? null : mapping.point(x, y);
    }

    private List<GroundTruth> frames() {
        List<GroundTruth> frames = new ArrayList<>();
        for (RobotState state : robots.values()) {
            frames.add(state.frame);
        }
        return frames;
    }

    /** Scale and offset that fit every arena into the component, y up. */
    private record Mapping(double scale, double left, double bottom) {
        Point2D point(double x, double y) {
            return new Point2D.Double(left + x * scale, bottom - y * scale);
        }

        double length(double millimetres) {
            return millimetres * scale;
        }
    }

    private Mapping mapping(List<GroundTruth> frames) {
        if (frames.isEmpty()) {
            return null;
        }
        double width = 0;
        double height = 0;
        for (GroundTruth frame : frames) {
            width = Math.max(width, frame.arena().width());
            height = Math.max(height, frame.arena().height());
        }
        double available = Math.max(1, getWidth() - 2 * MARGIN);
        double availableHeight = Math.max(1, getHeight() - 2 * MARGIN - CAPTION - LEGEND);
        double scale = Math.min(available / width, availableHeight / height);
        double left = (getWidth() - width * scale) / 2;
        double bottom = MARGIN + CAPTION + (availableHeight + height * scale) / 2;
        return new Mapping(scale, left, bottom);
    }

    // ---- painting ----

    @Override
    protected void paintComponent(Graphics graphics) {
        paints++;
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(BACKGROUND);
            g.fillRect(0, 0, getWidth(), getHeight());
            List<GroundTruth> frames;
            List<RobotState> states;
            synchronized (robots) {
                frames = frames();
                states = new ArrayList<>();
                for (RobotState state : robots.values()) {
                    RobotState copy = new RobotState();
                    copy.frame = state.frame;
                    copy.trail.addAll(state.trail);
                    copy.contactSince.putAll(state.contactSince);
                    states.add(copy);
                }
            }
            if (!frames.isEmpty()) {
                paintWorld(g, frames, states);
            } else {
                paintRobotFrame(g);
            }
        } finally {
            g.dispose();
        }
    }

    private void paintWorld(Graphics2D g, List<GroundTruth> frames, List<RobotState> states) {
        Mapping m = mapping(frames);
        GroundTruth first = frames.get(0);
        double width = 0;
        double height = 0;
        for (GroundTruth frame : frames) {
            width = Math.max(width, frame.arena().width());
            height = Math.max(height, frame.arena().height());
        }
        Point2D origin = m.point(0, 0);
        Rectangle2D floor = new Rectangle2D.Double(origin.getX(), origin.getY() - m.length(height), m.length(width),
                m.length(height));
        g.setColor(FLOOR);
        g.fill(floor);
        paintGrid(g, m, width, height);
        for (GroundTruth frame : frames) {
            g.setColor(OBSTACLE);
            for (GroundTruth.Obstacle o : frame.arena().obstacles()) {
                Point2D topLeft = m.point(o.x(), o.y() + o.height());
                g.fill(new Rectangle2D.Double(topLeft.getX(), topLeft.getY(), m.length(o.width()),
                        m.length(o.height())));
            }
        }
        g.setColor(TEXT);
        g.setStroke(new BasicStroke(2f));
        g.draw(floor);
        long now = System.nanoTime();
        List<Shape> clutter = new ArrayList<>(); // what a robot's name must not hide: obstacles, rays, numbers
        for (GroundTruth frame : frames) {
            for (GroundTruth.Obstacle o : frame.arena().obstacles()) {
                Point2D topLeft = m.point(o.x(), o.y() + o.height());
                clutter.add(new Rectangle2D.Double(topLeft.getX(), topLeft.getY(), m.length(o.width()),
                        m.length(o.height())));
            }
        }
        List<Object[]> names = new ArrayList<>();
        for (RobotState state : states) {
            paintTrail(g, m, state.trail);
            GroundTruth frame = state.frame;
            GroundTruth.Body body = frame.body();
            Point2D centre = m.point(body.x(), body.y());
            double radius = m.length(body.radius());
            List<double[]> rays = new ArrayList<>();
            for (GroundTruth.Ray ray : frame.rays()) {
                rays.add(new double[] {ray.angle(), ray.length(), ray.range(), ray.sensor()});
            }
            paintRays(g, centre, radius, body.heading(), m.scale(), rays, clutter);
            paintBody(g, centre, radius, body.heading());
            List<Object[]> bumpers = new ArrayList<>();
            for (GroundTruth.Bumper bumper : frame.bumpers()) {
                Long since = state.contactSince.get(bumper.address() * 16 + bumper.number());
                boolean flash = since != null && now - since < FLASH_NANOS;
                bumpers.add(new Object[] {bumper.angle(), bumper.span(), bumper.contact(), flash});
            }
            paintBumpers(g, centre, radius, body.heading(), bumpers);
            double left = Double.NaN;
            double right = Double.NaN;
            for (GroundTruth.Motor motor : frame.motors()) {
                if (motor.wheel().equals("left")) {
                    left = motor.actual();
                } else if (motor.wheel().equals("right")) {
                    right = motor.actual();
                }
            }
            paintTracks(g, centre, radius, body.heading(), left, right);
            names.add(new Object[] {frame.robot(), centre, ringOuter(radius)});
        }
        for (Object[] name : names) { // last: over everything else, where it hides the least
            clutter.add(paintName(g, (String) name[0], (Point2D) name[1], (Double) name[2], clutter));
        }
        paintCaption(g, first, frames.size());
        paintLegend(g, m);
    }

    private void paintGrid(Graphics2D g, Mapping m, double width, double height) {
        double step = 500;
        while (m.length(step) < 40) {
            step *= 2;
        }
        g.setColor(GRID);
        g.setStroke(new BasicStroke(1f));
        for (double x = step; x < width; x += step) {
            g.draw(new Line2D.Double(m.point(x, 0), m.point(x, height)));
        }
        for (double y = step; y < height; y += step) {
            g.draw(new Line2D.Double(m.point(0, y), m.point(width, y)));
        }
    }

    private static void paintTrail(Graphics2D g, Mapping m, Deque<double[]> trail) {
        if (trail.size() < 2) {
            return;
        }
        Path2D path = new Path2D.Double();
        boolean firstPoint = true;
        for (double[] point : trail) {
            Point2D p = m.point(point[1], point[2]);
            if (firstPoint) {
                path.moveTo(p.getX(), p.getY());
                firstPoint = false;
            } else {
                path.lineTo(p.getX(), p.getY());
            }
        }
        g.setColor(TRAIL);
        g.setStroke(new BasicStroke(2.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(path);
    }

    /** The colour of a ray measuring {@code length} of {@code range}. */
    public static Color rayColour(double length, double range) {
        if (!(length < range)) {
            return NO_HIT;
        }
        double fraction = length / range;
        return fraction < 1 / 3.0 ? NEAR : fraction < 2 / 3.0 ? MIDDLE : FAR;
    }

    /**
     * Rays {angle, length, range, sensor} from the body outline, each with its sensor's number in a small disc
     * beyond its end (outside the bumper ring); screen angles turn the other way (y down). Adds the rays and the
     * discs to {@code clutter}.
     */
    private void paintRays(Graphics2D g, Point2D centre, double radius, double heading, double scale,
            List<double[]> rays, List<Shape> clutter) {
        Stroke dashed = new BasicStroke(1.2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {4f, 4f},
                0f);
        Stroke solid = new BasicStroke(2.2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND);
        List<Object[]> numbers = new ArrayList<>();
        for (double[] ray : rays) {
            double direction = Math.toRadians(heading + ray[0]);
            double dx = Math.cos(direction);
            double dy = -Math.sin(direction);
            double startX = centre.getX() + radius * dx;
            double startY = centre.getY() + radius * dy;
            boolean hit = ray[1] < ray[2];
            double length = (hit ? ray[1] : ray[2]) * scale;
            Color colour = rayColour(ray[1], ray[2]);
            g.setColor(colour);
            g.setStroke(hit ? solid : dashed);
            Line2D line = new Line2D.Double(startX, startY, startX + length * dx, startY + length * dy);
            g.draw(line);
            clutter.add(line);
            if (hit) {
                g.fill(new Ellipse2D.Double(startX + length * dx - 3.5, startY + length * dy - 3.5, 7, 7));
            }
            double at = Math.max(radius + length + NUMBER_RADIUS + 4, ringOuter(radius) + NUMBER_RADIUS + 2);
            // inside the view, off the caption and the legend
            double x = Math.max(NUMBER_RADIUS + 1, Math.min(getWidth() - NUMBER_RADIUS - 1, centre.getX() + at * dx));
            double y = Math.max(CAPTION + NUMBER_RADIUS + 4, Math.min(getHeight() - LEGEND - NUMBER_RADIUS - 4,
                    centre.getY() + at * dy));
            numbers.add(new Object[] {x, y, colour, (int) ray[3]});
        }
        g.setFont(getFont().deriveFont(Font.BOLD, 10f));
        FontMetrics metrics = g.getFontMetrics();
        for (Object[] number : numbers) { // after every ray: no ray crosses a number
            Ellipse2D disc = new Ellipse2D.Double((Double) number[0] - NUMBER_RADIUS, (Double) number[1] - NUMBER_RADIUS,
                    2 * NUMBER_RADIUS, 2 * NUMBER_RADIUS);
            g.setColor(Color.WHITE);
            g.fill(disc);
            g.setColor((Color) number[2]);
            g.setStroke(new BasicStroke(1.6f));
            g.draw(disc);
            g.setColor(TEXT);
            String text = String.valueOf(number[3]);
            g.drawString(text, (float) ((Double) number[0] - metrics.stringWidth(text) / 2.0),
                    (float) ((Double) number[1] + (metrics.getAscent() - metrics.getDescent()) / 2.0));
            clutter.add(disc.getBounds2D());
        }
    }

    /** The outer edge of the bumper ring around a body of {@code radius} pixels. */
    private static double ringOuter(double radius) {
        return radius + Math.max(3, radius * 0.12) + 4;
    }

    /**
     * A robot's name on a light plate beside its body, on the side where the plate covers the fewest rays, numbers
     * and obstacles and stays inside the view. Returns the plate.
     */
    private Rectangle2D paintName(Graphics2D g, String name, Point2D centre, double ring, List<Shape> clutter) {
        g.setFont(getFont().deriveFont(Font.BOLD, 11.5f));
        FontMetrics metrics = g.getFontMetrics();
        double width = metrics.stringWidth(name) + 10;
        double height = metrics.getHeight() + 2;
        Rectangle2D best = null;
        double bestCost = Double.MAX_VALUE;
        for (int degrees : new int[] {45, 135, -45, -135, 90, -90, 0, 180}) { // up right first, as a map labels
            double a = Math.toRadians(degrees);
            double cos = Math.cos(a);
            double sin = Math.sin(a);
            double reach = ring + 4 + Math.abs(cos) * width / 2 + Math.abs(sin) * height / 2;
            Rectangle2D plate = new Rectangle2D.Double(centre.getX() + reach * cos - width / 2,
                    centre.getY() - reach * sin - height / 2, width, height);
            double cost = 0;
            if (plate.getMinX() < 0 || plate.getMinY() < CAPTION + 6 || plate.getMaxX() > getWidth()
                    || plate.getMaxY() > getHeight() - LEGEND - 2) {
                cost += 1000; // off the view, or over the caption or the legend
            }
            for (Shape shape : clutter) {
                if (shape instanceof Line2D line ? line.intersects(plate) : shape.intersects(plate)) {
                    cost += shape instanceof Line2D ? 10 : 6;
                }
            }
            if (cost < bestCost) {
                bestCost = cost;
                best = plate;
            }
        }
        java.awt.geom.RoundRectangle2D shape = new java.awt.geom.RoundRectangle2D.Double(best.getX(), best.getY(),
                best.getWidth(), best.getHeight(), 8, 8);
        g.setColor(new Color(0xFF, 0xFF, 0xFF, 0xEB));
        g.fill(shape);
        g.setColor(BODY);
        g.setStroke(new BasicStroke(1.2f));
        g.draw(shape);
        g.setColor(TEXT);
        g.drawString(name, (float) (best.getX() + 5), (float) (best.getY() + 1 + metrics.getAscent()));
        return best;
    }

    /** A robot's body: a disc with a white wedge pointing where it heads (degrees, counter-clockwise from +x). */
    static void paintBody(Graphics2D g, Point2D centre, double radius, double heading) {
        g.setColor(BODY);
        g.fill(new Ellipse2D.Double(centre.getX() - radius, centre.getY() - radius, 2 * radius, 2 * radius));
        // the heading: a white wedge near the front, leaving the centre in the body's colour
        double direction = Math.toRadians(heading);
        double dx = Math.cos(direction);
        double dy = -Math.sin(direction);
        Path2D wedge = new Path2D.Double();
        wedge.moveTo(centre.getX() + dx * radius * 0.9, centre.getY() + dy * radius * 0.9);
        wedge.lineTo(centre.getX() + dx * radius * 0.35 - dy * radius * 0.3,
                centre.getY() + dy * radius * 0.35 + dx * radius * 0.3);
        wedge.lineTo(centre.getX() + dx * radius * 0.35 + dy * radius * 0.3,
                centre.getY() + dy * radius * 0.35 - dx * radius * 0.3);
        wedge.closePath();
        g.setColor(Color.WHITE);
        g.fill(wedge);
    }

    /** Bumpers {angle, span, contact, flash} as arcs just outside the body. */
    private static void paintBumpers(Graphics2D g, Point2D centre, double radius, double heading,
            List<Object[]> bumpers) {
        double ring = radius + Math.max(3, radius * 0.12);
        for (Object[] bumper : bumpers) {
            double angle = (Double) bumper[0];
            double span = (Double) bumper[1];
            Boolean contact = (Boolean) bumper[2];
            boolean flash = (Boolean) bumper[3];
            Arc2D arc = new Arc2D.Double(centre.getX() - ring, centre.getY() - ring, 2 * ring, 2 * ring,
                    heading + angle - span / 2 + 2, Math.max(1, span - 4), Arc2D.OPEN);
            if (flash) {
                double halo = ring + 7;
                g.setColor(new Color(CONTACT.getRed(), CONTACT.getGreen(), CONTACT.getBlue(), 0x50));
                g.setStroke(new BasicStroke(12f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
                g.draw(new Arc2D.Double(centre.getX() - halo, centre.getY() - halo, 2 * halo, 2 * halo,
                        heading + angle - span / 2, span, Arc2D.OPEN));
            }
            g.setColor(contact == null ? NO_HIT : contact ? CONTACT : FREE);
            g.setStroke(new BasicStroke(contact != null && contact ? 7f : 4f, BasicStroke.CAP_BUTT,
                    BasicStroke.JOIN_ROUND));
            g.draw(arc);
        }
    }

    /** Track speeds (-1..1, NaN unknown) as arrows beside the body, along the heading. */
    private static void paintTracks(Graphics2D g, Point2D centre, double radius, double heading, double left,
            double right) {
        double direction = Math.toRadians(heading);
        double dx = Math.cos(direction);
        double dy = -Math.sin(direction);
        // the left side of the heading, in screen coordinates (y down)
        double px = dy;
        double py = -dx;
        double[][] tracks = {{left, 1}, {right, -1}};
        g.setStroke(new BasicStroke(2.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.setColor(TEXT);
        for (double[] track : tracks) {
            double speed = track[0];
            if (Double.isNaN(speed) || Math.abs(speed) < 0.005) {
                continue;
            }
            double side = track[1] * radius * 0.6;
            double baseX = centre.getX() + px * side;
            double baseY = centre.getY() + py * side;
            double length = speed * radius * 1.4;
            double tipX = baseX + dx * length;
            double tipY = baseY + dy * length;
            g.draw(new Line2D.Double(baseX, baseY, tipX, tipY));
            double back = Math.signum(speed) * 6;
            g.draw(new Line2D.Double(tipX, tipY, tipX - dx * back + px * 4, tipY - dy * back + py * 4));
            g.draw(new Line2D.Double(tipX, tipY, tipX - dx * back - px * 4, tipY - dy * back - py * 4));
        }
    }

    private void paintCaption(Graphics2D g, GroundTruth frame, int robotCount) {
        GroundTruth.Body body = frame.body();
        StringBuilder touching = new StringBuilder();
        for (GroundTruth.Bumper bumper : frame.bumpers()) {
            if (bumper.contact()) {
                touching.append(touching.isEmpty() ? "" : ", ").append(bumper.number());
            }
        }
        String caption = String.format(Locale.ROOT, "%s at x %.0f mm, y %.0f mm, heading %.0f°  ·  %s%s",
                frame.robot(), body.x(), body.y(), body.heading(),
                touching.isEmpty() ? "no bumper touching" : "TOUCHING: bumper " + touching,
                robotCount > 1 ? "  ·  " + robotCount + " robots" : "");
        g.setFont(getFont().deriveFont(Font.BOLD, 12.5f));
        g.setColor(touching.isEmpty() ? TEXT : CONTACT);
        g.drawString(caption, MARGIN, 18);
    }

    private void paintLegend(Graphics2D g, Mapping m) {
        g.setFont(getFont().deriveFont(11f));
        FontMetrics metrics = g.getFontMetrics();
        int y = getHeight() - 8;
        int x = MARGIN;
        x = legendItem(g, metrics, x, y, NEAR, "near");
        x = legendItem(g, metrics, x, y, MIDDLE, "middle");
        x = legendItem(g, metrics, x, y, FAR, "far");
        x = legendItem(g, metrics, x, y, NO_HIT, "nothing in range");
        x = legendItem(g, metrics, x, y, CONTACT, "bumper touching");
        // scale bar
        double bar = 100;
        while (m.length(bar) < 60) {
            bar *= bar >= 500 ? 2 : 5;
        }
        int barPixels = (int) Math.round(m.length(bar));
        int right = getWidth() - MARGIN;
        g.setColor(TEXT);
        g.setStroke(new BasicStroke(2f));
        g.drawLine(right - barPixels, y - 4, right, y - 4);
        g.drawLine(right - barPixels, y - 8, right - barPixels, y);
        g.drawLine(right, y - 8, right, y);
        String label = bar >= 1000 ? (bar / 1000) + " m" : (int) bar + " mm";
        g.drawString(label.replace(".0 m", " m"), right - barPixels - metrics.stringWidth(label) - 6, y);
    }

    private static int legendItem(Graphics2D g, FontMetrics metrics, int x, int y, Color colour, String text) {
        g.setColor(colour);
        g.setStroke(new BasicStroke(3f));
        g.drawLine(x, y - 4, x + 16, y - 4);
        g.setColor(TEXT);
        g.drawString(text, x + 20, y);
        return x + 20 + metrics.stringWidth(text) + 14;
    }

    /** Without ground truth: the first robot with readings, in its own frame, heading up. */
    private void paintRobotFrame(Graphics2D g) {
        RobotReadings.Snapshot snapshot = null;
        if (readings != null) {
            for (String robot : readings.robots()) {
                RobotReadings.Snapshot candidate = readings.of(robot);
                if (candidate.hasReadings()) {
                    snapshot = candidate;
                    break;
                }
            }
        }
        g.setFont(getFont().deriveFont(Font.BOLD, 12.5f));
        g.setColor(TEXT);
        if (snapshot == null) {
            g.drawString("Waiting for a simulator's ground truth or for readings of a robot's modules...", MARGIN, 18);
            return;
        }
        g.drawString(snapshot.robot() + " in its own frame (heading up), from its modules' last readings", MARGIN, 18);
        g.setFont(getFont().deriveFont(11f));
        g.drawString("no simulator publishes ground truth; sensor and bumper angles assumed as in the example robot",
                MARGIN, 34);
        double range = ASSUMED_RANGE;
        for (double distance : snapshot.distances()) {
            if (!Double.isNaN(distance)) {
                range = Math.max(range, distance);
            }
        }
        double robotRadius = 150;
        double available = Math.min(getWidth() - 2 * MARGIN, getHeight() - 2 * MARGIN - 40) / 2.0;
        double scale = Math.max(0.01, available / (range + robotRadius));
        Point2D centre = new Point2D.Double(getWidth() / 2.0, 40 + (getHeight() - 40) / 2.0);
        double radius = robotRadius * scale;
        g.setColor(GRID);
        g.setStroke(new BasicStroke(1f));
        for (double ring = 200; ring <= range; ring += 200) {
            double r = radius + ring * scale;
            g.draw(new Ellipse2D.Double(centre.getX() - r, centre.getY() - r, 2 * r, 2 * r));
        }
        List<double[]> rays = new ArrayList<>();
        double[] distances = snapshot.distances();
        for (int i = 0; i < distances.length; i++) {
            if (!Double.isNaN(distances[i])) {
                rays.add(new double[] {ASSUMED_SENSOR_ANGLES[i], distances[i], ASSUMED_RANGE, i + 1});
            }
        }
        paintRays(g, centre, radius, 90, scale, rays, new ArrayList<>());
        paintBody(g, centre, radius, 90);
        List<Object[]> bumpers = new ArrayList<>();
        Boolean[] contacts = snapshot.contacts();
        for (int i = 0; i < contacts.length; i++) {
            bumpers.add(new Object[] {ASSUMED_BUMPER_ANGLES[i], 40.0, contacts[i], false});
        }
        paintBumpers(g, centre, radius, 90, bumpers);
        paintTracks(g, centre, radius, 90, snapshot.speeds()[0], snapshot.speeds()[1]);
    }
}
