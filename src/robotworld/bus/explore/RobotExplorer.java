package robotworld.bus.explore;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.OptionalLong;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.AdapterEchoException;
import robotworld.bus.BusCrcException;
import robotworld.bus.BusException;
import robotworld.bus.BusProtocolException;
import robotworld.bus.BusTimeoutException;
import robotworld.bus.ModuleRefusedException;
import robotworld.bus.RS485Bus;
import robotworld.bus.modbus.DeviceIdentification;
import robotworld.bus.modbus.ServerIdReport;
import robotworld.description.BusModuleClassType;
import robotworld.description.DescriptionException;
import robotworld.description.ModuleDescriptionType;
import robotworld.description.RobotDescriptionDocument;

/**
 * Bus exploration: scans addresses, identifies each module that answers (identification, status, echo), looks
 * its NodeID up in the module catalogue, and writes a schema-valid robot description.
 *
 * <p>Silence at an address means nobody is there and costs only the short scan timeout
 * ({@link RS485Bus#scanReplyTimeout()}). Every other failure at an address (timeouts after a first answer, CRC
 * errors, exception responses, unknown NodeIDs) is reported to the listener and in the result, and the scan goes
 * on. A module slower than the scan timeout is not lost: its late reply arrives during a later address, is
 * recognised by its address, and the module is asked again with the normal timeout after the scan.
 */
public final class RobotExplorer {

    private static final Logger LOG = LoggerFactory.getLogger(RobotExplorer.class);

    /** The Modbus unicast address range. */
    public static final int FIRST_ADDRESS = 1;
    public static final int LAST_ADDRESS = 247;

