package robotworld.space;

/** A container with that name already exists (with a different spec, for lookup-or-create). */
public class ContainerNameTakenException extends SpaceException {

    /** With a message. */
    public ContainerNameTakenException(String message) {
        super(message);
    }
}
