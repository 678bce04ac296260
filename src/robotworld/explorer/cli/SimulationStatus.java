package robotworld.explorer.cli;

import java.util.Locale;
import java.util.StringJoiner;
import robotworld.observe.GroundTruth;
import robotworld.sim.robot.GroundTruthFeed;

/** The status line {@code rwe simulate robot} prints every second: where the robot is, what it touches, speeds. */
final class SimulationStatus {

    private SimulationStatus() {
    }

    /**
     * E.g. {@code [  12 s] at (612, 1000) heading 3°, tracks L +0.25 R +0.25, touching 4 6, 3 bumps}; speeds are
     * the actual track speeds, -1..1 of full speed.
     */
    static String line(long elapsedNanos, GroundTruthFeed feed) {
        GroundTruth frame = feed.latest();
        StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "[%4d s] at (%.0f, %.0f) heading %.0f°",
                elapsedNanos / 1_000_000_000L, frame.body().x(), frame.body().y(), frame.body().heading()));
        StringJoiner tracks = new StringJoiner(" ", ", tracks ", "");
        tracks.setEmptyValue("");
        for (GroundTruth.Motor motor : frame.motors()) {
            if (!motor.wheel().isEmpty()) {
                tracks.add(String.format(Locale.ROOT, "%s %+.2f", motor.wheel().equals("left") ? "L" : "R",
                        motor.actual()));
            }
        }
        line.append(tracks);
        StringJoiner touching = new StringJoiner(" ", ", touching ", "");
        touching.setEmptyValue(", free");
        frame.bumpers().stream().filter(GroundTruth.Bumper::contact).forEach(b -> touching.add("" + b.number()));
        line.append(frame.bumpers().isEmpty() ? "" : touching.toString());
        line.append(", ").append(feed.bumps()).append(feed.bumps() == 1 ? " bump" : " bumps");
        if (feed.problem() != null) {
            line.append(" (ground truth not published: ").append(feed.problem()).append(')');
        }
        return line.toString();
    }
}
