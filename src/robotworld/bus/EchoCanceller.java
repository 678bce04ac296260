package robotworld.bus;

import java.util.Arrays;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.modbus.FunctionCodes;

/**
 * Removes the echo of the request just sent from the front of what is received (see {@link EchoCancellation}).
 * Used by the master's one thread; not thread-safe.
 */
final class EchoCanceller {

    private static final Logger LOG = LoggerFactory.getLogger(EchoCanceller.class);

    /** What {@link #strip} says when the bytes so far are the start of the echo: read on before parsing. */
    static final int NEED_MORE = -1;
    /** What {@link #strip} says when echo cancellation is off and the echo came: the call has failed. */
    static final int ECHO_WHILE_OFF = -2;

    private final String portName;
    private volatile EchoCancellation mode = EchoCancellation.AUTO;
    private volatile boolean detected;
    /** AUTO: a reply came without an echo before it: this adapter does not echo. */
    private volatile boolean absent;
    private byte[] pending;
    /** The echo last dropped, when it could also have been the reply (a write, an echo request). */
    private byte[] ambiguousCopy;
    /**
     * A late reply to an earlier send of the same request may still come (a retry, or a reply given up on), so
     * two copies of a write prove no echo: on a busy machine they are that late reply and this one.
     */
    private boolean lateCopyPossible;

    EchoCanceller(String portName) {
        this.portName = portName;
    }

    void mode(EchoCancellation newMode) {
        mode = newMode;
    }

    EchoCancellation mode() {
        return mode;
    }

    /** AUTO, and not yet known whether the adapter echoes. */
    boolean undecided() {
        return mode == EchoCancellation.AUTO && !detected && !absent;
    }

    /** AUTO: a copy of a write came twice (echo, then reply), or did not (no echo). */
    void settle(boolean secondCopyCame) {
        if (secondCopyCame && lateCopyPossible) {
            return; // the second copy may be a late reply to an earlier send: the question stays open
        }
        if (secondCopyCame) {
            staleFrameEqualsLastRequest();
        } else if (!detected) {
            absent = true;
        }
    }

    /** Whether the adapter was seen echoing (in AUTO mode, echo cancellation is on from then on). */
    boolean detected() {
        return detected;
    }

    /**
     * A request went out: its echo may come next.
     *
     * @param mayBeAnsweredLate whether a reply to an earlier send of the same request may still come (this is a
     *        retry, or replies owed by its address were given up on): copies of it then prove no echo
     */
    void sent(byte[] frame, boolean mayBeAnsweredLate) {
        pending = frame;
        ambiguousCopy = null;
        lateCopyPossible = mayBeAnsweredLate;
    }

    /**
     * When no reply came after a dropped copy that could itself have been the reply (the adapter did not echo after
     * all), that copy: the caller takes it as the reply. Null otherwise.
     */
    byte[] takeAmbiguousCopy() {
        byte[] copy = ambiguousCopy;
        ambiguousCopy = null;
        return copy;
    }

    /**
     * Takes the echo off the front of {@code buffer}.
     *
     * @param lineSilent whether the line fell silent after the last read (a cut-short echo ends there)
     * @return the bytes left, or {@link #NEED_MORE}, or {@link #ECHO_WHILE_OFF}
     */
    int strip(byte[] buffer, int have, boolean lineSilent) {
        byte[] echo = pending;
        if (echo == null || have == 0) {
            return have;
        }
        int compared = Math.min(have, echo.length);
        if (!Arrays.equals(buffer, 0, compared, echo, 0, compared)) {
            pending = null; // not the echo: the reply itself (or noise)
            if (mode == EchoCancellation.AUTO && !detected && !replyMayEqualRequest(echo[1] & 0xFF)) {
                absent = true; // the reply came first: this adapter does not echo
            }
            return have;
        }
        if (have < echo.length) {
            if (lineSilent) {
                pending = null;
                return have;
            }
            return NEED_MORE;
        }
        pending = null;
        boolean twoCopies = !lateCopyPossible && have >= 2 * echo.length
                && Arrays.equals(buffer, echo.length, 2 * echo.length, echo, 0, echo.length);
        boolean proof = !replyMayEqualRequest(echo[1] & 0xFF) || twoCopies; // two copies: echo, then reply
        switch (mode) {
            case OFF -> {
                return proof ? ECHO_WHILE_OFF : have;
            }
            case AUTO -> {
                if (!detected && !proof) {
                    return have; // could be the reply of a write: not taken as an echo before one is proven
                }
                if (!detected) {
                    detected = true; // also after an adapter without echo: it may have been swapped
                    absent = false;
                    LOG.warn("{}: the adapter echoes every request (an RS-485 adapter without echo suppression): "
                            + "echo cancellation is on from now", portName);
                }
            }
            default -> {
                // ON: drop it
            }
        }
        if (!proof) {
            ambiguousCopy = echo;
        }
        System.arraycopy(buffer, echo.length, buffer, 0, have - echo.length);
        return have - echo.length;
    }

    /**
     * A frame that came unasked before a request and equals the request sent before it: in AUTO mode the reply of a
     * write or echo came after the request's own echo had been taken for it. Proof of an echoing adapter.
     */
    void staleFrameEqualsLastRequest() {
        if (mode == EchoCancellation.AUTO && !detected && !lateCopyPossible) {
            detected = true;
            LOG.warn("{}: the adapter echoes every request (a write's reply came after its echo): echo "
                    + "cancellation is on from now", portName);
        }
    }

    /** Functions whose correct reply repeats the request byte for byte, so an identical frame proves nothing. */
    static boolean replyMayEqualRequest(int function) {
        return function == FunctionCodes.WRITE_SINGLE_COIL || function == FunctionCodes.WRITE_SINGLE_REGISTER
                || function == FunctionCodes.DIAGNOSTICS;
    }

    /** The words for people when the echo came while cancellation is off. */
    static String hint() {
        return "the reply began with the request itself: the adapter echoes what it sends (an RS-485 adapter "
                + "without echo suppression); turn echo cancellation on (rwe explore --echo on, "
                + "RS485Bus.echoCancellation(EchoCancellation.ON)) or leave it at auto";
    }
}
