package robotworld.space.wire;

import robotworld.space.ContainerDestroyedException;
import robotworld.space.ContainerNameTakenException;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.InvalidOperationException;
import robotworld.space.SpaceClosedException;
import robotworld.space.SpaceException;
import robotworld.space.SpaceRequestRejectedException;
import robotworld.space.SpaceTimeoutException;

/**
 * The error kinds of the wire format, each with its HTTP status; an error answer is
 * {@code {"error": kind, "message": text}}. The server maps exceptions to kinds, the client maps kinds back to the
 * same exception types, so a remote failure is the same exception as an embedded one.
 */
public enum WireError {
    BAD_REQUEST(400, "bad-request"),
    UNAUTHORIZED(401, "unauthorized"),
    NO_SUCH_ENDPOINT(404, "no-such-endpoint"),
    METHOD_NOT_ALLOWED(405, "method-not-allowed"),
    TOO_LARGE(413, "too-large"),
    UNSUPPORTED_MEDIA_TYPE(415, "unsupported-media-type"),
    TIMEOUT(409, "timeout"),
    CONTAINER_NOT_FOUND(404, "container-not-found"),
    CONTAINER_DESTROYED(404, "container-destroyed"),
    NAME_TAKEN(409, "name-taken"),
    INVALID_OPERATION(422, "invalid-operation"),
    SPACE_CLOSED(410, "space-closed"),
    /** The call was cancelled by its client and had no effect. */
    CANCELLED(409, "cancelled"),
    /** A subscription request names an event session that is not (or no longer) connected. */
    NO_SESSION(409, "no-session"),
    /** The server is stopping; the call had no effect and may be retried elsewhere or later. */
    STOPPING(503, "stopping"),
    /** Too many calls are waiting on the server; the call had no effect. */
    BUSY(503, "busy"),
    /**
     * The server could not complete the call now (the cluster behind it is recovering, or its member is going away);
     * whether it took effect is not known: the client settles it like a call whose connection broke, with this
     * server or another one of the space.
     */
    UNAVAILABLE(503, "unavailable"),
    INTERNAL(500, "internal");

    private final int status;
    private final String kind;

    WireError(int status, String kind) {
        this.status = status;
        this.kind = kind;
    }

    public int status() {
        return status;
    }

    public String kind() {
        return kind;
    }

    /** The kind named {@code kind}, or null. */
    public static WireError byKind(String kind) {
        for (WireError error : values()) {
            if (error.kind.equals(kind)) {
                return error;
            }
        }
        return null;
    }

    /** The kind a server answers for a failure of a space operation. */
    public static WireError of(Throwable failure) {
        if (failure instanceof WireFormatException || failure instanceof IllegalArgumentException
                || failure instanceof NullPointerException) {
            return BAD_REQUEST;
        }
        if (failure instanceof SpaceTimeoutException) {
            return TIMEOUT;
        }
        if (failure instanceof ContainerDestroyedException) {
            return CONTAINER_DESTROYED;
        }
        if (failure instanceof ContainerNotFoundException) {
            return CONTAINER_NOT_FOUND;
        }
        if (failure instanceof ContainerNameTakenException) {
            return NAME_TAKEN;
        }
        if (failure instanceof InvalidOperationException) {
            return INVALID_OPERATION;
        }
        if (failure instanceof SpaceClosedException) {
            return SPACE_CLOSED;
        }
        if (failure instanceof robotworld.space.CallCancelledException) {
            return CANCELLED;
        }
        if (failure instanceof robotworld.space.SpaceUnavailableException) {
            return UNAVAILABLE;
        }
        return INTERNAL;
    }

    /**
     * The exception a client throws for this kind. Kinds that are no space outcome (malformed request, refused
     * credentials, ...) become {@link SpaceRequestRejectedException} with the status.
     */
    public SpaceException toException(String message) {
        return switch (this) {
            case TIMEOUT -> new SpaceTimeoutException(message);
            case CONTAINER_DESTROYED -> new ContainerDestroyedException(message);
            case CONTAINER_NOT_FOUND -> new ContainerNotFoundException(message);
            case NAME_TAKEN -> new ContainerNameTakenException(message);
            case INVALID_OPERATION -> new InvalidOperationException(message);
            case SPACE_CLOSED -> new SpaceClosedException(message);
            default -> new SpaceRequestRejectedException(status, kind + ": " + message);
        };
    }
}
