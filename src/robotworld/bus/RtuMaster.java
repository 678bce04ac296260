package robotworld.bus;

import java.io.IOException;
import java.time.Duration;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import java.util.function.IntFunction;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.modbus.Crc16;
import robotworld.bus.modbus.ExceptionCodes;
import robotworld.bus.modbus.FrameLength;
import robotworld.bus.modbus.FrameLengths;
import robotworld.bus.modbus.FunctionCodes;
import robotworld.bus.modbus.Pdus;
import robotworld.bus.modbus.RtuFrame;
import robotworld.bus.modbus.RtuTiming;

/**
 * The client (master) end of Modbus RTU over a {@link SerialLink}: one transaction at a time, replies found by
 * their computed length (silences do not survive TCP or ptys), corrupted replies retried, late replies from other
 * addresses recognised as stray frames instead of being mistaken for the awaited one.
 *
 * <p>A late reply from the <em>same</em> address cannot be told apart by its bytes (reading one bumper and reading
 * all eight both answer {@code 02 01 xx}), so an unanswered request leaves a debt: the reply is <em>owed</em> until
 * it arrives or until the late-reply window ({@value #LATE_REPLY_TIMEOUTS} reply timeouts after the request) has
 * passed, and that address is not asked anything new before. Owed replies that arrive are discarded as
 * <em>stale</em>; the other addresses are not held up (their replies are told apart by address). A write's
 * confirmation names the register and value it confirms, so one that comes later still (a busy machine can
 * outlast any window) is recognised by its content and never answers another write.
 */
final class RtuMaster {

    private static final Logger LOG = LoggerFactory.getLogger(RtuMaster.class);

    /** Lengths of identification replies (what bus exploration's probes get), to find them among broken bytes. */
    private static final FrameLength IDENTIFICATION_REPLY = FrameLengths.responseTo(Pdus.readDeviceIdentification());

    /** Upper bound for skipping a stream of garbage after a corrupted reply. */
    private static final long MAX_RESYNC_NANOS = 500_000_000L;

    /**
     * How long, in (normal) reply timeouts from the end of an unanswered request, its reply may still arrive and
     * is waited for before the same address is asked again. Covers a module or machine up to four timeouts late;
     * costs nothing unless an address did not answer, and then at most once, before the next request to it.
     */
    static final int LATE_REPLY_TIMEOUTS = 4;

    /**
     * Calls in a row that timed out without a single byte on the line, after which a {@code tcp://} link is opened
     * again before the next request: a connection can go silent without closing (a bridge that hung or crashed, a
     * connection a network device dropped), and only a new connection finds out. Silence from one absent module among
     * answering ones never adds up to this; a scan's silences do not count.
     */
    static final int SILENT_CALLS_BEFORE_REOPEN = 3;

    /**
     * How one call is made.
     *
     * @param replyTimeout how long the reply may take to start, counted from the end of the request on the wire
     * @param attempts how often the request is sent in all
     * @param retryTimeouts whether a missing reply is retried (not in a scan, where silence means "absent")
     */
    record CallPolicy(Duration replyTimeout, int attempts, boolean retryTimeouts) {
    }

    private enum Kind { OK, TIMEOUT, CORRUPT, WRONG_FUNCTION, REFUSED, WRONG_ADDRESS, ADAPTER_ECHO }

    /** What came back; {@code from} is the address the frame named. */
    private record Reply(Kind kind, byte[] pdu, int from) {
        static final Reply TIMEOUT = new Reply(Kind.TIMEOUT, null, -1);
        static final Reply CORRUPT = new Reply(Kind.CORRUPT, null, -1);
        static final Reply ADAPTER_ECHO = new Reply(Kind.ADAPTER_ECHO, null, -1);

        Reply(Kind kind, byte[] pdu) {
            this(kind, pdu, -1);
        }
    }

    private record Pending(int address, byte[] pdu, long sent, long deadline) {
    }

