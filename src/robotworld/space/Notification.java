package robotworld.space;

import java.util.List;
import java.util.Objects;

/**
 * One operation on a container, as delivered to a subscriber.
 *
 * @param container the container
 * @param operation what happened
 * @param entries   the entries written, shifted in, read, taken or destroyed (empty for
 *                  {@link Operation#DESTROY_CONTAINER})
 * @param displaced for {@link Operation#SHIFT}: the entries it pushed out; empty otherwise
 * @param sequence  position of the operation in the container's history; increases with every operation on
 *                  the container, so gaps only mean operations this subscription did not ask for
 */
public record Notification(ContainerRef container, Operation operation, List<Entry> entries, List<Entry> displaced,
                           long sequence) {

    /** Copies the lists. */
    public Notification {
        Objects.requireNonNull(container, "container");
        Objects.requireNonNull(operation, "operation");
        entries = List.copyOf(entries);
        displaced = List.copyOf(displaced);
    }
}
