package robotworld.x10;

import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.SerialLink;

/**
 * The host side of the CM11A serial protocol over one link. Not thread-safe: exactly one thread (the controller's
 * link worker) calls it, which is what keeps one frame on the wire at a time.
 *
 * <p>A transmission is: send frame, read the checksum echo (resend on a wrong or missing one, bounded), send
 * 0x00, wait for 0x55. The interface may poll (0x5A: upload waiting; 0xA5: power failure, clock wanted) where a
 * checksum or 0x55 was expected; the poll is answered and the frame sent again, because a polling interface has
 * ignored it. When a frame's checksum itself is 0x5A or 0xA5 the echo is taken as the checksum; if it was a poll
 * after all, the interface polls again instead of sending 0x55, which is then handled as above.
 */
final class CM11aProtocol {

    private static final Logger LOG = LoggerFactory.getLogger(CM11aProtocol.class);

    /** How long the idle watch waits for a first byte. */
    private static final Duration IDLE_LOOK = Duration.ofMillis(1);

    private final SerialLink link;
    private final CM11aConfig config;
    private final Consumer<List<X10Event>> eventSink;
    private final UploadDecoder decoder = new UploadDecoder();
    private int pollsThisCommand;
    /** When the last 0x55 came; the next frame keeps {@code pauseAfterReady} of quiet after it. */
    private long lastReadyAt = System.nanoTime() - Long.MAX_VALUE / 4;

    CM11aProtocol(SerialLink link, CM11aConfig config, Consumer<List<X10Event>> eventSink) {
        this.link = link;
        this.config = config;
        this.eventSink = eventSink;
    }

    String portName() {
        return link.portName();
    }

    /** Sends the frames in order, each as one complete exchange. */
    void transmit(List<X10Frame> frames) throws IOException {
        pollsThisCommand = 0;
        serviceIdle();
        for (X10Frame frame : frames) {
            transmit(frame);
        }
    }

    private void transmit(X10Frame frame) throws IOException {
        byte[] bytes = frame.bytes();
        int expected = frame.checksum();
        int wrongChecksums = 0;
        int silentSends = 0;
        while (true) {
            awaitQuietAfterReady();
            link.write(bytes);
            int reply = link.readByte(config.checksumTimeout());
            if (reply == expected) {
                link.write(X10Constants.CM11A_ACK);
                int ready = awaitReady(frame);
                if (ready == X10Constants.CM11A_READY) {
                    return;
                }
                answerPoll(ready, frame); // the interface polled instead of transmitting: send the frame again
                continue;
            }
            if (reply == X10Constants.CM11A_POLL || reply == X10Constants.CM11A_POWER_FAIL_POLL) {
                answerPoll(reply, frame);
                continue;
            }
            if (reply < 0) {
                silentSends++;
                if (silentSends >= config.sendsToASilentInterface()) {
                    throw new X10TimeoutException(portName(), "no checksum for frame " + frame + " within "
                            + config.checksumTimeout().toMillis() + " ms, " + silentSends + " attempts: the "
                            + "interface has said nothing for " + config.deadDeviceTimeout().toMillis()
                            + " ms (unplugged, no power, or not a CM11A on this port?)");
                }
                LOG.debug("{}: no checksum for {}, sending it again", portName(), frame);
                continue; // the checksum timeout was the pause
            }
            wrongChecksums++;
            if (wrongChecksums >= config.maxAttempts()) {
                throw new X10ProtocolException(portName(), "wrong checksum " + Hex.of(reply) + " (expected "
                        + Hex.of(expected) + ") for frame " + frame + ", " + wrongChecksums + " attempts");
            }
            LOG.debug("{}: checksum {} for {}, sending it again in {} ms", portName(), Hex.of(reply), frame,
                    config.resendDelay().toMillis());
            pause(config.resendDelay()); // the interface gives up waiting for our 0x00 first
        }
    }

