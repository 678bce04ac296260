package robotworld.explorer.cli;

import java.io.PrintWriter;

/**
 * A one-line text progress bar redrawn in place with a carriage return, e.g.
 * {@code [##########----------]  124/247  address 124  2 found}. Messages printed through it appear on lines of
 * their own above the bar.
 */
final class ProgressBar {

    private static final int WIDTH = 30;
    /** Redraw at most this often (plus whenever the bar grows), so a log of stderr stays short. */
    private static final long REDRAW_NANOS = 100_000_000L;

    private final PrintWriter out;
    private final int total;
    private String lastDrawn = "";
    private int lastLength;
    private int lastFilled = -1;
    private long lastDrawAt;

    ProgressBar(PrintWriter out, int total) {
        this.out = out;
        this.total = Math.max(1, total);
    }

    /** Redraws the bar when what it shows has changed. */
    void show(int done, int address, int found) {
        int filled = (int) ((long) done * WIDTH / total);
        String line = "[" + "#".repeat(filled) + "-".repeat(WIDTH - filled) + "] "
                + String.format("%3d/%d  address %3d  %d found", done, total, address, found);
        long now = System.nanoTime();
        boolean due = filled != lastFilled || done >= total || now - lastDrawAt >= REDRAW_NANOS;
        if (line.equals(lastDrawn) || !due) {
            return;
        }
        lastFilled = filled;
        lastDrawAt = now;
        draw(line);
    }

    /** Prints a message on its own line and redraws the bar below it. */
    void message(String text) {
        String bar = lastDrawn;
        clear();
        out.println(text);
        if (!bar.isEmpty()) {
            draw(bar);
        }
        out.flush();
    }

    /** Ends the bar's line. */
    void finish() {
        if (!lastDrawn.isEmpty()) {
            out.println();
            out.flush();
            lastDrawn = "";
            lastLength = 0;
        }
    }

    private void draw(String line) {
        out.print("\r" + line + " ".repeat(Math.max(0, lastLength - line.length())));
        out.flush();
        lastDrawn = line;
        lastLength = line.length();
    }

    private void clear() {
        if (lastLength > 0) {
            out.print("\r" + " ".repeat(lastLength) + "\r");
        }
        lastDrawn = "";
        lastLength = 0;
    }
}
