package robotworld.observe;

import java.time.Instant;

/**
 * The number of requests waiting in a module's REQUEST container changed: one was written, or a Local side (or a
 * caller withdrawing its request) took some.
 *
 * @param module the module
 * @param queued requests waiting now, as far as the tap knows
 * @param at     when the tap received the change
 */
public record QueueLength(ModuleRef module, int queued, Instant at) {
}
