package robotworld.description;

import java.util.List;
import java.util.stream.Collectors;

/** A description could not be loaded: carries every error found, not only the first. */
public final class DescriptionException extends Exception {

    private static final long serialVersionUID = 1L;

    private final transient List<DescriptionError> errors;

    public DescriptionException(List<DescriptionError> errors) {
        super(errors.stream().map(DescriptionError::toString).collect(Collectors.joining("\n")));
        if (errors.isEmpty()) {
            throw new IllegalArgumentException("a DescriptionException needs at least one error");
        }
        this.errors = List.copyOf(errors);
    }

    public DescriptionException(DescriptionError error) {
        this(List.of(error));
    }

    /** Every error, in document order. */
    public List<DescriptionError> errors() {
        return errors;
    }
}