    /** Waits for 0x55; returns it, or a poll byte that came instead. */
    private int awaitReady(X10Frame frame) throws IOException {
        long deadline = System.nanoTime() + config.readyTimeout().toNanos();
        while (true) {
            long left = deadline - System.nanoTime();
            int reply = left <= 0 ? -1 : link.readByte(Duration.ofNanos(left));
            if (reply == X10Constants.CM11A_READY) {
                lastReadyAt = System.nanoTime();
                return reply;
            }
            if (X10Constants.looksLikePoll(reply)) {
                return reply;
            }
            if (reply < 0) {
                throw new X10TimeoutException(portName(), "no ready byte 0x55 after frame " + frame + " within "
                        + config.readyTimeout().toMillis() + " ms");
            }
            LOG.debug("{}: ignored byte {} while waiting for 0x55", portName(), Hex.of(reply));
        }
    }

    private void answerPoll(int poll, X10Frame during) throws IOException {
        pollsThisCommand++;
        if (pollsThisCommand > config.maxPollsPerCommand()) {
            throw new X10ProtocolException(portName(), "the interface kept polling (" + pollsThisCommand
                    + " polls) while sending " + (during == null ? "a request" : "frame " + during));
        }
        if (poll == X10Constants.CM11A_POLL) {
            answerUploadPoll();
        } else {
            answerPowerFailPoll();
        }
    }

    /**
     * Between commands: handles what the interface sent, waiting a moment for the first byte, so a link closed at
     * the far end is noticed (a look at what is available would not see it) and can be opened again while idle.
     */
    void watchWhileIdle() throws IOException {
        byte[] one = new byte[1];
        while (link.read(one, 0, 1, IDLE_LOOK) > 0) {
            handleIdleByte(one[0] & 0xFF);
        }
    }

    /** Handles polls and stray bytes that arrived while no command was running. */
    void serviceIdle() throws IOException {
        while (link.available() > 0) {
            handleIdleByte(link.readByte(Duration.ZERO));
        }
    }

    private void handleIdleByte(int value) throws IOException {
        if (value == X10Constants.CM11A_POLL) {
            answerUploadPoll();
        } else if (value == X10Constants.CM11A_POWER_FAIL_POLL) {
            answerPowerFailPoll();
        } else if (value >= 0) {
            LOG.debug("{}: ignored stray byte {}", portName(), Hex.of(value));
        }
    }

    /** 0x5A: answer 0xC3, read {@code size mask data...}, decode, hand the events on. */
    private void answerUploadPoll() throws IOException {
        link.write(X10Constants.CM11A_POLL_ACK);
        int size = readSkippingPolls(X10Constants.CM11A_POLL, -1); // polls sent before our 0xC3 arrived
        if (size == X10Constants.CM11A_POWER_FAIL_POLL) {
            answerPowerFailPoll();
            return;
        }
        if (size < 1 || size > X10Constants.CM11A_MAX_UPLOAD_SIZE) {
            LOG.warn("{}: bad upload size {} after 0xC3: upload lost", portName(),
                    size < 0 ? "(none)" : Hex.of(size));
            return;
        }
        byte[] buffer = new byte[size];
        if (!readFully(buffer)) {
            LOG.warn("{}: upload cut short after 0xC3: lost", portName());
            return;
        }
        LOG.debug("{}: upload {} {}", portName(), Hex.of(size), Hex.of(buffer));
        List<X10Event> events = decoder.decode(buffer);
        if (!events.isEmpty()) {
            eventSink.accept(events);
        }
    }

    /** 0xA5: send the clock until the interface takes it. */
    private void answerPowerFailPoll() throws IOException {
        LOG.info("{}: interface reports a power failure; sending the clock", portName());
        sendClock();
    }

