package robotworld.x10;

import java.time.DayOfWeek;
import java.time.LocalTime;
import java.util.Set;
import java.util.TreeSet;

/**
 * The 14 bytes the CM11A answers to a status request (0x8B): battery timer, the interface clock, the monitored
 * house code and firmware revision, and three 16-bit unit maps of the monitored house. In the unit maps the bit
 * number is the unit's 4-bit X10 code (unit 1, code 0110, is bit 6), as in the interface's EEPROM format.
 *
 * @param batteryTimer battery use counter; 0xFFFF after a reset
 * @param time the interface clock
 * @param dayOfYear 1..366
 * @param dayOfWeek the weekday
 * @param monitoredHouse house whose units the maps describe
 * @param firmware firmware revision 0..15
 * @param addressedUnits units currently addressed
 * @param onUnits units that are on
 * @param dimmedUnits units that are dimmed
 */
public record CM11aStatus(int batteryTimer, LocalTime time, int dayOfYear, DayOfWeek dayOfWeek,
        HouseCode monitoredHouse, int firmware, Set<Integer> addressedUnits, Set<Integer> onUnits,
        Set<Integer> dimmedUnits) {

    public CM11aStatus {
        addressedUnits = Set.copyOf(addressedUnits);
        onUnits = Set.copyOf(onUnits);
        dimmedUnits = Set.copyOf(dimmedUnits);
    }

    /** Decodes the 14 status bytes. */
    public static CM11aStatus decode(byte[] bytes) {
        if (bytes.length != X10Constants.CM11A_STATUS_LENGTH) {
            throw new IllegalArgumentException("a status answer has 14 bytes, got " + bytes.length);
        }
        return new CM11aStatus((bytes[0] & 0xFF) << 8 | bytes[1] & 0xFF,
                CM11aClock.readTime(bytes, 2), CM11aClock.readDayOfYear(bytes, 2), CM11aClock.readDayOfWeek(bytes, 2),
                HouseCode.ofCode((bytes[7] & 0xFF) >> 4), bytes[7] & 0x0F,
                unitsOf(bytes, 8), unitsOf(bytes, 10), unitsOf(bytes, 12));
    }

    /** The 14 status bytes. */
    public byte[] encode() {
        byte[] bytes = new byte[X10Constants.CM11A_STATUS_LENGTH];
        bytes[0] = (byte) (batteryTimer >> 8);
        bytes[1] = (byte) batteryTimer;
        CM11aClock.writeTime(bytes, 2, time, dayOfYear, dayOfWeek);
        bytes[7] = (byte) (monitoredHouse.code() << 4 | firmware & 0x0F);
        writeUnits(bytes, 8, addressedUnits);
        writeUnits(bytes, 10, onUnits);
        writeUnits(bytes, 12, dimmedUnits);
        return bytes;
    }

    private static Set<Integer> unitsOf(byte[] bytes, int offset) {
        int map = (bytes[offset] & 0xFF) << 8 | bytes[offset + 1] & 0xFF;
        Set<Integer> units = new TreeSet<>();
        for (int unit = 1; unit <= 16; unit++) {
            if ((map >> X10Constants.unitCode(unit) & 1) != 0) {
                units.add(unit);
            }
        }
        return units;
    }

    private static void writeUnits(byte[] bytes, int offset, Set<Integer> units) {
        int map = 0;
        for (int unit : units) {
            map |= 1 << X10Constants.unitCode(unit);
        }
        bytes[offset] = (byte) (map >> 8);
        bytes[offset + 1] = (byte) map;
    }
}
