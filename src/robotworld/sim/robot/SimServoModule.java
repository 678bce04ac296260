package robotworld.sim.robot;

import robotworld.bus.modbus.ExceptionCodes;

/**
 * A simulated servo module: holding register {@code n-1} = target angle of servo {@code n} (0..180), input
 * register {@code n-1} = current angle, discrete input {@code n-1} = moving. Servos turn at a fixed speed and
 * start at 90 degrees.
 */
public final class SimServoModule extends SimModule {

    public static final int CHANNELS = 8;
    private static final int START = 90;

    private final int[] target = new int[CHANNELS];
    private final double[] current = new double[CHANNELS];
    private final double degreesPerSecond;

    /** @param degreesPerSecond how fast a servo turns (0 = at once) */
    public SimServoModule(int address, ModuleIdentity identity, ModuleFaults faults, double degreesPerSecond) {
        super(address, identity, faults);
        if (degreesPerSecond < 0) {
            throw new IllegalArgumentException("servo speed must not be negative");
        }
        this.degreesPerSecond = degreesPerSecond;
        java.util.Arrays.fill(target, START);
        java.util.Arrays.fill(current, START);
    }

    @Override
    public String moduleClass() {
        return "ServoModule";
    }

    /** The current angle of servo {@code servo} (1..8), in degrees. */
    public double angle(int servo) {
        return current[servo - 1];
    }

    @Override
    int discreteInputCount() {
        return CHANNELS;
    }

    @Override
    boolean discreteInput(int index) {
        return current[index] != target[index];
    }

    @Override
    int inputRegisterCount() {
        return CHANNELS;
    }

    @Override
    int inputRegister(int index) {
        return (int) Math.round(current[index]);
    }

    @Override
    int holdingRegisterCount() {
        return CHANNELS;
    }

    @Override
    int holdingRegister(int index) {
        return target[index];
    }

    @Override
    void writeHoldingRegister(int index, int value) throws ModbusRefusal {
        if (value > 180) {
            throw new ModbusRefusal(ExceptionCodes.ILLEGAL_DATA_VALUE, "angle " + value + " outside 0..180");
        }
        target[index] = value;
        if (degreesPerSecond == 0) {
            current[index] = value;
        }
    }

    @Override
    void step(double seconds) {
        double maxTurn = degreesPerSecond * seconds;
        for (int i = 0; i < CHANNELS; i++) {
            double difference = target[i] - current[i];
            current[i] = degreesPerSecond == 0 || Math.abs(difference) <= maxTurn ? target[i]
                    : current[i] + Math.signum(difference) * maxTurn;
        }
    }
}
