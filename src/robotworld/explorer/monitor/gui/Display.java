package robotworld.explorer.monitor.gui;

import java.awt.GraphicsEnvironment;

/**
 * Whether windows can be opened here, asked once: a display may be missing, named but unreachable (a stale
 * {@code DISPLAY}), or the Java runtime may be a headless one without a graphics toolkit. The answer is a short
 * reason a user can act on, never a stack trace.
 */
public final class Display {

    private static volatile String problem;
    private static volatile boolean probed;

    private Display() {
    }

    /** Null when windows can be opened, else why not, in a few words (no advice: the caller knows its options). */
    public static String problem() {
        if (!probed) {
            synchronized (Display.class) {
                if (!probed) {
                    problem = probe();
                    probed = true;
                }
            }
        }
        return problem;
    }

    /** Whether windows can be opened here. */
    public static boolean usable() {
        return problem() == null;
    }

    private static String probe() {
        String display = System.getenv("DISPLAY");
        boolean x11 = !System.getProperty("os.name", "").startsWith("Windows")
                && !System.getProperty("os.name", "").startsWith("Mac");
        if (GraphicsEnvironment.isHeadless()) {
            if (x11 && (display == null || display.isBlank())) {
                return "no display (DISPLAY is not set)";
            }
            return "this Java runtime runs headless (java.awt.headless=true)";
        }
        try {
            if (GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices().length == 0) {
                return "the display " + display + " has no screens";
            }
            return null;
        } catch (UnsatisfiedLinkError | NoClassDefFoundError e) {
            return "this Java runtime has no graphics toolkit (a headless JRE; install the full one, e.g. "
                    + "openjdk-17-jre)";
        } catch (Throwable e) { // AWTError and friends: a DISPLAY that names no reachable X server
            return "cannot open the display " + (display == null ? "" : "'" + display + "' ")
                    + "(no X server answers there)";
        }
    }
}
