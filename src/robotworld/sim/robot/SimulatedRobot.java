package robotworld.sim.robot;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robotworld.bus.PortName;
import robotworld.bus.SerialLink;
import robotworld.bus.SerialLinks;
import robotworld.bus.SerialSettings;
import robotworld.bus.modbus.RtuTiming;

/**
 * A simulated robot: Modbus RTU modules at bus addresses, attached to a 2-D world, served on {@code tcp://} and/or
 * on serial links such as one end of a socat pty pair.
 *
 * <pre>{@code
 * try (SimulatedRobot robot = SimulatedRobot.load(Path.of("docs/examples/simulated-robot.sim"))) {
 *     String port = robot.serve("tcp://127.0.0.1:0");   // e.g. tcp://127.0.0.1:40123
 *     ...
 * }
 * }</pre>
 */
public final class SimulatedRobot implements AutoCloseable {

    private final SimRobotConfig config;
    private final Simulation simulation;
    private final RtuTiming rtu;
    private final List<AutoCloseable> endpoints = new ArrayList<>();
    /** The sessions serving links now (closed ones are dropped from time to time). */
    private final java.util.Set<RtuServerSession> sessions = java.util.concurrent.ConcurrentHashMap.newKeySet();
    private volatile boolean echoRequests;

    private SimulatedRobot(SimRobotConfig config) {
        this.config = config;
        this.simulation = config.build();
        SerialSettings settings = SerialSettings.eightNoneOne(config.baud());
        this.rtu = RtuTiming.of(settings.baudRate(), settings.characterTimeNanos());
    }

    /** Builds the robot from a configuration and starts its clock. */
    public static SimulatedRobot create(SimRobotConfig config) {
        SimulatedRobot robot = new SimulatedRobot(config);
        robot.simulation.start();
        return robot;
    }

    /** Reads a configuration file ({@link SimRobotConfigReader}) and builds the robot. */
    public static SimulatedRobot load(Path configFile) throws IOException {
        return create(SimRobotConfigReader.read(configFile));
    }

    public SimRobotConfig config() {
        return config;
    }

    public Simulation simulation() {
        return simulation;
    }

    /** The module at {@code address}; fails when there is none. */
    public SimModule module(int address) {
        SimModule module = simulation.module(address);
        if (module == null) {
            throw new IllegalArgumentException("no simulated module at address " + address);
        }
        return module;
    }

    /** The fault switches of the module at {@code address}. */
    public ModuleFaults faults(int address) {
        return module(address).faults();
    }

    /** Where the robot is now. */
    public Pose pose() {
        return simulation.inspect(World::pose);
    }

    /**
     * Serves the bus on {@code portName}: {@code tcp://HOST:PORT} listens there (port 0 picks a free one), anything
     * else is opened as a serial device (e.g. a pty link made by socat) and served.
     *
     * @return the port name clients use: for TCP with the real port number
     */
    public synchronized String serve(String portName) throws IOException {
        PortName parsed = PortName.parseListening(portName);
        if (parsed instanceof PortName.Tcp tcp) {
            RobotBusServer server = new RobotBusServer(tcp.host(), tcp.port(), this::session);
            endpoints.add(server);
            return server.portName();
        }
        SerialLink link = SerialLinks.open(parsed.text(), SerialSettings.eightNoneOne(config.baud()));
        attach(link);
        return link.portName();
    }

    /** Serves the bus on an open link until the link closes or the robot is closed. */
    public synchronized void attach(SerialLink link) {
        RtuServerSession session = session(link);
        endpoints.add(session::close);
        Thread thread = new Thread(session, "robot-sim-session " + link.portName());
        thread.setDaemon(true);
        thread.start();
    }

    private RtuServerSession session(SerialLink link) {
        RtuServerSession session = new RtuServerSession(link, simulation, rtu, config.timing(), () -> echoRequests);
        sessions.removeIf(RtuServerSession::isClosed);
        sessions.add(session);
        return session;
    }

    /**
     * Fault injection: every link served now goes silent without closing (requests are read and never answered),
     * as when the far end of a TCP connection or a serial adapter hangs; links opened afterwards are served as
     * usual. Unlike a module's {@link ModuleFaults#silent silence}, only a new connection gets answers again.
     */
    public void hangOpenLinks() {
        sessions.removeIf(RtuServerSession::isClosed);
        sessions.forEach(RtuServerSession::hang);
    }

    /**
     * Makes the line echo every request back to the master before the reply, as a half-duplex RS-485 adapter
     * without echo suppression does on the master's side.
     */
    public void echoRequests(boolean value) {
        echoRequests = value;
    }

    /** Stops serving and stops the clock. */
    @Override
    public synchronized void close() {
        for (AutoCloseable endpoint : endpoints) {
            try {
                endpoint.close();
            } catch (Exception e) {
                // closing anyway
            }
        }
        endpoints.clear();
        simulation.close();
    }

    /** One line about the robot, e.g. for the command line. */
    public String describe() {
        StringBuilder text = new StringBuilder("simulated robot '" + config.name() + "': ");
        List<String> parts = new ArrayList<>();
        for (SimModule module : simulation.modules().values()) {
            parts.add(module.moduleClass() + " at " + module.address());
        }
        text.append(String.join(", ", parts)).append("; ").append(config.baud()).append(" baud, ")
                .append(config.timing().name().toLowerCase(java.util.Locale.ROOT)).append(" timing");
        return text.toString();
    }
}
