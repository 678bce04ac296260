package robotworld.space.server;

import robotworld.space.wire.WireError;

/** Ends a request with an error answer of the given kind; thrown by the request handling, caught by the servlet. */
final class ErrorAnswer extends RuntimeException {

    final WireError error;
    /** Whether the write of a {@code writeThenTake} happened before its take failed (said in the answer). */
    final boolean written;

    ErrorAnswer(WireError error, String message) {
        this(error, message, false);
    }

    ErrorAnswer(WireError error, String message, boolean written) {
        super(message, null, false, false);
        this.error = error;
        this.written = written;
    }
}
