package robotworld.explorer.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.LocalTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import robotworld.description.DescriptionLoader;
import robotworld.explorer.monitor.ConsoleMonitor;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.recording.Replayer;
import robotworld.space.EmbeddedSpace;

/**
 * Checks that a recording of the demo ({@code ./antw demo -Drecord=FILE}) replays to the console monitor with the
 * same sequence of bumper, motor and lamp events, each at the time it happened, within 5 % of the run's length.
 * {@link DemoTest} records its robot-viewpoint run and calls this, so the demo runs once for both.
 */
final class DemoReplayCheck {

    private DemoReplayCheck() {
    }

    /** One console monitor line the tally showed: when, and what (participant module function value (host)). */
    record Event(long millis, String category, String what) {
    }

    /**
     * Replays {@code file} at rate 1 to a console monitor and compares it with what the live demo's console monitor
     * showed ({@code liveOutput}, the demo's output with the console tally's lines).
     */
    static void assertReplaysAsLive(Path file, String liveOutput) throws Exception {
        assertTrue(liveOutput.contains("recorded ") && liveOutput.contains("(0 dropped)"), liveOutput);
        StringWriter replayed = new StringWriter();
        try (Replayer replayer = Replayer.open(file); EmbeddedSpace space = EmbeddedSpace.open()) {
            MonitoredWorld world = MonitoredWorld.of(DescriptionLoader.loadWorldFromString(new String(
                    replayer.worldDescription().orElseThrow(), StandardCharsets.UTF_8), "world.xml"));
            Replayer.Options options = new Replayer.Options(1, false);
            replayer.prepare(space, options);
            MonitorTally tally = new MonitorTally(new PrintWriter(replayed, true));
            ConsoleMonitor console = new ConsoleMonitor(world, space, new PrintWriter(tally, true));
            try {
                replayer.play(space, options, progress -> { });
                Thread.sleep(300); // the last answers reach the console
            } finally {
                console.close();
            }
        }
        assertTrue(replayed.toString().contains("# REPLAY of demo.mcap"), "marked as a replay:\n" + replayed);

        List<Event> before = events(liveOutput);
        List<Event> after = events(replayed.toString());
        Map<String, List<String>> liveSequences = sequences(before);
        Map<String, List<String>> replaySequences = sequences(after);
        assertTrue(liveSequences.get("bumper").stream().anyMatch(e -> e.contains("1>") || e.contains("true")),
                "the demo bumped:\n" + liveOutput);
        assertTrue(!liveSequences.get("motor").isEmpty() && !liveSequences.get("lamp").isEmpty(), liveOutput);
        assertEquals(liveSequences, replaySequences, "the same bumper, motor and lamp events in the same order");

        // timing: each event's offset from the first, replayed against live, within 5 % of the run's length
        long liveSpan = span(before);
        long replaySpan = span(after);
        assertTrue(liveSpan > 3_000, "a run of some seconds: " + liveSpan + " ms");
        assertTrue(Math.abs(replaySpan - liveSpan) <= liveSpan * 0.05, "length " + replaySpan + " ms replayed, "
                + liveSpan + " ms live");
        for (String category : List.of("bumper", "motor", "lamp")) {
            List<Event> liveOnes = only(before, category);
            List<Event> replayOnes = only(after, category);
            for (int i = 0; i < liveOnes.size(); i++) {
                long liveOffset = liveOnes.get(i).millis() - before.get(0).millis();
                long replayOffset = replayOnes.get(i).millis() - after.get(0).millis();
                assertTrue(Math.abs(replayOffset - liveOffset) <= liveSpan * 0.05, category + " event " + i + " ("
                        + liveOnes.get(i).what() + ") at " + replayOffset + " ms replayed, " + liveOffset
                        + " ms live");
            }
        }
    }

    /** The console monitor lines the tally echoed ("  monitor | HH:mm:ss.SSS participant module function ..."). */
    private static List<Event> events(String output) {
        List<Event> events = new ArrayList<>();
        long dayOffset = 0;
        long previous = -1;
        for (String line : output.lines().toList()) {
            if (!line.startsWith("  monitor | ")) {
                continue;
            }
            String text = line.substring("  monitor | ".length());
            String[] parts = text.trim().split("\\s+", 5);
            if (parts.length < 5 || !parts[0].matches("\\d\\d:\\d\\d:\\d\\d\\.\\d\\d\\d")) {
                continue; // "#" lines and earlier answers
            }
            long millis = LocalTime.parse(parts[0]).toNanoOfDay() / 1_000_000 + dayOffset;
            if (previous >= 0 && millis < previous - 12 * 3_600_000L) {
                dayOffset += 24 * 3_600_000L; // past midnight
                millis += 24 * 3_600_000L;
            }
            previous = millis;
            String module = parts[2];
            String function = parts[3];
            String category = module.contains("Bumper") ? "bumper" : function.startsWith("setMotor") ? "motor"
                    : function.equals("on") || function.equals("off") ? "lamp" : null;
            if (category != null) {
                events.add(new Event(millis, category, parts[1] + " " + module + " " + function + " " + parts[4]));
            }
        }
        return events;
    }

    private static Map<String, List<String>> sequences(List<Event> events) {
        Map<String, List<String>> sequences = new TreeMap<>();
        for (String category : List.of("bumper", "motor", "lamp")) {
            sequences.put(category, only(events, category).stream().map(Event::what).toList());
        }
        return sequences;
    }

    private static List<Event> only(List<Event> events, String category) {
        return events.stream().filter(e -> e.category().equals(category)).toList();
    }

    private static long span(List<Event> events) {
        return events.get(events.size() - 1).millis() - events.get(0).millis();
    }
}
