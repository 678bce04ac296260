package robotworld.sim.robot;

import java.time.Duration;
import java.util.Random;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Faults a simulated module can show, changeable while it runs: silence, corrupted replies (wrong CRC), slow
 * replies, refusing every request with an exception code, and reporting "not running" as its status.
 */
public final class ModuleFaults {

    private final AtomicInteger corruptNext = new AtomicInteger();
    private final Random random;
    private volatile boolean silent;
    private volatile double crcErrorRate;
    private volatile Duration replyDelay = Duration.ZERO;
    private volatile Duration trickle = Duration.ZERO;
    private volatile int refuseWith;
    private volatile boolean stopped;
    private volatile int answerAs;
    private final java.util.Set<Integer> muted = java.util.concurrent.ConcurrentHashMap.newKeySet();

    /** Faults whose random CRC errors follow {@code seed}, so a run can be repeated. */
    public ModuleFaults(long seed) {
        this.random = new Random(seed);
    }

    /** A silent module never answers (as if unplugged, but still configured). */
    public ModuleFaults silent(boolean value) {
        silent = value;
        return this;
    }

    /** Corrupts the CRC of the next {@code count} replies. */
    public ModuleFaults corruptNextReplies(int count) {
        corruptNext.set(Math.max(0, count));
        return this;
    }

    /** Corrupts each reply's CRC with this probability (0..1). */
    public ModuleFaults crcErrorRate(double rate) {
        if (!(rate >= 0 && rate <= 1)) {
            throw new IllegalArgumentException("CRC error rate must be 0..1, was " + rate);
        }
        crcErrorRate = rate;
        return this;
    }

    /** Delays every reply by this much, on top of the line timing. */
    public ModuleFaults replyDelay(Duration delay) {
        if (delay.isNegative()) {
            throw new IllegalArgumentException("reply delay must not be negative, was " + delay);
        }
        replyDelay = delay;
        return this;
    }

    /** Sends replies one byte at a time, this far apart (a slow gateway or a busy module); zero = as the line goes. */
    public ModuleFaults trickle(Duration perByte) {
        if (perByte.isNegative()) {
            throw new IllegalArgumentException("trickle must not be negative, was " + perByte);
        }
        trickle = perByte;
        return this;
    }

    public Duration trickle() {
        return trickle;
    }

    /** Refuses every request with this Modbus exception code (0 = answer normally). */
    public ModuleFaults refuseWith(int exceptionCode) {
        if (exceptionCode < 0 || exceptionCode > 255) {
            throw new IllegalArgumentException("exception code must be 0..255, was " + exceptionCode);
        }
        refuseWith = exceptionCode;
        return this;
    }

    /** Reports run indicator 0x00 ("not running") in Report Server ID. */
    public ModuleFaults stopped(boolean value) {
        stopped = value;
        return this;
    }

    /** Names {@code address} instead of its own in every reply (a module set to the wrong address); 0 = its own. */
    public ModuleFaults answerAs(int address) {
        if (address < 0 || address > 247) {
            throw new IllegalArgumentException("address must be 0 (its own) or 1..247, was " + address);
        }
        answerAs = address;
        return this;
    }

    /** The address replies name instead of the module's own, or 0. */
    public int answerAs() {
        return answerAs;
    }

    /** Never answers requests with this function code (e.g. 0x11: identifies itself, then fails its status). */
    public ModuleFaults mute(int functionCode) {
        muted.add(functionCode);
        return this;
    }

    /** Answers every function again (undoes {@link #mute}). */
    public ModuleFaults unmuteAll() {
        muted.clear();
        return this;
    }

    /** Whether requests with this function code go unanswered (silent module or muted function). */
    public boolean ignores(int functionCode) {
        return silent || muted.contains(functionCode);
    }

    public boolean isSilent() {
        return silent;
    }

    public Duration replyDelay() {
        return replyDelay;
    }

    public int refusal() {
        return refuseWith;
    }

    public boolean isStopped() {
        return stopped;
    }

    /** Whether the reply about to go out is to be corrupted; consumes one "corrupt next". */
    boolean takeCorruption() {
        if (corruptNext.getAndUpdate(n -> Math.max(0, n - 1)) > 0) {
            return true;
        }
        double rate = crcErrorRate;
        if (rate <= 0) {
            return false;
        }
        synchronized (random) {
            return random.nextDouble() < rate;
        }
    }
}
