package robotworld.space;

import java.net.URI;
import java.util.Objects;

/**
 * A reference to a container (a "cref"): which space it lives in and the container's identity there.
 *
 * <p>A cref is a plain value: it can be stored in other containers (it is an {@link Entry}), compared, printed
 * and sent to another process. The {@code space} URI names the space that owns the container (for example
 * {@code embedded:7f3c...} for an in-process space or {@code http://host:port/} for a remote one), so a cref
 * handed to the wrong space is recognised as foreign. The {@code id} is assigned by the space when the container
 * is created and never reused, so a cref to a destroyed container never reaches a newer container that happens
 * to get the same name.
 */
public record ContainerRef(URI space, String id) implements Entry {

    /** @throws NullPointerException if an argument is null; @throws IllegalArgumentException if id is blank */
    public ContainerRef {
        Objects.requireNonNull(space, "space");
        Objects.requireNonNull(id, "id");
        if (id.isBlank()) {
            throw new IllegalArgumentException("container id must not be blank");
        }
    }

    @Override
    public EntryType type() {
        return EntryType.CREF;
    }

    @Override
    public String toString() {
        return "cref(" + space + "#" + id + ")";
    }
}
