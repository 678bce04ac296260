package robotworld.program;

/**
 * A participant's port could not be opened. Names the participant, the kind of port ({@code bus} or {@code x10})
 * and the port, so the report can name the property that chooses another one.
 */
public final class PortException extends Exception {

    private static final long serialVersionUID = 1L;

    private final String participant;
    private final String kind;
    private final String port;

    public PortException(String participant, String kind, String port, Throwable cause) {
        super((participant == null ? "" : participant + ": ") + "cannot open the " + kind + " port " + port + ": "
                + cause.getMessage(), cause);
        this.participant = participant;
        this.kind = kind;
        this.port = port;
    }

    /** The participant whose port it is; null when opened for something else (e.g. {@code rwe explore}). */
    public String participant() {
        return participant;
    }

    /** {@code bus} or {@code x10}. */
    public String kind() {
        return kind;
    }

    public String port() {
        return port;
    }

    /** The system property that chooses this port at run time; null when not opened for a participant. */
    public String property() {
        return participant == null ? null : ParticipantMain.portProperty(participant, kind);
    }
}
