package robotworld.sim.robot;

import robotworld.bus.modbus.ExceptionCodes;

/**
 * A simulated motor module: holding register {@code n-1} = set speed of motor {@code n} in signed per-mille;
 * discrete input {@code n-1} = still ramping. The actual speed follows the set speed at a limited rate. Two
 * channels may drive the robot's left and right wheels.
 */
public final class SimMotorModule extends SimModule {

    public static final int CHANNELS = 8;

    private final int[] set = new int[CHANNELS];
    private final double[] actual = new double[CHANNELS];
    private final double rampPerSecond;
    private final int leftChannel;
    private final int rightChannel;

    /**
     * @param rampPerSecond how fast the actual speed follows, in per-mille per second (0 = at once)
     * @param leftChannel motor number (1..8) of the left wheel, 0 for none
     * @param rightChannel motor number (1..8) of the right wheel, 0 for none
     */
    public SimMotorModule(int address, ModuleIdentity identity, ModuleFaults faults, double rampPerSecond,
            int leftChannel, int rightChannel) {
        super(address, identity, faults);
        if (rampPerSecond < 0) {
            throw new IllegalArgumentException("ramp must not be negative");
        }
        checkChannel(leftChannel, "left");
        checkChannel(rightChannel, "right");
        this.rampPerSecond = rampPerSecond;
        this.leftChannel = leftChannel;
        this.rightChannel = rightChannel;
    }

    @Override
    public String moduleClass() {
        return "MotorModule";
    }

    /** Whether this module drives the robot's wheels. */
    public boolean drivesWheels() {
        return leftChannel > 0 && rightChannel > 0;
    }

    /** The actual speed (-1..1) of the left wheel. */
    double leftWheel() {
        return leftChannel == 0 ? 0 : actual[leftChannel - 1] / 1000;
    }

    /** The actual speed (-1..1) of the right wheel. */
    double rightWheel() {
        return rightChannel == 0 ? 0 : actual[rightChannel - 1] / 1000;
    }

    /** The actual speed of motor {@code motor} (1..8), -1..1. */
    double actualSpeed(int motor) {
        return actual[motor - 1] / 1000;
    }

    /** Which wheel motor {@code motor} (1..8) drives: {@code left}, {@code right} or empty. */
    String wheelOf(int motor) {
        return motor == leftChannel ? "left" : motor == rightChannel ? "right" : "";
    }

    /** The set speed of motor {@code motor} (1..8) in per-mille. */
    public int setSpeed(int motor) {
        return set[motor - 1];
    }

    @Override
    int discreteInputCount() {
        return CHANNELS;
    }

    @Override
    boolean discreteInput(int index) {
        return actual[index] != set[index];
    }

    @Override
    int holdingRegisterCount() {
        return CHANNELS;
    }

    @Override
    int holdingRegister(int index) {
        return set[index] & 0xFFFF;
    }

    @Override
    void writeHoldingRegister(int index, int value) throws ModbusRefusal {
        int speed = (short) value;
        if (speed < -1000 || speed > 1000) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "speed " + speed + " outside -1000..1000");
        }
        set[index] = speed;
        if (rampPerSecond == 0) {
            actual[index] = speed;
        }
    }

    /** The watchdog tripped: every motor is set to 0 (the actual speed follows at the ramp rate). */
    @Override
    void enterSafeState() {
        java.util.Arrays.fill(set, 0);
        if (rampPerSecond == 0) {
            java.util.Arrays.fill(actual, 0);
        }
    }

    @Override
    void step(double seconds) {
        double maxChange = rampPerSecond * seconds;
        for (int i = 0; i < CHANNELS; i++) {
            double difference = set[i] - actual[i];
            actual[i] = rampPerSecond == 0 || Math.abs(difference) <= maxChange ? set[i]
                    : actual[i] + Math.signum(difference) * maxChange;
        }
    }

    private static void checkChannel(int channel, String side) {
        if (channel < 0 || channel > CHANNELS) {
            throw new IllegalArgumentException(side + " wheel channel " + channel + " is outside 0..8");
        }
    }
}
