package robotworld.explorer.monitor;

import java.io.PrintWriter;
import java.time.Instant;
import java.time.LocalTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.StringJoiner;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import robotworld.explorer.monitor.logic.xvsm.AnswerText;
import robotworld.observe.AnswerSeen;
import robotworld.observe.Gap;
import robotworld.observe.Liveness;
import robotworld.observe.ModuleRef;
import robotworld.observe.ReplayMark;
import robotworld.observe.WorldObserver;
import robotworld.observe.WorldTap;
import robotworld.safety.StopRecord;
import robotworld.safety.StopWatcher;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/**
 * Monitoring as text, for machines without a display. It works for every module type, known or not, because it
 * only reads the common answer layout. Three ways to print:
 * <ul>
 *   <li>every call: one line per answer, {@code time participant module function value (host)};</li>
 *   <li>{@link Options#changesOnly() changes only}: a line only when a module function's value (per channel)
 *       differs from the last one printed, so a polling program does not flood the terminal;</li>
 *   <li>{@link Options#compact() compact}: one line per second with each module's number of calls and last
 *       answer, and who is alive.</li>
 * </ul>
 * Motor speeds are shown as -1..1 of full speed, as everywhere outside the wire. A stop of one of the world's
 * actuators is a line in every mode: {@code time participant module STOPPED by ... (cause: reason): what was done}.
 */
public final class ConsoleMonitor implements AutoCloseable, WorldObserver {

    /**
     * How to print.
     *
     * @param changesOnly only lines whose value changed
     * @param compact     one summary line per second instead of a line per call
     */
    public record Options(boolean changesOnly, boolean compact) {
        /** A line per call. */
        public static Options everyCall() {
            return new Options(false, false);
        }
    }

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS");
    private static final DateTimeFormatter SECOND = DateTimeFormatter.ofPattern("HH:mm:ss");

    private final PrintWriter out;
    private final Options options;
    private final WorldTap tap;
    private final int moduleCount;
    private final Map<String, String> lastValues = new HashMap<>();
    private final Map<ModuleRef, int[]> callsThisSecond = new LinkedHashMap<>();
    private final Map<ModuleRef, String> lastAnswer = new LinkedHashMap<>();
    private final Map<String, Liveness.State> liveness = new LinkedHashMap<>();
    private final ScheduledExecutorService ticker;
    private final java.util.Set<String> watched = new java.util.HashSet<>();
    private StopWatcher stops;

    /** Prints every call of every module of {@code world}; see {@link #ConsoleMonitor(MonitoredWorld, Capi, PrintWriter, Options)}. */
    public ConsoleMonitor(MonitoredWorld world, Capi space, PrintWriter out) {
        this(world, space, out, Options.everyCall());
    }

    /**
     * Starts watching every module of {@code world} in {@code space}.
     *
     * @throws robotworld.space.SpaceException when the space cannot be reached
     */
    public ConsoleMonitor(MonitoredWorld world, Capi space, PrintWriter out, Options options) {
        this.out = out;
        this.options = options;
        this.moduleCount = world.moduleCount();
        for (MonitoredParticipant participant : world.participants()) {
            liveness.put(participant.name(), Liveness.State.UNKNOWN);
            for (MonitoredModule module : participant.modules()) {
                callsThisSecond.put(module.ref(), new int[1]);
                watched.add(module.label());
            }
        }
        ReplayMark.find(space).ifPresent(mark -> print("# " + mark.label() + ": a recorded run; nothing is driven"));
        tap = new WorldTap(space, world.layout());
        tap.add(this);
        try {
            tap.start();
            stops = StopWatcher.start(space, this::stopped);
        } catch (RuntimeException e) {
            tap.close();
            throw e;
        }
        if (options.compact()) {
            ticker = Executors.newSingleThreadScheduledExecutor(task -> {
                Thread thread = new Thread(task, "console-monitor-second");
                thread.setDaemon(true);
                return thread;
            });
            long delay = 1000 - System.currentTimeMillis() % 1000;
            ticker.scheduleAtFixedRate(this::printSecond, delay, 1000, TimeUnit.MILLISECONDS);
        } else {
            ticker = null;
        }
    }

