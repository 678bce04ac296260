/**
 * Safety: no actuator outlives the program that commands it, and anyone can stop a whole world. Not a certified
 * safety function: a physical emergency stop is still needed (see {@code docs/safety.md}).
 *
 * <h2>The contract</h2>
 * An <b>actuator</b> is a module that moves or switches something ({@link robotworld.safety.Actuator}): motor,
 * servo, X10 lamp and appliance modules, and any new module type whose Local proxy implements the interface. Each
 * has a <b>safe state</b>: motors 0; servos hold their position (no new target is sent); X10 modules stay as they
 * are unless configured ({@link robotworld.safety.X10SafeState}). The program whose computer has an actuator's
 * hardware <i>serves</i> it; programs that call it, there or elsewhere, <i>command</i> it.
 * <ol>
 *   <li><b>Clean exits.</b> When a program that serves actuators ends (normal return and close of its runtime, an
 *       uncaught exception reported with {@code XVSMRuntime.failed}, Ctrl-C or SIGTERM, {@code System.exit}), it
 *       puts every actuator it serves into its safe state before the process ends, and refuses every later
 *       command ({@link robotworld.safety.SafetySupervisor#stopAll}).</li>
 *   <li><b>Hard deaths</b> (SIGKILL, a crash, a pulled cable): bus modules have a communication watchdog, a
 *       holding register with a timeout in ms (0 = off); a module that hears no valid frame addressed to it for
 *       that long goes to its safe state by itself and sets a status bit. {@code RS485Bus} arms it and keeps it
 *       fed while the program lives ({@code docs/bus.md}). The next program that arms a module and finds it
 *       tripped records that stop (nobody else was left to).</li>
 *   <li><b>Remote commanders.</b> An actuator is kept away from its safe state only while the programs that
 *       commanded it there are alive: the serving program stops it when one of them has been silent (no call, no
 *       changed heartbeat) for the actuator's <i>command timeout</i> (default 500 ms), or said in its last
 *       heartbeat that it ended.</li>
 *   <li><b>Losing the space.</b> A serving program that has not reached its space for an actuator's command
 *       timeout stops it if it is engaged and holds it in its safe state, refusing every command with the reason,
 *       until the space answers again (nobody elsewhere could stop the robot meanwhile), and says so once in its
 *       log. With {@code rwe.space.loss.stops=remote} it stops only the actuators a remote commander keeps
 *       engaged, and holds nothing.</li>
 *   <li><b>Stop everything.</b> A {@link robotworld.safety.StopRequest} (from {@code rwe stop WORLD} or a STOP
 *       button, {@link robotworld.safety.WorldStop}) makes every serving program stop its actuators of the named
 *       participants at once, and answer with one {@link robotworld.safety.StopAnswer} per module.</li>
 *   <li><b>Every stop is recorded</b>: logged by the program that stopped it, published as a
 *       {@link robotworld.safety.StopRecord} (who, why, when, what was done) and shown by monitors; a bus
 *       module's own watchdog stop after a hard death by the next program that arms the module.</li>
 * </ol>
 * After a stop, the commanders of the actuator are owed a notice: the next command of each is refused and not
 * carried out ({@code ActuatorStoppedException}), so a program learns that it must command again. Every
 * rule's stop is recorded by its {@link robotworld.safety.ActuatorGuard}.
 *
 * <h2>In the space</h2>
 * Programs publish {@link robotworld.safety.Heartbeat}s; stop requests, answers and records travel through the
 * containers of {@link robotworld.safety.SafetyContainers}. Their layouts are part of the contract (others read
 * them: monitors, recorders) and are documented in {@code docs/runtime.md}.
 *
 * <h2>Settings</h2>
 * {@link robotworld.safety.SafetySettings}: command timeout, bus watchdog, X10 safe state, per module from the
 * description ({@code <Safety>}) or at run time, and the heartbeat period.
 */
package robotworld.safety;
