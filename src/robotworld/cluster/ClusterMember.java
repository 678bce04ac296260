package robotworld.cluster;

import java.util.Objects;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;

import com.hazelcast.cluster.Address;
import com.hazelcast.cluster.Member;
import com.hazelcast.core.Hazelcast;
import com.hazelcast.core.HazelcastInstance;

import robotworld.space.ContainerRef;
import robotworld.space.EmbeddedSpace;

/**
 * This process as a member of a space cluster: a Hazelcast member (embedded, community edition) that holds a share
 * of every space's containers and backups of others', plus the machinery that runs the space's calls for the
 * handles opened on it ({@link #openSpace}).
 *
 * <pre>{@code
 * ClusterOptions options = ClusterOptions.named("lab").withBindAddress("10.0.0.1")
 *         .withMembers(List.of("10.0.0.1:5701", "10.0.0.2:5701", "10.0.0.3:5701"));
 * try (ClusterMember member = ClusterMember.start(options)) {
 *     Capi space = member.openSpace(ClusterMember.DEFAULT_SPACE);
 *     ...
 * }
 * }</pre>
 */
public final class ClusterMember implements AutoCloseable {

    /** The space a server serves unless told otherwise. */
    public static final String DEFAULT_SPACE = "space";

    private static final Pattern SPACE_NAME = Pattern.compile("[A-Za-z0-9._-]{1,64}");

    private final HazelcastInstance hazelcast;
    private final ClusterNode node;

    private ClusterMember(HazelcastInstance hazelcast, ClusterOptions options) {
        this.hazelcast = hazelcast;
        this.node = new ClusterNode(hazelcast, options);
    }

    /**
     * Starts a member and joins the cluster named in {@code options} through the listed members (or starts the
     * cluster if none of them answers).
     *
     * @throws IllegalStateException if the member cannot start (e.g. its port is taken)
     */
    public static ClusterMember start(ClusterOptions options) {
        Objects.requireNonNull(options, "options");
        HazelcastInstance hazelcast;
        try {
            hazelcast = Hazelcast.newHazelcastInstance(HazelcastSetup.config(options));
        } catch (RuntimeException e) {
            throw new IllegalStateException("cannot start cluster member on " + options.bindAddress() + ":"
                    + options.port() + ": " + e.getMessage(), e);
        }
        return new ClusterMember(hazelcast, options);
    }

    /**
     * A handle on space {@code spaceName} of this cluster, with the embedded space's notification queue per
     * subscription.
     */
    public ClusterSpace openSpace(String spaceName) {
        return openSpace(spaceName, EmbeddedSpace.DEFAULT_NOTIFICATION_QUEUE);
    }

    /** A handle on space {@code spaceName} whose subscriptions may each queue {@code notificationQueue} notifications. */
    public ClusterSpace openSpace(String spaceName, int notificationQueue) {
        Objects.requireNonNull(spaceName, "spaceName");
        if (!SPACE_NAME.matcher(spaceName).matches()) {
            throw new IllegalArgumentException("space name must be 1-64 letters, digits, '.', '_' or '-': "
                    + spaceName);
        }
        return new ClusterSpace(node, spaceName, notificationQueue);
    }

    /** The {@code host:port} this member announces to the others. */
    public String address() {
        Address address = hazelcast.getCluster().getLocalMember().getAddress();
        return address.getHost() + ":" + address.getPort();
    }

    /** How many members this member currently sees, itself included. */
    public int memberCount() {
        return hazelcast.getCluster().getMembers().size();
    }

    public ClusterOptions options() {
        return node.options();
    }

    ClusterNode node() {
        return node;
    }

    /**
     * Whether every partition has its backups in place as far as this member knows (no migration under way): until
     * then a crash can lose what the migrating partitions hold. For tests that crash members.
     */
    boolean isClusterSafe() {
        return hazelcast.getPartitionService().isClusterSafe();
    }

    /** Whether this member holds the primary copy of {@code container} (for tests that crash its owner). */
    boolean owns(ContainerRef container) {
        // a member that has not yet received the partition table knows no owner: wait for it
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        Member owner;
        while ((owner = hazelcast.getPartitionService().getPartition(container.id()).getOwner()) == null) {
            if (System.nanoTime() - deadline > 0) {
                throw new IllegalStateException("no owner known for " + container + " after 10 s");
            }
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while waiting for the partition table", e);
            }
        }
        return owner.localMember();
    }

    /**
     * Leaves the cluster gracefully: this member's handles end their calls and subscriptions, and its share of
     * the containers moves to the other members before it goes. Idempotent.
     */
    @Override
    public void close() {
        node.close();
        hazelcast.shutdown();
    }

    /**
     * Leaves at once, as a crash would (no hand-over; the others take over from the backups). For failure tests:
     * a real crash (the process killed) looks the same to the others.
     */
    public void crash() {
        node.close();
        hazelcast.getLifecycleService().terminate();
    }

    @Override
    public String toString() {
        return "ClusterMember[" + node.options().clusterName() + " " + address() + "]";
    }
}
