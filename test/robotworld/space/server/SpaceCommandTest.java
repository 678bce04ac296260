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
            return awaitUrl(10);
        }

        URI awaitUrl(int seconds) throws InterruptedException {
            long deadline = System.nanoTime() + seconds * 1_000_000_000L;
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

    /** Two cluster members started as a user would: what one member's server stores, the other's serves. */
    @Test
    @org.junit.jupiter.api.Timeout(180)
    void membersOfAClusterServeOneSpace() throws Exception {
        String name = "rwe-test-" + java.util.UUID.randomUUID().toString().substring(0, 8);
        Running first = new Running("space", "--port", "0", "--cluster", name, "--member-port", "0");
        URI firstUrl = first.awaitUrl(120);
        Matcher member = Pattern.compile("cluster member of '" + name + "' at (\\S+),").matcher(first.out.toString());
        assertTrue(member.find(), first.out.toString());
        Running second = new Running("space", "--port", "0", "--cluster", name, "--member-port", "0",
                "--member", member.group(1), "--min-members", "2");
        try {
            URI secondUrl = second.awaitUrl(120);
            try (RemoteSpace one = RemoteSpace.open(firstUrl);
                 RemoteSpace both = RemoteSpace.open(List.of(secondUrl, firstUrl), RemoteSpace.Options.defaults())) {
                ContainerRef ref = one.createContainer(ContainerSpec.of(Order.FIFO).named("shared"));
                one.write(ref, Timeout.TRY_ONCE, Entry.of("hello"));
                ContainerRef found = both.lookupContainer("shared");
                assertEquals(List.of(Entry.of("hello")), both.take(found, Timeout.TRY_ONCE));
                assertEquals(secondUrl, both.url(), "served by the first server of its list");
            }
        } finally {
            assertEquals(0, second.stop());
            assertEquals(0, first.stop());
        }
        assertTrue(second.out.toString().contains("space server stopped"), second.out.toString());
    }

    @Test
    void aClusterMemberNeedsOneAddressToAnnounce() throws Exception {
        StringWriter err = new StringWriter();
        int exit = Rwe.run(new PrintWriter(new StringWriter(), true), new PrintWriter(err, true), "space", "--port",
                "0", "--bind", "0.0.0.0", "--cluster", "lab", "--member", "10.0.0.1:5701");
        assertEquals(2, exit, err.toString());
        assertTrue(err.toString().contains("--member-bind ADDR"), err.toString());
        err.getBuffer().setLength(0);
        exit = Rwe.run(new PrintWriter(new StringWriter(), true), new PrintWriter(err, true), "space", "--port", "0",
                "--cluster", "lab", "--member", "10.0.0.1:port");
        assertEquals(2, exit, err.toString());
        assertTrue(err.toString().contains("not '10.0.0.1:port'"), err.toString());
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