    private final SerialLink link;
    private final RtuTiming timing;
    private final long frameGapNanos;
    private final long interByteNanos;
    private final long lateReplyNanos;
    private final IntFunction<String> describe;
    private final EchoCanceller echo;
    /** The last request frame written, to recognise its echo among stale bytes. */
    private byte[] lastSent;
    /** The last call was answered by a copy of its request (a write's reply, or its echo taken for it). */
    private boolean answeredByCopy;
    private final byte[] buffer = new byte[2 * RtuFrame.MAX_LENGTH];
    private final AtomicLong transactions = new AtomicLong();
    private final AtomicLong retries = new AtomicLong();
    private final AtomicLong timeouts = new AtomicLong();
    private final AtomicLong crcErrors = new AtomicLong();
    private final AtomicLong exceptionResponses = new AtomicLong();
    private final AtomicLong strayFrames = new AtomicLong();
    private final AtomicLong staleReplies = new AtomicLong();
    /** Per address: how many replies are owed (requests that timed out), the last such request, until when. */
    private final int[] owed = new int[248];
    private final byte[][] owedRequest = new byte[248][];
    private final long[] owedUntil = new long[248];
    private volatile Consumer<RtuFrame> strayListener = frame -> { };
    private volatile Disturbance disturbanceListener = (address, heard) -> { };

    /** Hears of an address whose exchange was disturbed (see {@link #onDisturbance}). */
    @FunctionalInterface
    interface Disturbance {
        /**
         * @param heard whether bytes came that start like a reply from it (its address, then the function asked):
         *        a module is there; otherwise it was only being asked when noise came
         */
        void disturbed(int address, boolean heard);
    }
    private long lineQuietSince = System.nanoTime();
    private Pending pending;
    private boolean linkBroken;
    /** Bytes read from the link so far (any: replies, strays, noise, echoes). */
    private long bytesHeard;
    /** Calls in a row that timed out with no byte heard (see {@link #SILENT_CALLS_BEFORE_REOPEN}). */
    private int silentCalls;
    /** Whether the link was opened again for silence and has not been heard since (said once in the log). */
    private boolean reopenedForSilence;
    /**
     * Whether a silent line is opened again: a {@code tcp://} link by default, whose connection may have died
     * without closing; on a local serial port silence means the modules are quiet, and reopening changes nothing.
     */
    private boolean reopenForSilence;
    /** During a call: a frame from an address that owes nothing, answering our request (see readReply). */
    private RtuFrame suspect;
    /** When the first byte of the frame being read came, and in how many reads it has come so far. */
    private long firstByteAt;
    private int reads;
    private final ReplyPacing pacing;

    /**
     * @param describe names an address for messages, e.g. "BumperModule 'Bumper-Sensor' at address 2"
     */
    RtuMaster(SerialLink link, RtuTiming timing, BusTiming busTiming, IntFunction<String> describe) {
        this.link = link;
        this.timing = timing;
        this.frameGapNanos = busTiming.frameGap().equals(BusTiming.AUTO_FRAME_GAP) ? timing.t35Nanos()
                : busTiming.frameGap().toNanos();
        this.interByteNanos = busTiming.interByteTimeout().toNanos();
        this.lateReplyNanos = LATE_REPLY_TIMEOUTS * busTiming.responseTimeout().toNanos();
        this.describe = describe;
        this.echo = new EchoCanceller(link.portName());
        this.pacing = new ReplyPacing(timing.characterNanos());
        this.reopenForSilence = link instanceof TcpSerialLink;
    }

    /** Whether a line silent for {@value #SILENT_CALLS_BEFORE_REOPEN} calls is opened again (tests of other links). */
    synchronized void reopenForSilence(boolean on) {
        reopenForSilence = on;
    }

    /** How fast replies arrive on this line, for a hint when the modules talk at another baud rate. */
    ReplyPacing pacing() {
        return pacing;
    }

    /** How an adapter's echo of each request is handled (default {@link EchoCancellation#AUTO}). */
    void echoCancellation(EchoCancellation mode) {
        echo.mode(mode);
    }

    EchoCancellation echoCancellation() {
        return echo.mode();
    }

    /** Whether the adapter was seen echoing requests. */
    boolean echoDetected() {
        return echo.detected();
    }

    RtuTiming timing() {
        return timing;
    }

    /**
     * Who hears about valid frames that answer no current request: frames from addresses nobody asked at that
     * moment, and late replies discarded as stale (each is proof that its address answers).
     */
    void onStrayFrame(Consumer<RtuFrame> listener) {
        this.strayListener = listener == null ? frame -> { } : listener;
    }

    /**
     * Who hears of addresses whose exchange was disturbed: the address asked when a corrupted or cut-short reply
     * came, and the address byte of bytes that were no whole frame (perhaps a late reply that was cut). Bus
     * exploration asks them again, so that a module is not lost to noise.
     */
    void onDisturbance(Disturbance listener) {
        this.disturbanceListener = listener == null ? (address, heard) -> { } : listener;
    }

