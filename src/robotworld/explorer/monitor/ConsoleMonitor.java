package robotworld.explorer.monitor;

import java.io.PrintWriter;
import java.time.Instant;
import java.time.LocalTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robotworld.explorer.monitor.logic.xvsm.AnswerListener;
import robotworld.explorer.monitor.logic.xvsm.AnswerText;
import robotworld.explorer.monitor.logic.xvsm.AnswerWatcher;
import robotworld.safety.StopRecord;
import robotworld.safety.StopWatcher;
import robotworld.observe.ReplayMark;
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/**
 * Monitoring as text, for machines without a display: one line per answer of any module of the world,
 * {@code time participant module function value (host)}. Works for every module type, known or not, because it
 * only reads the common answer layout. A stop of one of the world's actuators is a line too:
 * {@code time participant module STOPPED by ... (cause: reason): what was done}.
 */
public final class ConsoleMonitor implements AutoCloseable {

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS");

    private final PrintWriter out;
    private final List<AnswerWatcher> watchers = new ArrayList<>();
    private final java.util.Set<String> modules = new java.util.HashSet<>();
    private StopWatcher stops;

    /**
     * Starts watching every module of {@code world} in {@code space}.
     *
     * @throws robotworld.space.SpaceException when the space cannot be reached
     */
    public ConsoleMonitor(MonitoredWorld world, Capi space, PrintWriter out) {
        this.out = out;
        ReplayMark.find(space).ifPresent(mark -> print("# " + mark.label() + ": a recorded run; nothing is driven"));
        try {
            for (MonitoredParticipant participant : world.participants()) {
                for (MonitoredModule module : participant.modules()) {
                    watchers.add(new AnswerWatcher(space, module.participant(), module.moduleName(),
                            new Printer(module)).start());
                    modules.add(module.label());
                }
            }
            stops = StopWatcher.start(space, this::stopped);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /** How many modules are watched. */
    public int moduleCount() {
        return watchers.size();
    }

    @Override
    public void close() {
        watchers.forEach(AnswerWatcher::close);
        if (stops != null) {
            stops.close();
        }
    }

    private void stopped(StopRecord record) {
        if (modules.contains(record.where())) {
            print(stopLine(record));
        }
    }

    /** The line for a stop of one of the world's actuators. */
    static String stopLine(StopRecord record) {
        return String.format(Locale.ROOT, "%-12s  %-18s %-18s STOPPED by %s (%s: %s): %s",
                TIME.format(LocalTime.ofInstant(record.at(), ZoneId.systemDefault())), record.participant(),
                record.module(), record.stoppedBy(), record.cause().wireName(), record.reason(), record.action());
    }

    /** The line for one answer; {@code when} null for one found when monitoring started. */
    static String line(Instant when, MonitoredModule module, CallTuple answer) {
        return String.format(Locale.ROOT, "%-12s  %-18s %-18s %-22s %s  (%s)",
                when == null ? "earlier" : TIME.format(LocalTime.ofInstant(when, ZoneId.systemDefault())),
                module.participant(),
                module.moduleName(), AnswerText.function(answer), AnswerText.value(answer), AnswerText.host(answer));
    }

    private synchronized void print(String line) {
        out.println(line);
        out.flush();
    }

    private final class Printer implements AnswerListener {

        private final MonitoredModule module;

        Printer(MonitoredModule module) {
            this.module = module;
        }

        @Override
        public void answer(CallTuple answer, Instant when) {
            print(line(when, module, answer));
        }

        @Override
        public void earlier(CallTuple answer) {
            print(line(null, module, answer));
        }

        @Override
        public void stopped(String why) {
            print("# " + module.label() + ": " + why);
        }
    }
}
