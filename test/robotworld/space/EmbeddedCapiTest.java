package robotworld.space;

import robotworld.space.contract.CapiContractSuite;

/** The whole {@link Capi} contract against {@link EmbeddedSpace}. */
class EmbeddedCapiTest extends CapiContractSuite {

    @Override
    protected Capi open(int notificationQueue) {
        return EmbeddedSpace.open(notificationQueue);
    }
}
