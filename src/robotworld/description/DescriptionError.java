package robotworld.description;

/**
 * One problem found in a description, located in its source.
 *
 * @param source where the description came from (a file path, or a name the caller gave a stream or string)
 * @param line   1-based line, or 0 when the problem has no position (the file cannot be read at all)
 * @param column 1-based column, or 0 when unknown
 * @param message what is wrong, in words a user can act on
 */
public record DescriptionError(String source, int line, int column, String message) {

    /** Formats the error as {@code source:line:column: message}, the form compilers and editors understand. */
    @Override
    public String toString() {
        if (line <= 0) {
            return source + ": " + message;
        }
        return source + ":" + line + ":" + Math.max(column, 1) + ": " + message;
    }
}
