package robotworld.sim.robot;

/**
 * What a simulated module says about itself in Read Device Identification and Report Server ID.
 *
 * @param vendorName VendorName object
 * @param nodeId ProductCode object: the NodeID that names the module's description
 * @param version MajorMinorRevision object
 * @param serverId the server ID of Report Server ID, sent as ASCII (any length, as some devices do); empty for
 *        the default: one byte, the module's address
 */
public record ModuleIdentity(String vendorName, String nodeId, String version, String serverId) {

    /** An identity whose server ID is the module's address. */
    public ModuleIdentity(String vendorName, String nodeId, String version) {
        this(vendorName, nodeId, version, "");
    }
}
