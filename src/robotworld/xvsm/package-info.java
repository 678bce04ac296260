/**
 * The runtime for communication type {@code xvsm}: every module of a RobotWorld shared through the space.
 *
 * <p>{@link robotworld.xvsm.XVSMRuntime} connects a participant program to the space. For each module interface
 * {@code C} of {@code robotworld.core}, {@code XVSM<C>Local} serves the module on the computer that has its
 * hardware (waiting for requests without a thread; a small pool carries them out), and {@code XVSM<C>Remote} calls it from any other computer; both implement
 * {@code C}, so a control program does not see where a module is. They share
 * {@link robotworld.xvsm.XVSMModule} (names and containers), and the request/answer machinery of
 * {@link robotworld.xvsm.XVSMLocalModule} and {@link robotworld.xvsm.XVSMRemoteModule}. The Local proxies of actuators
 * are guarded by the program's safety layer ({@code robotworld.safety}): a refused command surfaces as
 * {@link robotworld.xvsm.ActuatorStoppedException}. See {@code docs/runtime.md} and {@code docs/safety.md}.
 */
package robotworld.xvsm;
