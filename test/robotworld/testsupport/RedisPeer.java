package robotworld.testsupport;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import redis.clients.jedis.Jedis;

/**
 * A private Redis server (Debian's {@code redis-server}) on a free loopback port, without persistence, for
 * benchmarks that compare the space with what an engineer would use instead. {@link #start()} returns null, having
 * said why, when it cannot run one; close it to stop the process.
 */
public final class RedisPeer implements AutoCloseable {

    private final Process process;
    private final int port;
    private final Path directory;

    private RedisPeer(Process process, int port, Path directory) {
        this.process = process;
        this.port = port;
        this.directory = directory;
    }

    /** A running server, or null (after printing the reason and how to install it). */
    public static RedisPeer start() throws IOException, InterruptedException {
        if (!TestPeers.onPath("redis-server")) {
            System.out.println("(no Redis row: redis-server is missing: install it with 'sudo apt-get install"
                    + " redis-server'; ./antw does so itself when run as root or with password-less sudo)");
            return null;
        }
        int port;
        try (ServerSocket probe = new ServerSocket(0)) {
            port = probe.getLocalPort();
        }
        Path directory = Files.createTempDirectory("rwe-redis");
        Process process = new ProcessBuilder(List.of("redis-server", "--port", Integer.toString(port), "--bind",
                "127.0.0.1", "--save", "", "--appendonly", "no", "--dir", directory.toString(), "--loglevel",
                "warning")).redirectErrorStream(true).redirectOutput(directory.resolve("redis.log").toFile()).start();
        RedisPeer peer = new RedisPeer(process, port, directory);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (true) {
            try (Jedis jedis = peer.connect()) {
                if ("PONG".equals(jedis.ping())) {
                    return peer;
                }
            } catch (RuntimeException notYet) {
                if (!process.isAlive() || System.nanoTime() > deadline) {
                    peer.close();
                    System.out.println("(no Redis row: redis-server did not start: " + notYet.getMessage() + ")");
                    return null;
                }
                Thread.sleep(20);
            }
        }
    }

    /** A new connection (Jedis connections are not thread-safe: one per thread). */
    public Jedis connect() {
        return new Jedis("127.0.0.1", port, 10_000, 30_000);
    }

    /** The port it listens on. */
    public int port() {
        return port;
    }

    /** The server's process id (for counting its threads). */
    public long pid() {
        return process.pid();
    }

    @Override
    public void close() {
        process.destroy();
        try {
            if (!process.waitFor(5, TimeUnit.SECONDS)) {
                process.destroyForcibly();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            process.destroyForcibly();
        }
        try (var files = Files.walk(directory)) {
            files.sorted(java.util.Comparator.reverseOrder()).forEach(path -> path.toFile().delete());
        } catch (IOException ignored) {
            // a temporary directory
        }
    }
}
