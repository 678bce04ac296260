package robotworld.xvsm;

import static robotworld.xvsm.IRDistanceTuples.ALL_SENSORS;
import static robotworld.xvsm.IRDistanceTuples.GET_ALL_SENSORS;
import static robotworld.xvsm.IRDistanceTuples.GET_ALL_SENSORS_BYTE_REP;
import static robotworld.xvsm.IRDistanceTuples.GET_SINGLE_SENSOR;
import static robotworld.xvsm.IRDistanceTuples.GET_SINGLE_SENSOR_CACHED;

import robotworld.core.IRDistanceModule;
import robotworld.core.ModuleArguments;

/**
 * An IR distance module of another participant, reached through the space. {@link #getSingleSensor_Cached}
 * answers from the cache at the module's host (the last reading made there, by anyone).
 */
public class XVSMIRDistanceModuleRemote extends XVSMRemoteModule implements IRDistanceModule {

    /** Connects to {@code <participant><moduleName>REQUEST}/{@code ANSWER}. */
    public XVSMIRDistanceModuleRemote(XVSMRuntime runtime, String participant, String moduleName) {
        super(runtime, participant, moduleName);
    }

    @Override
    public String getAllSensors() {
        return IRDistanceTuples.text(call(GET_ALL_SENSORS, ALL_SENSORS));
    }

    @Override
    public int[] getAllSensors_ByteRep() {
        return IRDistanceTuples.bytes(call(GET_ALL_SENSORS_BYTE_REP, ALL_SENSORS));
    }

    @Override
    public int getSingleSensor_Cached(int sensorNr) {
        ModuleArguments.irSensorNumber(sensorNr);
        return IRDistanceTuples.distance(call(GET_SINGLE_SENSOR_CACHED, sensorNr), sensorNr);
    }

    @Override
    public int getSingleSensor(int sensorNr) {
        ModuleArguments.irSensorNumber(sensorNr);
        return IRDistanceTuples.distance(call(GET_SINGLE_SENSOR, sensorNr), sensorNr);
    }
}
