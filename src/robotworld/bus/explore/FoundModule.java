package robotworld.bus.explore;

/**
 * A module that answered identification, status and echo and whose NodeID is in the catalogue.
 *
 * @param address its bus address (the description's NodeNumber)
 * @param name its unique name in the robot description
 * @param nodeId the model, as reported
 * @param moduleClass the module class from its description, e.g. "BumperModule"
 * @param version the version the module reported (or the catalogue's, if the reported one is unusable)
 * @param vendor the vendor the module reported
 */
public record FoundModule(int address, String name, String nodeId, String moduleClass, String version,
        String vendor) {

    @Override
    public String toString() {
        return "address " + address + ": " + moduleClass + " '" + name + "' (NodeID " + nodeId + ", version " + version
                + ")";
    }
}
