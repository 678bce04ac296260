package robotworld.xvsm;

import java.util.List;
import java.util.Locale;
import robotworld.space.Entry;
import robotworld.space.StringEntry;
import robotworld.space.Tuple;

/**
 * What a module's host answers when a call failed, in the common layout with the reserved function name
 * {@value #FUNCTION}: {@code <key, failedFunction, <kind, exceptionType, message, host>, "ERROR">}. The caller
 * turns it back into an exception ({@link #toException}).
 *
 * @param failedFunction the function field of the failed request, verbatim
 * @param kind           what went wrong, which decides the caller's exception
 * @param type           the exception class at the module's host
 * @param message        its message
 * @param host           the host that serves the module
 */
record ErrorAnswer(Entry failedFunction, Kind kind, String type, String message, String host) {

    /** The function name that marks an error answer. */
    static final String FUNCTION = "ERROR";

    /** Kinds of failure, as they travel (lower case). */
    enum Kind {
        /** An argument was refused: the caller gets an {@link IllegalArgumentException}, as in a local call. */
        ARGUMENT,
        /** The hardware did not answer: the caller gets a {@link ModuleCallTimeoutException}. */
        TIMEOUT,
        /** The hardware failed otherwise: the caller gets an {@link XVSMRemoteException}. */
        FAILURE,
        /** The request was malformed or named an unknown function: an {@link XVSMRemoteException} too. */
        REQUEST,
        /**
         * The actuator had been stopped since the caller last commanded it, and the call was not carried out: the
         * caller gets an {@link ActuatorStoppedException}.
         */
        STOPPED;

        String wireName() {
            return name().toLowerCase(Locale.ROOT);
        }

        static Kind ofWireName(String name) {
            for (Kind kind : values()) {
                if (kind.wireName().equals(name)) {
                    return kind;
                }
            }
            return FAILURE; // a newer host's kind: still a failure
        }
    }

    /** The error answer for {@code failure} of {@code request}, served by {@code host}. */
    static ErrorAnswer of(CallTuple request, Throwable failure, String host) {
        return new ErrorAnswer(request.function(), classify(failure), failure.getClass().getName(),
                failure.getMessage() == null ? failure.getClass().getSimpleName() : failure.getMessage(), host);
    }

    /** The answer refusing {@code request} because the actuator was stopped; {@code stop} says how, in words. */
    static ErrorAnswer stopped(CallTuple request, String stop, String host) {
        return new ErrorAnswer(request.function(), Kind.STOPPED, ActuatorStoppedException.class.getName(), stop, host);
    }

    /** Whether an answer is an error answer. */
    static boolean isError(CallTuple answer) {
        return answer.is(FUNCTION);
    }

    /** Reads an error answer. */
    static ErrorAnswer parse(CallTuple answer) {
        Tuple detail = answer.tupleAt(1);
        if (detail.arity() != 4) {
            throw new MalformedCallException("malformed error answer " + answer);
        }
        return new ErrorAnswer(answer.fields().get(0), Kind.ofWireName(text(detail, 0)), text(detail, 1),
                text(detail, 2), text(detail, 3));
    }

    /** The answer tuple under the requester's key. */
    CallTuple toAnswer(String key) {
        Tuple detail = Tuple.of(kind.wireName(), type, message, host);
        return new CallTuple(key, List.of(failedFunction, detail), Entry.of(FUNCTION));
    }

    /** The exception the caller throws for this answer. */
    RuntimeException toException(String participant, String module, String function) {
        String where = participant + "/" + module + " " + function;
        return switch (kind) {
            case ARGUMENT -> new IllegalArgumentException(where + ": " + message);
            case TIMEOUT -> new ModuleCallTimeoutException(participant, module, function, -1,
                    where + ": the hardware did not answer host " + host + ": " + message);
            case FAILURE, REQUEST -> new XVSMRemoteException(participant, module, function, host, type, message);
            case STOPPED -> new ActuatorStoppedException(participant, module, function, host, message);
        };
    }

    private static Kind classify(Throwable failure) {
        if (failure instanceof ActuatorStoppedException) {
            return Kind.STOPPED;
        }
        if (failure instanceof MalformedCallException) {
            return Kind.REQUEST;
        }
        if (failure instanceof IllegalArgumentException) {
            return Kind.ARGUMENT;
        }
        // hardware layers have their own timeout types (BusTimeoutException, X10TimeoutException, ...)
        for (Class<?> type = failure.getClass(); type != null; type = type.getSuperclass()) {
            if (type.getSimpleName().endsWith("TimeoutException")) {
                return Kind.TIMEOUT;
            }
        }
        return Kind.FAILURE;
    }

    private static String text(Tuple tuple, int index) {
        return tuple.get(index) instanceof StringEntry text ? text.value() : tuple.get(index).toString();
    }
}
