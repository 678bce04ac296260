package robotworld.xvsm;

/**
 * The call was refused, and not carried out, because the actuator had been put into its safe state since this
 * program last commanded it: its commander was silent, the program serving it lost its space, someone stopped the
 * world ({@code rwe stop}), its bus watchdog tripped, or the program serving it is ending. While the program
 * serving it cannot reach its space, every command is refused this way. The message says who
 * stopped it, when and why ({@code robotworld.safety.StopRecord#summary()}). A program that wants the actuator to
 * move again commands it again; the next call is carried out.
 */
public class ActuatorStoppedException extends ModuleCallException {

    private final String stoppingHost;

    /**
     * @param stoppingHost the host serving the actuator, which stopped it
     * @param stop         the stop, in words
     */
    public ActuatorStoppedException(String participant, String module, String function, String stoppingHost,
                                    String stop) {
        this(participant, module, function, stoppingHost, stop, "command it again to move it");
    }

    /**
     * @param stoppingHost the host serving the actuator, which stopped it
     * @param stop         the stop, in words
     * @param advice       what the caller can do about it, in words
     */
    public ActuatorStoppedException(String participant, String module, String function, String stoppingHost,
                                    String stop, String advice) {
        super(participant, module, function, participant + "/" + module + " " + function + " refused: the actuator "
                + "was " + stop + "; " + advice, null);
        this.stoppingHost = stoppingHost;
    }

    /** The host serving the actuator. */
    public String stoppingHost() {
        return stoppingHost;
    }
}
