package robotworld.observe;

import robotworld.core.BumperModule;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMRuntime;

/**
 * A program that serves one bumper module and does nothing else, in a JVM of its own so that a test can kill it:
 * {@code ServingChild SPACE_URL HOST PARTICIPANT MODULE}. Prints {@code READY <program id>} once it serves.
 */
public final class ServingChild {

    private ServingChild() {
    }

    public static void main(String[] args) throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(args[0], args[1])) {
            serveIdleBumper(runtime, args[2], args[3]);
            System.out.println("READY " + runtime.programId());
            System.out.flush();
            runtime.serveUntilStopped();
        }
    }

    /** Serves a bumper module that never touches anything: a program with a module and nothing to do. */
    static void serveIdleBumper(XVSMRuntime runtime, String participant, String module) {
        runtime.own(new XVSMBumperModuleLocal(runtime, participant, module, new BumperModule() {
            @Override
            public int getAllBumper() {
                return 0;
            }

            @Override
            public boolean getSingleBumper(int bumperNumber) {
                return false;
            }
        }));
    }
}