    /**
     * Sends a request and returns the response PDU.
     *
     * @throws BusTimeoutException no reply in any attempt
     * @throws BusCrcException only corrupted replies
     * @throws BusProtocolException replies that do not fit the request
     * @throws ModuleRefusedException an exception response
     * @throws BusException the link failed
     */
    synchronized byte[] call(int address, byte[] pdu, CallPolicy policy) {
        settlePending();
        byte[] frame = new RtuFrame(address, pdu).encode();
        FrameLength length = FrameLengths.responseTo(pdu);
        Reply last = null;
        int unanswered = 0;
        long lastUnansweredSent = 0;
        long heardBefore = bytesHeard;
        try {
            for (int attempt = 1; attempt <= policy.attempts(); attempt++) {
                if (attempt > 1) {
                    retries.incrementAndGet();
                }
                long sent = send(address, frame, attempt > 1);
                // a late reply to an earlier attempt of this call answers the same request: it is accepted
                Reply reply = readReply(address, pdu, length, sent + policy.replyTimeout().toNanos(), true);
                if (LOG.isTraceEnabled()) {
                    LOG.trace("{} {} attempt {}/{}: {}", describe.apply(address), FunctionCodes.name(pdu[0]), attempt,
                            policy.attempts(), reply.kind());
                }
                if (reply.kind() == Kind.OK) {
                    answeredByCopy = Arrays.equals(reply.pdu(), pdu);
                    if (answeredByCopy && echo.undecided()) {
                        settleEchoQuestion(address, pdu, length, sent + policy.replyTimeout().toNanos());
                    }
                    return reply.pdu();
                }
                if (reply.kind() == Kind.REFUSED) {
                    throw refused(address, pdu, reply.pdu());
                }
                if (reply.kind() == Kind.ADAPTER_ECHO) {
                    throw failure(address, pdu, reply, attempt, policy); // every retry would be the same
                }
                last = reply;
                if (reply.kind() == Kind.TIMEOUT) {
                    timeouts.incrementAndGet();
                    unanswered++;
                    lastUnansweredSent = sent;
                    if (!policy.retryTimeouts()) {
                        throw failure(address, pdu, reply, attempt, policy);
                    }
                }
            }
            throw failure(address, pdu, last, policy.attempts(), policy);
        } finally {
            // n requests, at most one reply taken per answered attempt: one still owed per unanswered attempt
            owe(address, pdu, unanswered, lastUnansweredSent);
            noteSilence(heardBefore, unanswered > 0 && policy.retryTimeouts());
        }
    }

    /**
     * Counts calls that timed out in a silence nothing broke: after {@value #SILENT_CALLS_BEFORE_REOPEN} of them
     * in a row the link is opened again before the next request. Any byte heard ends the count.
     */
    private void noteSilence(long heardBefore, boolean timedOut) {
        if (bytesHeard != heardBefore) {
            silentCalls = 0;
            if (reopenedForSilence) {
                reopenedForSilence = false;
                LOG.info("{}: the line answers again", link.portName());
            }
            return;
        }
        if (!reopenForSilence || !timedOut || ++silentCalls < SILENT_CALLS_BEFORE_REOPEN) {
            return;
        }
        silentCalls = 0;
        linkBroken = true; // the next request opens the link again
        if (!reopenedForSilence) {
            reopenedForSilence = true;
            LOG.info("{}: no byte on the line in {} calls in a row; opening the link again (and after every {}"
                    + " more silent calls)", link.portName(), SILENT_CALLS_BEFORE_REOPEN, SILENT_CALLS_BEFORE_REOPEN);
        } else {
            LOG.debug("{}: still silent; opening the link again", link.portName());
        }
    }

    /** Reads from the link, counting what was heard. */
    private int read(byte[] into, int offset, int length, Duration wait) throws IOException {
        int n = link.read(into, offset, length, wait);
        if (n > 0) {
            bytesHeard += n;
        }
        return n;
    }

    /**
     * Sends a request and returns at once. Its reply is read (and checked, failures logged) before the next
     * request, because on a half-duplex bus nobody may talk while a module answers.
     */
    synchronized void callQuietly(int address, byte[] pdu, Duration replyTimeout) {
        settlePending();
        long sent = send(address, new RtuFrame(address, pdu).encode(), false);
        pending = new Pending(address, pdu, sent, sent + replyTimeout.toNanos());
    }

