package robotworld.space.server;

import robotworld.space.wire.WireError;

/** Ends a request with an error answer of the given kind; thrown by the request handling, caught by the servlet. */
final class ErrorAnswer extends RuntimeException {

    final WireError error;

    ErrorAnswer(WireError error, String message) {
        super(message, null, false, false);
        this.error = error;
    }
}
