package robotworld.space.remote;

import java.net.URI;
import java.util.List;
import java.util.Set;

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
import robotworld.space.server.SpaceServer;

/**
 * A fresh server on a free loopback port with a remote client in front of it, as one {@link Capi}: every call
 * goes through the client; closing closes the client, then stops the server.
 */
final class ServedSpace extends robotworld.testsupport.ForwardingCapi {

    final SpaceServer server;
    final RemoteSpace client;

    private ServedSpace(SpaceServer server, RemoteSpace client) {
        super(client);
        this.server = server;
        this.client = client;
    }

    static ServedSpace open(int notificationQueue) {
        SpaceServer server = SpaceServer.start(testServerOptions().notificationQueue(notificationQueue));
        // the contract is about the space, not the network: an allowance a busy machine does not use up (with the
        // default 3 s, a loaded machine broke writes off as "the connection broke before the answer")
        RemoteSpace client = RemoteSpace.open(server.uri(),
                RemoteSpace.Options.defaults().notificationQueue(notificationQueue).networkAllowanceMillis(30_000));
        return new ServedSpace(server, client);
    }

    /**
     * Runs the remote paths the contract stresses (blocking hand-offs on a bounded queue, notifications) for a
     * moment, so that the JIT has compiled them before timed tests run. The contract's stress tests allow 5 s for
     * up to 18 000 remote calls; on a cold JVM on 2 cores, compiling Jetty's, Jackson's and our request paths eats
     * a large part of that.
     */
    static void warmUp() throws Exception {
        try (ServedSpace served = open(1_000)) {
            ContainerRef queue = served.createContainer(ContainerSpec.of(robotworld.space.Order.FIFO).bounded(16));
            served.subscribe(queue, java.util.EnumSet.of(Operation.WRITE), NotificationMode.INFINITE, Timeout.INFINITE,
                    notification -> { });
            java.util.concurrent.ExecutorService threads = java.util.concurrent.Executors.newFixedThreadPool(4);
            try {
                List<java.util.concurrent.Future<?>> workers = new java.util.ArrayList<>();
                for (int t = 0; t < 2; t++) {
                    workers.add(threads.submit(() -> {
                        for (int i = 0; i < 1_500; i++) {
                            served.write(queue, Timeout.INFINITE, Entry.of(i));
                        }
                        return null;
                    }));
                    workers.add(threads.submit(() -> {
                        for (int i = 0; i < 1_500; i++) {
                            served.take(queue, Timeout.INFINITE);
                        }
                        return null;
                    }));
                }
                for (java.util.concurrent.Future<?> worker : workers) {
                    worker.get(60, java.util.concurrent.TimeUnit.SECONDS);
                }
            } finally {
                threads.shutdownNow();
            }
        }
    }

    /** Free port, short stop grace, otherwise the defaults. */
    static SpaceServer.Options testServerOptions() {
        return SpaceServer.Options.defaults().port(0).stopGraceMillis(200);
    }

    @Override
    public void close() {
        super.close();
        server.stop();
    }
}
