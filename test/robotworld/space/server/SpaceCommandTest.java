package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import robotworld.explorer.cli.Rwe;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.SpaceRequestRejectedException;
import robotworld.space.SpaceUnavailableException;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;

/** {@code rwe space}: prints its URL, serves until stopped, stops cleanly; honours --token-file. */
@org.junit.jupiter.api.Timeout(30)
class SpaceCommandTest {

    private static final Pattern URL = Pattern.compile("listening on (http://\\S+)");

    /** Runs {@code rwe space ARGS} on its own thread; stop it by interrupting that thread. */
    private static final class Running {
        final StringWriter out = new StringWriter();
        final AtomicInteger exit = new AtomicInteger(-1);
        final Thread thread;

        Running(String... args) {
            thread = new Thread(() -> exit.set(Rwe.run(new PrintWriter(out, true), new PrintWriter(new StringWriter(),
                    true), args)), "rwe-space-under-test");
            thread.start();
        }

        URI awaitUrl() throws InterruptedException {
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (System.nanoTime() < deadline) {
                Matcher matcher = URL.matcher(out.toString());
                if (matcher.find()) {
                    return URI.create(matcher.group(1));
                }
                Thread.sleep(5);
            }
            fail("no URL printed: " + out);
            return null;
        }

        int stop() throws InterruptedException {
            thread.interrupt();
            thread.join(10_000);
            return exit.get();
        }
    }

    @Test
    void servesOnLoopbackUntilStopped() throws Exception {
        Running command = new Running("space", "--port", "0");
        URI url = command.awaitUrl();
        assertEquals("127.0.0.1", url.getHost());
        try (RemoteSpace space = RemoteSpace.open(url)) {
            ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
            space.write(ref, Timeout.TRY_ONCE, Entry.of("hello"));
            assertEquals(List.of(Entry.of("hello")), space.take(ref, Timeout.TRY_ONCE));
        }
        assertEquals(0, command.stop());
        assertTrue(command.out.toString().contains("space server stopped"), command.out.toString());
        assertThrows(SpaceUnavailableException.class, () -> RemoteSpace.open(url,
                RemoteSpace.Options.defaults().networkAllowanceMillis(200)));
    }

    @Test
    void aTokenFileMakesTheTokenMandatory(@TempDir Path dir) throws Exception {
        Path tokenFile = dir.resolve("token");
        Files.writeString(tokenFile, "s3cret-token\n");
        Running command = new Running("space", "--port", "0", "--token-file", tokenFile.toString());
        URI url = command.awaitUrl();
        assertTrue(command.out.toString().contains("token required"), command.out.toString());
        SpaceRequestRejectedException refused = assertThrows(SpaceRequestRejectedException.class,
                () -> RemoteSpace.open(url));
        assertEquals(401, refused.status());
        try (RemoteSpace space = RemoteSpace.open(url, RemoteSpace.Options.defaults().token("s3cret-token"))) {
            space.createContainer(ContainerSpec.defaults());
        }
        assertEquals(0, command.stop());
    }

    @Test
    void anEmptyTokenFileIsAnError(@TempDir Path dir) throws Exception {
        Path tokenFile = dir.resolve("empty");
        Files.writeString(tokenFile, "  \n");
        StringWriter err = new StringWriter();
        int exit = Rwe.run(new PrintWriter(new StringWriter(), true), new PrintWriter(err, true), "space", "--port", "0",
                "--token-file", tokenFile.toString());
        assertEquals(1, exit);
        assertTrue(err.toString().contains("empty"), err.toString());
    }
}
