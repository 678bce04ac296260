package robotworld.cluster;

import java.util.ArrayList;
import java.util.List;
import java.util.UUID;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

import robotworld.space.Capi;
import robotworld.space.contract.CapiContractSuite;

/**
 * The whole {@link Capi} contract (its concurrency group at half its volume) against a space kept by a 3-member
 * cluster, each call of a test going to the next member: blocked operations, their wake-ups, notifications and
 * naming all cross members.
 */
class ClusterCapiTest extends CapiContractSuite {

    private static LocalCluster cluster;

    @BeforeAll
    static void startCluster() {
        cluster = LocalCluster.startPatient(3);
    }

    @AfterAll
    static void stopCluster() {
        if (cluster != null) {
            cluster.close();
        }
    }

    /** Every operation is an entry processor on a partition that may live on another member: half the volume. */
    @Override
    protected double concurrencyVolume() {
        return 0.5;
    }

    /** A fresh space (its own maps in the cluster) with one handle per member. */
    @Override
    protected Capi open(int notificationQueue) {
        String space = "contract-" + UUID.randomUUID().toString().substring(0, 8);
        List<ClusterSpace> handles = new ArrayList<>();
        for (ClusterMember member : cluster.members) {
            handles.add(member.openSpace(space, notificationQueue));
        }
        return new RotatingCapi(handles);
    }
}
