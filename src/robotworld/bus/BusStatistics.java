package robotworld.bus;

/**
 * Counters of a bus since it was opened: what went over it and what went wrong.
 *
 * @param transactions requests sent (each attempt counts)
 * @param retries attempts beyond the first
 * @param timeouts attempts that got no (complete) reply in time
 * @param crcErrors replies with a wrong CRC or cut short
 * @param exceptionResponses replies that refused the request
 * @param strayFrames valid frames from another address than the one asked (late replies)
 * @param staleReplies late replies from an address whose request had timed out, discarded before that address was
 *        asked again (so that they could not pass for the new answer)
 */
public record BusStatistics(long transactions, long retries, long timeouts, long crcErrors,
        long exceptionResponses, long strayFrames, long staleReplies) {
}
