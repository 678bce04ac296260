package robotworld.core;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/** Reads a space access token from a file (its first line, trimmed), so that it never appears in a command line. */
public final class TokenFile {

    private TokenFile() {
    }

    /**
     * The token in {@code file}.
     *
     * @throws IllegalStateException naming the file and what is wrong with it
     */
    public static String read(Path file) {
        String token;
        try {
            token = Files.readString(file, StandardCharsets.UTF_8).lines().findFirst().orElse("").strip();
        } catch (NoSuchFileException e) {
            throw new IllegalStateException("the token file " + file + " does not exist");
        } catch (IOException e) {
            throw new IllegalStateException("cannot read the token file " + file + ": " + e.getMessage());
        }
        if (token.isEmpty()) {
            throw new IllegalStateException("the token file " + file + " is empty");
        }
        return token;
    }
}
