package robotworld.bus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The default timing, and the setting that gives programs on a slow link a longer response timeout. */
class BusTimingTest {

    @AfterEach
    void clear() {
        System.clearProperty(BusTiming.RESPONSE_TIMEOUT_PROPERTY);
    }

    @Test
    void aRealModuleGets100MillisecondsUnlessTheSettingSaysOtherwise() {
        assertEquals(Duration.ofMillis(100), BusTiming.defaults().responseTimeout());
        System.setProperty(BusTiming.RESPONSE_TIMEOUT_PROPERTY, "1000");
        assertEquals(Duration.ofMillis(1000), BusTiming.defaults().responseTimeout());
        assertEquals(3, BusTiming.defaults().attempts());
    }

    @Test
    void aSlowLinkMayAlsoPauseLongerInsideAReply() {
        assertEquals(Duration.ofMillis(20), BusTiming.defaults().interByteTimeout());
        System.setProperty(BusTiming.RESPONSE_TIMEOUT_PROPERTY, "1000");
        assertEquals(Duration.ofMillis(200), BusTiming.defaults().interByteTimeout());
        System.setProperty(BusTiming.RESPONSE_TIMEOUT_PROPERTY, "50");
        assertEquals(Duration.ofMillis(20), BusTiming.defaults().interByteTimeout());
    }

    @Test
    void aBadSettingIsNamedNotIgnored() {
        System.setProperty(BusTiming.RESPONSE_TIMEOUT_PROPERTY, "soon");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, BusTiming::defaults);
        assertTrue(e.getMessage().contains("rwe.bus.timeout.ms") && e.getMessage().contains("'soon'"), e.getMessage());
        System.setProperty(BusTiming.RESPONSE_TIMEOUT_PROPERTY, "0");
        assertThrows(IllegalArgumentException.class, BusTiming::defaults);
    }
}
