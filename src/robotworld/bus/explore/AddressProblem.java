package robotworld.bus.explore;

/**
 * Something went wrong at one bus address during exploration; the address was skipped.
 *
 * @param address the bus address
 * @param kind what kind of problem
 * @param message what happened, for people
 */
public record AddressProblem(int address, Kind kind, String message) {

    /** Kinds of problems at an address. */
    public enum Kind {
        /** A module started answering, then stopped (or a late responder did not answer again). */
        TIMEOUT,
        /** Replies kept failing the CRC check. */
        CRC_ERROR,
        /** The module refused a mandatory command with a Modbus exception response. */
        EXCEPTION_RESPONSE,
        /** A reply did not fit the request (wrong function, altered echo, malformed identification). */
        PROTOCOL_ERROR,
        /** The status command reported that the module is not running. */
        NOT_RUNNING,
        /** The module's NodeID has no description in the catalogue, or an unusable one. */
        UNKNOWN_NODE_ID,
        /** The serial link failed while talking to this address. */
        LINK_ERROR,
        /**
         * A module answered here, or exchanges with the address were disturbed, and it could not be asked again
         * undisturbed before exploration gave up asking: a module may be there.
         */
        DISTURBED
    }

    @Override
    public String toString() {
        return "address " + address + ": " + kind.name().toLowerCase(java.util.Locale.ROOT).replace('_', ' ') + ": "
                + message;
    }
}
