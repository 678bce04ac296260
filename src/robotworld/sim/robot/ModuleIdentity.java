package robotworld.sim.robot;

/**
 * What a simulated module says about itself in Read Device Identification.
 *
 * @param vendorName VendorName object
 * @param nodeId ProductCode object: the NodeID that names the module's description
 * @param version MajorMinorRevision object
 */
public record ModuleIdentity(String vendorName, String nodeId, String version) {
}
