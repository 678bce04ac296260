package robotworld.explorer.demo;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robotworld.sim.robot.Pose;

/** What a demo run did: the outcome the summary prints and the test checks. */
public final class DemoSummary {

    /**
     * The robot stopping after its control program was killed ({@code --kill-control}).
     *
     * @param program      the killed main class
     * @param left         left motor's speed when killed, per-mille
     * @param right        right motor's speed when killed, per-mille
     * @param atKill       where the robot was
     * @param millisToZero from the kill to both motors reading 0 at the module; -1 when they did not
     * @param atRest       where the robot came to rest
     * @param stoppedBy    what stopped it
     */
    public record Kill(String program, int left, int right, Pose atKill, double millisToZero, Pose atRest,
                       String stoppedBy) {
    }

    /** Timing of one group of calls made by the control program. */
    public record CallStats(String name, int calls, long p50Micros, long p99Micros, long maxMicros) {
    }

    final List<String> failures = new ArrayList<>();
    Viewpoint viewpoint;
    Pose startPose;
    Pose endPose;
    int bumps = -1;
    int lampOnFrames;
    int lampOffFrames;
    int monitorAnswers;
    int monitorBumps;
    int monitorLampOn;
    int monitorLampOff;
    int monitorMotor;
    int monitorStops;
    Kill kill;
    MemberKill memberKill;
    boolean safe;
    final List<String> safeState = new ArrayList<>();
    final List<String> stops = new ArrayList<>();
    final List<CallStats> calls = new ArrayList<>();
    Path robotProject;
    Path environmentProject;
    Path world;
    Path robotDescription;
    long elapsedMillis;

    public boolean succeeded() {
        return failures.isEmpty();
    }

    public List<String> failures() {
        return List.copyOf(failures);
    }

    public Viewpoint viewpoint() {
        return viewpoint;
    }

    public Pose startPose() {
        return startPose;
    }

    public Pose endPose() {
        return endPose;
    }

    /** Millimetres between the start and end position of the simulated robot (0 when unknown). */
    public double distanceMoved() {
        return startPose == null || endPose == null ? 0 : startPose.distanceTo(endPose);
    }

    /** Front bumper contacts the control program reacted to; -1 when it reported none. */
    public int bumps() {
        return bumps;
    }

    /** "On" commands for A3 on the simulated CM11A's power line during the run. */
    public int lampOnFrames() {
        return lampOnFrames;
    }

    /** "Off" commands for A3 on the simulated CM11A's power line during the run. */
    public int lampOffFrames() {
        return lampOffFrames;
    }

    public int monitorAnswers() {
        return monitorAnswers;
    }

    public int monitorBumps() {
        return monitorBumps;
    }

    public int monitorLampOn() {
        return monitorLampOn;
    }

    public int monitorLampOff() {
        return monitorLampOff;
    }

    public int monitorMotor() {
        return monitorMotor;
    }

    /** Whether every actuator was found in its safe state after the programs ended. */
    public boolean safe() {
        return safe;
    }

    /** What the actuators read after the programs ended, one line each. */
    public List<String> safeState() {
        return List.copyOf(safeState);
    }

    /** The stop records the space held at the end, one line each. */
    public List<String> stops() {
        return List.copyOf(stops);
    }

    /**
     * A clustered space server killed (SIGKILL) while the control program ran, and what happened in the world after
     * it, up to the end of the run.
     *
     * @param url           the killed server
     * @param atKill        the robot's pose at the kill
     * @param bumpsAfter    front bumper contacts the control program reported after the kill
     * @param switchesAfter X10 lamp commands at the simulated CM11A after the kill
     * @param atEnd         the robot's pose when the control program ended
     */
    public record MemberKill(String url, Pose atKill, int bumpsAfter, int switchesAfter, Pose atEnd) {

        /** How far the robot got from where it was at the kill. */
        public double distanceAfter() {
            return atKill == null || atEnd == null ? 0 : atKill.distanceTo(atEnd);
        }
    }

