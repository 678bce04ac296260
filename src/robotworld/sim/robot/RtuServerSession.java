package robotworld.sim.robot;

import java.io.IOException;
import java.time.Duration;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.LinkClosedException;
import robotworld.bus.SerialLink;
import robotworld.bus.modbus.Crc16;
import robotworld.bus.modbus.FrameLength;
import robotworld.bus.modbus.FrameLengths;
import robotworld.bus.modbus.RtuFrame;
import robotworld.bus.modbus.RtuTiming;

/**
 * Serves the simulated bus on one link (a TCP connection or a pty): reads request frames, lets the addressed
 * module answer, applies its faults, and sends the reply with fast or real line timing. Frames for absent
 * addresses, with a wrong CRC, or broadcasts get no reply, as on a real bus.
 */
final class RtuServerSession implements Runnable {

    private static final Logger LOG = LoggerFactory.getLogger(RtuServerSession.class);
    private static final Duration IDLE_POLL = Duration.ofMillis(200);
    /** Fast timing has no real silences; a pause this long still ends a frame of unknown length. */
    private static final long FAST_SILENCE_NANOS = 5_000_000L;

    private final SerialLink link;
    private final Simulation simulation;
    private final RtuTiming rtu;
    private final LineTiming timing;
    private final long silenceNanos;
    private final BooleanSupplier echoRequests;
    private final AtomicLong requests = new AtomicLong();
    private final byte[] buffer = new byte[2 * RtuFrame.MAX_LENGTH];
    private volatile boolean closed;
    /** Fault: requests are read and never answered, the link stays open. */
    private volatile boolean hung;

    RtuServerSession(SerialLink link, Simulation simulation, RtuTiming rtu, LineTiming timing) {
        this(link, simulation, rtu, timing, () -> false);
    }

    /**
     * @param echoRequests whether the line echoes every request back to the master before any reply, as an RS-485
     *        adapter without echo suppression does
     */
    RtuServerSession(SerialLink link, Simulation simulation, RtuTiming rtu, LineTiming timing,
            BooleanSupplier echoRequests) {
        this.echoRequests = echoRequests;
        this.link = link;
        this.simulation = simulation;
        this.rtu = rtu;
        this.timing = timing;
        this.silenceNanos = timing == LineTiming.REAL ? Math.max(rtu.t35Nanos(), 2_000_000L) : FAST_SILENCE_NANOS;
    }

    /** Requests seen (valid frames, any address). */
    long requests() {
        return requests.get();
    }

    @Override
    public void run() {
        int have = 0;
        long firstByteAt = 0;
        long lastByteAt = 0;
        FrameLength lengths = FrameLengths.requests();
        try {
            while (!closed) {
                Duration wait = have == 0 ? IDLE_POLL : Duration.ofMillis(Math.max(1, silenceNanos / 1_000_000));
                int n = link.read(buffer, have, buffer.length - have, wait);
                if (n > 0) {
                    long now = System.nanoTime();
                    if (have == 0) {
                        firstByteAt = now;
                    }
                    have += n;
                    lastByteAt = now;
                }
                while (have > 0) {
                    int expected = lengths.of(buffer, have);
                    int frameLength;
                    if (expected > 0 && have >= expected) {
                        frameLength = expected;
                    } else if (n == 0 && expected == FrameLength.UNKNOWN) {
                        frameLength = have;
                    } else if (n == 0 || expected > RtuFrame.MAX_LENGTH || have >= buffer.length) {
                        LOG.debug("dropped an incomplete request: {}", RtuFrame.hex(buffer, have));
                        have = 0;
                        break;
                    } else {
                        break;
                    }
                    byte[] frame = Arrays.copyOf(buffer, frameLength);
                    have -= frameLength;
                    System.arraycopy(buffer, frameLength, buffer, 0, have);
                    serve(frame, firstByteAt, lastByteAt);
                    firstByteAt = lastByteAt;
                }
            }
        } catch (LinkClosedException e) {
            LOG.debug("bus session ended: {}", e.getMessage());
        } catch (IOException e) {
            if (!closed) {
                LOG.warn("bus session on {} failed: {}", link.portName(), e.getMessage());
            }
        } finally {
            close();
        }
    }

    /** Fault injection: from now on nothing is answered on this link (not even echoed), which stays open. */
    void hang() {
        hung = true;
    }

    boolean isClosed() {
        return closed;
    }

    private void serve(byte[] frame, long firstByteAt, long lastByteAt) throws IOException {
        if (hung) {
            return;
        }
        if (echoRequests.getAsBoolean()) {
            link.write(frame); // the master's adapter hears its own request
        }
        if (!Crc16.isValidFrame(frame, frame.length)) {
            LOG.debug("ignored a request with a wrong CRC: {}", RtuFrame.hex(frame, frame.length));
            return;
        }
        requests.incrementAndGet();
        RtuFrame request = RtuFrame.decode(frame, frame.length);
        if (request.address() == 0) {
            simulation.broadcast(request.pdu());
            return;
        }
        SimModule module = simulation.module(request.address());
        if (module == null || module.faults().ignores(request.functionCode())) {
            return;
        }
        int replyAddress = module.faults().answerAs() != 0 ? module.faults().answerAs() : request.address();
        byte[] reply = new RtuFrame(replyAddress, simulation.respond(module, request.pdu())).encode();
        if (module.faults().takeCorruption()) {
            reply[reply.length - 1] ^= (byte) 0xA5;
        }
        long start = System.nanoTime();
        if (timing == LineTiming.REAL) {
            // the request ends on the wire after its characters; the reply waits for the 3.5-character silence
            long requestEnd = Math.max(lastByteAt, firstByteAt + rtu.wireNanos(frame.length));
            start = requestEnd + rtu.t35Nanos();
        }
        start += module.faults().replyDelay().toNanos();
        send(reply, start, module.faults().trickle().toNanos());
    }

    private void send(byte[] reply, long start, long trickleNanos) throws IOException {
        if (trickleNanos > 0) {
            for (int i = 0; i < reply.length; i++) {
                sleepUntil(start + i * trickleNanos);
                link.write(reply[i] & 0xFF);
            }
            return;
        }
        if (timing == LineTiming.FAST) {
            sleepUntil(start);
            link.write(reply);
            return;
        }
        for (int i = 0; i < reply.length; i++) {
            // a byte is complete at the far end one character time after the previous one
            sleepUntil(start + rtu.wireNanos(i + 1));
            link.write(reply[i] & 0xFF);
        }
    }

    void close() {
        closed = true;
        try {
            link.close();
        } catch (IOException e) {
            // closing anyway
        }
    }

    private static void sleepUntil(long nanoTime) {
        long left;
        while ((left = nanoTime - System.nanoTime()) > 0) {
            LockSupport.parkNanos(left);
        }
    }
}
