package robotworld.space.remote;

import org.junit.jupiter.api.BeforeAll;

import robotworld.space.Capi;
import robotworld.space.contract.CapiContractSuite;

/** The whole {@link Capi} contract, unchanged, against {@link RemoteSpace} talking to a {@code SpaceServer} on loopback. */
class RemoteCapiTest extends CapiContractSuite {

    /** Compiles the remote paths before the contract's timed stress tests (see {@link ServedSpace#warmUp()}). */
    @BeforeAll
    static void warmUp() throws Exception {
        ServedSpace.warmUp();
    }

    @Override
    protected Capi open(int notificationQueue) {
        return ServedSpace.open(notificationQueue);
    }
}
