package robotworld.bus.explore;

/** Hears how a bus exploration goes; every method has a do-nothing default. Called on the exploring thread. */
public interface ExplorationListener {

    /**
     * An address has been dealt with.
     *
     * @param address the address just scanned
     * @param done how many addresses are done
     * @param total how many addresses the scan covers
     */
    default void progress(int address, int done, int total) {
    }

    /** A module was found and checked. */
    default void moduleFound(FoundModule module) {
    }

    /** An address had a problem and was skipped. */
    default void problem(AddressProblem problem) {
    }
}
