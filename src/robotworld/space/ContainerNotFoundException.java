package robotworld.space;

/** No container has that name, or the cref names a container that does not exist (any more) in this space. */
public class ContainerNotFoundException extends SpaceException {

    /** With a message. */
    public ContainerNotFoundException(String message) {
        super(message);
    }
}
