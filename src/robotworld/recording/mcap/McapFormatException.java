package robotworld.recording.mcap;

import java.io.IOException;

/** A file that is not MCAP, is damaged, or uses a feature this reader lacks (the message says which, and where). */
public final class McapFormatException extends IOException {

    private static final long serialVersionUID = 1L;

    /** A problem at byte {@code offset} of the file. */
    public McapFormatException(long offset, String message) {
        super("at byte " + offset + ": " + message);
    }

    /** A problem with the file as a whole. */
    public McapFormatException(String message) {
        super(message);
    }
}
