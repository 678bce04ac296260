package robotworld.space;

import java.util.Collections;
import java.util.EnumSet;
import java.util.Set;

/** What happened on a container, as reported by notifications. */
public enum Operation {
    /** Entries were read. */
    READ,
    /** Entries were taken (read and removed). */
    TAKE,
    /** Entries were removed without being returned. */
    DESTROY,
    /** Entries were written. */
    WRITE,
    /** Entries were shifted in, possibly displacing others. */
    SHIFT,
    /** The container itself was destroyed. */
    DESTROY_CONTAINER;

    private static final Set<Operation> ANY = Collections.unmodifiableSet(EnumSet.allOf(Operation.class));

    /** Every operation, including the container's destruction. */
    public static Set<Operation> any() {
        return ANY;
    }
}
