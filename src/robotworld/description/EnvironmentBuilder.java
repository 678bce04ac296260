package robotworld.description;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Writes an environment description from a list of X10 devices ({@code A3=appliance:Lamp}), so that a world can
 * be assembled without editing XML. Version, details and documentation page of each device are taken from the
 * module description of its class in {@code ModuleDescriptions/} when one is there.
 *
 * <pre>{@code
 * EnvironmentDocument room = new EnvironmentBuilder("Room").host("room-pc").cm11aPort("/dev/ttyUSB1")
 *         .add(X10Device.parse("A3=appliance:Lamp")).build();
 * }</pre>
 */
public final class EnvironmentBuilder {

    /** The port a CM11A usually hangs on when none is given; every program can override it at run time. */
    public static final String DEFAULT_CM11A_PORT = "/dev/ttyS0";

    private static final String[] UNITS = {"ONE", "TWO", "THREE", "FOUR", "FIVE", "SIX", "SEVEN", "EIGHT", "NINE",
        "TEN", "ELEVEN", "TWELVE", "THIRTEEN", "FOURTEEN", "FIFTEEN", "SIXTEEN"};

    private final String name;
    private String host = "localhost";
    private String cm11aPort = DEFAULT_CM11A_PORT;
    private Path moduleDescriptions;
    private final List<X10Device> devices = new ArrayList<>();

    /**
     * One X10 device: its address (house code A..P, unit 1..16), {@code lamp} or {@code appliance}, and its module
     * name (null: named after its kind).
     */
    public record X10Device(char houseCode, int unit, String kind, String name) {

        private static final Pattern SPEC = Pattern.compile("([A-Za-z])([0-9]{1,2})=([A-Za-z]+)(?::(.*))?");

        public X10Device {
            if (houseCode < 'A' || houseCode > 'P') {
                throw new IllegalArgumentException("the house code is a letter from A to P; got '" + houseCode + "'");
            }
            if (unit < 1 || unit > 16) {
                throw new IllegalArgumentException("the unit is a number from 1 to 16; got " + unit);
            }
            if (!kind.equals("lamp") && !kind.equals("appliance")) {
                throw new IllegalArgumentException("the kind is lamp or appliance; got '" + kind + "'");
            }
            if (name != null && !name.matches("[A-Za-z][A-Za-z0-9_\\-]{0,63}")) {
                throw new IllegalArgumentException("module names may contain only letters, digits, _ and -, and start"
                        + " with a letter; got '" + name + "'");
            }
        }

        /** {@code A3=appliance}, {@code B1=lamp:Ceiling-Lamp} (house code, unit, kind, and optionally a name). */
        public static X10Device parse(String spec) {
            Matcher matcher = SPEC.matcher(spec.strip());
            if (!matcher.matches()) {
                throw new IllegalArgumentException("'" + spec + "' is not ADDRESS=KIND[:NAME], e.g. A3=appliance:Lamp");
            }
            String name = matcher.group(4);
            return new X10Device(Character.toUpperCase(matcher.group(1).charAt(0)), Integer.parseInt(matcher.group(2)),
                    matcher.group(3).toLowerCase(Locale.ROOT), name == null || name.isBlank() ? null : name.strip());
        }

        /** The module class: X10LampModule or X10ApplianceModule. */
        public String moduleClass() {
            return kind.equals("lamp") ? "X10LampModule" : "X10ApplianceModule";
        }

        /** "A3". */
        public String address() {
            return houseCode + Integer.toString(unit);
        }

        @Override
        public String toString() {
            return address() + "=" + kind + (name == null ? "" : ":" + name);
        }
    }

    public EnvironmentBuilder(String name) {
        this.name = Objects.requireNonNull(name, "name");
    }

    /** The computer that runs the environment's program (default localhost). */
    public EnvironmentBuilder host(String host) {
        this.host = Objects.requireNonNull(host, "host");
        return this;
    }

    /** The CM11A's serial port (default {@value #DEFAULT_CM11A_PORT}). */
    public EnvironmentBuilder cm11aPort(String port) {
        this.cm11aPort = Objects.requireNonNull(port, "port");
        return this;
    }

    /** Where to find module descriptions for the devices' version, details and documentation page. */
    public EnvironmentBuilder moduleDescriptions(Path folder) {
        this.moduleDescriptions = folder;
        return this;
    }

    public EnvironmentBuilder add(X10Device device) {
        devices.add(Objects.requireNonNull(device, "device"));
        return this;
    }

    /** The environment, validated; errors are reported as for a file named {@code environment '<name>'}. */
    public EnvironmentDocument build() throws DescriptionException {
        EnvironmentDocument document = EnvironmentDocument.Factory.newInstance();
        EnvModuleListType environment = document.addNewEnvironment();
        environment.setEnvironmentName(name);
        environment.setHost(host);
        environment.setCOMPort(cm11aPort);
        Set<String> names = new HashSet<>();
        for (X10Device device : devices) {
            X10ModuleType module = environment.addNewX10Module();
            module.setName(moduleName(device, names));
            module.setHouseCode(String.valueOf(device.houseCode()));
            module.setUnitCode(UnitCodeType.Enum.forString(UNITS[device.unit() - 1]));
            module.setClass1(X10ModuleClassType.Enum.forString(device.moduleClass()));
            ModuleDescriptionType template = template(device.moduleClass());
            module.setVersion(template == null ? "1.0" : template.getVersion());
            if (template != null && template.isSetDetails()) {
                module.setDetails(template.getDetails());
            }
            if (template != null) {
                module.setDocRef(template.getDocRef());
            }
        }
        DescriptionLoader.validate(document, "environment '" + name + "'");
        return document;
    }

    /** The given name, else "Lamp" or "Appliance", made unique with the address ("Lamp-A4"). */
    private static String moduleName(X10Device device, Set<String> taken) {
        String chosen = device.name() != null ? device.name()
                : device.kind().equals("lamp") ? "Lamp" : "Appliance";
        if (!taken.add(chosen) && device.name() == null) {
            chosen = chosen + "-" + device.address();
            taken.add(chosen);
        }
        return chosen;
    }

    /** The first module description (by file name) of this class, or null. */
    private ModuleDescriptionType template(String moduleClass) {
        if (moduleDescriptions == null || !Files.isDirectory(moduleDescriptions)) {
            return null;
        }
        try (Stream<Path> files = Files.list(moduleDescriptions)) {
            for (Path file : files.filter(f -> f.toString().endsWith(".xml")).sorted().toList()) {
                try {
                    ModuleDescriptionType description = DescriptionLoader.loadModuleDescription(file)
                            .getModuleDescription();
                    if (moduleClass.equals(ModuleClassName.of(description))) {
                        return description;
                    }
                } catch (DescriptionException e) {
                    // a broken catalogue entry is rwe validate's business, not a reason to fail here
                }
            }
        } catch (IOException e) {
            return null;
        }
        return null;
    }
}
