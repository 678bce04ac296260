package robotworld.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.x10.X10Address;
import robotworld.x10.X10Function;

/** How the simulated modules react, and how device lists are read. */
class ModuleModelTest {

    private final SimulatedLampModule lamp = new SimulatedLampModule(X10Address.of('A', 1));
    private final SimulatedApplianceModule appliance = new SimulatedApplianceModule(X10Address.of('A', 2));

    @Test
    void lampComesOnAtFullBrightnessAndKeepsADimmedLevelOnOn() {
        assertEquals(0, lamp.brightnessPercent());
        lamp.apply(X10Function.ON, 0);
        assertEquals(100, lamp.brightnessPercent());
        lamp.apply(X10Function.DIM, 11);
        assertEquals(50, lamp.brightnessPercent());
        lamp.apply(X10Function.ON, 0);
        assertEquals(50, lamp.brightnessPercent());
    }

    @Test
    void dimmingAnOffLampSwitchesItOnAtFullFirst() {
        lamp.apply(X10Function.DIM, 4);
        assertTrue(lamp.isOn());
        assertEquals(18, lamp.level());
    }

    @Test
    void brightnessStaysWithinTheRange() {
        lamp.apply(X10Function.BRIGHT, 22);
        assertEquals(22, lamp.level());
        lamp.apply(X10Function.DIM, 22);
        assertEquals(0, lamp.level());
        lamp.apply(X10Function.DIM, 5);
        assertEquals(0, lamp.level());
    }

    @Test
    void presetDimExtendedCodeSetsTheLevel() {
        lamp.applyExtended(0x1F, 0x31); // 31 of 63
        assertEquals(11, lamp.level());
        assertTrue(lamp.isOn());
        lamp.applyExtended(0x00, 0x31);
        assertFalse(lamp.isOn());
    }

    @Test
    void applianceIgnoresDimsAndLightsFunctions() {
        appliance.apply(X10Function.ON, 0);
        appliance.apply(X10Function.DIM, 5);
        appliance.apply(X10Function.ALL_LIGHTS_OFF, 0);
        assertTrue(appliance.isOn());
        appliance.apply(X10Function.ALL_UNITS_OFF, 0);
        assertFalse(appliance.isOn());
    }

    @Test
    void deviceListsAreParsed() {
        List<SimulatedX10Module> modules = DeviceSpec.parse("A1=lamp, a3=Appliance,P16=lamp");
        assertEquals(3, modules.size());
        assertEquals(SimulatedX10Module.Kind.LAMP, modules.get(0).kind());
        assertEquals(X10Address.of('A', 3), modules.get(1).address());
        assertEquals(SimulatedX10Module.Kind.APPLIANCE, modules.get(1).kind());
        assertEquals(List.of(), DeviceSpec.parse(""));
    }

    @Test
    void badDeviceListsSayWhatIsWrong() {
        assertMessage("A1", "is not ADDRESS=lamp|appliance");
        assertMessage("A1=fridge", "neither lamp nor appliance");
        assertMessage("Q1=lamp", "house codes are A..P");
        assertMessage("A17=lamp", "unit codes are 1..16");
        assertMessage("A1=lamp,A1=appliance", "listed twice");
    }

    private static void assertMessage(String spec, String expected) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> DeviceSpec.parse(spec));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
    }
}
