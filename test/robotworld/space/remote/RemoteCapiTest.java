package robotworld.space.remote;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Nested;

import robotworld.space.Capi;
import robotworld.space.contract.BlockingContract;
import robotworld.space.contract.ConcurrencyContract;
import robotworld.space.contract.NamingContract;
import robotworld.space.contract.NotificationContract;
import robotworld.space.contract.OrderContract;
import robotworld.space.contract.TemplateContract;
import robotworld.space.contract.ViewContract;

/** The whole {@link Capi} contract, unchanged, against {@link RemoteSpace} talking to a {@code SpaceServer} on loopback. */
class RemoteCapiTest {

    /** Compiles the remote paths before the contract's timed stress tests (see {@link ServedSpace#warmUp()}). */
    @BeforeAll
    static void warmUp() throws Exception {
        ServedSpace.warmUp();
    }

    static Capi open(int notificationQueue) {
        return ServedSpace.open(notificationQueue);
    }

    @Nested
    class Naming extends NamingContract {
        @Override
        protected Capi newSpace(int notificationQueue) {
            return open(notificationQueue);
        }
    }

    @Nested
    class Orders extends OrderContract {
        @Override
        protected Capi newSpace(int notificationQueue) {
            return open(notificationQueue);
        }
    }

    @Nested
    class Views extends ViewContract {
        @Override
        protected Capi newSpace(int notificationQueue) {
            return open(notificationQueue);
        }
    }

    @Nested
    class Templates extends TemplateContract {
        @Override
        protected Capi newSpace(int notificationQueue) {
            return open(notificationQueue);
        }
    }

    @Nested
    class Blocking extends BlockingContract {
        @Override
        protected Capi newSpace(int notificationQueue) {
            return open(notificationQueue);
        }
    }

    @Nested
    class Notifications extends NotificationContract {
        @Override
        protected Capi newSpace(int notificationQueue) {
            return open(notificationQueue);
        }
    }

    @Nested
    class Concurrency extends ConcurrencyContract {
        @Override
        protected Capi newSpace(int notificationQueue) {
            return open(notificationQueue);
        }
    }
}
