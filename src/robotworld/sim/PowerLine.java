package robotworld.sim;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.Collection;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import robotworld.x10.HouseCode;
import robotworld.x10.X10Address;
import robotworld.x10.X10Constants;
import robotworld.x10.X10Function;

/**
 * The simulated power line with its modules. X10 addressing: addresses of a house accumulate until a function
 * for that house; the next address after a function starts a new list. A function acts on the addressed modules
 * of its house; All Units Off / All Lights On / All Lights Off act on the whole house. Thread-safe.
 */
final class PowerLine {

    private final Map<X10Address, SimulatedX10Module> modules = new LinkedHashMap<>();
    private final Map<HouseCode, Set<Integer>> addressed = new EnumMap<>(HouseCode.class);
    private final Map<HouseCode, Boolean> functionSeen = new EnumMap<>(HouseCode.class);
    /** How many power-line transmissions the log keeps. */
    static final int LOG_CAPACITY = 10_000;

    private final Deque<String> log = new ArrayDeque<>();
    private final List<Consumer<String>> observers = new CopyOnWriteArrayList<>();

    void observe(Consumer<String> observer) {
        observers.add(observer);
    }

    private void record(String transmission) {
        if (log.size() == LOG_CAPACITY) {
            log.removeFirst();
        }
        log.addLast(transmission);
        observers.forEach(observer -> observer.accept(transmission));
    }

    synchronized void add(SimulatedX10Module module) {
        if (modules.putIfAbsent(module.address(), module) != null) {
            throw new IllegalArgumentException("two modules at " + module.address());
        }
    }

    synchronized SimulatedX10Module module(X10Address address) {
        return modules.get(address);
    }

    synchronized Collection<SimulatedX10Module> modules() {
        return List.copyOf(modules.values());
    }

    /** An address frame heard on the line. */
    synchronized void address(X10Address address) {
        Set<Integer> units = addressed.computeIfAbsent(address.house(), h -> new TreeSet<>());
        if (functionSeen.getOrDefault(address.house(), false)) {
            units.clear();
            functionSeen.put(address.house(), false);
        }
        units.add(address.unit());
        record(address.toString());
    }

    /** A function frame heard on the line. */
    synchronized void function(HouseCode house, X10Function function, int dimSteps) {
        for (SimulatedX10Module module : targets(house, function)) {
            module.apply(function, dimSteps);
        }
        functionSeen.put(house, true);
        record(house.name() + " " + function + (function.usesDimSteps() ? " " + dimSteps : ""));
    }

    /** An extended code frame heard on the line. */
    synchronized void extended(X10Address address, int data, int command) {
        SimulatedX10Module module = modules.get(address);
        if (module != null) {
            module.applyExtended(data, command);
        }
        functionSeen.put(address.house(), true);
        record(String.format("%s %s data %02X command %02X", address, X10Function.EXTENDED_CODE, data, command));
    }

    /** Applies a host frame (header + code, or the five bytes of an extended frame) that went out on the line. */
    synchronized void transmit(byte[] frame) {
        int header = frame[0] & 0xFF;
        int code = frame[1] & 0xFF;
        HouseCode house = HouseCode.ofCode(code >> 4);
        if ((header & X10Constants.HEADER_EXTENDED_BIT) != 0) {
            extended(new X10Address(house, X10Constants.unitOfCode(frame[2])), frame[3] & 0xFF, frame[4] & 0xFF);
        } else if ((header & X10Constants.HEADER_FUNCTION_BIT) != 0) {
            X10Function function = X10Function.ofCode(code);
            if (function == X10Function.PRESET_DIM_1 || function == X10Function.PRESET_DIM_2) {
                // the "house" nibble is part of the level
                presetDim(X10Constants.presetDimLevel(code >> 4, function == X10Function.PRESET_DIM_2));
            } else {
                function(house, function, header >> X10Constants.HEADER_DIMS_SHIFT);
            }
        } else {
            address(X10Address.ofCode(code));
        }
    }

    /** A Preset Dim frame heard on the line: it acts on the modules addressed and not yet given a function. */
    synchronized void presetDim(int level) {
        for (SimulatedX10Module module : modules.values()) {
            HouseCode house = module.address().house();
            if (!functionSeen.getOrDefault(house, false)
                    && addressed.getOrDefault(house, Set.of()).contains(module.address().unit())) {
                module.applyPresetDim(level);
            }
        }
        for (HouseCode house : addressed.keySet()) {
            functionSeen.put(house, true);
        }
        record("Preset Dim " + level + "/31");
    }

    private List<SimulatedX10Module> targets(HouseCode house, X10Function function) {
        List<SimulatedX10Module> targets = new ArrayList<>();
        Set<Integer> units = addressed.getOrDefault(house, Set.of());
        for (SimulatedX10Module module : modules.values()) {
            if (module.address().house() == house
                    && (function.isHouseWide() || units.contains(module.address().unit()))) {
                targets.add(module);
            }
        }
        return targets;
    }

    /** Units of {@code house} addressed now. */
    synchronized Set<Integer> addressedUnits(HouseCode house) {
        return Set.copyOf(addressed.getOrDefault(house, Set.of()));
    }

    /** Units of {@code house} whose modules are on. */
    synchronized Set<Integer> onUnits(HouseCode house) {
        Set<Integer> units = new TreeSet<>();
        for (SimulatedX10Module module : modules.values()) {
            if (module.address().house() == house && module.isOn()) {
                units.add(module.address().unit());
            }
        }
        return units;
    }

    /** Units of {@code house} whose lamps are dimmed. */
    synchronized Set<Integer> dimmedUnits(HouseCode house) {
        Set<Integer> units = new TreeSet<>();
        for (SimulatedX10Module module : modules.values()) {
            if (module.address().house() == house && module.isDimmed()) {
                units.add(module.address().unit());
            }
        }
        return units;
    }

    /** Forgets what was addressed (a power failure or a status clear). */
    synchronized void clearAddressing() {
        addressed.clear();
        functionSeen.clear();
    }

    /** What was heard on the line (the latest transmissions), oldest first, e.g. "A3", "A On", "A Dim 11". */
    synchronized List<String> log() {
        return List.copyOf(log);
    }
}
