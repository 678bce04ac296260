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
 * The whole {@link Capi} contract, unchanged, against a 3-member cluster served over HTTP: a space server in front
 * of each member, a remote client of each server, and every call of a test going to the next client. Crefs one
 * server hands out work on the others; blocked operations wait without threads on whichever member their client
 * talks to.
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

    @Override
    protected Capi open(int notificationQueue) {
        String space = "served-" + UUID.randomUUID().toString().substring(0, 8);
        return Served.open(cluster, space, notificationQueue);
    }

    /** Servers in front of each member's handle, a client of each, calls in turn. */
    static final class Served implements Capi {
        private final List<ClusterSpace> handles = new ArrayList<>();
        private final List<SpaceServer> servers = new ArrayList<>();
        private final List<RemoteSpace> clients = new ArrayList<>();
        private final RotatingCapi rotating;

        private Served(LocalCluster cluster, String space, int notificationQueue) {
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
            rotating = new RotatingCapi(new ArrayList<>(clients));
        }

        static Served open(LocalCluster cluster, String space, int notificationQueue) {
            return new Served(cluster, space, notificationQueue);
        }

        @Override
        public URI spaceUri() {
            return rotating.spaceUri();
        }

        @Override
        public ContainerRef createContainer(ContainerSpec spec) {
            return rotating.createContainer(spec);
        }

        @Override
        public ContainerRef lookupContainer(String name) {
            return rotating.lookupContainer(name);
        }

        @Override
        public ContainerRef lookupOrCreateContainer(ContainerSpec spec) {
            return rotating.lookupOrCreateContainer(spec);
        }

        @Override
        public void destroyContainer(ContainerRef container) {
            rotating.destroyContainer(container);
        }

        @Override
        public ContainerInfo describeContainer(ContainerRef container) {
            return rotating.describeContainer(container);
        }

        @Override
        public List<Entry> read(ContainerRef container, Timeout timeout, Selector... selectors) {
            return rotating.read(container, timeout, selectors);
        }

        @Override
        public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
            return rotating.take(container, timeout, selectors);
        }

        @Override
        public int destroy(ContainerRef container, Timeout timeout, Selector... selectors) {
            return rotating.destroy(container, timeout, selectors);
        }

        @Override
        public void write(ContainerRef container, Timeout timeout, List<Item> items) {
            rotating.write(container, timeout, items);
        }

        @Override
        public List<Entry> shift(ContainerRef container, Timeout timeout, List<Item> items) {
            return rotating.shift(container, timeout, items);
        }

        @Override
        public Subscription subscribe(ContainerRef container, Set<Operation> operations, NotificationMode mode,
                                      Timeout timeout, NotificationListener listener) {
            return rotating.subscribe(container, operations, mode, timeout, listener);
        }

        @Override
        public void close() {
            rotating.close();
            servers.forEach(SpaceServer::stop);
            handles.forEach(ClusterSpace::close);
        }
    }
}
