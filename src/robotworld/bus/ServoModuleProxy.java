package robotworld.bus;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import robotworld.core.ModuleArguments;
import robotworld.core.ServoModule;

/**
 * A servo module on the bus. Register map: holding register {@code n-1} = target angle of servo {@code n}
 * (0..180); input register {@code n-1} = its current angle; discrete input {@code n-1} = still moving.
 *
 * <p>{@link #setServo} polls "moving" until it clears, at most {@link BusTiming#servoMoveTimeout()}.
 */
public class ServoModuleProxy extends ModuleProxy implements ServoModule {

    /** Pause between two polls of "moving", so a waiting servo call leaves the bus to other callers. */
    private static final long POLL_PAUSE_NANOS = TimeUnit.MILLISECONDS.toNanos(5);

    public ServoModuleProxy(RS485Bus bus, int address) {
        this(bus, address, null);
    }

    public ServoModuleProxy(RS485Bus bus, int address, String name) {
        super("ServoModule", bus, address, name);
    }

    /**
     * {@inheritDoc}
     *
     * @throws BusTimeoutException when the servo still moves after the servo move timeout
     */
    @Override
    public void setServo(int servoNr, int position) {
        ModuleArguments.servoNumber(servoNr);
        ModuleArguments.servoPosition(position);
        bus().writeRegister(address(), servoNr - 1, position);
        long deadline = System.nanoTime() + bus().timing().servoMoveTimeout().toNanos();
        while (isMoving(servoNr)) {
            if (System.nanoTime() - deadline > 0) {
                throw new BusTimeoutException(bus().portName(), address(), bus().describe(address()) + " on "
                        + bus().portName() + ": servo " + servoNr + " did not reach " + position + " degrees within "
                        + bus().timing().servoMoveTimeout().toMillis() + " ms (it is at " + getServo(servoNr) + ")");
            }
            LockSupport.parkNanos(POLL_PAUSE_NANOS);
        }
    }

    @Override
    public void setServoQuiet(int servoNr, int position) {
        ModuleArguments.servoNumber(servoNr);
        ModuleArguments.servoPosition(position);
        bus().writeRegisterQuietly(address(), servoNr - 1, position);
    }

    /** The servo's current angle in degrees (beyond the thesis interface: for monitors and tests). */
    public int getServo(int servoNr) {
        ModuleArguments.servoNumber(servoNr);
        return bus().readInputRegisters(address(), servoNr - 1, 1)[0];
    }

    /** Whether the servo is still on its way to its target. */
    public boolean isMoving(int servoNr) {
        ModuleArguments.servoNumber(servoNr);
        return bus().readDiscreteInputs(address(), servoNr - 1, 1)[0];
    }
}
