package robotworld.xvsm;

import java.util.concurrent.atomic.AtomicInteger;
import robotworld.core.BumperModule;

/** Test helper: a bumper module that counts how often its hardware is read (for adaptive batching). */
final class CountingBumper implements BumperModule {

    final AtomicInteger reads = new AtomicInteger();
    private final BumperModule hardware;

    CountingBumper(BumperModule hardware) {
        this.hardware = hardware;
    }

    @Override
    public int getAllBumper() {
        reads.incrementAndGet();
        return hardware.getAllBumper();
    }

    @Override
    public boolean getSingleBumper(int bumperNumber) {
        reads.incrementAndGet();
        return hardware.getSingleBumper(bumperNumber);
    }
}
