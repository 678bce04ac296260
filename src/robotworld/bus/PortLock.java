package robotworld.bus;

import java.io.Closeable;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Makes sure no other program uses a serial device before it is opened, and tells other programs that we do.
 * jSerialComm already opens a port exclusively (TIOCEXCL and flock), but neither stops a program that does not ask
 * (TIOCEXCL does not apply to root, and many X10 and terminal programs use neither), so two more checks come first:
 * <ol>
 * <li>the UUCP lock file ({@code /var/lock/LCK..ttyUSB0}, holding the PID of its owner in ASCII), which heyu,
 *     minicom and other serial programs honour: a live owner refuses the port, a dead one's file is removed, and
 *     we write our own while we hold the port (where we may: the folder is often root's only);</li>
 * <li>on Linux, any other process that has the device open ({@code /proc/PID/fd}), except the process holding the
 *     master side of a pseudo-terminal, which is its other end (e.g. socat).</li>
 * </ol>
 * A refusal is a {@link PortInUseException} naming the holder. The lock folder is {@code /var/lock}, or the system
 * property {@code rwe.lock.dir} (empty: no lock files).
 */
final class PortLock implements Closeable {

    private static final Logger LOG = LoggerFactory.getLogger(PortLock.class);
    private static final Path PROC = Path.of("/proc");

    private final Path lockFile;

    private PortLock(Path lockFile) {
        this.lockFile = lockFile;
    }

    /**
     * Checks and locks {@code portName} (a device path).
     *
     * @throws PortInUseException naming the program that holds it
     * @throws IOException naming what is wrong with the path (missing, a directory, not a device)
     */
    static PortLock acquire(String portName) throws IOException {
        Path given = Path.of(portName);
        if (!portName.startsWith("/")) {
            return new PortLock(null); // COM4 and the like: the operating system keeps ports exclusive there
        }
        if (!Files.exists(given)) {
            throw new NoSuchFileException(portName, null, "no such serial device (is the adapter plugged in? "
                    + "see ls /dev/ttyUSB* /dev/ttyACM*)");
        }
        if (Files.isDirectory(given)) {
            throw new IOException(portName + ": is a directory, not a serial device: give the device itself, e.g. "
                    + "/dev/ttyUSB0");
        }
        Path device = given.toRealPath();
        if (Files.isRegularFile(device, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException(portName + ": is a regular file, not a serial device");
        }
        Optional<Path> folder = lockFolder();
        Path lock = folder.map(f -> f.resolve("LCK.." + lockName(device))).orElse(null);
        if (lock != null) {
            checkLockFile(portName, lock);
        }
        checkOpenElsewhere(portName, device);
        return new PortLock(lock == null ? null : create(portName, lock));
    }

    /** The lock file's name after {@code LCK..}: the device's path under /dev, '/' as '_' (ttyUSB0, pts_3). */
    static String lockName(Path device) {
        Path dev = Path.of("/dev");
        String name = device.startsWith(dev) ? dev.relativize(device).toString() : device.getFileName().toString();
        return name.replace('/', '_');
    }

    private static Optional<Path> lockFolder() {
        String configured = System.getProperty("rwe.lock.dir");
        if (configured != null) {
            return configured.isBlank() ? Optional.empty() : Optional.of(Path.of(configured));
        }
        Path standard = Path.of("/var/lock");
        return Files.isDirectory(standard) ? Optional.of(standard) : Optional.empty();
    }

    private static void checkLockFile(String portName, Path lock) throws IOException {
        if (!Files.exists(lock, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        long pid = readPid(lock);
        if (pid > 0 && pid != ProcessHandle.current().pid() && isAlive(pid)) {
            throw new PortInUseException(portName, describe(pid), "is in use by " + describe(pid) + " (its lock file "
                    + lock + " says so): stop that program, or give another port");
        }
        if (pid == ProcessHandle.current().pid()) {
            throw new PortInUseException(portName, "this program", "is already open in this program (lock file " + lock
                    + ")");
        }
        try {
            Files.deleteIfExists(lock);
            LOG.info("{}: removed the stale lock file {} (process {} is gone)", portName, lock, pid);
        } catch (IOException e) {
            LOG.debug("{}: cannot remove the stale lock file {}: {}", portName, lock, e.getMessage());
        }
    }

    /** The owner's PID: ten ASCII digits and a newline (HDB UUCP), or a binary int of old systems; 0 if unreadable. */
    private static long readPid(Path lock) {
        try {
            byte[] content = Files.readAllBytes(lock);
            String text = new String(content, StandardCharsets.US_ASCII).trim();
            if (text.matches("\\d{1,10}")) {
                return Long.parseLong(text);
            }
            if (content.length == 4) {
                return (content[0] & 0xFF) | (content[1] & 0xFF) << 8 | (content[2] & 0xFF) << 16
                        | (long) (content[3] & 0xFF) << 24;
            }
        } catch (IOException e) {
            LOG.debug("cannot read lock file {}: {}", lock, e.getMessage());
        }
        return 0;
    }

    private static boolean isAlive(long pid) {
        return ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(Files.isDirectory(PROC.resolve(
                Long.toString(pid))));
    }

    /** "heyu (process 1234)", or just the process when its name cannot be read. */
    static String describe(long pid) {
        String name = null;
        try {
            name = Files.readString(PROC.resolve(pid + "/comm")).trim();
        } catch (IOException e) {
            name = ProcessHandle.of(pid).flatMap(p -> p.info().command()).map(c -> Path.of(c).getFileName()
                    .toString()).orElse(null);
        }
        return (name == null || name.isEmpty() ? "a program" : name) + " (process " + pid + ")";
    }

    /** Linux: another process with the device open, other than its pseudo-terminal master, refuses the port. */
    private static void checkOpenElsewhere(String portName, Path device) throws IOException {
        if (!Files.isDirectory(PROC.resolve("self/fd"))) {
            return;
        }
        long self = ProcessHandle.current().pid();
        Integer ptyIndex = ptyIndex(device);
        try (DirectoryStream<Path> processes = Files.newDirectoryStream(PROC, "[0-9]*")) {
            for (Path process : processes) {
                long pid = Long.parseLong(process.getFileName().toString());
                if (pid != self && holds(process, device) && !(ptyIndex != null && holdsMaster(process, ptyIndex))) {
                    throw new PortInUseException(portName, describe(pid), "is in use by " + describe(pid) + ", which "
                            + "has it open: stop that program, or give another port");
                }
            }
        } catch (IOException e) {
            if (e instanceof PortInUseException) {
                throw e;
            }
            LOG.debug("cannot look for other users of {}: {}", portName, e.getMessage());
        }
    }

    private static boolean holds(Path process, Path device) {
        try (DirectoryStream<Path> fds = Files.newDirectoryStream(process.resolve("fd"))) {
            for (Path fd : fds) {
                try {
                    if (device.equals(Files.readSymbolicLink(fd))) {
                        return true;
                    }
                } catch (IOException | UnsupportedOperationException e) {
                    // gone meanwhile, or not ours to see
                }
            }
        } catch (IOException e) {
            // the process ended, or we may not look
        }
        return false;
    }

    /** Whether the process holds the master side of pseudo-terminal {@code index} (/dev/ptmx with that tty-index). */
    private static boolean holdsMaster(Path process, int index) {
        try (DirectoryStream<Path> fds = Files.newDirectoryStream(process.resolve("fd"))) {
            for (Path fd : fds) {
                try {
                    if (Path.of("/dev/ptmx").equals(Files.readSymbolicLink(fd))) {
                        for (String line : Files.readAllLines(process.resolve("fdinfo/" + fd.getFileName()))) {
                            if (line.equals("tty-index:\t" + index)) {
                                return true;
                            }
                        }
                    }
                } catch (IOException | UnsupportedOperationException e) {
                    // gone meanwhile
                }
            }
        } catch (IOException e) {
            // the process ended
        }
        return false;
    }

    private static Integer ptyIndex(Path device) {
        if (device.getParent() != null && device.getParent().equals(Path.of("/dev/pts"))) {
            try {
                return Integer.parseInt(device.getFileName().toString());
            } catch (NumberFormatException e) {
                return null;
            }
        }
        return null;
    }

    /** Writes our lock file; null when the folder is not ours to write (the checks above still held). */
    private static Path create(String portName, Path lock) throws IOException {
        String content = String.format("%10d%n", ProcessHandle.current().pid());
        try {
            Files.writeString(lock, content, StandardCharsets.US_ASCII, StandardOpenOption.CREATE_NEW,
                    StandardOpenOption.WRITE);
            return lock;
        } catch (FileAlreadyExistsException e) {
            long pid = readPid(lock);
            throw new PortInUseException(portName, describe(pid), "was taken by " + describe(pid) + " just now (lock "
                    + "file " + lock + ")");
        } catch (AccessDeniedException | NoSuchFileException e) {
            LOG.debug("no lock file {}: {}", lock, e.getMessage());
            return null;
        }
    }

    /** Removes our lock file. */
    @Override
    public void close() {
        if (lockFile != null) {
            try {
                Files.deleteIfExists(lockFile);
            } catch (IOException e) {
                LOG.debug("cannot remove lock file {}: {}", lockFile, e.getMessage());
            }
        }
    }
}
