package robotworld.cluster;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;

/**
 * Members of one fresh cluster in this JVM, on loopback with free ports and a cluster name no other test run
 * shares (several builds may run on this machine at once), with fast failure detection for failure tests.
 */
final class LocalCluster implements AutoCloseable {

    final String name = "rwe-test-" + UUID.randomUUID().toString().substring(0, 8);
    final List<ClusterMember> members = new ArrayList<>();
    private final int minimumMembers;
    private final Duration failureDetection;
    private final Duration callAllowance;

    private LocalCluster(int minimumMembers, Duration failureDetection, Duration callAllowance) {
        this.minimumMembers = minimumMembers;
        this.failureDetection = failureDetection;
        this.callAllowance = callAllowance;
    }

    /**
     * {@code size} members that see each other, for failure tests: a member that stays silent for 3 s counts as
     * gone; the space serves while a majority of them does.
     */
    static LocalCluster start(int size) {
        return start(size, Duration.ofSeconds(3), Duration.ofSeconds(3));
    }

    /**
     * {@code size} members for tests of semantics, not of failures: on a machine busy with other builds a member
     * may be starved of CPU for seconds, which must not count as a failure there.
     */
    static LocalCluster startPatient(int size) {
        return start(size, Duration.ofSeconds(60), Duration.ofSeconds(20));
    }

    private static LocalCluster start(int size, Duration failureDetection, Duration callAllowance) {
        LocalCluster cluster = new LocalCluster(size / 2 + 1, failureDetection, callAllowance);
        try {
            for (int i = 0; i < size; i++) {
                cluster.addMember();
            }
            cluster.awaitSize(size);
        } catch (RuntimeException | Error e) {
            cluster.close();
            throw e;
        }
        return cluster;
    }

    ClusterOptions options() {
        List<String> known = new ArrayList<>();
        for (ClusterMember member : members) {
            known.add(member.address());
        }
        return ClusterOptions.named(name).withPort(0).withMembers(known).withMinimumMembers(minimumMembers)
                .withFailureDetection(failureDetection).withCallAllowance(callAllowance);
    }

    ClusterMember addMember() {
        ClusterMember member = ClusterMember.start(options());
        members.add(member);
        return member;
    }

    ClusterMember member(int index) {
        return members.get(index);
    }

    /**
     * Waits until every member sees {@code size} members and the partitions' backups are in place (a crash during
     * a migration may lose what the moving partitions hold, which tests of a member's crash must not run into).
     */
    void awaitSize(int size) {
        long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
        for (ClusterMember member : members) {
            while (member.memberCount() != size) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError(member + " sees " + member.memberCount() + " members, not " + size);
                }
                sleep(20);
            }
        }
        for (ClusterMember member : members) {
            while (!member.isClusterSafe()) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError(member + ": partitions still migrating after 60 s");
                }
                sleep(20);
            }
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
    }

    @Override
    public void close() {
        for (ClusterMember member : members) {
            try {
                member.crash(); // no hand-over needed at the end of a test: quicker
            } catch (RuntimeException e) {
                // already gone
            }
        }
        members.clear();
    }
}
