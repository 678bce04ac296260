package robotworld.explorer.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Thesis listing 5.2, as the demo puts it into a generated main class, with the world-unique module names.
 * The same text goes into either viewpoint (thesis 5.3: the program is interchangeable).
 */
public final class ControlProgram {

    /** The marked place in a generated main class's control() method: the program replaces what is between. */
    public static final String MARKER = "// >>> control logic begins here";
    public static final String END_MARKER = "// <<< control logic ends here";

    /** System property: end of the run, milliseconds since the epoch. */
    public static final String UNTIL_PROPERTY = "rwe.demo.until";

    /** The prefix of the lines the program prints at its end, read back by the demo for its summary. */
    public static final String STATS = "DEMO-STATS";

    /**
     * Listing 5.2 with the demo's documented changes: the loop ends at {@code rwe.demo.until} or on an interrupt
     * instead of never; the waits are shortened (back off 300 ms instead of 500, evaluate 600 ms instead of 3000,
     * turn 700 ms instead of 1000) so a 30 s run shows several bumps; the forward loop polls every 100 ms instead of
     * flat out; the motors stop at the end; every module call is timed and the bumps counted for the summary.
     */
    public static final String LISTING_5_2 = """
            // ---- thesis listing 5.2, bounded and timed for `rwe demo` (see docs/demo.md) ----
            final int LEFT = 1;
            final int RIGHT = 2;
            final long until = Long.getLong("rwe.demo.until", Long.MAX_VALUE);
            class Timer {
                final String name;
                final java.util.List<Long> micros = new java.util.ArrayList<>();
                long started;
                Timer(String name) { this.name = name; }
                void start() { started = System.nanoTime(); }
                void stop() { micros.add((System.nanoTime() - started) / 1000); }
                String stats() {
                    java.util.List<Long> sorted = new java.util.ArrayList<>(micros);
                    java.util.Collections.sort(sorted);
                    int n = sorted.size();
                    return "DEMO-STATS name=" + name + " calls=" + n
                            + " p50us=" + (n == 0 ? 0 : sorted.get((n - 1) / 2))
                            + " p99us=" + (n == 0 ? 0 : sorted.get((int) Math.ceil(n * 0.99) - 1))
                            + " maxus=" + (n == 0 ? 0 : sorted.get(n - 1));
                }
            }
            Timer drive = new Timer("drive");
            Timer lamp = new Timer("lamp");
            int bumps = 0;
            try {
                while (!Thread.currentThread().isInterrupted() && System.currentTimeMillis() < until) {
                    //--- forward ---
                    drive.start(); MotorModule1.setMotor(LEFT, 0.25); drive.stop();
                    drive.start(); MotorModule1.setMotor(RIGHT, 0.25); drive.stop();
                    drive.start(); boolean front = BumperModule1.getSingleBumper(6); drive.stop();
                    if (!front) {
                        drive.start(); front = BumperModule1.getSingleBumper(4); drive.stop();
                    }
                    if (front) {
                        bumps++;
                        System.out.println("DEMO-BUMP " + bumps);
                        //--- back ---
                        drive.start(); MotorModule1.setMotor(LEFT, -0.3); drive.stop();
                        drive.start(); MotorModule1.setMotor(RIGHT, -0.3); drive.stop();
                        Thread.sleep(300);
                        //--- switch lamp on ---
                        lamp.start(); X10ApplianceModule1.on(); lamp.stop();
                        //--- evaluate situation (simulated) ---
                        Thread.sleep(600);
                        //--- turn ---
                        drive.start(); MotorModule1.setMotor(LEFT, 0.4); drive.stop();
                        drive.start(); MotorModule1.setMotor(RIGHT, -0.4); drive.stop();
                        Thread.sleep(700);
                        //--- switch lamp off again ---
                        lamp.start(); X10ApplianceModule1.off(); lamp.stop();
                    } else {
                        Thread.sleep(100);
                    }
                }
            } catch (InterruptedException stopped) {
                Thread.currentThread().interrupt();
            } catch (RuntimeException failed) {
                System.out.println("DEMO-FAILED " + failed);
                throw failed;
            } finally {
                MotorModule1.setMotor(LEFT, 0);
                MotorModule1.setMotor(RIGHT, 0);
                System.out.println(drive.stats());
                System.out.println(lamp.stats());
                System.out.println("DEMO-STATS name=bumps count=" + bumps);
                System.out.println("DEMO-END");
                System.out.flush();
            }
            """;

    private ControlProgram() {
    }

    /** Puts the listing between the markers of {@code mainSource}, in place of what the generator wrote there. */
    public static void insert(Path mainSource) throws IOException {
        String source = Files.readString(mainSource);
        int begin = source.indexOf(MARKER);
        int end = source.indexOf(END_MARKER);
        if (begin < 0 || end < begin) {
            throw new IllegalStateException(mainSource + " has no marked place for control logic");
        }
        if (source.contains("DEMO-STATS")) {
            return; // already in (a re-run over the same project)
        }
        int lineEnd = source.indexOf('\n', begin) + 1;
        int endLine = source.lastIndexOf('\n', end) + 1;
        Files.writeString(mainSource, source.substring(0, lineEnd) + LISTING_5_2 + source.substring(endLine));
    }
}