    /** After this many link failures in a row the link is taken as gone and the scan stops. */
    private static final int LINK_FAILURES_TO_GIVE_UP = 3;
    /** Rounds of asking again after the scan (each round may bring late replies of the one before to light). */
    private static final int MAX_ASK_AGAIN_ROUNDS = 4;
    private static final Pattern VERSION = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._\\-]{0,31}");

    private final RS485Bus bus;
    private final ModuleCatalog catalog;
    private int firstAddress = FIRST_ADDRESS;
    private int lastAddress = LAST_ADDRESS;
    private String host = "localhost";

    public RobotExplorer(RS485Bus bus, ModuleCatalog catalog) {
        this.bus = bus;
        this.catalog = catalog;
    }

    /** Scans only {@code first..last} (default 1..247). */
    public RobotExplorer addresses(int first, int last) {
        if (first < FIRST_ADDRESS || last > LAST_ADDRESS || first > last) {
            throw new IllegalArgumentException("address range " + first + ".." + last + " is not within 1..247");
        }
        this.firstAddress = first;
        this.lastAddress = last;
        return this;
    }

    /** The {@code <Host>} of the description: the computer that runs the robot's program (default localhost). */
    public RobotExplorer host(String hostName) {
        this.host = hostName;
        return this;
    }

    /** How many addresses a scan covers. */
    public int addressCount() {
        return lastAddress - firstAddress + 1;
    }

    /**
     * Explores the bus.
     *
     * @param robotName the {@code <RobotName>}
     * @throws DescriptionException before scanning, when the robot name or host cannot go into a description
     */
    public ExplorationResult explore(String robotName, ExplorationListener listener) throws DescriptionException {
        RobotDescriptionBuilder.checkNames(robotName, host);
        long started = System.nanoTime();
        Scan scan = new Scan(listener);
        Set<Integer> late = scan.late;
        Set<Integer> disturbed = scan.disturbed;
        bus.onStrayFrame(frame -> {
            if (frame.address() >= firstAddress && frame.address() <= lastAddress) {
                scan.touched(frame.address());
                if (late.add(frame.address())) {
                    LOG.debug("address {}: heard (a late reply)", frame.address());
                }
            }
        });
        bus.onDisturbance((heard, address) -> {
            if (address >= firstAddress && address <= lastAddress) {
                scan.touched(address);
                // heard: the start of its reply came, so it is there
                if ((heard ? late : disturbed).add(address)) {
                    LOG.debug("address {}: {}", address, heard ? "heard (the start of a cut reply)" : "disturbed");
                }
            }
        });
        try {
            int total = addressCount();
            for (int address = firstAddress; address <= lastAddress && !scan.linkGone(); address++) {
                scan.probe(address);
                listener.progress(address, address - firstAddress + 1, total);
            }
            if (!scan.linkGone()) {
                bus.listenForStrays(bus.timing().responseTimeout());
                askAgainUntilSettled(scan, late, disturbed);
            }
        } finally {
            bus.onStrayFrame(null);
            bus.onDisturbance(null);
        }
        return scan.result(robotName, Duration.ofNanos(System.nanoTime() - started));
    }

    /**
     * Asks again, with the normal timeout, every address that answered late (a failure there is reported) and
     * every address whose exchange was disturbed (silence there means nobody, but only silence in an exchange that
     * nothing disturbed), round after round while asking brings new late replies or disturbances to light. What is
     * still open after the last round is reported, never dropped.
     */
    private void askAgainUntilSettled(Scan scan, Set<Integer> late, Set<Integer> disturbed) {
        for (int round = 0; round < MAX_ASK_AGAIN_ROUNDS && !scan.linkGone(); round++) {
            Set<Integer> todo = scan.open();
            if (todo.isEmpty()) {
                return;
            }
            LOG.debug("asking again, round {}: {} (heard: {})", round + 1, todo, late);
            for (int address : todo) {
                scan.askAgain(address, late.contains(address));
            }
        }
        if (!scan.linkGone()) {
            for (int address : scan.open()) {
                scan.unsettled(address, late.contains(address));
            }
        }
    }

    /** The state of one exploration run. */
    private final class Scan {

        private final ExplorationListener listener;
        private final List<FoundModule> found = new ArrayList<>();
        private final List<String> details = new ArrayList<>();
        private final List<String> docRefs = new ArrayList<>();
        private final List<AddressProblem> problems = new ArrayList<>();
        private final List<String> notes = new ArrayList<>();
        private final Set<Integer> settled = new HashSet<>();
        /** Addresses heard answering (a late reply, or the start of one): a module is there. */
        final Set<Integer> late = new TreeSet<>();
        /** Addresses whose exchange was disturbed: perhaps a module is there. */
        final Set<Integer> disturbed = new TreeSet<>();
        /** Disturbed addresses that were asked again and stayed silent in an undisturbed exchange: nobody there. */
        private final Set<Integer> absent = new HashSet<>();
        /** Per address, how often bytes from or for it were heard or disturbed (to tell a quiet exchange). */
        private final java.util.Map<Integer, Integer> touches = new java.util.HashMap<>();
        private final Set<String> names = new HashSet<>();
        private int linkFailures;
        /** The adapter echoes and echo cancellation is off: every address would fail the same way. */
        private boolean echoing;

        Scan(ExplorationListener listener) {
            this.listener = listener;
        }

        boolean linkGone() {
            return linkFailures >= LINK_FAILURES_TO_GIVE_UP || echoing;
        }

        /** First contact with the short scan timeout. */
        void probe(int address) {
            try {
                DeviceIdentification identity = bus.probe(address);
                linkFailures = 0;
                settled.add(address);
                check(address, identity);
            } catch (BusTimeoutException e) {
                linkFailures = 0; // nobody there (or slow: a late reply brings it back)
            } catch (BusException e) {
                settled.add(address);
                fail(address, e);
            }
        }

        boolean settled(int address) {
            return settled.contains(address);
        }

        /** Something was heard from or about {@code address}: any silence it showed before proves nothing more. */
        void touched(int address) {
            touches.merge(address, 1, Integer::sum);
            absent.remove(address);
        }

        /** Heard or disturbed addresses not yet found, reported, or shown to be empty. */
        Set<Integer> open() {
            Set<Integer> todo = new TreeSet<>(late);
            todo.addAll(disturbed);
            todo.removeIf(address -> settled.contains(address) || !late.contains(address) && absent.contains(address));
            return todo;
        }

        /** An address still open when the rounds of asking again are used up: reported, not dropped. */
        void unsettled(int address, boolean answered) {
            settled.add(address);
            problem(address, AddressProblem.Kind.DISTURBED, (answered ? "a module answered here during the scan"
                    : "exchanges with this address were disturbed (cut short, garbled, or crossed by other replies)")
                    + ", but it could not be asked again undisturbed in " + MAX_ASK_AGAIN_ROUNDS + " rounds; explore "
                    + "again, and if this persists check the line (baud rate, termination, noise)");
        }

        /**
         * An address asked again with the normal timeout.
         *
         * @param answered whether it was heard (a late reply): then silence is reported, else it means nobody
         */
        void askAgain(int address, boolean answered) {
            if (settled.contains(address)) {
                return;
            }
            int touchedBefore = touches.getOrDefault(address, 0);
            try {
                // a module heard late gets every retry; an address only disturbed, one ask (silence: nobody there)
                DeviceIdentification identity = answered ? bus.identify(address) : bus.reprobe(address);
                settled.add(address);
                check(address, identity);
            } catch (BusTimeoutException e) {
                if (answered) {
                    settled.add(address);
                    fail(address, e);
                } else if (touches.getOrDefault(address, 0) == touchedBefore) {
                    absent.add(address);
                    LOG.debug("address {}: silent when asked again: nobody there", address);
                } else {
                    // an attempt was cut or garbled before the silence: that silence proves nothing, ask again
                    LOG.debug("address {}: asked again, disturbed again", address);
                }
            } catch (BusException e) {
                settled.add(address);
                fail(address, e);
            }
        }

        private void check(int address, DeviceIdentification identity) {
            if (!identity.productCode().isEmpty()) {
                bus.nameModule(address, "module " + identity.productCode()); // later messages say what it is
            }
            try {
                ServerIdReport status = bus.reportServerId(address);
                if (!status.running()) {
                    problem(address, AddressProblem.Kind.NOT_RUNNING, "the module reports that it is not running "
                            + "(run indicator 0x00)");
                    return;
                }
                int word = 0xA500 | address; // differs per address, so a stray echo cannot pass for ours
                bus.echo(address, word);
            } catch (BusException e) {
                fail(address, e);
                return;
            }
            String nodeId = identity.productCode();
            ModuleDescriptionType description;
            try {
                Optional<ModuleDescriptionType> known = catalog.lookUp(nodeId);
                if (known.isEmpty()) {
                    problem(address, AddressProblem.Kind.UNKNOWN_NODE_ID, "NodeID '" + nodeId + "' has no description"
                            + " (looked for " + catalog.fileOf(nodeId) + ")");
                    return;
                }
                description = known.get();
            } catch (IllegalArgumentException e) {
                problem(address, AddressProblem.Kind.UNKNOWN_NODE_ID, e.getMessage());
                return;
            } catch (DescriptionException e) {
                problem(address, AddressProblem.Kind.UNKNOWN_NODE_ID, "the description of NodeID '" + nodeId
                        + "' is invalid: " + e.getMessage().replace('\n', ';'));
                return;
            }
            if (BusModuleClassType.Enum.forString(description.getClass1()) == null) {
                problem(address, AddressProblem.Kind.UNKNOWN_NODE_ID, "NodeID '" + nodeId + "' describes a "
                        + description.getClass1() + ", which is not a bus module");
                return;
            }
            String version = identity.revision();
            if (!VERSION.matcher(version).matches()) {
                notes.add("address " + address + ": reported version '" + version + "' is not usable; the catalogue's "
                        + description.getVersion() + " was written instead");
                version = description.getVersion();
            }
            FoundModule module = new FoundModule(address, uniqueName(description.getName(), address), nodeId,
                    description.getClass1(), version, identity.vendorName());
            found.add(module);
            details.add(description.isSetDetails() ? description.getDetails() : null);
            docRefs.add(description.getDocRef());
            listener.moduleFound(module);
        }

        private String uniqueName(String name, int address) {
            String unique = names.contains(name) ? name + "-" + address : name;
            names.add(unique);
            return unique;
        }

        private void fail(int address, BusException e) {
            AddressProblem.Kind kind;
            if (e instanceof BusTimeoutException) {
                kind = AddressProblem.Kind.TIMEOUT;
            } else if (e instanceof BusCrcException) {
                kind = AddressProblem.Kind.CRC_ERROR;
            } else if (e instanceof AdapterEchoException) {
                kind = AddressProblem.Kind.PROTOCOL_ERROR;
                echoing = true;
            } else if (e instanceof ModuleRefusedException) {
                kind = AddressProblem.Kind.EXCEPTION_RESPONSE;
            } else if (e instanceof BusProtocolException) {
                kind = AddressProblem.Kind.PROTOCOL_ERROR;
            } else {
                kind = AddressProblem.Kind.LINK_ERROR;
                linkFailures++;
            }
            if (kind != AddressProblem.Kind.LINK_ERROR) {
                linkFailures = 0;
            }
            problem(address, kind, e.getMessage());
        }

        private void problem(int address, AddressProblem.Kind kind, String message) {
            AddressProblem problem = new AddressProblem(address, kind, message);
            problems.add(problem);
            listener.problem(problem);
        }

        ExplorationResult result(String robotName, Duration elapsed) throws DescriptionException {
            if (echoing) {
                notes.add("the scan stopped early: the adapter echoes every request and echo cancellation is off "
                        + "(--echo on, or auto)");
            } else if (linkGone()) {
                notes.add("the scan stopped early: the link failed " + LINK_FAILURES_TO_GIVE_UP + " times in a row");
            }
            if (bus.echoDetected()) {
                notes.add("the adapter echoes every request (an RS-485 adapter without echo suppression): echo "
                        + "cancellation was turned on (--echo on sets it from the start)");
            }
            List<Integer> order = new ArrayList<>();
            for (int i = 0; i < found.size(); i++) {
                order.add(i);
            }
            order.sort((a, b) -> Integer.compare(found.get(a).address(), found.get(b).address()));
            List<FoundModule> modules = order.stream().map(found::get).toList();
            problems.sort((a, b) -> Integer.compare(a.address(), b.address()));
            Optional<RobotDescriptionDocument> description = Optional.empty();
            if (!modules.isEmpty()) {
                String port = bus.portName();
                if (!RobotDescriptionBuilder.isDescribablePort(port)) {
                    notes.add("port name '" + port + "' cannot go into <COMPort>; it was left out");
                    port = null;
                }
                description = Optional.of(RobotDescriptionBuilder.build(robotName, host, port, modules,
                        order.stream().map(details::get).toList(), order.stream().map(docRefs::get).toList()));
            }
            OptionalLong paced = bus.replyPacing().slowerLineBaud(bus.settings().bitsPerCharacter());
            // a mismatch garbles (or slows) the replies of most modules; a few troubled modules among clean ones
            // are troubled modules
            long garbled = problems.stream().filter(p -> p.kind() == AddressProblem.Kind.CRC_ERROR)
                    .mapToInt(AddressProblem::address).distinct().count();
            boolean mismatch = paced.isPresent() || (garbled >= 2 && garbled > modules.size())
                    || (modules.isEmpty() && bus.statistics().crcErrors() >= 3);
            if (paced.isPresent()) {
                notes.add("replies arrive at about " + paced.getAsLong() + " baud, not " + bus.settings().baudRate()
                        + ": if the modules talk at " + paced.getAsLong() + " baud, explore with --baud "
                        + paced.getAsLong() + " (or --baud auto)");
            } else if (mismatch) {
                notes.add("replies were garbled (" + bus.statistics().crcErrors() + " corrupted): this looks like a"
                        + " baud-rate mismatch; check the modules' line speed and --baud (or try --baud auto)");
            }
            OptionalInt suggested = paced.isPresent() ? OptionalInt.of((int) paced.getAsLong()) : OptionalInt.empty();
            return new ExplorationResult(description, modules, problems, notes, elapsed, bus.statistics(), suggested,
                    mismatch);
        }
    }
}
