package robotworld.explorer.demo;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import robotworld.program.JvmOptions;

/**
 * The demo's clustered space: {@code rwe space --cluster} processes on loopback (free ports), the first started
 * alone and the others joining it; the space's URL is their servers' URLs separated by commas. One of them can be
 * killed with SIGKILL, as when its computer fails.
 */
final class DemoCluster implements AutoCloseable {

    private static final Pattern URL = Pattern.compile("listening on (http://\\S+)");
    private static final Pattern MEMBER = Pattern.compile("cluster member of '[^']+' at (\\S+),");
    /** What Hazelcast needs of the JDK; given explicitly since the members are started with -cp, not -jar. */
    private static final List<String> JDK_ACCESS = List.of("--add-exports", "java.base/jdk.internal.ref=ALL-UNNAMED",
            "--add-opens", "java.base/java.lang=ALL-UNNAMED", "--add-opens", "java.base/sun.nio.ch=ALL-UNNAMED",
            "--add-opens", "java.management/sun.management=ALL-UNNAMED", "--add-opens",
            "jdk.management/com.sun.management.internal=ALL-UNNAMED");

    private final List<Process> processes = new ArrayList<>();
    private final List<String> urls = new ArrayList<>();

    /** Starts {@code size} members of a fresh cluster; their logs go to {@code logs}/member-N.log. */
    static DemoCluster start(int size, Path logs) throws IOException {
        DemoCluster cluster = new DemoCluster();
        String name = "rwe-demo-" + Long.toHexString(System.nanoTime());
        try {
            String first = null;
            for (int i = 0; i < size; i++) {
                List<String> command = new ArrayList<>();
                command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
                command.add("-Xmx256m");
                command.addAll(JvmOptions.LATENCY);
                command.addAll(JDK_ACCESS);
                command.addAll(List.of("-cp", System.getProperty("java.class.path"), "robotworld.explorer.cli.Rwe",
                        "space", "--cluster", name, "--port", "0", "--member-port", "0", "--min-members",
                        Integer.toString(size / 2 + 1)));
                if (first != null) {
                    command.addAll(List.of("--member", first));
                }
                Process process = new ProcessBuilder(command)
                        .redirectError(ProcessBuilder.Redirect.appendTo(logs.resolve("member-" + i + ".log").toFile()))
                        .start();
                cluster.processes.add(process);
                String[] started = cluster.awaitStart(process, i, logs);
                cluster.urls.add(started[0]);
                if (first == null) {
                    first = started[1];
                }
            }
        } catch (IOException | RuntimeException e) {
            cluster.close();
            throw e;
        }
        return cluster;
    }

    /** Reads the member's URL and cluster address from what it prints; then keeps reading so it never blocks. */
    private String[] awaitStart(Process process, int index, Path logs) throws IOException {
        BufferedReader out = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        String url = null;
        String address = null;
        String line;
        while (url == null && (line = out.readLine()) != null) {
            Matcher m = MEMBER.matcher(line);
            if (m.find()) {
                address = m.group(1);
            }
            m = URL.matcher(line);
            if (m.find()) {
                url = m.group(1);
            }
        }
        if (url == null || address == null) {
            throw new IOException("cluster member " + index + " did not start; see " + logs.resolve("member-" + index
                    + ".log"));
        }
        Thread drain = new Thread(() -> {
            try {
                while (out.readLine() != null) {
                    // keep its output pipe from filling
                }
            } catch (IOException e) {
                // it ended
            }
        }, "demo-member-" + index);
        drain.setDaemon(true);
        drain.start();
        return new String[] {url, address};
    }

    /** The space's URL as programs get it: every member's server, separated by commas. */
    String spaceUrl() {
        return String.join(",", urls);
    }

    /** The URL of member {@code index}'s server. */
    String url(int index) {
        return urls.get(index);
    }

    /** Kills member {@code index} with SIGKILL (no goodbye, as when its computer fails); returns its pid. */
    long kill(int index) throws InterruptedException {
        Process process = processes.get(index);
        process.destroyForcibly();
        process.waitFor(10, TimeUnit.SECONDS);
        return process.pid();
    }

    @Override
    public void close() {
        for (Process process : processes) {
            process.destroy(); // rwe space leaves the cluster cleanly on SIGTERM
        }
        for (Process process : processes) {
            try {
                if (!process.waitFor(10, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                }
            } catch (InterruptedException e) {
                process.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }
}
