package robotworld.sim.control;

import java.util.List;

/** The commands one simulator understands on its control channel. */
public interface ControlCommands {

    /**
     * Carries out one command.
     *
     * @param words the command's words, the first being its name, never empty
     * @return what to answer after "ok " (may be empty)
     * @throws IllegalArgumentException with the words to answer after "error ": an unknown command, wrong
     *         arguments, or a command the simulator refused
     */
    String execute(List<String> words);

    /** One line per command: its form and what it does, e.g. "remote A5 on   a remote control sends A5 On". */
    List<String> help();
}
