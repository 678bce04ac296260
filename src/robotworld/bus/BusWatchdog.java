package robotworld.bus;

import java.time.Duration;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Arms the communication watchdogs of modules on one bus and keeps them fed while the program lives. A module's
 * watchdog (see {@code docs/bus.md}) is a holding register, {@link #TIMEOUT_REGISTER}, with a timeout in ms
 * (0 = off); a module that hears no valid frame addressed to it for that long goes to its safe state by itself
 * (a motor module stops its motors) and sets discrete input {@link #TRIPPED_INPUT} until the timeout register is
 * written again. So when the program dies hard (SIGKILL, a crash, a pulled cable), its modules stop anyway.
 *
 * <p>Every exchange with a module feeds its watchdog, so a busy bus costs nothing extra. A module that has not
 * been spoken to for a quarter of its timeout gets a heartbeat: a read of its tripped input (one request of 8
 * bytes, one reply of 6), which also tells whether it tripped meanwhile (the program was frozen too long); then
 * the listener is told and the watchdog armed again. One daemon thread per bus, started with the first armed
 * module and ended by {@link RS485Bus#close()}.
 */
public final class BusWatchdog implements AutoCloseable {

    /** Holding register: the watchdog timeout in ms, 0 = off. */
    public static final int TIMEOUT_REGISTER = 0x0100;
    /** Discrete input: 1 = the watchdog tripped and the module went to its safe state. */
    public static final int TRIPPED_INPUT = 0x0100;

    private static final Logger LOG = LoggerFactory.getLogger(BusWatchdog.class);
    private static final long LONGEST_TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(100);
    private static final long SHORTEST_TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(2);

    private record Armed(int address, int millis, Consumer<String> onTrip, Consumer<String> onFoundTripped) {
    }

    /** What {@code onFoundTripped} is told when a module is found tripped as it is armed. */
    public static final String FOUND_TRIPPED = "stopped by its watchdog while no program fed it";

    private final RS485Bus bus;
    private final AtomicLongArray lastExchange = new AtomicLongArray(248);
    private final Map<Integer, Armed> armed = new ConcurrentHashMap<>();
    /** Modules that did not answer when they were to be armed: tried again every second. */
    private final Map<Integer, Armed> pending = new ConcurrentHashMap<>();
    private long lastPendingTry;
    private final AtomicLong heartbeats = new AtomicLong();
    private final AtomicLong failedHeartbeats = new AtomicLong();
    private Thread feeder;
    private volatile boolean closed;

    BusWatchdog(RS485Bus bus) {
        this.bus = bus;
    }

    /** A module answered (or refused) a request: its watchdog was fed. Called for every exchange. */
    void exchanged(int address) {
        lastExchange.set(address, System.nanoTime());
    }

    /**
     * Arms the watchdog of the module at {@code address}, with nobody told when it is found tripped as it is armed
     * ({@link #arm(int, Duration, Consumer, Consumer)}).
     *
     * @param timeout 10..65535 ms
     * @param onTrip  told, with a sentence, whenever the module's watchdog is found tripped while this program feeds it
     * @return false when the module has no watchdog (it refuses the register); it is then logged once
     */
    public boolean arm(int address, Duration timeout, Consumer<String> onTrip) {
        return arm(address, timeout, onTrip, detail -> { });
    }

    /**
     * Arms the watchdog of the module at {@code address}. That it had tripped before (its previous master went
     * silent or died: it stopped by itself) is logged and told to {@code onFoundTripped}, so that the stop is
     * recorded and shown; it happened before this program, which has commanded nothing yet, so nobody is owed a
     * notice. A module that does not answer now is logged and armed as soon as it answers (tried every second), so a
     * program does not fail to start for a module that is off for a moment.
     *
     * @param timeout        10..65535 ms
     * @param onTrip         told, with a sentence, whenever the module's watchdog is found tripped while this
     *                       program feeds it
     * @param onFoundTripped told, with {@link #FOUND_TRIPPED}, when the module is found tripped as it is armed
     * @return false when the module has no watchdog (it refuses the register); it is then logged once
     */
    public boolean arm(int address, Duration timeout, Consumer<String> onTrip, Consumer<String> onFoundTripped) {
        Objects.requireNonNull(onTrip, "onTrip");
        Objects.requireNonNull(onFoundTripped, "onFoundTripped");
        long millis = timeout.toMillis();
        if (millis < 10 || millis > 65_535) {
            throw new IllegalArgumentException("a watchdog timeout is 10..65535 ms, was " + millis);
        }
        Armed entry = new Armed(address, (int) millis, onTrip, onFoundTripped);
        try {
            return armNow(entry);
        } catch (BusException noAnswer) {
            LOG.warn("{} on {} did not answer when its communication watchdog was to be armed ({}); trying again "
                    + "every second", bus.describe(address), bus.portName(), noAnswer.getMessage());
            pending.put(address, entry);
            startFeeder();
            return true;
        }
    }

    /**
     * Arms the module's watchdog now.
     *
     * @return false when it has none
     * @throws BusException when it does not answer
     */
    private boolean armNow(Armed entry) {
        int address = entry.address();
        boolean trippedBefore;
        try {
            trippedBefore = bus.readDiscreteInputs(address, TRIPPED_INPUT, 1)[0];
            bus.writeRegister(address, TIMEOUT_REGISTER, entry.millis());
        } catch (ModuleRefusedException refused) {
            LOG.warn("{} on {} has no communication watchdog ({}): it will not stop by itself if this program dies",
                    bus.describe(address), bus.portName(), refused.getMessage());
            return false;
        }
        armed.put(address, entry);
        startFeeder();
        if (trippedBefore) {
            LOG.info("{} on {}: its communication watchdog had tripped before this program armed it (its previous "
                    + "master went silent or died)", bus.describe(address), bus.portName());
            try {
                entry.onFoundTripped().accept(FOUND_TRIPPED);
            } catch (RuntimeException e) {
                LOG.warn("recording the earlier trip of {} failed: {}", bus.describe(address), e.toString());
            }
        }
        return true;
    }

    /** Stops feeding the module's watchdog; it stays armed in the module, which stops when the timeout runs out. */
    public void release(int address) {
        armed.remove(address);
        pending.remove(address);
    }

    /** The timeout the watchdog of {@code address} was armed with, in ms; 0 when not armed by this program. */
    public int armedMillis(int address) {
        Armed entry = armed.get(address);
        return entry == null ? 0 : entry.millis();
    }

    /** Heartbeats sent so far (exchanges made only to feed a watchdog). */
    public long heartbeats() {
        return heartbeats.get();
    }

    /** Heartbeats that failed (no reply). */
    public long failedHeartbeats() {
        return failedHeartbeats.get();
    }

    /** Ends the feeding thread. The modules' watchdogs stay armed: they stop the modules when their time runs out. */
    @Override
    public void close() {
        Thread thread;
        synchronized (this) {
            closed = true;
            thread = feeder;
        }
        if (thread != null && thread != Thread.currentThread()) {
            thread.interrupt();
            try {
                thread.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private synchronized void startFeeder() {
        if (feeder != null || closed) {
            return;
        }
        feeder = new Thread(this::feed, "bus-watchdog " + bus.portName());
        feeder.setDaemon(true);
        feeder.start();
    }

    private void feed() {
        while (!closed) {
            long tick = LONGEST_TICK_NANOS;
            for (Armed entry : armed.values()) {
                tick = Math.min(tick, TimeUnit.MILLISECONDS.toNanos(entry.millis()) / 20);
            }
            LockSupport.parkNanos(Math.max(SHORTEST_TICK_NANOS, tick));
            if (closed || Thread.currentThread().isInterrupted()) {
                return;
            }
            armPending();
            for (Armed entry : armed.values()) {
                long idle = System.nanoTime() - lastExchange.get(entry.address());
                // a quarter: three quarters of the timeout are left for a feeding thread that is slow to get the CPU
                if (idle >= TimeUnit.MILLISECONDS.toNanos(entry.millis()) / 4) {
                    heartbeat(entry);
                }
            }
        }
    }

    private void armPending() {
        if (pending.isEmpty() || System.nanoTime() - lastPendingTry < TimeUnit.SECONDS.toNanos(1)) {
            return;
        }
        lastPendingTry = System.nanoTime();
        for (Armed entry : pending.values()) {
            try {
                boolean has = armNow(entry);
                pending.remove(entry.address());
                if (has) {
                    LOG.info("{} on {} answers again: its communication watchdog is armed", bus.describe(entry.address()),
                            bus.portName());
                }
            } catch (RuntimeException stillSilent) {
                // tried again in a second
            }
        }
    }

    private void heartbeat(Armed entry) {
        try {
            boolean tripped = bus.readDiscreteInputs(entry.address(), TRIPPED_INPUT, 1)[0];
            heartbeats.incrementAndGet();
            if (tripped) {
                entry.onTrip().accept("its communication watchdog tripped: no frame from this program for over "
                        + entry.millis() + " ms");
                bus.writeRegister(entry.address(), TIMEOUT_REGISTER, entry.millis());
            }
        } catch (RuntimeException e) { // the feeder must not die: the modules would stop
            if (closed) {
                return;
            }
            if (failedHeartbeats.incrementAndGet() % 100 == 1) {
                LOG.warn("watchdog heartbeat to {} on {} failed ({} so far): {}", bus.describe(entry.address()),
                        bus.portName(), failedHeartbeats.get(), e.toString());
            }
        }
    }
}