    /**
     * Listens for late replies and reports every valid frame to the stray listener: how bus exploration hears late
     * replies to its last requests. Listens at least {@code window}, and on while a reply is owed whose late-reply
     * window is still open ({@value #LATE_REPLY_TIMEOUTS} reply timeouts after its request), so a module answering
     * the last addresses of a scan late is given the same time as any other; it ends early once nothing is owed.
     */
    synchronized void listenForStrays(Duration window, byte[] lastRequestPdu) {
        settlePending();
        long deadline = System.nanoTime() + window.toNanos();
        for (int address = 0; address < owed.length; address++) {
            if (owed[address] > 0 && owedUntil[address] - deadline > 0) {
                deadline = owedUntil[address];
            }
        }
        FrameLength length = FrameLengths.responseTo(lastRequestPdu);
        // frame by frame, so the window can close early once no address owes a reply any more
        while (anyReplyOwed() && readReply(-1, lastRequestPdu, length, deadline).kind() != Kind.TIMEOUT) {
            // each valid frame went to the stray listener; corrupted ones were skipped up to the next silence
        }
    }

    private boolean anyReplyOwed() {
        for (int count : owed) {
            if (count > 0) {
                return true;
            }
        }
        return false;
    }

    BusStatistics statistics() {
        return new BusStatistics(transactions.get(), retries.get(), timeouts.get(), crcErrors.get(),
                exceptionResponses.get(), strayFrames.get(), staleReplies.get());
    }

    /** Writes a frame after the line has been quiet for the frame gap; returns when it has left the wire. */
    private long send(int address, byte[] frame, boolean retry) {
        try {
            reopenIfBroken();
            boolean repliesGivenUp = awaitOwedReplies(address);
            drainStale();
            sleepUntil(lineQuietSince + frameGapNanos);
            link.write(frame);
            echo.sent(frame, retry || repliesGivenUp);
            lastSent = frame;
            answeredByCopy = false;
            transactions.incrementAndGet();
            // the bytes are on their way: the line is busy until they have left at the baud rate
            lineQuietSince = System.nanoTime() + timing.wireNanos(frame.length);
            return lineQuietSince;
        } catch (IOException e) {
            throw linkFailure(address, e);
        }
    }

    private Reply readReply(int address, byte[] request, FrameLength length, long deadline) {
        return readReply(address, request, length, deadline, false);
    }

    /**
     * Reads until the reply from {@code address} or the deadline. Valid frames from other addresses are stray
     * frames (late replies), except, when {@code answersRequest}, a frame that answers this very request from an
     * address that owes nothing, followed by silence from {@code address}: that is a module answering under the
     * wrong address, reported as such instead of a timeout here and a phantom module there.
     */
    private Reply readReply(int address, byte[] request, FrameLength length, long deadline, boolean answersRequest) {
        suspect = null;
        Reply reply = readFrames(address, request, length, deadline, answersRequest);
        RtuFrame misaddressed = suspect;
        suspect = null;
        if (misaddressed != null) {
            if (reply.kind() == Kind.TIMEOUT) {
                // a module answering under the wrong address, or a late reply from that address after its debt was
                // paid (a second reply to a request sent twice): exploration asks that address once more, where
                // silence means nobody, so neither a phantom nor a lost module results
                disturbed(misaddressed.address(), false);
                return new Reply(Kind.WRONG_ADDRESS, misaddressed.pdu(), misaddressed.address());
            }
            stray(misaddressed); // the right module answered too: the other frame was a late reply after all
        }
        return reply;
    }

