package robotworld.observe;

import java.time.Instant;

/**
 * An actuator reached its safe state: every motor channel of a motor module that was moving is at 0.
 *
 * @param module the module
 * @param at     when the tap saw the answer that stopped the last channel
 * @param by     the host that set the last channel to 0
 */
public record ActuatorStopped(ModuleRef module, Instant at, String by) {
}
