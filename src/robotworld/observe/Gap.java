package robotworld.observe;

import java.time.Instant;

/**
 * Events may be missing: the tap could not deliver everything that happened.
 *
 * @param at       when the tap noticed
 * @param module   the module concerned, or null when it concerns the whole world (observers fell behind, ground
 *                 truth)
 * @param missed   how many events were lost, or -1 when unknown
 * @param why      what happened, in words
 * @param ended    whether watching ended for good ({@code module} or, when null, everything): no more events come
 */
public record Gap(Instant at, ModuleRef module, long missed, String why, boolean ended) {
}