    /** The clustered space server killed mid-run, or null when the space was not clustered. */
    public MemberKill memberKill() {
        return memberKill;
    }

    /** The kill of the control program, or null without {@code --kill-control}. */
    public Kill kill() {
        return kill;
    }

    /** Stops the monitor showed. */
    public int monitorStops() {
        return monitorStops;
    }

    public List<CallStats> calls() {
        return List.copyOf(calls);
    }

    public Path robotProject() {
        return robotProject;
    }

    public Path environmentProject() {
        return environmentProject;
    }

    void print(PrintWriter out) {
        out.println();
        out.println("==== summary (" + viewpoint + " viewpoint runs the control program) ====");
        out.printf(Locale.ROOT, "robot moved       %.0f mm: %s -> %s%n", distanceMoved(), startPose, endPose);
        out.println("bumps             " + (bumps < 0 ? "unknown (no statistics from the control program)"
                : bumps + " front bumper contacts handled by the control program"));
        out.println("lamp switches     " + lampOnFrames + " on, " + lampOffFrames
                + " off (X10 commands for A3 at the simulated CM11A)");
        out.println("monitor received  " + monitorAnswers + " answers: " + monitorBumps + " bumper contacts, "
                + monitorLampOn + " lamp on, " + monitorLampOff + " lamp off, " + monitorMotor + " motor calls");
        for (CallStats stats : calls) {
            String where = stats.name().equals("lamp")
                    ? (viewpoint == Viewpoint.ROBOT ? "remote, via the space to DimRoom" : "local X10 in DimRoom")
                    : (viewpoint == Viewpoint.ROBOT ? "local bus calls, published to the space"
                            : "remote, via the space to CaterpillarRobot");
            out.printf(Locale.ROOT, "%-17s %d calls (%s): p50 %.2f ms, p99 %.2f ms, max %.2f ms%n",
                    stats.name() + " calls", stats.calls(), where, stats.p50Micros() / 1000.0,
                    stats.p99Micros() / 1000.0, stats.maxMicros() / 1000.0);
        }
        if (kill != null) {
            out.printf(Locale.ROOT, "killed mid-drive  %s (SIGKILL) at %+.3f/%+.3f: motors read 0 %s; robot came to "
                    + "rest %.0f mm further at %s%n", kill.program(), kill.left() / 1000.0, kill.right() / 1000.0,
                    kill.millisToZero() < 0 ? "NEVER" : String.format(Locale.ROOT, "%.0f ms after the kill, stopped "
                            + "by %s", kill.millisToZero(), kill.stoppedBy()),
                    kill.atKill() == null || kill.atRest() == null ? 0 : kill.atKill().distanceTo(kill.atRest()),
                    kill.atRest());
        }
        if (memberKill != null) {
            out.printf(Locale.ROOT, "member killed     %s (SIGKILL) mid-run; after it the robot moved %.0f mm, %d bumps"
                    + " handled, %d lamp switches%n", memberKill.url(), memberKill.distanceAfter(),
                    memberKill.bumpsAfter(), memberKill.switchesAfter());
        }
        out.println("safe state        " + (safeState.isEmpty() ? "not checked"
                : safe ? "the robot's actuators are in their safe state (motors read 0 at the module)"
                : "NOT every actuator is in its safe state"));
        for (String line : safeState) {
            out.println("                    " + line);
        }
        out.println("stops recorded    " + stops.size() + " (the monitor showed " + monitorStops + ")");
        for (String line : stops) {
            out.println("                    " + line);
        }
        out.println("robot description " + robotDescription);
        out.println("world description " + world);
        out.println("robot project     " + robotProject + "   (open in Eclipse, or: ant compile)");
        out.println("environment proj. " + environmentProject);
        out.printf(Locale.ROOT, "took              %.1f s%n", elapsedMillis / 1000.0);
        if (failures.isEmpty()) {
            out.println("result            OK");
        } else {
            out.println("result            FAILED");
            failures.forEach(f -> out.println("  - " + f));
        }
        out.flush();
    }
}
