package robotworld.cluster;

import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.regex.Pattern;

/**
 * How a cluster member starts: the cluster it joins and how it finds the others, where it listens, and how much
 * safety it keeps. Immutable; start from {@link #named(String)} and change what you need.
 *
 * @param clusterName       members join only a cluster of the same name (letters, digits, {@code ._-})
 * @param members           {@code host:port} of members to contact when joining (may include this one); no
 *                          multicast, no discovery: an explicit list
 * @param bindAddress       the address this member listens on and announces; {@code 127.0.0.1} by default, so a
 *                          member is reachable from this computer only unless told otherwise
 * @param port              the member port (cluster traffic, not the space's HTTP port); 0 picks a free one
 * @param backups           synchronous backups of every container (at least 1 to survive a member's failure)
 * @param minimumMembers    fewest members that must see each other for the space to serve (split-brain
 *                          protection); 0 means a majority of {@code members} (at least 1)
 * @param journalCapacity   events each container keeps for its subscribers to repair a broken chain
 * @param callAllowance     how long past its own timeout a call may take before it fails with
 *                          {@link robotworld.space.SpaceUnavailableException}
 * @param failureDetection  how long a member may stay silent before the others count it as gone (a member whose
 *                          process died is noticed sooner: its connections close)
 * @param lease             how long a take or destroy a server answered is held for its client's confirmation
 *                          before its entries come back (in the container, so any member's server honours it)
 */
public record ClusterOptions(String clusterName, List<String> members, String bindAddress, int port, int backups,
                             int minimumMembers, int journalCapacity, Duration callAllowance,
                             Duration failureDetection, Duration lease) {

    /** The member port Hazelcast uses by default. */
    public static final int DEFAULT_PORT = 5701;

    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9._-]{1,64}");

    /** Validates the fields. */
    public ClusterOptions {
        Objects.requireNonNull(clusterName, "clusterName");
        if (!NAME.matcher(clusterName).matches()) {
            throw new IllegalArgumentException("cluster name must be 1-64 letters, digits, '.', '_' or '-': "
                    + clusterName);
        }
        members = List.copyOf(members);
        Objects.requireNonNull(bindAddress, "bindAddress");
        if (port < 0 || port > 65_535) {
            throw new IllegalArgumentException("member port out of range: " + port);
        }
        if (backups < 0 || backups > 6) {
            throw new IllegalArgumentException("backups must be 0..6: " + backups);
        }
        if (minimumMembers < 0) {
            throw new IllegalArgumentException("minimum members must not be negative: " + minimumMembers);
        }
        if (journalCapacity < 1) {
            throw new IllegalArgumentException("journal capacity must be at least 1: " + journalCapacity);
        }
        Objects.requireNonNull(callAllowance, "callAllowance");
        Objects.requireNonNull(failureDetection, "failureDetection");
        if (failureDetection.toSeconds() < 1) {
            throw new IllegalArgumentException("failure detection must be at least 1 s: " + failureDetection);
        }
        Objects.requireNonNull(lease, "lease");
        if (lease.toMillis() < 10) {
            throw new IllegalArgumentException("lease must be at least 10 ms: " + lease);
        }
    }

    /**
     * A member of cluster {@code clusterName} on {@code 127.0.0.1:5701}, no other members listed, one synchronous
     * backup, split-brain protection by majority of the listed members.
     */
    public static ClusterOptions named(String clusterName) {
        return new ClusterOptions(clusterName, List.of(), "127.0.0.1", DEFAULT_PORT, 1, 0, 1024,
                Duration.ofSeconds(3), Duration.ofSeconds(5), Duration.ofSeconds(10));
    }

    public ClusterOptions withMembers(List<String> newMembers) {
        return new ClusterOptions(clusterName, newMembers, bindAddress, port, backups, minimumMembers,
                journalCapacity, callAllowance, failureDetection, lease);
    }

    public ClusterOptions withBindAddress(String address) {
        return new ClusterOptions(clusterName, members, address, port, backups, minimumMembers, journalCapacity,
                callAllowance, failureDetection, lease);
    }

    public ClusterOptions withPort(int newPort) {
        return new ClusterOptions(clusterName, members, bindAddress, newPort, backups, minimumMembers,
                journalCapacity, callAllowance, failureDetection, lease);
    }

    public ClusterOptions withBackups(int count) {
        return new ClusterOptions(clusterName, members, bindAddress, port, count, minimumMembers, journalCapacity,
                callAllowance, failureDetection, lease);
    }

    public ClusterOptions withMinimumMembers(int count) {
        return new ClusterOptions(clusterName, members, bindAddress, port, backups, count, journalCapacity,
                callAllowance, failureDetection, lease);
    }

    public ClusterOptions withJournalCapacity(int events) {
        return new ClusterOptions(clusterName, members, bindAddress, port, backups, minimumMembers, events,
                callAllowance, failureDetection, lease);
    }

    public ClusterOptions withCallAllowance(Duration allowance) {
        return new ClusterOptions(clusterName, members, bindAddress, port, backups, minimumMembers,
                journalCapacity, allowance, failureDetection, lease);
    }

    public ClusterOptions withFailureDetection(Duration silence) {
        return new ClusterOptions(clusterName, members, bindAddress, port, backups, minimumMembers,
                journalCapacity, callAllowance, silence, lease);
    }

    public ClusterOptions withLease(Duration newLease) {
        return new ClusterOptions(clusterName, members, bindAddress, port, backups, minimumMembers,
                journalCapacity, callAllowance, failureDetection, newLease);
    }

    /** The split-brain protection minimum actually used: the given one, or a majority of the listed members. */
    public int effectiveMinimumMembers() {
        if (minimumMembers > 0) {
            return minimumMembers;
        }
        return Math.max(1, members.size() / 2 + 1);
    }
}
