package robotworld.sim.robot;

import robotworld.bus.BusWatchdog;
import robotworld.bus.modbus.FunctionCodes;

/**
 * The communication watchdog of a simulated module, as real drive controllers have one: holding register
 * {@link BusWatchdog#TIMEOUT_REGISTER} holds a timeout in ms (0 = off, the value at power-up); when no valid frame
 * addressed to the module arrives for that long, the module goes to its safe state ({@link SimModule#enterSafeState})
 * and sets discrete input {@link BusWatchdog#TRIPPED_INPUT}, which stays set until the master writes the timeout
 * register again. Broadcasts do not feed it. Changed under the {@link Simulation}'s lock.
 */
final class ModuleWatchdog {

    // changed under the simulation's lock; volatile so that tests and monitors can read them without it
    private volatile int timeoutMillis;
    private volatile long lastFrameNanos = System.nanoTime();
    private volatile boolean tripped;
    private volatile long trips;

    /** A valid frame addressed to the module arrived. */
    void fed(long nanos) {
        lastFrameNanos = nanos;
    }

    /** The simulator did not run for {@code nanos}: that pause is not silence of the master. */
    void stalled(long nanos) {
        lastFrameNanos += nanos;
    }

    /**
     * Whether the timeout has run out now and the watchdog has not tripped for this silence yet: the module must go
     * to its safe state, then {@link #trip()}.
     */
    boolean expired(long nanos) {
        return timeoutMillis != 0 && !tripped && nanos - lastFrameNanos >= timeoutMillis * 1_000_000L;
    }

    /**
     * Sets the tripped bit, once the module is in its safe state: as on a real drive, whoever reads the bit set
     * (the master, a monitor, a test) finds the module already stopped.
     */
    void trip() {
        tripped = true;
        trips++;
    }

    /**
     * Answers the request if it is one for the watchdog (read or write of the timeout register alone, read of the
     * tripped input alone); null otherwise.
     */
    byte[] respond(byte[] request) {
        if (request.length < 5) {
            return null;
        }
        int function = request[0] & 0xFF;
        int address = word(request, 1);
        int value = word(request, 3);
        if (function == FunctionCodes.READ_HOLDING_REGISTERS && address == BusWatchdog.TIMEOUT_REGISTER
                && value == 1 && request.length == 5) {
            return new byte[] {request[0], 2, (byte) (timeoutMillis >>> 8), (byte) timeoutMillis};
        }
        if (function == FunctionCodes.READ_DISCRETE_INPUTS && address == BusWatchdog.TRIPPED_INPUT && value == 1
                && request.length == 5) {
            return new byte[] {request[0], 1, (byte) (tripped ? 1 : 0)};
        }
        if (function == FunctionCodes.WRITE_SINGLE_REGISTER && address == BusWatchdog.TIMEOUT_REGISTER
                && request.length == 5) {
            arm(value);
            return request.clone();
        }
        if (function == FunctionCodes.WRITE_MULTIPLE_REGISTERS && address == BusWatchdog.TIMEOUT_REGISTER
                && value == 1 && request.length == 8 && (request[5] & 0xFF) == 2) {
            arm(word(request, 6));
            return new byte[] {request[0], request[1], request[2], request[3], request[4]};
        }
        return null;
    }

    /** The timeout in ms; 0 when off. */
    int timeoutMillis() {
        return timeoutMillis;
    }

    /** Whether it has tripped since the timeout register was last written. */
    boolean tripped() {
        return tripped;
    }

    /** How often it has tripped. */
    long trips() {
        return trips;
    }

    private void arm(int millis) {
        timeoutMillis = millis;
        tripped = false;
        lastFrameNanos = System.nanoTime();
    }

    private static int word(byte[] bytes, int at) {
        return (bytes[at] & 0xFF) << 8 | bytes[at + 1] & 0xFF;
    }
}
