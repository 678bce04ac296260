package robotworld.explorer.generator;

/** Generation failed; the message says what and where. Nothing was left at the destination. */
public final class GenerationException extends Exception {

    private static final long serialVersionUID = 1L;

    public GenerationException(String message) {
        super(message);
    }

    public GenerationException(String message, Throwable cause) {
        super(message, cause);
    }
}
