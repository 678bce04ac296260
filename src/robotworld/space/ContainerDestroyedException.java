package robotworld.space;

/**
 * The container was destroyed while the operation was waiting on it. A subclass of
 * {@link ContainerNotFoundException}, since afterwards the container is simply gone.
 */
public class ContainerDestroyedException extends ContainerNotFoundException {

    /** With a message. */
    public ContainerDestroyedException(String message) {
        super(message);
    }
}
