package robotworld.sim;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import robotworld.x10.X10Address;

/** Parses a device list such as {@code A1=lamp,A3=appliance} into simulated modules. */
public final class DeviceSpec {

    private DeviceSpec() {
    }

    /**
     * The modules of {@code spec}: comma-separated {@code ADDRESS=lamp|appliance} items.
     *
     * @throws IllegalArgumentException naming the bad item
     */
    public static List<SimulatedX10Module> parse(String spec) {
        List<SimulatedX10Module> modules = new ArrayList<>();
        Set<X10Address> seen = new HashSet<>();
        if (spec == null || spec.isBlank()) {
            return modules;
        }
        for (String item : spec.split(",")) {
            String trimmed = item.trim();
            int equals = trimmed.indexOf('=');
            if (equals < 0) {
                throw new IllegalArgumentException("device '" + trimmed + "' is not ADDRESS=lamp|appliance, "
                        + "e.g. A1=lamp");
            }
            X10Address address = X10Address.parse(trimmed.substring(0, equals));
            if (!seen.add(address)) {
                throw new IllegalArgumentException("device " + address + " is listed twice");
            }
            String kind = trimmed.substring(equals + 1).trim().toLowerCase(Locale.ROOT);
            modules.add(switch (kind) {
                case "lamp" -> new SimulatedLampModule(address);
                case "appliance" -> new SimulatedApplianceModule(address);
                default -> throw new IllegalArgumentException("device " + address + ": kind '" + kind
                        + "' is neither lamp nor appliance");
            });
        }
        return modules;
    }
}
