package robotworld.explorer.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import robotworld.bus.BusTiming;
import robotworld.bus.EchoCancellation;
import robotworld.bus.InvalidPortNameException;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.explore.AddressProblem;
import robotworld.bus.explore.BaudRateSearch;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.FoundModule;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.description.DescriptionError;
import robotworld.description.DescriptionException;
import robotworld.description.RobotWorldAssembler;
import robotworld.explorer.WorldAssembly;
import robotworld.program.PortException;

/** {@code rwe explore --port P --name N --out FILE}: scans a robot's bus and writes its robot description. */
@Command(name = "explore", mixinStandardHelpOptions = true,
        description = {"Explore a robot's module bus (Modbus RTU, addresses 1..247) and write its robot description.",
                "Each module that answers is identified, checked (status, echo) and looked up by its NodeID in the "
                        + "module descriptions. Problems at an address are listed and the address is skipped.",
                "Exit code 0 when a description was written, 1 when no module was found or the port failed.",
                "Then: rwe assemble --robot FILE ... --name WORLD --out WORLD.xml."})
final class ExploreCommand implements Callable<Integer> {

    @Option(names = "--port", required = true, paramLabel = "PORT",
            description = "the bus: a serial device (/dev/ttyUSB0, COM4) or tcp://HOST:PORT")
    private String port;

