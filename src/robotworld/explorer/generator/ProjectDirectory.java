package robotworld.explorer.generator;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * A project being generated: everything is written into a hidden temporary directory beside the destination
 * and moved into place only when complete, so a failed generation leaves nothing behind (not even the parent
 * directories it had to create) and a reader never sees a half-written project. Directories and files are
 * created with the default permissions, so the project honours the user's umask.
 */
public final class ProjectDirectory implements AutoCloseable {

    private static final SecureRandom RANDOM = new SecureRandom();

    private final Path destination;
    private final Path staging;
    /** Parent directories this generation created, deepest first: removed again if it fails. */
    private final List<Path> createdParents;
    private final List<Path> written = new ArrayList<>();
    private boolean committed;

    private ProjectDirectory(Path destination, Path staging, List<Path> createdParents) {
        this.destination = destination;
        this.staging = staging;
        this.createdParents = createdParents;
    }

    /** Checks the destination and opens a staging directory beside it. */
    public static ProjectDirectory forDestination(Path destination, boolean force) throws GenerationException {
        Path target = destination.toAbsolutePath().normalize();
        if (Files.exists(target) && !Files.isDirectory(target)) {
            throw new GenerationException(target + " exists and is not a directory");
        }
        if (!force && Files.isDirectory(target) && !isEmpty(target)) {
            throw new GenerationException(target + " exists and is not empty; choose another destination or"
                    + " use --force to replace it");
        }
        Path parent = target.getParent();
        List<Path> created = new ArrayList<>();
        try {
            for (Path missing = parent; missing != null && Files.notExists(missing, LinkOption.NOFOLLOW_LINKS);
                 missing = missing.getParent()) {
                created.add(missing);
            }
            Files.createDirectories(parent);
            return new ProjectDirectory(target, createStaging(parent), created);
        } catch (IOException e) {
            removeEmpty(created);
            throw new GenerationException("cannot write to " + parent + ": " + describe(e), e);
        }
    }

    /**
     * A fresh hidden directory beside the destination. Not {@link Files#createTempDirectory}: that makes it
     * private (0700), and the project would keep that mode whatever the user's umask says.
     */
    private static Path createStaging(Path parent) throws IOException {
        for (int attempt = 0; ; attempt++) {
            Path candidate = parent.resolve(".rwe-generate-" + Long.toUnsignedString(RANDOM.nextLong(), 36));
            try {
                return Files.createDirectory(candidate);
            } catch (java.nio.file.FileAlreadyExistsException e) {
                if (attempt > 10) {
                    throw e;
                }
            }
        }
    }

    private static void removeEmpty(List<Path> directories) {
        for (Path directory : directories) {
            try {
                Files.deleteIfExists(directory);
            } catch (IOException e) {
                return; // not empty (someone else wrote there meanwhile) or not ours to remove: leave the rest
            }
        }
    }

    public void writeText(String relative, String text) throws GenerationException {
        Path file = resolve(relative);
        try {
            Files.createDirectories(file.getParent());
            Files.writeString(file, text, StandardCharsets.UTF_8);
            written.add(destination.resolve(relative));
        } catch (IOException e) {
            throw new GenerationException("cannot write " + relative + ": " + describe(e), e);
        }
    }

    public void copy(Path source, String relative) throws GenerationException {
        Path file = resolve(relative);
        try {
            Files.createDirectories(file.getParent());
            Files.copy(source, file);
            written.add(destination.resolve(relative));
        } catch (IOException e) {
            throw new GenerationException("cannot copy " + source + " into the project: " + describe(e), e);
        }
    }

    /** Moves the finished project into place, replacing an old one only now, when the new one is complete. */
    public List<Path> commit() throws GenerationException {
        Path previous = null;
        try {
            if (Files.exists(destination)) {
                previous = staging.resolveSibling(staging.getFileName() + ".old");
                move(destination, previous);
            }
            move(staging, destination);
            committed = true;
        } catch (IOException e) {
            if (previous != null && !Files.exists(destination)) {
                try {
                    move(previous, destination);
                    previous = null;
                } catch (IOException restore) {
                    e.addSuppressed(restore);
                }
            }
            throw new GenerationException("cannot move the project into " + destination + ": " + describe(e), e);
        } finally {
            if (previous != null) {
                deleteQuietly(previous);
            }
        }
        return List.copyOf(written);
    }

    /** Removes the staging directory, and the parent directories made for it, unless the project was committed. */
    @Override
    public void close() {
        if (!committed) {
            deleteQuietly(staging);
            removeEmpty(createdParents);
        }
    }

    private Path resolve(String relative) throws GenerationException {
        Path file = staging.resolve(relative).normalize();
        if (!file.startsWith(staging)) {
            throw new GenerationException("refusing to write outside the project: " + relative);
        }
        return file;
    }

    private static void move(Path from, Path to) throws IOException {
        try {
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to);
        }
    }

    private static boolean isEmpty(Path directory) throws GenerationException {
        try (Stream<Path> entries = Files.list(directory)) {
            return entries.findAny().isEmpty();
        } catch (IOException e) {
            throw new GenerationException("cannot read " + directory + ": " + describe(e), e);
        }
    }

    private static void deleteQuietly(Path root) {
        if (!Files.exists(root)) {
            return;
        }
        try (Stream<Path> paths = Files.walk(root)) {
            paths.sorted(Comparator.reverseOrder()).forEach(path -> {
                try {
                    Files.deleteIfExists(path);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        } catch (IOException | UncheckedIOException e) {
            // best effort: a leftover hidden staging directory is harmless and named .rwe-generate-*
        }
    }

    private static String describe(IOException e) {
        String message = e.getMessage();
        return e.getClass().getSimpleName().replace("Exception", "").replaceAll("([a-z])([A-Z])", "$1 $2")
                .toLowerCase() + (message == null ? "" : " (" + message + ")");
    }
}
