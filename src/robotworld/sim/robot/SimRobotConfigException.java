package robotworld.sim.robot;

import java.io.IOException;
import java.util.List;

/** A simulated-robot configuration is malformed; the message lists every problem found, one per line. */
public class SimRobotConfigException extends IOException {

    private final List<String> problems;

    public SimRobotConfigException(List<String> problems) {
        super(String.join("\n", problems));
        this.problems = List.copyOf(problems);
    }

    /** Every problem, each starting with the file name. */
    public List<String> problems() {
        return problems;
    }
}