    @Option(names = "--name", required = true, paramLabel = "NAME", description = "the robot's name (a Java identifier)")
    private String name;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "where to write the robot description")
    private Path out;

    @Option(names = "--force", description = "replace FILE if it exists")
    private boolean force;

    @Option(names = "--descriptions", paramLabel = "DIR",
            description = "module descriptions folder (default: ModuleDescriptions/ of the RobotWorldExplorer home)")
    private Path descriptions;

    @Option(names = "--host", paramLabel = "HOST",
            description = "<Host> of the robot, the computer that runs its program (default: this computer's name)")
    private String host;

    @Option(names = "--baud", paramLabel = "BAUD|auto", defaultValue = "115200",
            description = "line speed of a serial device (default: ${DEFAULT-VALUE}); also sets the scan timing; "
                    + "auto tries the common rates until one gives a clean result")
    private String baudText;

    private int baud;

    @Option(names = "--timeout", paramLabel = "MS", defaultValue = "100",
            description = "how long a found module may take to start a reply (default: ${DEFAULT-VALUE})")
    private int timeoutMillis;

    @Option(names = "--scan-allowance", paramLabel = "MS", defaultValue = "8",
            description = "scan: extra time an address gets to start answering beyond the line's 3.5-character "
                    + "silence; every absent address costs it (default: ${DEFAULT-VALUE})")
    private int scanAllowanceMillis;

    @Option(names = "--attempts", paramLabel = "N", defaultValue = "3",
            description = "tries per command before an address is given up (default: ${DEFAULT-VALUE})")
    private int attempts;

    @Option(names = "--echo", paramLabel = "auto|on|off", defaultValue = "auto",
            description = "an RS-485 adapter that echoes what it sends: auto detects it, on drops the echo, off "
                    + "reports it (default: ${DEFAULT-VALUE})")
    private String echo;

    @Option(names = "--from", paramLabel = "ADDRESS", defaultValue = "1", description = "first address (default: 1)")
    private int from;

    @Option(names = "--to", paramLabel = "ADDRESS", defaultValue = "247", description = "last address (default: 247)")
    private int to;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws IOException, PortException {
        PrintWriter stdout = spec.commandLine().getOut();
        PrintWriter stderr = spec.commandLine().getErr();
        boolean autoBaud = baudText.equalsIgnoreCase("auto");
        try {
            baud = autoBaud ? RS485Bus.DEFAULT_BAUD : Integer.parseInt(baudText);
        } catch (NumberFormatException e) {
            throw new ParameterException(spec.commandLine(), "--baud must be a number or auto, not '" + baudText + "'");
        }
        BusTiming timing = timing();
        String nameProblem = WorldAssembly.problemWithName(name);
        if (nameProblem != null) {
            throw new ParameterException(spec.commandLine(), "--name: " + nameProblem);
        }
        if (Files.exists(out) && !force) {
            throw new ParameterException(spec.commandLine(), out + " exists; choose another --out or add --force to"
                    + " replace it");
        }
        Path folder = descriptions != null ? descriptions : defaultDescriptions();
        if (!Files.isDirectory(folder)) {
            throw new ParameterException(spec.commandLine(), "module descriptions folder " + folder + " does not exist");
        }
        if (autoBaud) {
            return exploreAtEveryRate(folder, timing, stdout, stderr);
        }
        RS485Bus bus;
        try {
            bus = new RS485Bus(port, SerialSettings.eightNoneOne(baud), timing);
        } catch (InvalidPortNameException e) {
            throw new ParameterException(spec.commandLine(), "--port: " + e.getMessage());
        } catch (IOException e) {
            throw new PortException(null, "bus", port, e);
        }
        try (bus) {
            try {
                bus.echoCancellation(EchoCancellation.parse(echo));
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), "--echo: " + e.getMessage());
            }
            RobotExplorer explorer;
            try {
                explorer = new RobotExplorer(bus, new ModuleCatalog(folder)).addresses(from, to)
                        .host(host != null ? host : WorldAssembly.thisComputer());
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
            stderr.println("exploring " + bus + ", addresses " + from + ".." + to + ", scan timeout "
                    + String.format(java.util.Locale.ROOT, "%.1f ms", bus.scanReplyTimeout().toNanos() / 1e6)
                    + " per address");
            ProgressBar bar = new ProgressBar(stderr, explorer.addressCount());
            ExplorationResult result;
            try {
                result = explorer.explore(name, new BarListener(bar));
            } catch (DescriptionException e) {
                bar.finish();
                for (DescriptionError error : e.errors()) {
                    stderr.println("rwe: " + error.message());
                }
                return 1;
            } finally {
                bar.finish();
            }
            return report(result, explorer.addressCount(), stdout, stderr);
        }
    }

    /** {@code --baud auto}: one exploration per common rate until one is clean. */
    private int exploreAtEveryRate(Path folder, BusTiming timing, PrintWriter stdout, PrintWriter stderr)
            throws IOException {
        EchoCancellation echoMode;
        try {
            echoMode = EchoCancellation.parse(echo);
            robotworld.bus.PortName.parse(port);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        String robotHost = host != null ? host : WorldAssembly.thisComputer();
        BaudRateSearch.Outcome outcome;
        try {
            outcome = BaudRateSearch.explore(rate -> new RS485Bus(port, SerialSettings.eightNoneOne(rate), timing)
                    .echoCancellation(echoMode), bus -> {
                        stderr.println("exploring " + bus + ", addresses " + from + ".." + to);
                        return new RobotExplorer(bus, new ModuleCatalog(folder)).addresses(from, to).host(robotHost);
                    }, name, new ExplorationListener() { }, line -> stderr.println("--baud auto: " + line));
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        } catch (DescriptionException e) {
            for (DescriptionError error : e.errors()) {
                stderr.println("rwe: " + error.message());
            }
            return 1;
        }
        stdout.println("baud rate " + outcome.baud() + " (tried " + outcome.tried() + ")");
        return report(outcome.result(), to - from + 1, stdout, stderr);
    }

    private int report(ExplorationResult result, int scanned, PrintWriter stdout, PrintWriter stderr)
            throws IOException {
        for (FoundModule module : result.modules()) {
            stdout.println("found   " + module);
        }
        for (AddressProblem problem : result.problems()) {
            stdout.println("skipped " + problem);
        }
        for (String note : result.notes()) {
            stdout.println("note    " + note);
        }
        stdout.println(result.summary(scanned));
        if (result.description().isEmpty()) {
            stderr.println("rwe explore: no module answered on " + port + "; nothing written.");
            stderr.println("Check that the robot is switched on and its bus connected (for a simulator: that rwe"
                    + " simulate robot runs there), and the baud rate (--baud auto tries them).");
            return 1;
        }
        RobotWorldAssembler.write(result.description().get(), out);
        stdout.println("wrote " + out + ": robot '" + name + "' with " + result.modules().size()
                + (result.modules().size() == 1 ? " module" : " modules"));
        stdout.println("next: rwe assemble --robot " + out + " [--x10 A3=appliance:Lamp] --name WORLD --out WORLD.xml");
        return 0;
    }

    private BusTiming timing() {
        if (timeoutMillis < 1 || scanAllowanceMillis < 1 || attempts < 1 || attempts > 10 || baud < 300) {
            throw new ParameterException(spec.commandLine(),
                    "--timeout and --scan-allowance must be at least 1 ms, --attempts 1..10, --baud at least 300");
        }
        return BusTiming.defaults().withResponseTimeout(Duration.ofMillis(timeoutMillis)).withAttempts(attempts)
                .withScanAllowance(Duration.ofMillis(scanAllowanceMillis));
    }

    private static Path defaultDescriptions() {
        return Path.of(System.getProperty("rwe.home", ".")).resolve("ModuleDescriptions");
    }

    /** Feeds the progress bar and lists problems as they happen. */
    private static final class BarListener implements ExplorationListener {

        private final ProgressBar bar;
        private int found;

        BarListener(ProgressBar bar) {
            this.bar = bar;
        }

        @Override
        public void progress(int address, int done, int total) {
            bar.show(done, address, found);
        }

        @Override
        public void moduleFound(FoundModule module) {
            found++;
            bar.message("found   " + module);
        }

        @Override
        public void problem(AddressProblem problem) {
            bar.message("skipped " + problem);
        }
    }
}
