package robotworld.x10;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.SerialLink;
import robotworld.bus.SerialLinks;

/**
 * Drives X10 devices through a CM11A computer interface on a serial port or a {@code tcp://} serial bridge.
 *
 * <p>Every command is a sequence of frames (e.g. address A3, then A On) that goes out as one unit: commands from
 * several threads are queued and never interleave, so no other address can slip in between an address and its
 * function. A command returns when the interface has reported the power-line transmission done (0x55).
 *
 * <p>Failures are unchecked: {@link X10TimeoutException} when the interface does not answer (after
 * {@link CM11aConfig#deadDeviceTimeout()} for a dead device), {@link X10ProtocolException} for wrong answers
 * beyond the retries, {@link X10Exception} for a lost link or a closed controller.
 *
 * <p>Uploads from the power line (remote controls, motion sensors) arrive as {@link X10Event}s at the listeners.
 */
public final class CM11aController implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(CM11aController.class);
    private static final long CLOSE_WAIT_MILLIS = 2_000;

    private final SerialLink link;
    private final CM11aConfig config;
    private final LinkWorker worker;
    private final List<X10Listener> listeners = new CopyOnWriteArrayList<>();
    private final ExecutorService eventThread;

    /**
     * Takes over an open link and starts the controller's link thread. Closing the controller closes the link.
     */
    public CM11aController(SerialLink link, CM11aConfig config) {
        if (!link.isOpen()) {
            throw new IllegalArgumentException(link.portName() + ": the link must be open");
        }
        this.link = link;
        this.config = config;
        this.eventThread = Executors.newSingleThreadExecutor(runnable -> {
            Thread thread = new Thread(runnable, "cm11a-events " + link.portName());
            thread.setDaemon(true);
            return thread;
        });
        this.worker = new LinkWorker(new CM11aProtocol(link, config, this::publish), config);
    }

    /** Opens {@code portName} (a serial device or {@code tcp://host:port}) at 4800 8N1 with default timing. */
    public static CM11aController open(String portName) throws IOException {
        return open(portName, CM11aConfig.defaults());
    }

    /** Opens {@code portName} (a serial device or {@code tcp://host:port}) at 4800 8N1. */
    public static CM11aController open(String portName, CM11aConfig config) throws IOException {
        return new CM11aController(SerialLinks.open(portName, X10Constants.CM11A_SERIAL), config);
    }

    /** The port of the interface. */
    public String portName() {
        return link.portName();
    }

    /** The timing in use. */
    public CM11aConfig config() {
        return config;
    }

    // ----- commands -----

    /** Sends the frames as one command, in order, each with checksum, acknowledge and ready. */
    public void send(X10Frame... frames) {
        send(List.of(frames));
    }

    /** Sends the frames as one command, in order, each with checksum, acknowledge and ready. */
    public void send(List<X10Frame> frames) {
        List<X10Frame> copy = List.copyOf(frames);
        await(worker.submit(protocol -> {
            protocol.transmit(copy);
            return null;
        }));
    }

    /** Addresses {@code address} and sends {@code function} to its house, e.g. A3 then A On. */
    public void send(X10Address address, X10Function function) {
        send(X10Frame.address(address), X10Frame.function(address.house(), function));
    }

    /** Switches the device at {@code address} on. */
    public void on(X10Address address) {
        send(address, X10Function.ON);
    }

    /** Switches the device at {@code address} off. */
    public void off(X10Address address) {
        send(address, X10Function.OFF);
    }

    /** Dims the lamp at {@code address} by {@code steps} of 22 (0 sends nothing). */
    public void dim(X10Address address, int steps) {
        dimOrBright(address, X10Function.DIM, steps);
    }

    /** Brightens the lamp at {@code address} by {@code steps} of 22 (0 sends nothing). */
    public void bright(X10Address address, int steps) {
        dimOrBright(address, X10Function.BRIGHT, steps);
    }

    private void dimOrBright(X10Address address, X10Function function, int steps) {
        X10Frame change = X10Frame.function(address.house(), function, steps); // validates 0..22
        if (steps > 0) {
            send(X10Frame.address(address), change);
        }
    }

    /**
     * Sets the lamp at {@code address} to {@code level} of 31 with Preset Dim (0 = off): the address frame, then
     * Preset Dim 1 (levels 0..15) or 2 (16..31) with the level's four low bits, in reversed order, in place of the
     * house code.
     */
    public void presetDim(X10Address address, int level) {
        if (level < 0 || level > 31) {
            throw new IllegalArgumentException("preset dim level must be 0..31, was " + level);
        }
        int nibble = X10Constants.presetDimNibble(level);
        X10Function preset = level < 16 ? X10Function.PRESET_DIM_1 : X10Function.PRESET_DIM_2;
        send(X10Frame.address(address), X10Frame.function(HouseCode.ofCode(nibble), preset));
    }

    /** Sends an extended code (e.g. preset dim, command 0x31) to {@code address}. */
    public void sendExtended(X10Address address, int data, int command) {
        send(X10Frame.extended(address, data, command));
    }

    /** All Units Off for one house: every module of that house goes off. */
    public void allUnitsOff(HouseCode house) {
        send(X10Frame.function(house, X10Function.ALL_UNITS_OFF));
    }

    /** All Lights On for one house: every lamp module of that house goes on. */
    public void allLightsOn(HouseCode house) {
        send(X10Frame.function(house, X10Function.ALL_LIGHTS_ON));
    }

    /** All Lights Off for one house: every lamp module of that house goes off. */
    public void allLightsOff(HouseCode house) {
        send(X10Frame.function(house, X10Function.ALL_LIGHTS_OFF));
    }

    /** All Units Off for all sixteen houses, as one command (about 16 power-line transmissions). */
    public void allUnitsOff() {
        sendToEveryHouse(X10Function.ALL_UNITS_OFF);
    }

    /** All Lights On for all sixteen houses, as one command. */
    public void allLightsOn() {
        sendToEveryHouse(X10Function.ALL_LIGHTS_ON);
    }

    /** All Lights Off for all sixteen houses, as one command. */
    public void allLightsOff() {
        sendToEveryHouse(X10Function.ALL_LIGHTS_OFF);
    }

    private void sendToEveryHouse(X10Function function) {
        List<X10Frame> frames = new ArrayList<>();
        for (HouseCode house : HouseCode.values()) {
            frames.add(X10Frame.function(house, function));
        }
        send(frames);
    }

    /** Asks the interface for its 14-byte status (clock, monitored house, unit maps). */
    public CM11aStatus requestStatus() {
        return await(worker.submit(CM11aProtocol::requestStatus));
    }

    /** Sets the interface clock from the configured clock (the interface also asks for it after a power failure). */
    public void setClock() {
        await(worker.submit(protocol -> {
            protocol.sendClock();
            return null;
        }));
    }

    // ----- events -----

    /** Registers a listener for uploads; it is called on the controller's event thread. */
    public void addListener(X10Listener listener) {
        listeners.add(listener);
    }

    /** Removes a listener. */
    public void removeListener(X10Listener listener) {
        listeners.remove(listener);
    }

    private void publish(List<X10Event> events) {
        // a separate thread, so a listener may call the controller without waiting on itself
        eventThread.execute(() -> {
            for (X10Event event : events) {
                for (X10Listener listener : listeners) {
                    try {
                        listener.onEvent(event);
                    } catch (RuntimeException e) {
                        LOG.warn("{}: listener failed on {}", portName(), event, e);
                    }
                }
            }
        });
    }

    // ----- lifecycle -----

    /** Stops the link thread, fails queued commands, closes the link and stops event delivery. */
    @Override
    public void close() {
        worker.stop();
        try {
            link.close(); // unblocks a read in progress
        } catch (IOException e) {
            LOG.debug("{}: closing the link: {}", portName(), e.getMessage());
        }
        worker.join(CLOSE_WAIT_MILLIS);
        eventThread.shutdown();
    }

    private <T> T await(CompletableFuture<T> result) {
        try {
            return result.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new X10Exception(portName(), "interrupted while waiting for the interface", e);
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof X10Exception x10) {
                throw x10;
            }
            if (cause instanceof IOException io) {
                throw new X10Exception(portName(), io.getMessage(), io);
            }
            if (cause instanceof RuntimeException runtime) {
                throw runtime;
            }
            throw new X10Exception(portName(), String.valueOf(cause), cause);
        }
    }
}
