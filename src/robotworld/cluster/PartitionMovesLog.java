package robotworld.cluster;

import java.lang.System.Logger.Level;
import java.util.concurrent.atomic.AtomicInteger;

import com.hazelcast.partition.MigrationListener;
import com.hazelcast.partition.MigrationState;
import com.hazelcast.partition.ReplicaMigrationEvent;

/**
 * At DEBUG, when the members move partitions (after a member joins or leaves): when a round of moves starts, when
 * it ends with how many partitions got a new owner, and each move that failed. With the slow-call log of
 * {@link ClusterNode} and the stories of {@link WaiterStory}, it shows what held calls up after a member's loss.
 */
final class PartitionMovesLog implements MigrationListener {

    private static final System.Logger LOG = System.getLogger(PartitionMovesLog.class.getName());

    private final AtomicInteger newOwners = new AtomicInteger();

    /** Whether to register it: only when its messages would be shown. */
    static boolean wanted() {
        return LOG.isLoggable(Level.DEBUG);
    }

    @Override
    public void migrationStarted(MigrationState state) {
        newOwners.set(0);
        LOG.log(Level.DEBUG, "partition moves started: " + state.getPlannedMigrations() + " planned");
    }

    @Override
    public void migrationFinished(MigrationState state) {
        LOG.log(Level.DEBUG, "partition moves finished after " + state.getTotalElapsedTime() + " ms: "
                + state.getCompletedMigrations() + " of " + state.getPlannedMigrations() + " done, "
                + newOwners.get() + " partitions with a new owner here or elsewhere");
    }

    @Override
    public void replicaMigrationCompleted(ReplicaMigrationEvent event) {
        if (event.getReplicaIndex() == 0) {
            newOwners.incrementAndGet();
        }
    }

    @Override
    public void replicaMigrationFailed(ReplicaMigrationEvent event) {
        LOG.log(Level.DEBUG, "partition move failed: " + event);
    }
}
