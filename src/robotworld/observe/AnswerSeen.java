package robotworld.observe;

import java.time.Duration;
import java.time.Instant;
import robotworld.xvsm.CallTuple;

/**
 * An answer arrived in a module's ANSWER container: a served remote call, a published local call, or an error
 * answer (function {@code ERROR}).
 *
 * @param module  the module
 * @param answer  the answer {@code <key, values..., function>}
 * @param at      when the tap received it; for an answer found when watching started ({@code earlier}), when the
 *                tap read it
 * @param earlier whether it was already in the container when watching started (when it was written is unknown)
 * @param latency from the tap seeing the request to seeing this answer; null when unknown (local calls, quiet
 *                calls, earlier answers, a request the tap did not see)
 * @param queued  requests waiting in the module's queue, as far as the tap knows
 */
public record AnswerSeen(ModuleRef module, CallTuple answer, Instant at, boolean earlier, Duration latency,
                         int queued) {

    /** The function name of an error answer. */
    public static final String ERROR = "ERROR";

    /** Whether the answer reports a failed call. */
    public boolean isError() {
        return answer.is(ERROR);
    }

    /** The host in the answer's key: {@code laptop} for {@code laptop#k3x9.7} and for {@code laptop}. */
    public String host() {
        int hash = answer.key().indexOf('#');
        return hash < 0 ? answer.key() : answer.key().substring(0, hash);
    }

    /** Whether it answers a remote call (its key is {@code host#call}), not a published local call. */
    public boolean isRemoteCall() {
        return answer.key().indexOf('#') >= 0;
    }
}
