package robotworld.explorer.demo;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import robotworld.sim.robot.Pose;

/** What a demo run did: the outcome the summary prints and the test checks. */
public final class DemoSummary {

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
