package robotworld.bus;

import java.util.Arrays;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.stream.Collectors;
import robotworld.core.IRDistanceModule;
import robotworld.core.ModuleArguments;

/**
 * An IR distance module on the bus. Register map: input register {@code n-1} = distance of sensor {@code n} in
 * millimetres; input register {@code 7+n-1} = its raw 8-bit reading (0..255).
 *
 * <p>Every read of distances also fills the cache that {@link #getSingleSensor_Cached} answers from.
 */
public class IRDistanceModuleProxy extends ModuleProxy implements IRDistanceModule {

    /** First input register of the raw readings. */
    public static final int RAW_REGISTERS = SENSORS;

    private final AtomicIntegerArray cache = new AtomicIntegerArray(SENSORS);
    private volatile boolean cacheFilled;

    public IRDistanceModuleProxy(RS485Bus bus, int address) {
        this(bus, address, null);
    }

    public IRDistanceModuleProxy(RS485Bus bus, int address, String name) {
        super("IRDistanceModule", bus, address, name);
    }

    @Override
    public String getAllSensors() {
        return Arrays.stream(readAll()).mapToObj(Integer::toString).collect(Collectors.joining(" "));
    }

    @Override
    public int[] getAllSensors_ByteRep() {
        return bus().readInputRegisters(address(), RAW_REGISTERS, SENSORS);
    }

    @Override
    public int getSingleSensor_Cached(int sensorNr) {
        ModuleArguments.irSensorNumber(sensorNr);
        if (!cacheFilled) {
            readAll();
        }
        return cache.get(sensorNr - 1);
    }

    @Override
    public int getSingleSensor(int sensorNr) {
        ModuleArguments.irSensorNumber(sensorNr);
        int distance = bus().readInputRegisters(address(), sensorNr - 1, 1)[0];
        cache.set(sensorNr - 1, distance);
        return distance;
    }

    private int[] readAll() {
        int[] distances = bus().readInputRegisters(address(), 0, SENSORS);
        for (int i = 0; i < SENSORS; i++) {
            cache.set(i, distances[i]);
        }
        cacheFilled = true;
        return distances;
    }
}
