package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.testsupport.TestPeers;
import robotworld.x10.CM11aController;

/**
 * A serial device another program holds is refused with the holder named, whether the holder left a UUCP lock file
 * or simply has the device open; a stale lock file is taken over; our own lock file lives as long as our link.
 */
class PortLockTest {

    @TempDir
    Path lockDir;

    private SocatPty pty;
    private Process holder;
    private String previousLockDir;

    @BeforeEach
    void start() throws Exception {
        TestPeers.requireCommand("socat", "socat");
        previousLockDir = System.setProperty("rwe.lock.dir", lockDir.toString());
        pty = SocatPty.start();
    }

    @AfterEach
    void stop() throws Exception {
        if (holder != null) {
            holder.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
        }
        if (pty != null) {
            pty.close();
        }
        if (previousLockDir == null) {
            System.clearProperty("rwe.lock.dir");
        } else {
            System.setProperty("rwe.lock.dir", previousLockDir);
        }
    }

    private Path lockFileOf(Path link) throws IOException {
        return lockDir.resolve("LCK.." + PortLock.lockName(link.toRealPath()));
    }

    @Test
    void aLiveLockFileOwnerIsNamedAndNothingIsSent() throws Exception {
        holder = new ProcessBuilder("sleep", "60").start();
        Files.writeString(lockFileOf(pty.b()), String.format("%10d%n", holder.pid()));
        PortInUseException e = assertThrows(PortInUseException.class,
                () -> CM11aController.open(pty.b().toString()));
        assertTrue(e.getMessage().contains("in use by sleep (process " + holder.pid() + ")"), e.getMessage());
        assertTrue(e.getMessage().contains(lockFileOf(pty.b()).toString()), e.getMessage());
        try (SerialLink other = SerialLinks.open(pty.a().toString(), SerialSettings.eightNoneOne(4800))) {
            assertEquals(0, other.read(new byte[8], 0, 8, java.time.Duration.ofMillis(100)), "no frame went out");
        }
    }

    @Test
    void aProgramThatHasTheDeviceOpenIsNamedWithoutAnyLockFile() throws Exception {
        holder = new ProcessBuilder("sleep", "60").redirectInput(pty.b().toRealPath().toFile()).start();
        long giveUp = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        PortInUseException e = null;
        while (e == null) { // the child opens the device just after start()
            try {
                SerialLinks.open(pty.b().toString(), SerialSettings.eightNoneOne(115_200)).close();
                assertTrue(System.nanoTime() < giveUp, "the holder was never noticed");
            } catch (PortInUseException refused) {
                e = refused;
            }
        }
        assertTrue(e.getMessage().contains("in use by sleep (process " + holder.pid() + "), which has it open"),
                e.getMessage());
    }

    @Test
    void aStaleLockFileIsTakenOverAndOursLastsAsLongAsTheLink() throws Exception {
        Process gone = new ProcessBuilder("true").start();
        gone.waitFor(5, TimeUnit.SECONDS);
        Path lock = lockFileOf(pty.b());
        Files.writeString(lock, String.format("%10d%n", gone.pid()));
        try (SerialLink link = SerialLinks.open(pty.b().toString(), SerialSettings.eightNoneOne(115_200))) {
            assertTrue(link.isOpen());
            assertEquals(String.format("%10d%n", ProcessHandle.current().pid()), Files.readString(lock));
            PortInUseException twice = assertThrows(PortInUseException.class,
                    () -> SerialLinks.open(pty.b().toString(), SerialSettings.eightNoneOne(115_200)));
            assertTrue(twice.getMessage().contains("already open in this program"), twice.getMessage());
        }
        assertFalse(Files.exists(lock), "removed when the link closed");
    }

    @Test
    void aFolderOrAMissingDeviceGetsAMessageThatSaysSo(@TempDir Path folder) {
        IOException directory = assertThrows(IOException.class,
                () -> SerialLinks.open(folder.toString(), SerialSettings.eightNoneOne(115_200)));
        assertTrue(directory.getMessage().contains("is a directory, not a serial device"), directory.getMessage());
        IOException missing = assertThrows(IOException.class,
                () -> SerialLinks.open(folder.resolve("ttyUSB9").toString(), SerialSettings.eightNoneOne(115_200)));
        assertTrue(missing.getMessage().contains("no such serial device"), missing.getMessage());
    }
}
