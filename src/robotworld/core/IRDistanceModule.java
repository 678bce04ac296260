package robotworld.core;

/**
 * An infrared distance sensor module: {@value #SENSORS} triangulation sensors, numbered 1..{@value #SENSORS}, that
 * measure the distance to the nearest object in their direction, in millimetres.
 */
public interface IRDistanceModule {

    /** Number of sensors. */
    int SENSORS = 7;

    /**
     * Reads all sensors.
     *
     * @return the seven distances in millimetres, sensor 1 first, separated by single spaces (e.g.
     *         {@code "312 800 800 455 800 800 120"})
     */
    String getAllSensors();

    /**
     * Reads the raw 8-bit readings of all sensors (0..255; larger means closer, as a triangulation sensor's
     * output voltage).
     *
     * @return seven readings, index {@code n-1} for sensor {@code n}
     */
    int[] getAllSensors_ByteRep();

    /**
     * The distance measured by a sensor at the last read, without asking the module again. Reads all sensors
     * first when nothing has been read yet.
     *
     * @param sensorNr 1..{@value #SENSORS}
     * @return millimetres
     */
    int getSingleSensor_Cached(int sensorNr);

    /**
     * Reads one sensor from the module now.
     *
     * @param sensorNr 1..{@value #SENSORS}
     * @return millimetres
     */
    int getSingleSensor(int sensorNr);
}