    private Reply readFrames(int address, byte[] request, FrameLength length, long deadline, boolean answersRequest) {
        int have = 0;
        boolean looked = false;
        try {
            while (true) {
                long wait = have == 0 ? deadline - System.nanoTime() : interByteNanos;
                if (wait <= 0) {
                    byte[] copy = echo.takeAmbiguousCopy();
                    if (copy != null && copy[0] == (byte) address) {
                        // what was dropped as the adapter's echo was the reply itself: this adapter did not echo
                        return classify(address, request, RtuFrame.decode(copy, copy.length).pdu());
                    }
                    // past the deadline before we even looked (a quiet call's reply is read at the next call, and a
                    // busy machine runs threads late): a reply that came in time is in the buffer, so take what is
                    // there once; after a read that waited out the deadline, silence is a timeout
                    if (looked || link.available() == 0) {
                        return Reply.TIMEOUT;
                    }
                }
                Duration readFor = wait <= 0 ? Duration.ZERO : millisAtLeastOne(wait);
                int n = read(buffer, have, buffer.length - have, readFor);
                looked = true;
                if (n > 0) {
                    if (have == 0) {
                        firstByteAt = System.nanoTime();
                        reads = 0;
                    }
                    have += n;
                    reads++;
                    lineQuietSince = System.nanoTime();
                }
                int stripped = echo.strip(buffer, have, n == 0);
                if (stripped == EchoCanceller.NEED_MORE) {
                    continue;
                }
                if (stripped == EchoCanceller.ECHO_WHILE_OFF) {
                    skipUntilSilence();
                    return Reply.ADAPTER_ECHO;
                }
                have = stripped;
                if (have == 0) {
                    continue;
                }
                int expected = length.of(buffer, have);
                if (expected == FrameLength.UNKNOWN && have >= 2
                        && buffer[1] == (byte) FunctionCodes.ENCAPSULATED_INTERFACE) {
                    // an identification reply while something else is asked: a probe's late answer, measured as
                    // such, so that it is not merged with what follows it and lost as one broken piece
                    expected = IDENTIFICATION_REPLY.of(buffer, have);
                }
                int frameLength;
                if (expected > 0 && have >= expected) {
                    frameLength = expected;
                } else if (n == 0 && expected == FrameLength.UNKNOWN) {
                    frameLength = have; // silence ends a frame we cannot measure
                } else if (n == 0 || expected > RtuFrame.MAX_LENGTH || have >= buffer.length) {
                    return corrupt(address, have, "cut short or oversized");
                } else {
                    continue;
                }
                if (!Crc16.isValidFrame(buffer, frameLength)) {
                    return corrupt(address, have, "CRC error");
                }
                RtuFrame frame = RtuFrame.decode(buffer, frameLength);
                pacing.frameReceived(frame.address(), frameLength, reads, lineQuietSince - firstByteAt);
                have -= frameLength;
                System.arraycopy(buffer, frameLength, buffer, 0, have);
                firstByteAt = lineQuietSince;
                if (frame.address() != address) {
                    if (answersRequest && suspect == null && answersUnowed(frame, request)) {
                        suspect = frame; // decided when our own reply comes or does not
                        continue;
                    }
                    stray(frame);
                    continue;
                }
                if (frame.functionCode() == FunctionCodes.ENCAPSULATED_INTERFACE
                        && (request[0] & 0xFF) != FunctionCodes.ENCAPSULATED_INTERFACE) {
                    stray(frame); // a late identification reply of this module: proof of life, not the answer
                    continue;
                }
                if (confirmsAnotherWrite(request, frame.pdu())) {
                    staleWriteConfirmation(frame, request);
                    continue; // ours may still come
                }
                if (have > 0) {
                    salvage(readUntilSilence(have)); // behind our reply: noise, or a late reply of another
                }
                return classify(address, request, frame.pdu());
            }
        } catch (IOException e) {
            throw linkFailure(address, e);
        }
    }

    /**
     * A write (or echo request) was answered by a copy of itself, and whether the adapter echoes is not known yet:
     * the copy was either the reply or the adapter's echo of the request. Waiting once for a second copy tells, so
     * that the real reply can never be taken for the answer to the next request.
     */
    private void settleEchoQuestion(int address, byte[] request, FrameLength length, long deadline) {
        Reply second = readReply(address, request, length, deadline);
        boolean copy = second.kind() == Kind.OK && Arrays.equals(second.pdu(), request);
        echo.settle(copy);
        LOG.debug("{}: {}", link.portName(), copy ? "the adapter echoes requests" : "the adapter does not echo");
    }

    /** Whether {@code frame} looks like the answer to {@code request} from an address that owes no reply. */
    private boolean answersUnowed(RtuFrame frame, byte[] request) {
        int requested = request[0] & 0xFF;
        int function = frame.functionCode();
        boolean sameFunction = function == requested || function == (requested | FunctionCodes.EXCEPTION_BIT);
        boolean owes = frame.address() < owed.length && owed[frame.address()] > 0
                || pending != null && pending.address() == frame.address();
        return sameFunction && frame.address() != 0 && !owes;
    }

    /**
     * Whether {@code response} confirms a write, but another one than {@code request}: a write is confirmed by
     * repeating its function code, its first register or coil and its value (one item) or count (several), so a
     * confirmation that repeats something else is the late answer to an earlier write, however late it comes.
     */
    static boolean confirmsAnotherWrite(byte[] request, byte[] response) {
        int function = request[0] & 0xFF;
        boolean write = function == FunctionCodes.WRITE_SINGLE_COIL || function == FunctionCodes.WRITE_SINGLE_REGISTER
                || function == FunctionCodes.WRITE_MULTIPLE_COILS || function == FunctionCodes.WRITE_MULTIPLE_REGISTERS;
        return write && (response[0] & 0xFF) == function && request.length >= 5
                && !(response.length == 5 && Arrays.equals(request, 0, 5, response, 0, 5));
    }

