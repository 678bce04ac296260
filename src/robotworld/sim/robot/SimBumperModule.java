package robotworld.sim.robot;

import java.util.Map;
import java.util.TreeMap;

/**
 * A simulated bumper module: discrete input {@code n-1} = contact of bumper {@code n}. Each mounted bumper covers
 * an arc of the robot's outline; it closes while a wall or obstacle touches the body within that arc.
 */
public final class SimBumperModule extends SimModule {

    public static final int BUMPERS = 8;

    /** Where a bumper sits: centre angle relative to the heading (degrees, left positive) and arc width. */
    public record Mount(double angle, double span) {
        public Mount {
            if (!(span > 0 && span <= 360)) {
                throw new IllegalArgumentException("bumper span must be in (0, 360], was " + span);
            }
        }
    }

    private final World world;
    private final Map<Integer, Mount> mounts;

    /** @param mounts bumper number (1..8) to its mount; unmounted bumpers never close */
    public SimBumperModule(int address, ModuleIdentity identity, ModuleFaults faults, World world,
            Map<Integer, Mount> mounts) {
        super(address, identity, faults);
        for (int number : mounts.keySet()) {
            if (number < 1 || number > BUMPERS) {
                throw new IllegalArgumentException("bumper number " + number + " is outside 1..8");
            }
        }
        this.world = world;
        this.mounts = new TreeMap<>(mounts);
    }

    @Override
    public String moduleClass() {
        return "BumperModule";
    }

    /** Bumper number to its mount, for the ground truth. */
    Map<Integer, Mount> mounts() {
        return mounts;
    }

    @Override
    int discreteInputCount() {
        return BUMPERS;
    }

    @Override
    boolean discreteInput(int index) {
        Mount mount = mounts.get(index + 1);
        return mount != null && world.contact(mount.angle() - mount.span() / 2, mount.angle() + mount.span() / 2);
    }
}
