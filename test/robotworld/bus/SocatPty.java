package robotworld.bus;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import robotworld.testsupport.TestPeers;

/**
 * A pseudo-terminal pair made by {@code socat -d -d pty,rawer,link=A pty,rawer,link=B} in a temporary folder:
 * what one end writes, the other reads, as through a null-modem cable. Close it to end socat.
 */
public final class SocatPty implements AutoCloseable {

    private static final long START_TIMEOUT_MS = 5_000;

    private final Path folder;
    private final Process socat;

    private SocatPty(Path folder, Process socat) {
        this.folder = folder;
        this.socat = socat;
    }

    /** Starts socat and waits until both links exist. Skips the calling test when socat is not installed. */
    public static SocatPty start() throws IOException, InterruptedException {
        return startIn(Files.createTempDirectory("rwe-pty"));
    }

    /**
     * Starts socat with its links A and B in {@code folder}: after {@link #unplug()}, a new pair in the same folder
     * is the same device plugged in again (same names, new pseudo-terminals).
     */
    public static SocatPty startIn(Path folder) throws IOException, InterruptedException {
        TestPeers.requireCommand("socat", "socat");
        Process socat;
        try {
            socat = new ProcessBuilder("socat", "-d", "-d",
                    "pty,rawer,link=" + folder.resolve("A"), "pty,rawer,link=" + folder.resolve("B"))
                    .redirectErrorStream(true)
                    .redirectOutput(folder.resolve("socat.log").toFile())
                    .start();
        } catch (IOException e) {
            throw new IOException("socat is needed for the pty tests (apt-get install socat): " + e.getMessage(), e);
        }
        SocatPty pty = new SocatPty(folder, socat);
        long deadline = System.currentTimeMillis() + START_TIMEOUT_MS;
        while (!(Files.exists(pty.a()) && Files.exists(pty.b()))) {
            if (!socat.isAlive() || System.currentTimeMillis() > deadline) {
                String log = Files.exists(folder.resolve("socat.log")) ? Files.readString(folder.resolve("socat.log"))
                        : "";
                pty.close();
                throw new IOException("socat did not create the pty pair: " + log);
            }
            Thread.sleep(10);
        }
        return pty;
    }

    /** Path of one end. */
    public Path a() {
        return folder.resolve("A");
    }

    /** Path of the other end. */
    public Path b() {
        return folder.resolve("B");
    }

    /** The folder of the links. */
    public Path folder() {
        return folder;
    }

    /** Ends socat: both ptys and their links vanish, as a USB adapter that is pulled out; the folder stays. */
    public void unplug() {
        socat.destroy();
        try {
            if (!socat.waitFor(2, TimeUnit.SECONDS)) {
                socat.destroyForcibly();
                socat.waitFor(2, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Ends socat (both ptys vanish) and removes the folder. */
    @Override
    public void close() throws IOException {
        unplug();
        try (Stream<Path> files = Files.walk(folder)) {
            files.sorted(Comparator.reverseOrder()).forEach(path -> path.toFile().delete());
        }
    }
}
