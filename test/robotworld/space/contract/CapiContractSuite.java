package robotworld.space.contract;

import org.junit.jupiter.api.Nested;

import robotworld.space.Capi;

/**
 * The whole {@link Capi} contract, one nested group per part. A test class for one implementation extends this
 * and says how to open a space; JUnit runs every group against it.
 */
public abstract class CapiContractSuite {

    /** A new, empty space of the implementation under test. */
    protected abstract Capi open(int notificationQueue);

    /**
     * The share of the concurrency group's full operation counts this implementation runs (1 = all); see
     * {@link ConcurrencyContract#volume(int)}.
     */
    protected double concurrencyVolume() {
        return 1.0;
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

        @Override
        protected int volume(int full) {
            return Math.max(1, (int) Math.round(full * concurrencyVolume()));
        }
    }
}
