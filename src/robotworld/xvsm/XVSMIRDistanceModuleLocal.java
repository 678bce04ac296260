package robotworld.xvsm;

import static robotworld.xvsm.IRDistanceTuples.ALL_SENSORS;
import static robotworld.xvsm.IRDistanceTuples.GET_ALL_SENSORS;
import static robotworld.xvsm.IRDistanceTuples.GET_ALL_SENSORS_BYTE_REP;
import static robotworld.xvsm.IRDistanceTuples.GET_SINGLE_SENSOR;
import static robotworld.xvsm.IRDistanceTuples.GET_SINGLE_SENSOR_CACHED;

import java.util.List;
import java.util.function.Supplier;
import robotworld.core.IRDistanceModule;
import robotworld.core.ModuleArguments;
import robotworld.space.Entry;

/**
 * An IR distance module attached to this computer, shared through the space. Requests {@code <key, sensorNr|0,
 * function>}; answers as in {@link IRDistanceTuples}. With adaptive batching, all waiting requests are answered
 * from at most one read of all distances and one read of all raw readings.
 */
public class XVSMIRDistanceModuleLocal extends XVSMSensorLocalModule<IRDistanceModule> implements IRDistanceModule {

    /** Serves with the runtime's default batching ({@code rwe.sensor.batching}). */
    public XVSMIRDistanceModuleLocal(XVSMRuntime runtime, String participant, String moduleName,
                                     IRDistanceModule hardware) {
        this(runtime, participant, moduleName, hardware, runtime.adaptiveBatchingByDefault());
    }

    /** Serves with adaptive batching on or off. */
    public XVSMIRDistanceModuleLocal(XVSMRuntime runtime, String participant, String moduleName,
                                     IRDistanceModule hardware, boolean adaptiveBatching) {
        super(runtime, participant, moduleName, hardware, adaptiveBatching);
        start();
    }

    @Override
    public String getAllSensors() {
        return IRDistanceTuples.text(callLocally(GET_ALL_SENSORS, ALL_SENSORS));
    }

    @Override
    public int[] getAllSensors_ByteRep() {
        return IRDistanceTuples.bytes(callLocally(GET_ALL_SENSORS_BYTE_REP, ALL_SENSORS));
    }

    @Override
    public int getSingleSensor_Cached(int sensorNr) {
        ModuleArguments.irSensorNumber(sensorNr);
        return IRDistanceTuples.distance(callLocally(GET_SINGLE_SENSOR_CACHED, sensorNr), sensorNr);
    }

    @Override
    public int getSingleSensor(int sensorNr) {
        ModuleArguments.irSensorNumber(sensorNr);
        return IRDistanceTuples.distance(callLocally(GET_SINGLE_SENSOR, sensorNr), sensorNr);
    }

    @Override
    protected List<Entry> perform(CallTuple request) {
        request.expectFields(1);
        if (request.is(GET_ALL_SENSORS)) {
            return IRDistanceTuples.textAnswer(hardware().getAllSensors());
        }
        if (request.is(GET_ALL_SENSORS_BYTE_REP)) {
            return IRDistanceTuples.bytesAnswer(hardware().getAllSensors_ByteRep());
        }
        int sensor = request.intAt(0);
        if (request.is(GET_SINGLE_SENSOR_CACHED)) {
            return IRDistanceTuples.distanceAnswer(sensor, hardware().getSingleSensor_Cached(sensor));
        }
        if (request.is(GET_SINGLE_SENSOR)) {
            return IRDistanceTuples.distanceAnswer(sensor, hardware().getSingleSensor(sensor));
        }
        throw request.unknownFunction();
    }

    /** Every answer of a batch from at most one read of the distances and one of the raw readings. */
    @Override
    protected Performer batchPerformer() {
        Supplier<String> text = readOnce(hardware()::getAllSensors);
        Supplier<int[]> distances = readOnce(() -> IRDistanceTuples.parseDistances(text.get()));
        Supplier<int[]> raw = readOnce(hardware()::getAllSensors_ByteRep);
        return request -> {
            request.expectFields(1);
            if (request.is(GET_ALL_SENSORS)) {
                return IRDistanceTuples.textAnswer(text.get());
            }
            if (request.is(GET_ALL_SENSORS_BYTE_REP)) {
                return IRDistanceTuples.bytesAnswer(raw.get());
            }
            if (request.is(GET_SINGLE_SENSOR) || request.is(GET_SINGLE_SENSOR_CACHED)) {
                int sensor = ModuleArguments.irSensorNumber(request.intAt(0));
                return IRDistanceTuples.distanceAnswer(sensor, distances.get()[sensor - 1]);
            }
            throw request.unknownFunction();
        };
    }
}
