/**
 * A control channel for the simulators: a small line protocol, read from standard input or from loopback TCP
 * connections, that drives a running simulator from outside, as a person at a terminal or a test would.
 *
 * <p>Contract: every line is one command, words separated by blanks; blank lines and lines starting with
 * {@code #} are skipped. Every command gets exactly one answer line: {@code ok} with what was done or what was
 * asked, or {@code error} with what is wrong and what would be right. A command never blocks longer than its own
 * action takes. {@code help} lists the commands, {@code quit} ends the connection (on standard input: stops
 * reading). Commands of the CM11A simulator are in {@link robotworld.sim.control.Cm11aControl}, of the robot
 * simulator in {@link robotworld.sim.control.RobotControl}; the protocol is documented in docs/x10.md and
 * docs/bus.md.
 */
package robotworld.sim.control;