    /** Sends 0x9B and the clock; the checksum covers the six clock bytes only. */
    void sendClock() throws IOException {
        for (int attempt = 1; attempt <= config.maxAttempts(); attempt++) {
            CM11aClock clock = CM11aClock.now(config.clock(), config.clockTime(), config.monitoredHouse());
            int expected = clock.checksum();
            awaitQuietAfterReady();
            link.write(clock.frame());
            int reply = readSkippingPolls(X10Constants.CM11A_POWER_FAIL_POLL, expected); // polls sent before it came
            if (reply != expected) {
                LOG.debug("{}: clock checksum {} (expected {})", portName(),
                        reply < 0 ? "missing" : Hex.of(reply), Hex.of(expected));
                continue;
            }
            link.write(X10Constants.CM11A_ACK);
            int ready = link.readByte(config.readyTimeout());
            if (ready == X10Constants.CM11A_READY) {
                lastReadyAt = System.nanoTime();
                return;
            }
            LOG.debug("{}: {} instead of 0x55 after the clock", portName(), ready < 0 ? "nothing" : Hex.of(ready));
        }
        throw new X10ProtocolException(portName(), "the interface did not accept the clock after "
                + config.maxAttempts() + " attempts");
    }

    /**
     * Reads the answer to what was just sent, passing over {@code poll} bytes (unless {@code poll} is the
     * answer expected): the interface polls until what we sent has arrived, so polls it sent before that may be
     * waiting ahead of the answer, the more so the longer this host was held up (a busy machine, a slow bridge).
     * They are passed over for up to one checksum timeout, so an interface that keeps polling still fails in
     * bounded time. Returns the first other byte, or -1 if none came.
     */
    private int readSkippingPolls(int poll, int expected) throws IOException {
        long deadline = System.nanoTime() + config.checksumTimeout().toNanos();
        int reply = link.readByte(config.checksumTimeout());
        while (reply == poll && reply != expected) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                break;
            }
            reply = link.readByte(Duration.ofNanos(left));
        }
        return reply;
    }

    /** 0x8B: read the 14 status bytes. */
    CM11aStatus requestStatus() throws IOException {
        pollsThisCommand = 0;
        serviceIdle();
        for (int attempt = 1; attempt <= config.maxAttempts(); attempt++) {
            awaitQuietAfterReady();
            link.write(X10Constants.CM11A_STATUS_REQUEST);
            byte[] status = new byte[X10Constants.CM11A_STATUS_LENGTH];
            if (readFully(status)) {
                return CM11aStatus.decode(status);
            }
            LOG.debug("{}: status answer incomplete, asking again", portName());
            drain();
        }
        throw new X10TimeoutException(portName(), "no complete status answer within "
                + config.checksumTimeout().toMillis() + " ms, " + config.maxAttempts() + " attempts");
    }

    /** Reads exactly buffer.length bytes, allowing checksumTimeout between bytes; false when they do not come. */
    private boolean readFully(byte[] buffer) throws IOException {
        int filled = 0;
        while (filled < buffer.length) {
            int n = link.read(buffer, filled, buffer.length - filled, config.checksumTimeout());
            if (n == 0) {
                return false;
            }
            filled += n;
        }
        return true;
    }

    private void drain() throws IOException {
        byte[] junk = new byte[64];
        while (link.read(junk, 0, junk.length, Duration.ofMillis(20)) > 0) {
            // discard what is left of a broken answer
        }
    }

    /** Keeps {@code pauseAfterReady} of quiet after the last 0x55 before anything new goes out. */
    private void awaitQuietAfterReady() {
        long until = lastReadyAt + config.pauseAfterReady().toNanos();
        long left = until - System.nanoTime();
        if (left > 0) {
            pause(Duration.ofNanos(left));
        }
    }

    private static void pause(Duration duration) {
        long until = System.nanoTime() + duration.toNanos();
        long left;
        while ((left = until - System.nanoTime()) > 0) {
            java.util.concurrent.locks.LockSupport.parkNanos(left);
            if (Thread.currentThread().isInterrupted()) {
                return; // closing: the caller fails on the closed link next
            }
        }
    }

    /** Whether opening the link again may cure a silent interface (see {@link SerialLink}). */
    boolean silenceMayMeanADeadConnection() {
        return link.silenceMayMeanADeadConnection();
    }

    /** Closes and opens the link again: after a lost connection, or a silence that may be a dead one. */
    void reopen() throws IOException {
        link.close();
        link.open();
        lastReadyAt = System.nanoTime() - Long.MAX_VALUE / 4;
    }
}
