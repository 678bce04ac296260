package robotworld.x10;

import java.time.Clock;
import java.time.DayOfWeek;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.time.zone.ZoneRules;

/**
 * The clock download that answers a power-fail poll (0xA5) or sets the clock at any time:
 * {@code 9B ss mm hh dd mask|d8 house|flags}, where the minutes run 0..119 within a two-hour block, hh is the
 * hour divided by two, the day of the year (0-based, 9 bits) is split over two bytes, the day mask has bit 0 for
 * Sunday to bit 6 for Saturday, and the last byte holds the monitored house code and three flags. The interface
 * echoes the sum of the six bytes after 0x9B.
 *
 * @param time time of day, to the second
 * @param dayOfYear 1..366
 * @param dayOfWeek the weekday
 * @param monitoredHouse house whose status the interface keeps
 * @param flags bit 2 clear battery timer, bit 1 clear monitored status, bit 0 purge timers
 */
public record CM11aClock(LocalTime time, int dayOfYear, DayOfWeek dayOfWeek, HouseCode monitoredHouse, int flags) {

    /** Flag: reset the battery timer. */
    public static final int CLEAR_BATTERY_TIMER = 0x04;
    /** Flag: clear the monitored status bits. */
    public static final int CLEAR_MONITORED_STATUS = 0x02;
    /** Flag: erase downloaded timers. */
    public static final int PURGE_TIMERS = 0x01;

    public CM11aClock {
        if (dayOfYear < 1 || dayOfYear > 366) {
            throw new IllegalArgumentException("day of year must be 1..366, was " + dayOfYear);
        }
        if ((flags & ~0x07) != 0) {
            throw new IllegalArgumentException("only flags 0..7 exist, was " + flags);
        }
        time = time.withNano(0);
    }

    /** The clock for {@code dateTime} with no flags set. */
    public static CM11aClock of(LocalDateTime dateTime, HouseCode monitoredHouse) {
        return new CM11aClock(dateTime.toLocalTime(), dateTime.getDayOfYear(), dateTime.getDayOfWeek(),
                monitoredHouse, 0);
    }

    /**
     * The clock for the current instant of {@code clock}, in its zone's standard time or legal (summer) time, with
     * no flags set.
     */
    public static CM11aClock now(Clock clock, CM11aConfig.ClockTime kind, HouseCode monitoredHouse) {
        Instant now = clock.instant();
        ZoneRules rules = clock.getZone().getRules();
        ZoneOffset offset = kind == CM11aConfig.ClockTime.STANDARD ? rules.getStandardOffset(now)
                : rules.getOffset(now);
        return of(LocalDateTime.ofInstant(now, offset), monitoredHouse);
    }

    /** The six clock bytes (without the 0x9B header). */
    public byte[] encode() {
        byte[] bytes = new byte[X10Constants.CM11A_CLOCK_LENGTH];
        writeTime(bytes, 0, time, dayOfYear, dayOfWeek);
        bytes[5] = (byte) (monitoredHouse.code() << 4 | flags);
        return bytes;
    }

    /** The whole download: 0x9B followed by the six clock bytes. */
    public byte[] frame() {
        byte[] frame = new byte[1 + X10Constants.CM11A_CLOCK_LENGTH];
        frame[0] = (byte) X10Constants.CM11A_SET_CLOCK;
        System.arraycopy(encode(), 0, frame, 1, X10Constants.CM11A_CLOCK_LENGTH);
        return frame;
    }

    /** The checksum the interface echoes: the sum of the six clock bytes, modulo 256 (0x9B not included). */
    public int checksum() {
        int sum = 0;
        for (byte b : encode()) {
            sum += b & 0xFF;
        }
        return sum & 0xFF;
    }

    /** Decodes the six clock bytes (without the 0x9B header). */
    public static CM11aClock decode(byte[] six) {
        if (six.length != X10Constants.CM11A_CLOCK_LENGTH) {
            throw new IllegalArgumentException("a clock download has 6 bytes, got " + six.length);
        }
        return new CM11aClock(readTime(six, 0), readDayOfYear(six, 0), readDayOfWeek(six, 0),
                HouseCode.ofCode((six[5] & 0xFF) >> 4), six[5] & 0x07);
    }

    // The five time bytes are laid out the same way in the clock download and in the status answer.

    static void writeTime(byte[] bytes, int offset, LocalTime time, int dayOfYear, DayOfWeek dayOfWeek) {
        int wireDay = dayOfYear - 1;
        bytes[offset] = (byte) time.getSecond();
        bytes[offset + 1] = (byte) (time.getHour() % 2 * 60 + time.getMinute());
        bytes[offset + 2] = (byte) (time.getHour() / 2);
        bytes[offset + 3] = (byte) (wireDay & 0xFF);
        bytes[offset + 4] = (byte) ((wireDay >> 8 & 1) << 7 | 1 << (dayOfWeek.getValue() % 7));
    }

    static LocalTime readTime(byte[] bytes, int offset) {
        int seconds = Math.min(59, bytes[offset] & 0xFF);
        int minutes = Math.min(119, bytes[offset + 1] & 0xFF);
        int hours = Math.min(23, (bytes[offset + 2] & 0xFF) * 2 + minutes / 60);
        return LocalTime.of(hours, minutes % 60, seconds);
    }

    static int readDayOfYear(byte[] bytes, int offset) {
        int wireDay = (bytes[offset + 3] & 0xFF) | ((bytes[offset + 4] & 0x80) << 1);
        return Math.min(366, wireDay + 1);
    }

    static DayOfWeek readDayOfWeek(byte[] bytes, int offset) {
        int mask = bytes[offset + 4] & 0x7F;
        int sundayBased = mask == 0 ? 0 : Integer.numberOfTrailingZeros(mask);
        return sundayBased == 0 ? DayOfWeek.SUNDAY : DayOfWeek.of(sundayBased);
    }
}
