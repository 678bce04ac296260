package robotworld.explorer.monitor;

/**
 * The brightness of an X10 lamp as far as a monitor can know it. X10 commands are relative (dim by n %,
 * brighten by n %) and a lamp cannot be asked, so the level is the sum of the changes seen, clamped to 0..100,
 * starting from the lamp's known behaviour: switched on from off it goes to full brightness, and a dim or
 * brighten while off first switches it on at full brightness (as the LM465 and {@code SimulatedLampModule} do).
 * The estimate is exact once the lamp has been switched on while monitored; before that it assumes full.
 * Not thread-safe.
 */
public final class LampLevel {

    /** Full brightness, percent. */
    public static final int FULL = 100;

    private boolean on;
    private int level = FULL;

    /** {@code on()}: full brightness when it was off, unchanged when it was on. */
    public void on() {
        if (!on) {
            level = FULL;
            on = true;
        }
    }

    /** {@code off()}: the level is kept for display, the lamp is dark. */
    public void off() {
        on = false;
    }

    /** {@code brighten(percent)}. */
    public void brighten(int percent) {
        on();
        level = Math.min(FULL, level + percent);
    }

    /** {@code dim(percent)}. */
    public void dim(int percent) {
        on();
        level = Math.max(0, level - percent);
    }

    /** Whether the lamp is on. */
    public boolean isOn() {
        return on;
    }

    /** The estimated brightness while on, percent 0..100. */
    public int level() {
        return level;
    }
}