    /** A late confirmation of an earlier write: discarded, no longer owed, and heard of as proof of life. */
    private void staleWriteConfirmation(RtuFrame frame, byte[] request) {
        int address = frame.address();
        staleReplies.incrementAndGet();
        if (address < owed.length && owed[address] > 0) {
            owed[address]--;
        }
        strayListener.accept(frame);
        LOG.debug("{} on {}: discarded a late confirmation of an earlier write while waiting for {}: {}",
                describe.apply(address), link.portName(), RtuFrame.hex(request, request.length),
                RtuFrame.hex(frame.pdu(), frame.pdu().length));
    }

    private Reply classify(int address, byte[] request, byte[] response) {
        int requested = request[0] & 0xFF;
        int answered = response[0] & 0xFF;
        if (answered == requested) {
            return new Reply(Kind.OK, response);
        }
        if (answered == (requested | FunctionCodes.EXCEPTION_BIT) && response.length == 2) {
            exceptionResponses.incrementAndGet();
            return new Reply(Kind.REFUSED, response);
        }
        return new Reply(Kind.WRONG_FUNCTION, response);
    }

    private ModuleRefusedException refused(int address, byte[] request, byte[] response) {
        int requested = request[0] & 0xFF;
        int code = response[1] & 0xFF;
        return new ModuleRefusedException(link.portName(), address, describe.apply(address) + " on "
                + link.portName() + " refused " + FunctionCodes.name(requested) + " with Modbus exception "
                + code + " (" + ExceptionCodes.name(code) + ")", requested, code);
    }

    /**
     * A reply that is no valid frame: read on to the next silence, then look through everything for whole frames
     * (a late reply from another module may be among the bytes) and report who may have been cut short, so that a
     * scan can ask those addresses again instead of losing them.
     */
    private Reply corrupt(int address, int have, String what) throws IOException {
        crcErrors.incrementAndGet();
        int total = readUntilSilence(have);
        LOG.debug("{}: corrupted reply ({}): {}", describe.apply(address), what, RtuFrame.hex(buffer, total));
        if (address > 0) {
            disturbed(address, false);
        }
        salvage(total);
        return Reply.CORRUPT;
    }

    /** Reads on after {@code have} bytes until the line is silent; returns how many bytes the buffer holds. */
    private int readUntilSilence(int have) throws IOException {
        long giveUp = System.nanoTime() + MAX_RESYNC_NANOS;
        int total = have;
        int n;
        // a full buffer ends the reading: what follows stays on the link for the next read, nothing is dropped
        while (total < buffer.length && System.nanoTime() < giveUp
                && (n = read(buffer, total, buffer.length - total, millisAtLeastOne(interByteNanos))) > 0) {
            total += n;
            lineQuietSince = System.nanoTime();
        }
        return total;
    }

    /**
     * Finds whole frames among {@code have} bytes that failed as one (resynchronising byte by byte, with the
     * lengths of replies to the last request) and reports them as stray frames; the address byte of each piece
     * that is no frame goes to the disturbance listener.
     */
    private void salvage(int have) {
        if (lastSent == null) {
            return;
        }
        FrameLength lengths = FrameLengths.responseTo(Arrays.copyOfRange(lastSent, 1, lastSent.length - 2));
        int start = 0;
        boolean pieceReported = false;
        while (start < have) {
            int address = buffer[start] & 0xFF;
            if (start + 1 == have) {
                if (!pieceReported) {
                    disturbed(address, false); // a piece of one byte: perhaps a reply cut after its address
                }
                break;
            }
            if (address >= 1 && address <= 247) {
                if (start + 4 <= have) {
                    byte[] rest = Arrays.copyOfRange(buffer, start, have);
                    int length = wholeFrame(rest, lengths);
                    if (length > 0) {
                        stray(RtuFrame.decode(rest, length));
                        start += length;
                        pieceReported = false;
                        continue;
                    }
                }
                if (startsLikeAReply(start, have)) {
                    disturbed(address, true); // the start of a reply that was cut: a module is there
                } else if (!pieceReported) {
                    disturbed(address, false); // perhaps
                }
                pieceReported = true;
            }
            start++;
        }
    }

