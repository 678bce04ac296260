package robotworld.cluster;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;

/**
 * A private network of Linux network namespaces made for one test: one namespace per member, each with a veth
 * pair into a switch namespace (a bridge), private addresses {@code 10.X.Y.n/24} inside the member namespaces only.
 * Nothing is added to this computer's own network, and nothing in it relies on loopback. A member can be cut off
 * (its cable pulled: the bridge port goes down) and reconnected. {@link #close()} deletes every namespace, which
 * deletes their links.
 */
final class NetnsRig implements AutoCloseable {

    private final String tag = Integer.toString(ThreadLocalRandom.current().nextInt(0x10000, 0xfffff), 36);
    private final String subnet = "10." + ThreadLocalRandom.current().nextInt(64, 250) + "."
            + ThreadLocalRandom.current().nextInt(1, 250) + ".";
    private final List<String> namespaces = new ArrayList<>();
    private final int members;

    private NetnsRig(int members) {
        this.members = members;
    }

    /** Why namespaces cannot be made here, or null if they can. */
    static String unavailableReason() {
        if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
            return "network namespaces need Linux";
        }
        if (!robotworld.testsupport.TestPeers.onPath("ip")) {
            return "the ip command is missing: install it with 'sudo apt-get install iproute2'";
        }
        try {
            String probe = "rwe-probe-" + ThreadLocalRandom.current().nextInt(1 << 20);
            Result made = run("ip", "netns", "add", probe);
            if (made.exit != 0) {
                return "cannot make network namespaces here (" + made.output.trim()
                        + "): run the tests as root or with CAP_SYS_ADMIN";
            }
            run("ip", "netns", "del", probe);
            return null;
        } catch (IOException e) {
            return "cannot run ip: " + e.getMessage();
        }
    }

    static NetnsRig create(int members) throws IOException {
        NetnsRig rig = new NetnsRig(members);
        try {
            rig.build();
        } catch (IOException | RuntimeException e) {
            rig.close();
            throw e;
        }
        return rig;
    }

    private void build() throws IOException {
        String sw = switchNamespace();
        must("ip", "netns", "add", sw);
        namespaces.add(sw);
        must("ip", "netns", "exec", sw, "ip", "link", "add", "br0", "type", "bridge");
        must("ip", "netns", "exec", sw, "ip", "link", "set", "br0", "up");
        for (int i = 1; i <= members; i++) {
            String ns = namespace(i);
            must("ip", "netns", "add", ns);
            namespaces.add(ns);
            String inside = "rwe" + tag + "m" + i; // interface names: at most 15 characters
            String port = "rwe" + tag + "s" + i;
            must("ip", "link", "add", inside, "type", "veth", "peer", "name", port);
            must("ip", "link", "set", inside, "netns", ns);
            must("ip", "link", "set", port, "netns", sw);
            must("ip", "netns", "exec", sw, "ip", "link", "set", port, "master", "br0");
            must("ip", "netns", "exec", sw, "ip", "link", "set", port, "up");
            must("ip", "netns", "exec", ns, "ip", "link", "set", "lo", "up");
            must("ip", "netns", "exec", ns, "ip", "addr", "add", address(i) + "/24", "dev", inside);
            must("ip", "netns", "exec", ns, "ip", "link", "set", inside, "up");
        }
    }

    private String switchNamespace() {
        return "rwe-" + tag + "-sw";
    }

    /** The namespace of member {@code i} (1-based). */
    String namespace(int i) {
        return "rwe-" + tag + "-m" + i;
    }

    /** The address of member {@code i} (1-based), inside its namespace. */
    String address(int i) {
        return subnet + i;
    }

    /** The command prefix that runs a program in member {@code i}'s namespace. */
    List<String> inNamespace(int i) {
        return List.of("ip", "netns", "exec", namespace(i));
    }

    /** Pulls member {@code i}'s cable: its bridge port goes down, so it can reach nobody and nobody it. */
    void disconnect(int i) throws IOException {
        must("ip", "netns", "exec", switchNamespace(), "ip", "link", "set", "rwe" + tag + "s" + i, "down");
    }

    void reconnect(int i) throws IOException {
        must("ip", "netns", "exec", switchNamespace(), "ip", "link", "set", "rwe" + tag + "s" + i, "up");
    }

    @Override
    public void close() {
        for (String ns : namespaces) {
            try {
                run("ip", "netns", "del", ns);
            } catch (IOException e) {
                System.err.println("could not delete network namespace " + ns + ": " + e.getMessage());
            }
        }
        namespaces.clear();
    }

    private static void must(String... command) throws IOException {
        Result result = run(command);
        if (result.exit != 0) {
            throw new IOException(String.join(" ", command) + " failed (" + result.exit + "): " + result.output);
        }
    }

    private record Result(int exit, String output) {
    }

    private static Result run(String... command) throws IOException {
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        try {
            if (!process.waitFor(30, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                throw new IOException(String.join(" ", command) + " did not finish");
            }
            return new Result(process.exitValue(), new String(process.getInputStream().readAllBytes(),
                    StandardCharsets.UTF_8));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
    }
}
