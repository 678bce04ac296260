package robotworld.explorer.demo;

import java.io.PrintWriter;
import java.io.Writer;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Reads the console monitor's lines ({@code time participant module function value (host)}): counts what the
 * monitor received and prints only the changes (a line whose value differs from the module function's last one),
 * so a polling control program does not flood the terminal.
 */
final class MonitorTally extends Writer {

    /** A single bumper's answer {@code <number, contact>} with contact 1 or true. */
    private static final java.util.regex.Pattern CONTACT = java.util.regex.Pattern.compile("<\\d+,\\s*(1|true)>");

    private volatile PrintWriter echo;
    private final StringBuilder pending = new StringBuilder();
    private final Map<String, String> last = new HashMap<>();
    final AtomicInteger answers = new AtomicInteger();
    final AtomicInteger bumpAnswers = new AtomicInteger();
    final AtomicInteger lampOn = new AtomicInteger();
    final AtomicInteger lampOff = new AtomicInteger();
    final AtomicInteger motorAnswers = new AtomicInteger();
    final AtomicInteger stops = new AtomicInteger();

    /** @param echo where the changed lines go, or null for none */
    MonitorTally(PrintWriter echo) {
        this.echo = echo;
    }

    @Override
    public synchronized void write(char[] buffer, int offset, int length) {
        for (int i = offset; i < offset + length; i++) {
            char c = buffer[i];
            if (c == '\n') {
                line(pending.toString().stripTrailing());
                pending.setLength(0);
            } else {
                pending.append(c);
            }
        }
    }

    private void line(String line) {
        if (line.isBlank()) {
            return;
        }
        String[] parts = line.trim().split("\\s+");
        if (line.startsWith("#") || parts.length < 4) {
            print(line);
            return;
        }
        if (parts[3].equals("STOPPED")) {
            stops.incrementAndGet();
            print(line);
            return;
        }
        answers.incrementAndGet();
        String participant = parts[1];
        String module = parts[2];
        String function = parts[3];
        String value = parts.length > 5 ? String.join(" ", java.util.Arrays.copyOfRange(parts, 4, parts.length - 1))
                : "";
        if (function.startsWith("getSingleBumper") && CONTACT.matcher(value).find()) {
            bumpAnswers.incrementAndGet();
        } else if (function.startsWith("setMotor")) {
            motorAnswers.incrementAndGet();
        } else if (function.equals("on")) {
            lampOn.incrementAndGet();
        } else if (function.equals("off")) {
            lampOff.incrementAndGet();
        }
        // the first value is the motor or bumper number: one "last value" per motor and per bumper
        String first = value.isEmpty() ? "" : value.split("[\\s,]+")[0];
        String key = participant + " " + module + " " + function + " " + first;
        if (!value.equals(last.put(key, value)) || function.equals("on") || function.equals("off")) {
            print(line);
        }
    }

    private void print(String line) {
        if (echo != null) {
            echo.println("  monitor | " + line);
            echo.flush();
        }
    }

    /** From now on, prints the changed lines to {@code newEcho} (the window could not be opened after all). */
    void echoTo(PrintWriter newEcho) {
        echo = newEcho;
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
    }
}