    /**
     * The length of the whole frame at the start of {@code bytes}, measured as a reply to the last request or,
     * failing that, as an identification reply (a late answer to a probe may come while anything else is asked);
     * 0 when there is none.
     */
    private static int wholeFrame(byte[] bytes, FrameLength lastRequest) {
        for (FrameLength lengths : new FrameLength[] {lastRequest, IDENTIFICATION_REPLY}) {
            int length = lengths.of(bytes, bytes.length);
            if (length >= 4 && length <= bytes.length && Crc16.isValidFrame(bytes, length)) {
                return length;
            }
        }
        return 0;
    }

    /**
     * Whether the bytes at {@code start} begin like a reply to the last request (an address, then its function
     * code or its exception, and for identification the MEI type 0x0E, so that noise rarely passes) or like an
     * identification reply, the answer to a probe that may come late while anything else is asked.
     */
    private boolean startsLikeAReply(int start, int have) {
        if (start + 2 < have && buffer[start + 1] == (byte) FunctionCodes.ENCAPSULATED_INTERFACE
                && (buffer[start + 2] & 0xFF) == FunctionCodes.MEI_READ_DEVICE_ID) {
            return true;
        }
        int requested = lastSent[1] & 0xFF;
        if ((buffer[start + 1] & 0x7F) != (requested & 0x7F)) {
            return false;
        }
        boolean exception = (buffer[start + 1] & FunctionCodes.EXCEPTION_BIT) != 0;
        return requested != FunctionCodes.ENCAPSULATED_INTERFACE || exception || start + 2 >= have
                || (buffer[start + 2] & 0xFF) == FunctionCodes.MEI_READ_DEVICE_ID;
    }

    private void disturbed(int address, boolean heard) {
        if (address >= 1 && address <= 247) {
            disturbanceListener.disturbed(address, heard);
        }
    }

    private void settlePending() {
        if (pending == null) {
            return;
        }
        Pending quiet = pending;
        pending = null;
        Reply reply = readReply(quiet.address(), quiet.pdu(), FrameLengths.responseTo(quiet.pdu()),
                quiet.deadline());
        if (reply.kind() == Kind.TIMEOUT) {
            timeouts.incrementAndGet();
            owe(quiet.address(), quiet.pdu(), 1, quiet.sent());
        }
        if (reply.kind() == Kind.REFUSED) {
            LOG.warn("quiet call: {}", refused(quiet.address(), quiet.pdu(), reply.pdu()).getMessage());
        } else if (reply.kind() != Kind.OK) {
            LOG.warn("{} on {}: quiet {} got no valid reply ({})", describe.apply(quiet.address()),
                    link.portName(), FunctionCodes.name(quiet.pdu()[0]), reply.kind());
        }
    }

    /** Records replies still owed by {@code address}: {@code count} requests, the last sent at {@code sent}. */
    private void owe(int address, byte[] request, int count, long sent) {
        if (count > 0) {
            owed[address] += count;
            owedRequest[address] = request;
            owedUntil[address] = sent + lateReplyNanos;
        }
    }

    /**
     * Before {@code address} is asked anything new, its owed late replies are waited for and discarded, so none of
     * them can pass for the answer to the new request; the wait ends as soon as all have come, at the latest when
     * the late-reply window closes. Frames from other addresses meanwhile are stray frames as usual.
     *
     * @return whether some owed replies did not come (they may still come, later than the window)
     */
    private boolean awaitOwedReplies(int address) throws IOException {
        if (owed[address] == 0) {
            return false; // the normal path: nothing to wait for
        }
        boolean givenUp = false;
        byte[] request = owedRequest[address];
        FrameLength length = FrameLengths.responseTo(request);
        while (owed[address] > 0) {
            Reply reply = readReply(address, request, length, owedUntil[address]);
            if (reply.kind() == Kind.TIMEOUT) {
                LOG.debug("{} on {}: {} owed replies did not come within the late-reply window",
                        describe.apply(address), link.portName(), owed[address]);
                givenUp = true;
                break;
            }
            if (reply.kind() != Kind.CORRUPT) { // a corrupted frame may be noise: the reply may still come
                owed[address]--;
                staleReplies.incrementAndGet();
                // too late for its request, but proof that the address answers: exploration must hear of it
                strayListener.accept(new RtuFrame(address, reply.pdu()));
                LOG.debug("{} on {}: discarded a stale reply to an earlier {}: {}", describe.apply(address),
                        link.portName(), FunctionCodes.name(request[0]), RtuFrame.hex(reply.pdu(),
                                reply.pdu().length));
            }
        }
        owed[address] = 0;
        owedRequest[address] = null;
        return givenUp;
    }

