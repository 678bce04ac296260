package robotworld.observe;

import java.time.Instant;
import robotworld.xvsm.CallTuple;

/**
 * A request was written into a module's REQUEST container: a remote call (or a quiet command) on its way.
 *
 * @param module  the module called
 * @param request the request {@code <key, arguments..., function>}
 * @param at      when the tap received it
 * @param queued  requests waiting in the module's queue after this one arrived, as far as the tap knows
 */
public record RequestSeen(ModuleRef module, CallTuple request, Instant at, int queued) {
}
