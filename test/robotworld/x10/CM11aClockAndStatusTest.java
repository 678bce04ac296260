package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.DayOfWeek;
import java.time.LocalDateTime;
import java.time.LocalTime;
import java.util.Set;
import org.junit.jupiter.api.Test;

class CM11aClockAndStatusTest {

    @Test
    void clockBytesFollowTheInterfaceLayout() {
        // Tuesday 3 March 2009, 13:45:30, day 62 of the year (0-based 61)
        CM11aClock clock = CM11aClock.of(LocalDateTime.of(2009, 3, 3, 13, 45, 30), HouseCode.B);
        byte[] six = clock.encode();
        assertArrayEquals(Bytes.of("1E 69 06 3D 04 E0"), six);
        // 0x1E=30 s; 0x69=105 = 60+45 min (odd hour); 0x06 = 13/2; 0x3D = 61; mask bit 2 = Tuesday; house B = E
        int sum = 0;
        for (byte b : six) {
            sum += b & 0xFF;
        }
        assertEquals(sum & 0xFF, clock.checksum());
        assertEquals(0x9B, clock.frame()[0] & 0xFF);
        assertEquals(clock, CM11aClock.decode(six));
    }

    @Test
    void dayOfYearAbove255UsesTheHighBit() {
        CM11aClock clock = CM11aClock.of(LocalDateTime.of(2008, 12, 31, 0, 0, 0), HouseCode.A);
        byte[] six = clock.encode();
        assertEquals(365 & 0xFF, six[3] & 0xFF); // 0-based day 365 of a leap year
        assertEquals(0x80, six[4] & 0x80);
        assertEquals(366, CM11aClock.decode(six).dayOfYear());
    }

    @Test
    void statusRoundTripsAndUsesX10CodeBitPositions() {
        CM11aStatus status = new CM11aStatus(0xFFFF, LocalTime.of(8, 15, 2), 200, DayOfWeek.FRIDAY, HouseCode.A, 1,
                Set.of(1), Set.of(1, 3), Set.of(3));
        byte[] bytes = status.encode();
        assertEquals(14, bytes.length);
        // unit 1 has code 6: bit 6 of the 16-bit map, i.e. 00 40 (as in the interface's EEPROM format)
        assertArrayEquals(Bytes.of("00 40"), new byte[] {bytes[8], bytes[9]});
        assertArrayEquals(Bytes.of("00 44"), new byte[] {bytes[10], bytes[11]});
        assertEquals(0x61, bytes[7] & 0xFF); // house A, firmware 1
        assertEquals(status, CM11aStatus.decode(bytes));
    }
}