    /**
     * Bytes waiting before a request belong to nobody's reply any more: report valid frames, drop the rest. A late
     * reply may be arriving at this very moment, so reading goes on until the line falls silent: cutting the
     * frame would lose it and turn its tail into a CRC error for the next request.
     */
    private void drainStale() throws IOException {
        if (link.available() <= 0) {
            return;
        }
        int have = 0;
        long giveUp = System.nanoTime() + MAX_RESYNC_NANOS;
        while (have < buffer.length && System.nanoTime() < giveUp) {
            int n = read(buffer, have, buffer.length - have, millisAtLeastOne(interByteNanos));
            if (n <= 0) {
                break; // silence: the frame, if it is one, is complete
            }
            have += n;
        }
        if (have == 0) {
            return;
        }
        if (answeredByCopy && have == lastSent.length && Arrays.equals(buffer, 0, have, lastSent, 0, have)) {
            echo.staleFrameEqualsLastRequest(); // the real reply of a write, after its echo passed for it
            LOG.debug("dropped a late copy of the last request on {}", link.portName());
        } else if (Crc16.isValidFrame(buffer, have)) {
            stray(RtuFrame.decode(buffer, have));
        } else {
            LOG.debug("stale bytes on {}: {}", link.portName(), RtuFrame.hex(buffer, have));
            salvage(have);
        }
        lineQuietSince = System.nanoTime();
    }

    private void skipUntilSilence() throws IOException {
        byte[] scratch = new byte[RtuFrame.MAX_LENGTH];
        long giveUp = System.nanoTime() + MAX_RESYNC_NANOS;
        while (System.nanoTime() < giveUp
                && read(scratch, 0, scratch.length, millisAtLeastOne(interByteNanos)) > 0) {
            lineQuietSince = System.nanoTime();
        }
    }

    private void stray(RtuFrame frame) {
        strayFrames.incrementAndGet();
        if (frame.address() < owed.length && owed[frame.address()] > 0) {
            owed[frame.address()]--; // a late reply to a request that timed out: no longer owed
        }
        LOG.debug("stray frame on {}: {}", link.portName(), frame);
        strayListener.accept(frame);
    }

    private void reopenIfBroken() throws IOException {
        if (linkBroken) {
            link.close();
            link.open();
            linkBroken = false;
        }
    }

    private BusException failure(int address, byte[] request, Reply last, int attempts, CallPolicy policy) {
        String who = describe.apply(address) + " on " + link.portName();
        String function = FunctionCodes.name(request[0]);
        String tries = attempts == 1 ? "1 attempt" : attempts + " attempts";
        return switch (last.kind()) {
            case TIMEOUT -> new BusTimeoutException(link.portName(), address, who + ": no reply to " + function
                    + " within " + millis(policy.replyTimeout()) + " (" + tries + ")");
            case CORRUPT -> new BusCrcException(link.portName(), address, who + ": corrupted reply (CRC error) to "
                    + function + " (" + tries + ")");
            case ADAPTER_ECHO -> new AdapterEchoException(link.portName(), address, who + ": "
                    + EchoCanceller.hint());
            case WRONG_ADDRESS -> new BusProtocolException(link.portName(), address, who + ": the reply to "
                    + function + " came from address " + last.from() + " (" + tries + "): a module listens at address "
                    + address + " but answers as address " + last.from() + "; check its address setting");
            default -> new BusProtocolException(link.portName(), address, who + ": unexpected reply to " + function
                    + ": " + RtuFrame.hex(last.pdu(), last.pdu().length) + " (" + tries + ")");
        };
    }

    private BusException linkFailure(int address, IOException e) {
        linkBroken = true;
        return new BusException(link.portName(), address, describe.apply(address) + " on " + link.portName()
                + ": the link failed: " + e.getMessage(), e);
    }

    private static String millis(Duration duration) {
        return duration.toNanos() % 1_000_000 == 0 ? duration.toMillis() + " ms"
                : String.format("%.1f ms", duration.toNanos() / 1e6);
    }

    /** Link reads wait in whole milliseconds, and 0 would mean "do not wait": round up. */
    private static Duration millisAtLeastOne(long nanos) {
        return Duration.ofMillis(Math.max(1, (nanos + 999_999) / 1_000_000));
    }

    private static void sleepUntil(long nanoTime) {
        long left;
        while ((left = nanoTime - System.nanoTime()) > 0) {
            LockSupport.parkNanos(left);
        }
    }
}
