package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static robotworld.safety.SafetyRig.eventually;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;
import robotworld.x10.CM11aController;
import robotworld.x10.X10Address;
import robotworld.x10.X10LampModuleLocal;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMX10LampModuleLocal;
import robotworld.xvsm.XVSMX10LampModuleRemote;

/** X10 modules stay as they are when stopped, unless configured: then they are switched to their safe state. */
class X10SafeStateTest {

    private static final X10Address LAMP = X10Address.of('A', 1);

    private SafetyRig rig;
    private XVSMRuntime room;

    @BeforeEach
    void start() throws Exception {
        rig = SafetyRig.start();
        room = XVSMRuntime.connect(rig.spaceUrl, "room-pc");
        // a silent commander's lamp is switched off after this; a live one's heartbeats (every 100 ms) are never
        // that late, even on a busy machine (where the default 500 ms can pass between two)
        room.safety().setDefaultCommandTimeout(Duration.ofSeconds(3));
    }

    @AfterEach
    void stop() {
        room.close();
        rig.close();
    }

    private XVSMX10LampModuleLocal serveLamp() throws Exception {
        CM11aController x10 = room.own(CM11aController.open(rig.x10Port));
        return room.own(new XVSMX10LampModuleLocal(room, SafetyRig.ROOM, SafetyRig.LAMP,
                new X10LampModuleLocal(x10, LAMP)));
    }

    @Test
    void byDefaultALampIsLeftAsItIs() throws Exception {
        serveLamp().on();
        try (Capi ops = RemoteSpace.open(rig.space.uri())) {
            WorldStop.Result result = WorldStop.stop(ops, "ops", "", List.of(
                    new WorldStop.Target(SafetyRig.ROOM, SafetyRig.LAMP, true)), Duration.ofSeconds(30));
            assertEquals("left as it is (X10 safe state: unchanged)", result.outcomes().get(0).answer().detail());
        }
        assertTrue(rig.cm11a.lamp(LAMP).isOn());
    }

    @Test
    void aLampConfiguredOffIsSwitchedOffByAStopAndWhenItsCommanderIsLost() throws Exception {
        room.safety().describe(SafetyRig.ROOM, SafetyRig.LAMP, new ModuleSafety(null, null, "off"));
        XVSMX10LampModuleLocal lamp = serveLamp();
        lamp.on();
        try (Capi ops = RemoteSpace.open(rig.space.uri())) {
            WorldStop.Result result = WorldStop.stop(ops, "ops", "", List.of(
                    new WorldStop.Target(SafetyRig.ROOM, SafetyRig.LAMP, true)), Duration.ofSeconds(30));
            assertEquals("switched off", result.outcomes().get(0).answer().detail());
        }
        assertTrue(!rig.cm11a.lamp(LAMP).isOn(), "switched off");

        XVSMRuntime laptop = XVSMRuntime.connect(rig.spaceUrl, "laptop");
        XVSMX10LampModuleRemote remote = laptop.own(new XVSMX10LampModuleRemote(laptop, SafetyRig.ROOM,
                SafetyRig.LAMP));
        remote.setCallTimeout(Duration.ofSeconds(30));
        remote.brighten(20); // away from its safe state: engaged by the laptop
        assertTrue(rig.cm11a.lamp(LAMP).isOn());
        laptop.space().close(); // the laptop is cut off
        eventually("switched off for the lost commander", () -> !rig.cm11a.lamp(LAMP).isOn());
        // the lamp goes off before the stop is recorded: the record follows the action
        eventually("the stop recorded", () -> room.safety().recentStops().stream().anyMatch(
                s -> s.cause() == StopCause.COMMANDER_SILENT && s.action().equals("switched off")));
        laptop.close();
    }
}
