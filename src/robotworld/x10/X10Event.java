package robotworld.x10;

import java.util.List;
import java.util.stream.Collectors;

/**
 * Something the CM11A heard on the power line and uploaded: a function for a house, with the units that were
 * addressed in that house when it came (empty for house-wide functions such as All Units Off).
 *
 * @param house the house code of the function
 * @param units addressed units 1..16 in ascending order; for extended code the unit of the extended frame
 * @param function the function
 * @param dimLevel for Dim and Bright the change in brightness, 0..210 (210 = full range); for Preset Dim the
 *        level 0..31 (its house is that of the units addressed last); otherwise 0
 * @param extendedData for extended code the data byte; otherwise 0
 * @param extendedCommand for extended code the command byte; otherwise 0
 */
public record X10Event(HouseCode house, List<Integer> units, X10Function function, int dimLevel,
        int extendedData, int extendedCommand) {

    public X10Event {
        units = List.copyOf(units);
    }

    /** A function without extra bytes, e.g. {@code B6 On}. */
    public static X10Event of(HouseCode house, List<Integer> units, X10Function function) {
        return new X10Event(house, units, function, 0, 0, 0);
    }

    /** Whether the event concerns {@code address} (addressed unit, or a house-wide function of its house). */
    public boolean concerns(X10Address address) {
        return house == address.house() && (function.isHouseWide() || units.contains(address.unit()));
    }

    /** For Dim and Bright: the change in percent of the full range. */
    public int dimPercent() {
        return Math.round(dimLevel * 100f / X10Constants.UPLOAD_LEVELS_FULL_RANGE);
    }

    /** e.g. "B6 On", "A1,A2 Bright 88/210", "C All Units Off". */
    @Override
    public String toString() {
        String who = units.isEmpty() ? house.name()
                : units.stream().map(unit -> house.name() + unit).collect(Collectors.joining(","));
        String what = function.toString();
        if (function.usesDimSteps()) {
            what += " " + dimLevel + "/210";
        } else if (function == X10Function.PRESET_DIM_1 || function == X10Function.PRESET_DIM_2) {
            what += " " + dimLevel + "/31";
        } else if (function == X10Function.EXTENDED_CODE) {
            what += String.format(" data %02X command %02X", extendedData, extendedCommand);
        }
        return who + " " + what;
    }
}
