package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.core.X10ApplianceModule;
import robotworld.core.X10LampModule;
import robotworld.x10.Cm11aRig.Transport;

/** The module proxies drive the simulated modules through the controller. */
class X10ModuleLocalTest {

    private Cm11aRig rig;

    @BeforeEach
    void connect() throws Exception {
        rig = Cm11aRig.connect(Transport.TCP, Cm11aRig.fastSim(), Cm11aRig.fastConfig());
    }

    @AfterEach
    void close() throws Exception {
        rig.close();
    }

    @Test
    void applianceSwitchesOnAndOff() {
        X10ApplianceModule appliance = new X10ApplianceModuleLocal(rig.controller, 'A', 3);
        appliance.on();
        assertTrue(rig.sim.appliance(X10Address.of('A', 3)).isOn());
        appliance.off();
        assertFalse(rig.sim.appliance(X10Address.of('A', 3)).isOn());
    }

    @Test
    void lampDimsAndBrightensByPercentOfTheFullRange() {
        X10LampModule lamp = new X10LampModuleLocal(rig.controller, X10Address.of('A', 1));
        lamp.on();
        assertEquals(100, rig.sim.lamp(X10Address.of('A', 1)).brightnessPercent());
        rig.sim.wire().clear();
        lamp.dim(50); // 11 of 22 steps
        assertEquals(List.of("host 04 66", "cm11a 6A", "host 00", "cm11a 55",
                "host 5E 64", "cm11a C2", "host 00", "cm11a 55"), rig.sim.wire().lines());
        assertEquals(50, rig.sim.lamp(X10Address.of('A', 1)).brightnessPercent());
        lamp.brighten(25); // 6 steps (5.5 rounds up)
        assertEquals(17, rig.sim.lamp(X10Address.of('A', 1)).level());
        lamp.brighten(100);
        assertEquals(100, rig.sim.lamp(X10Address.of('A', 1)).brightnessPercent());
        lamp.off();
        assertEquals(0, rig.sim.lamp(X10Address.of('A', 1)).brightnessPercent());
    }

    @Test
    void lampRejectsLevelsOutside0To100WithoutSending() {
        X10LampModule lamp = new X10LampModuleLocal(rig.controller, 'A', 1);
        assertThrows(IllegalArgumentException.class, () -> lamp.dim(101));
        assertThrows(IllegalArgumentException.class, () -> lamp.brighten(-5));
        lamp.dim(0);
        assertEquals(List.of(), rig.sim.wire().lines());
    }

    @Test
    void failuresSurfaceAsUncheckedX10Exceptions() {
        X10ApplianceModule appliance = new X10ApplianceModuleLocal(rig.controller, 'A', 3);
        rig.sim.powerOff();
        assertThrows(X10TimeoutException.class, appliance::on);
    }
}
