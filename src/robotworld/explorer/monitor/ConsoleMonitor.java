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
import robotworld.space.Capi;
import robotworld.xvsm.CallTuple;

/**
 * Monitoring as text, for machines without a display: one line per answer of any module of the world,
 * {@code time participant module function value (host)}. Works for every module type, known or not, because it
 * only reads the common answer layout.
 */
public final class ConsoleMonitor implements AutoCloseable {

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS");

    private final PrintWriter out;
    private final List<AnswerWatcher> watchers = new ArrayList<>();

    /**
     * Starts watching every module of {@code world} in {@code space}.
     *
     * @throws robotworld.space.SpaceException when the space cannot be reached
     */
    public ConsoleMonitor(MonitoredWorld world, Capi space, PrintWriter out) {
        this.out = out;
        try {
            for (MonitoredParticipant participant : world.participants()) {
                for (MonitoredModule module : participant.modules()) {
                    watchers.add(new AnswerWatcher(space, module.participant(), module.moduleName(),
                            new Printer(module)).start());
                }
            }
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
