package robotworld.testsupport;

import java.nio.file.Path;

/** Where the project's own files are when tests run (the build passes rwe.home; IDEs run from the root). */
public final class ProjectFiles {

    private ProjectFiles() {
    }

    public static Path root() {
        return Path.of(System.getProperty("rwe.home", System.getProperty("user.dir"))).toAbsolutePath();
    }

    public static Path resolve(String relative) {
        return root().resolve(relative);
    }
}
