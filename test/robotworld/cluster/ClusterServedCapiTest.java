package robotworld.cluster;

import java.net.URI;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.UUID;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

import robotworld.space.Capi;
import robotworld.space.ContainerInfo;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.NotificationListener;
import robotworld.space.NotificationMode;
import robotworld.space.Operation;
import robotworld.space.Selector;
import robotworld.space.Subscription;
import robotworld.space.Timeout;
import robotworld.space.contract.CapiContractSuite;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;

/**
 * The whole {@link Capi} contract (its concurrency group at a third of its volume) against a 3-member cluster
 * served over HTTP: a space server in front of each member, a remote client of each server, and every call of a
 * test going to the next client. Crefs one server hands out work on the others; blocked operations wait without
 * threads on whichever member their client talks to.
 */
class ClusterServedCapiTest extends CapiContractSuite {

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

    /** Every call crosses a client, a server and up to two members: a third of the stress volume. */
    @Override
    protected double concurrencyVolume() {
        return 1.0 / 3;
    }

    @Override
    protected Capi open(int notificationQueue) {
        String space = "served-" + UUID.randomUUID().toString().substring(0, 8);
        return Served.open(cluster, space, notificationQueue);
    }

    /** Servers in front of each member's handle, a client of each, calls in turn. */
    static final class Served extends robotworld.testsupport.ForwardingCapi {
        private final List<ClusterSpace> handles;
        private final List<SpaceServer> servers;

        private Served(List<ClusterSpace> handles, List<SpaceServer> servers, List<RemoteSpace> clients) {
            super(new RotatingCapi(new ArrayList<>(clients)));
            this.handles = handles;
            this.servers = servers;
        }

        private static Served start(LocalCluster cluster, String space, int notificationQueue) {
            List<ClusterSpace> handles = new ArrayList<>();
            List<SpaceServer> servers = new ArrayList<>();
            List<RemoteSpace> clients = new ArrayList<>();
            for (ClusterMember member : cluster.members) {
                ClusterSpace handle = member.openSpace(space, notificationQueue);
                handles.add(handle);
                SpaceServer server = SpaceServer.start(handle, SpaceServer.Options.defaults().port(0)
                        .stopGraceMillis(100));
                servers.add(server);
                // a patient client: what is tested here is semantics, on a machine that may be very busy
                clients.add(RemoteSpace.open(server.uri(), RemoteSpace.Options.defaults()
                        .notificationQueue(notificationQueue).networkAllowanceMillis(20_000)));
            }
            return new Served(handles, servers, clients);
        }

        static Served open(LocalCluster cluster, String space, int notificationQueue) {
            return start(cluster, space, notificationQueue);
        }

        @Override
        public void close() {
            super.close();
            servers.forEach(SpaceServer::stop);
            handles.forEach(ClusterSpace::close);
        }
    }
}
