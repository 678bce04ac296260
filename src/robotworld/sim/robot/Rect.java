package robotworld.sim.robot;

/**
 * An axis-aligned rectangle in the world plane, in millimetres: an obstacle or a wall.
 *
 * @param x left edge
 * @param y bottom edge
 * @param width extent along x, positive
 * @param height extent along y, positive
 */
public record Rect(double x, double y, double width, double height) {

    public Rect {
        if (!(width > 0 && height > 0)) {
            throw new IllegalArgumentException("a rectangle needs a positive width and height, not " + width + " x "
                    + height);
        }
    }

    /** The point of this rectangle closest to {@code (px, py)} (the point itself when it is inside). */
    public double[] closestPoint(double px, double py) {
        return new double[] {clamp(px, x, x + width), clamp(py, y, y + height)};
    }

    /** Distance from {@code (px, py)} to this rectangle; 0 inside. */
    public double distanceTo(double px, double py) {
        double[] c = closestPoint(px, py);
        return Math.hypot(c[0] - px, c[1] - py);
    }

    /**
     * Where a ray from {@code (ox, oy)} along the unit vector {@code (dx, dy)} first meets this rectangle (slab
     * method).
     *
     * @return the distance along the ray, 0 when the origin is inside, {@link Double#POSITIVE_INFINITY} on a miss
     */
    public double rayDistance(double ox, double oy, double dx, double dy) {
        double near = 0;
        double far = Double.POSITIVE_INFINITY;
        double[][] slabs = {{ox, dx, x, x + width}, {oy, dy, y, y + height}};
        for (double[] slab : slabs) {
            double origin = slab[0];
            double direction = slab[1];
            if (Math.abs(direction) < 1e-12) {
                if (origin < slab[2] || origin > slab[3]) {
                    return Double.POSITIVE_INFINITY;
                }
                continue;
            }
            double t1 = (slab[2] - origin) / direction;
            double t2 = (slab[3] - origin) / direction;
            near = Math.max(near, Math.min(t1, t2));
            far = Math.min(far, Math.max(t1, t2));
            if (near > far) {
                return Double.POSITIVE_INFINITY;
            }
        }
        return near;
    }

    private static double clamp(double value, double min, double max) {
        return Math.max(min, Math.min(max, value));
    }
}
