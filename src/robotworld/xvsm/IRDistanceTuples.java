package robotworld.xvsm;

import java.util.ArrayList;
import java.util.List;
import robotworld.core.IRDistanceModule;
import robotworld.space.Entry;
import robotworld.space.Tuple;

/**
 * Tuples of an IR distance module (thesis table 8): {@code <key, value, function>}. In a request the value is the
 * sensor number (0 for the functions that read all sensors). In an answer its type depends on the function:
 * a string for {@code getAllSensors}, a tuple of seven integers for {@code getAllSensors_ByteRep}, and the pair
 * {@code <sensorNr, millimetres>} for {@code getSingleSensor} and {@code getSingleSensor_Cached}, so that a
 * monitor knows which sensor the answer is about.
 */
final class IRDistanceTuples {

    static final String GET_ALL_SENSORS = "getAllSensors";
    static final String GET_ALL_SENSORS_BYTE_REP = "getAllSensors_ByteRep";
    static final String GET_SINGLE_SENSOR_CACHED = "getSingleSensor_Cached";
    static final String GET_SINGLE_SENSOR = "getSingleSensor";
    /** The value of a request for all sensors. */
    static final int ALL_SENSORS = 0;

    private IRDistanceTuples() {
    }

    static List<Entry> textAnswer(String distances) {
        return List.of(Entry.of(distances));
    }

    static List<Entry> bytesAnswer(int[] readings) {
        List<Entry> fields = new ArrayList<>(readings.length);
        for (int reading : readings) {
            fields.add(Entry.of(reading));
        }
        return List.of(new Tuple(fields));
    }

    static List<Entry> distanceAnswer(int sensor, int millimetres) {
        return List.of(Tuple.of(sensor, millimetres));
    }

    static String text(CallTuple answer) {
        return answer.expectFields(1).stringAt(0);
    }

    static int[] bytes(CallTuple answer) {
        Tuple readings = answer.expectFields(1).tupleAt(0);
        int[] values = new int[readings.arity()];
        for (int i = 0; i < values.length; i++) {
            values[i] = (int) readings.longAt(i);
        }
        return values;
    }

    static int distance(CallTuple answer, int sensor) {
        Tuple pair = answer.expectFields(1).tupleAt(0);
        if (pair.arity() != 2 || pair.longAt(0) != sensor) {
            throw new MalformedCallException("the answer " + answer + " is not about sensor " + sensor);
        }
        return (int) pair.longAt(1);
    }

    /** The distances in a {@code getAllSensors} text ("312 800 ..."), sensor 1 first. */
    static int[] parseDistances(String text) {
        String[] parts = text.strip().split("\\s+");
        if (parts.length != IRDistanceModule.SENSORS) {
            throw new IllegalStateException("expected " + IRDistanceModule.SENSORS + " distances from the module, got '"
                    + text + "'");
        }
        int[] distances = new int[parts.length];
        for (int i = 0; i < parts.length; i++) {
            distances[i] = Integer.parseInt(parts[i]);
        }
        return distances;
    }
}
