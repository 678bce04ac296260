/**
 * Stopping a whole world from the command line ({@code rwe stop}) and the STOP buttons of the windows: the modules
 * of a loaded world ({@link robotworld.explorer.stop.StopTargets}), the stop and its report
 * ({@link robotworld.explorer.stop.WorldStopper}), and the button ({@link robotworld.explorer.stop.StopButton}).
 * The stop itself is {@link robotworld.safety.WorldStop}.
 */
package robotworld.explorer.stop;
