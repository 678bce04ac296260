package robotworld.core;

import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Warns, once per process, when the space token was given as {@code -Drwe.space.token=...}: every user of the
 * computer can read it in the process list ({@code ps}). The warning names the safer ways.
 */
final class TokenOnCommandLine {

    private static final AtomicBoolean WARNED = new AtomicBoolean();

    private TokenOnCommandLine() {
    }

    static void warnIfSo() {
        if (WARNED.get()) {
            return;
        }
        List<String> arguments = ProcessHandle.current().info().arguments().map(List::of).orElse(List.of());
        boolean visible = arguments.stream().anyMatch(argument -> argument.startsWith("-Drwe.space.token="));
        if (visible && WARNED.compareAndSet(false, true)) {
            System.getLogger("robotworld.core.RuntimeSettings").log(System.Logger.Level.WARNING,
                    "the space token is on the command line, where every user of this computer can read it (ps);"
                            + " set RWE_SPACE_TOKEN or -Drwe.space.tokenFile=FILE instead");
        }
    }
}
