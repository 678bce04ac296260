package robotworld.testsupport;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

/**
 * The independent programs the tests talk to (socat, mbpoll, Python and npm packages), as {@code ./antw test}
 * provides them (see {@code test-setup/README.md}). A test that needs a peer asks for it here; when the peer is
 * missing the test is skipped, never failed, with one line naming what is missing and the command that installs
 * it. The test summary lists those lines.
 */
public final class TestPeers {

    private static final Map<String, Boolean> PYTHON_MODULES = new ConcurrentHashMap<>();

    private TestPeers() {
    }

    /** Skips the test unless {@code command} is on the PATH; {@code debianPackage} is what provides it. */
    public static void requireCommand(String command, String debianPackage) {
        assumeTrue(onPath(command), command + " is missing: install it with 'sudo apt-get install " + debianPackage
                + "' (./antw test does so itself when run as root or with password-less sudo)");
    }

    /**
     * Skips the test unless this Java runtime can open windows: a headless JRE (Debian's {@code -headless} package)
     * lacks the X11 toolkit ({@code libawt_xawt}) and reports itself headless whatever the display.
     */
    public static void requireFullJre() {
        String jrePackage = "openjdk-" + Runtime.version().feature() + "-jre";
        assumeTrue(Files.exists(Path.of(System.getProperty("java.home"), "lib", "libawt_xawt.so")),
                "the full Java runtime is missing (this one is headless, without libawt_xawt): install it with 'sudo"
                        + " apt-get install " + jrePackage + "' (./antw test does so itself when run as root or with"
                        + " password-less sudo)");
    }

    /** Whether an executable {@code command} is on the PATH. */
    public static boolean onPath(String command) {
        String path = System.getenv().getOrDefault("PATH", "");
        for (String folder : path.split(File.pathSeparator)) {
            if (!folder.isEmpty() && Files.isExecutable(Path.of(folder, command))) {
                return true;
            }
        }
        return false;
    }

    /**
     * A Python interpreter that can import every one of {@code modules}, or the test is skipped. It is the one
     * {@code ./antw test} set up from {@code test-setup/requirements.txt} ({@code -Drwe.test.python}), else
     * {@code python3} from the PATH.
     */
    public static String python(String... modules) {
        String python = System.getProperty("rwe.test.python", "python3");
        for (String module : modules) {
            boolean importable = PYTHON_MODULES.computeIfAbsent(python + " " + module, key -> canImport(python, module));
            assumeTrue(importable, "the Python package " + module + " is missing: ./antw test installs"
                    + " test-setup/requirements.txt into a virtual environment (needs python3 with venv: 'sudo apt-get"
                    + " install python3-venv')");
        }
        return python;
    }

    private static boolean canImport(String python, String module) {
        try {
            Process process = new ProcessBuilder(python, "-c", "import " + module)
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            if (!process.waitFor(60, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                return false;
            }
            return process.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /**
     * The {@code node_modules} folder holding the npm package {@code name} (as installed by {@code ./antw test}
     * from {@code test-setup/package.json}, {@code -Drwe.test.node_modules}), or the test is skipped.
     */
    public static Path nodeModules(String name) {
        requireCommand("node", "nodejs");
        String folder = System.getProperty("rwe.test.node_modules");
        assumeTrue(folder != null && Files.isDirectory(Path.of(folder, name)), "the npm package " + name
                + " is missing: ./antw test installs test-setup/package.json (needs npm: 'sudo apt-get install npm')");
        return Path.of(folder);
    }
}
