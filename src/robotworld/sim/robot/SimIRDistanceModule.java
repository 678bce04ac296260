package robotworld.sim.robot;

import java.util.Map;
import java.util.TreeMap;

/**
 * A simulated IR distance module: input register {@code n-1} = distance seen by sensor {@code n} in mm, input
 * register {@code 7+n-1} = its raw 8-bit reading. A sensor casts a ray from the body outline at its mounting
 * angle; beyond its range (and for unmounted sensors) it reads the range. Raw model: {@code 255 * (range - d) /
 * range}, so 255 at contact and 0 at the range: larger means closer, like a triangulation sensor's voltage.
 */
public final class SimIRDistanceModule extends SimModule {

    public static final int SENSORS = 7;

    private final World world;
    private final Map<Integer, Double> angles;
    private final int range;

    /**
     * @param angles sensor number (1..7) to its mounting angle (degrees relative to the heading, left positive)
     * @param range the largest distance the sensors report, in mm (1..65535)
     */
    public SimIRDistanceModule(int address, ModuleIdentity identity, ModuleFaults faults, World world,
            Map<Integer, Double> angles, int range) {
        super(address, identity, faults);
        for (int number : angles.keySet()) {
            if (number < 1 || number > SENSORS) {
                throw new IllegalArgumentException("IR sensor number " + number + " is outside 1..7");
            }
        }
        if (range < 1 || range > 0xFFFF) {
            throw new IllegalArgumentException("IR range " + range + " is outside 1..65535 mm");
        }
        this.world = world;
        this.angles = new TreeMap<>(angles);
        this.range = range;
    }

    @Override
    public String moduleClass() {
        return "IRDistanceModule";
    }

    /** The distance sensor {@code sensor} (1..7) sees now, in mm. */
    public int distance(int sensor) {
        Double angle = angles.get(sensor);
        if (angle == null) {
            return range;
        }
        return (int) Math.round(Math.min(range, world.rangeAt(angle)));
    }

    /** Sensor number to mounting angle, for the ground truth. */
    Map<Integer, Double> angles() {
        return angles;
    }

    /** The largest distance the sensors report, in mm. */
    int range() {
        return range;
    }

    @Override
    int inputRegisterCount() {
        return 2 * SENSORS;
    }

    @Override
    int inputRegister(int index) {
        if (index < SENSORS) {
            return distance(index + 1);
        }
        return (int) Math.round(255.0 * (range - distance(index - SENSORS + 1)) / range);
    }
}