    /** How many modules are watched. */
    public int moduleCount() {
        return moduleCount;
    }

    @Override
    public void close() {
        if (ticker != null) {
            ticker.shutdownNow();
        }
        tap.close();
        if (stops != null) {
            stops.close();
        }
    }

    private void stopped(StopRecord record) {
        if (watched.contains(record.where())) {
            print(stopLine(record));
        }
    }

    /** The line for a stop of one of the world's actuators. */
    static String stopLine(StopRecord record) {
        return String.format(Locale.ROOT, "%-12s  %-18s %-18s STOPPED by %s (%s: %s): %s",
                TIME.format(LocalTime.ofInstant(record.at(), ZoneId.systemDefault())), record.participant(),
                record.module(), record.stoppedBy(), record.cause().wireName(), record.reason(), record.action());
    }

    /** The line for one answer of {@code module}; {@code when} null for one found when monitoring started. */
    static String line(Instant when, MonitoredModule module, CallTuple answer) {
        return line(when, module.ref(), answer);
    }

    private static String line(Instant when, ModuleRef module, CallTuple answer) {
        return String.format(Locale.ROOT, "%-12s  %-18s %-18s %-22s %s  (%s)",
                when == null ? "earlier" : TIME.format(LocalTime.ofInstant(when, ZoneId.systemDefault())),
                module.participant(), module.name(), AnswerText.function(answer),
                AnswerText.value(module.moduleClass(), answer), AnswerText.host(answer));
    }

    @Override
    public synchronized void answerSeen(AnswerSeen event) {
        String value = AnswerText.value(event.module().moduleClass(), event.answer());
        if (options.compact()) {
            if (!event.earlier()) {
                callsThisSecond.get(event.module())[0]++;
            }
            lastAnswer.put(event.module(), AnswerText.function(event.answer()) + " " + value);
            return;
        }
        if (options.changesOnly()) {
            // one "last value" per module function and channel (the first value is the motor, servo or sensor number)
            String channel = value.isEmpty() ? "" : value.split("[\\s,<>]+", 3)[value.startsWith("<") ? 1 : 0];
            String key = event.module().label() + " " + AnswerText.function(event.answer()) + " " + channel;
            if (value.equals(lastValues.put(key, value))) {
                return;
            }
        }
        print(line(event.earlier() ? null : event.at(), event.module(), event.answer()));
    }

    @Override
    public synchronized void liveness(Liveness event) {
        liveness.put(event.participant(), event.state());
    }

    @Override
    public void gap(Gap gap) {
        print("# " + (gap.module() == null ? "" : gap.module().label() + ": ") + gap.why());
    }

    /** The compact mode's line for the second that just ended. */
    private void printSecond() {
        String line;
        synchronized (this) {
            StringJoiner calls = new StringJoiner("; ");
            for (Map.Entry<ModuleRef, int[]> entry : callsThisSecond.entrySet()) {
                int count = entry.getValue()[0];
                entry.getValue()[0] = 0;
                if (count > 0) {
                    calls.add(entry.getKey().name() + " " + count + (count == 1 ? " call" : " calls") + ", last "
                            + lastAnswer.get(entry.getKey()).strip());
                }
            }
            Map<Liveness.State, List<String>> byState = new LinkedHashMap<>();
            liveness.forEach((name, state) -> byState.computeIfAbsent(state, s -> new ArrayList<>()).add(name));
            StringJoiner alive = new StringJoiner("; ");
            byState.forEach((state, names) -> alive.add(words(state) + ": " + String.join(", ", names)));
            line = SECOND.format(LocalTime.now()) + "  " + (calls.length() == 0 ? "no calls" : calls.toString())
                    + "  | " + alive;
        }
        print(line);
    }

    private static String words(Liveness.State state) {
        return switch (state) {
            case ALIVE -> "alive";
            case SILENT -> "SILENT";
            case ENDED -> "ended";
            case NOT_ANSWERING -> "NOT ANSWERING";
            case UNKNOWN -> "quiet";
        };
    }

    private void print(String line) {
        synchronized (out) {
            out.println(line);
            out.flush();
        }
    }
}
