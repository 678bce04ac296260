package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class SerialSettingsTest {

    @Test
    void eightNoneOneAt4800TakesTenBitsPerCharacter() {
        SerialSettings settings = SerialSettings.eightNoneOne(4800);
        assertEquals(10, settings.bitsPerCharacter());
        assertEquals(2_083_333, settings.characterTimeNanos());
        assertEquals("4800 8N1", settings.toString());
    }

    @Test
    void parityAndTwoStopBitsAddBits() {
        SerialSettings settings = new SerialSettings(9600, 7, SerialSettings.Parity.EVEN, SerialSettings.StopBits.TWO);
        assertEquals(11, settings.bitsPerCharacter());
    }

    @Test
    void nonsenseIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> SerialSettings.eightNoneOne(0));
        assertThrows(IllegalArgumentException.class,
                () -> new SerialSettings(4800, 9, SerialSettings.Parity.NONE, SerialSettings.StopBits.ONE));
    }
}
