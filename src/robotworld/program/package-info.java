/**
 * How a participant program starts, ends and fails, for generated programs and the {@code rwe} command line.
 *
 * <p>Contract:
 * <ul>
 *   <li>{@link robotworld.program.ParticipantMain#run} runs a generated program's {@code main}: when the control
 *       program returns, the program's resources are closed (the runtime stops what it owns) and the process
 *       ends with status 0; a program that only serves its modules does so until it is stopped (Ctrl-C).</li>
 *   <li>An operational failure (a missing or busy port, a device or simulator that does not answer, an
 *       unreachable space, a refused token, a module whose program is not running) ends the process with status
 *       1 and at most three lines on standard error that say what happened and name the fix (the property or
 *       command to use), never a stack trace unless {@code -Drwe.debug=true} (or {@code RWE_DEBUG=true}). The
 *       runtime's log (what it serves, safety stops, retries) goes to standard output, beside what the program
 *       prints, so that standard error holds only what went wrong.</li>
 *   <li>{@link robotworld.program.Failures} turns any exception into those lines; the {@code rwe} verbs use it
 *       too.</li>
 *   <li>{@link robotworld.program.ParticipantMain#open} opens a participant's port so that a failure names the
 *       property that chooses another ({@code rwe.port.<Participant>.<kind>}).</li>
 * </ul>
 */
package robotworld.program;
