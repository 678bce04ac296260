package robotworld.x10;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Turns CM11A upload buffers ({@code mask data...}) into {@link X10Event}s. X10 addressing spans frames and even
 * uploads: addresses of a house accumulate until a function for that house comes; the first address after a
 * function starts a new list. So the decoder keeps, per house, the units addressed so far.
 *
 * <p>Mask bit i set means data byte i is a function byte. Dim and Bright are followed by a level byte (0..210),
 * extended code by unit, data and command bytes; those extra bytes are data, whatever their mask bits.
 */
final class UploadDecoder {

    private static final Logger LOG = LoggerFactory.getLogger(UploadDecoder.class);

    private final Map<HouseCode, TreeSet<Integer>> addressed = new EnumMap<>(HouseCode.class);
    private final Map<HouseCode, Boolean> functionSeen = new EnumMap<>(HouseCode.class);

    /**
     * Decodes one upload buffer without its size byte.
     *
     * @param buffer the function/address mask followed by the data bytes
     */
    private HouseCode lastAddressed;

    List<X10Event> decode(byte[] buffer) {
        List<X10Event> events = new ArrayList<>();
        if (buffer.length == 0) {
            return events;
        }
        int mask = buffer[0] & 0xFF;
        int index = 0;
        int dataLength = buffer.length - 1;
        while (index < dataLength) {
            int value = buffer[1 + index] & 0xFF;
            HouseCode house = HouseCode.ofCode(value >> 4);
            if ((mask >> index & 1) == 0) {
                address(house, X10Constants.unitOfCode(value));
                index++;
                continue;
            }
            X10Function function = X10Function.ofCode(value);
            if (function == X10Function.PRESET_DIM_1 || function == X10Function.PRESET_DIM_2) {
                // the "house" nibble is part of the level: the units are those addressed last
                HouseCode addressedHouse = lastAddressed == null ? house : lastAddressed;
                events.add(new X10Event(addressedHouse, addressedIn(addressedHouse), function,
                        X10Constants.presetDimLevel(value >> 4, function == X10Function.PRESET_DIM_2), 0, 0));
                functionSeen.put(addressedHouse, true);
                index++;
                continue;
            }
            int extra = function.usesDimSteps() ? 1 : function == X10Function.EXTENDED_CODE ? 3 : 0;
            if (index + extra >= dataLength) {
                LOG.warn("upload ends inside {} {} (buffer {}): ignored", house, function, Hex.of(buffer));
                break;
            }
            events.add(event(house, function, buffer, 2 + index, extra));
            functionSeen.put(house, true);
            index += 1 + extra;
        }
        return events;
    }

    private void address(HouseCode house, int unit) {
        lastAddressed = house;
        TreeSet<Integer> units = addressed.computeIfAbsent(house, h -> new TreeSet<>());
        if (functionSeen.getOrDefault(house, false)) {
            units.clear();
            functionSeen.put(house, false);
        }
        units.add(unit);
    }

    private X10Event event(HouseCode house, X10Function function, byte[] buffer, int extraAt, int extra) {
        if (function.usesDimSteps()) {
            return new X10Event(house, addressedIn(house), function, buffer[extraAt] & 0xFF, 0, 0);
        }
        if (function == X10Function.EXTENDED_CODE) {
            int unit = X10Constants.unitOfCode(buffer[extraAt]);
            return new X10Event(house, List.of(unit), function, 0, buffer[extraAt + 1] & 0xFF,
                    buffer[extraAt + 2] & 0xFF);
        }
        return X10Event.of(house, function.isHouseWide() ? List.of() : addressedIn(house), function);
    }

    private List<Integer> addressedIn(HouseCode house) {
        return List.copyOf(addressed.getOrDefault(house, new TreeSet<>()));
    }
}
