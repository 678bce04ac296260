package robotworld.explorer.stop;

import java.io.PrintWriter;
import java.time.Duration;
import java.util.List;
import robotworld.core.HostNames;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.safety.WorldStop;
import robotworld.space.Capi;

/**
 * Stops every actuator of a loaded world through its space, and reports per module: what {@code rwe stop} and the
 * STOP buttons share.
 */
public final class WorldStopper {

    private WorldStopper() {
    }

    /**
     * Opens the space at {@code spaceUrl}, sends the stop and waits for the answers.
     *
     * @param via    how the stop was asked for, e.g. {@code rwe stop} or {@code STOP button}
     * @param reason why, in words (may be empty)
     * @throws IllegalStateException when the world's communication type has no space ({@code none})
     * @throws robotworld.space.SpaceException when the space cannot be reached
     */
    public static WorldStop.Result stop(MonitoredWorld world, String spaceUrl, String via, String reason,
                                        Duration wait) throws InterruptedException {
        if (!world.communicationType().equalsIgnoreCase("xvsm")) {
            throw new IllegalStateException("the world " + world.name() + " has communication type "
                    + world.communicationType() + ": its programs share no space to be stopped through; stop them "
                    + "directly (Ctrl-C)");
        }
        try (Capi space = MonitorSpace.open(spaceUrl)) {
            return stop(world, space, via, reason, wait);
        }
    }

    /** Sends the stop on an open space connection. */
    public static WorldStop.Result stop(MonitoredWorld world, Capi space, String via, String reason, Duration wait)
            throws InterruptedException {
        List<WorldStop.Target> targets = StopTargets.of(world);
        return WorldStop.stop(space, HostNames.thisComputer() + " (" + via + ")", reason, targets, wait);
    }

    /** Prints one line per module, aligned, then a summary line. */
    public static void print(WorldStop.Result result, PrintWriter out) {
        int width = result.outcomes().stream().mapToInt(o -> o.target().toString().length()).max().orElse(0);
        for (WorldStop.Outcome outcome : result.outcomes()) {
            String line = outcome.toString();
            String name = outcome.target().toString();
            out.println(name + " ".repeat(width - name.length()) + line.substring(name.length()));
        }
        out.println(summary(result));
        out.flush();
    }

    /** A few words for a button's side: {@code all 2 actuators stopped (18 ms)} or what was not. */
    public static String shortSummary(WorldStop.Result result) {
        long stopped = result.outcomes().stream().filter(o -> o.reached()
                && o.answer().state() == robotworld.safety.StopAnswer.State.STOPPED).count();
        List<WorldStop.Outcome> failures = result.failures();
        if (failures.isEmpty()) {
            return "all " + stopped + " actuator(s) stopped (" + result.elapsed().toMillis() + " ms)";
        }
        return "NOT confirmed stopped: " + String.join(", ", failures.stream().map(f -> f.target().toString())
                .toList());
    }

    /** One line: how many modules answered, how many actuators stopped, what failed. */
    public static String summary(WorldStop.Result result) {
        long answered = result.outcomes().stream().filter(WorldStop.Outcome::reached).count();
        long stopped = result.outcomes().stream().filter(o -> o.reached()
                && o.answer().state() == robotworld.safety.StopAnswer.State.STOPPED).count();
        List<WorldStop.Outcome> failures = result.failures();
        String text = answered + " of " + result.outcomes().size() + " modules answered in "
                + result.elapsed().toMillis() + " ms; " + stopped + " actuator(s) stopped";
        if (failures.isEmpty()) {
            return text + "; every actuator is in its safe state";
        }
        return text + "; " + failures.size() + " actuator(s) NOT confirmed stopped: "
                + String.join(", ", failures.stream().map(f -> f.target().toString()).toList())
                + " (an unreachable one still stops by itself when its program loses its commander or its space, "
                + "or by its bus watchdog when its program dies)";
    }
}
