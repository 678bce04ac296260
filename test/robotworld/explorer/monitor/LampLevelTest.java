package robotworld.explorer.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The lamp's brightness as the sum of the relative X10 changes. */
class LampLevelTest {

    @Test
    void changesAddUpAndStayWithinTheRange() {
        LampLevel lamp = new LampLevel();
        assertFalse(lamp.isOn());
        lamp.on();
        assertEquals(100, lamp.level());
        lamp.dim(30);
        lamp.dim(30);
        assertEquals(40, lamp.level());
        lamp.brighten(80);
        assertEquals(100, lamp.level());
        lamp.dim(150 / 2);
        lamp.dim(50);
        assertEquals(0, lamp.level());
    }

    @Test
    void switchingOnFromOffGoesToFullAndADimWhileOffSwitchesOnFirst() {
        LampLevel lamp = new LampLevel();
        lamp.on();
        lamp.dim(50);
        lamp.on();
        assertEquals(50, lamp.level(), "on while on keeps the level");
        lamp.off();
        assertFalse(lamp.isOn());
        lamp.dim(20);
        assertTrue(lamp.isOn());
        assertEquals(80, lamp.level(), "comes on at full, then dims");
    }
}
