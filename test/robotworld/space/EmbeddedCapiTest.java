package robotworld.space;

import org.junit.jupiter.api.Nested;

import robotworld.space.contract.BlockingContract;
import robotworld.space.contract.ConcurrencyContract;
import robotworld.space.contract.NamingContract;
import robotworld.space.contract.NotificationContract;
import robotworld.space.contract.OrderContract;
import robotworld.space.contract.TemplateContract;
import robotworld.space.contract.ViewContract;

/** The whole {@link Capi} contract against {@link EmbeddedSpace}. The remote client's test mirrors this class. */
class EmbeddedCapiTest {

    static Capi open(int notificationQueue) {
        return EmbeddedSpace.open(notificationQueue);
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
