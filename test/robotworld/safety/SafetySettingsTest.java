package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;

/** Where safety settings come from: module setting, description, setting for every module, default. */
class SafetySettingsTest {

    private static Properties properties(String... pairs) {
        Properties properties = new Properties();
        for (int i = 0; i < pairs.length; i += 2) {
            properties.setProperty(pairs[i], pairs[i + 1]);
        }
        return properties;
    }

    @Test
    void defaultsWithoutAnySetting() {
        SafetySettings settings = SafetySettings.of(new Properties(), Map.of());
        assertEquals(Duration.ofMillis(500), settings.defaultCommandTimeout());
        assertEquals(Duration.ofMillis(100), settings.heartbeatPeriod());
        assertEquals(500, settings.watchdogMillis("Bot", "Motor", ModuleSafety.NONE, 500));
        assertEquals(0, settings.watchdogMillis("Bot", "Servo", ModuleSafety.NONE, 0));
        assertEquals(X10SafeState.UNCHANGED, settings.x10SafeState("Room", "Lamp", ModuleSafety.NONE));
    }

    @Test
    void theModulesSettingBeatsTheDescriptionWhichBeatsTheSettingForEveryModule() {
        ModuleSafety described = new ModuleSafety(800, 300, "off");
        SafetySettings everyModule = SafetySettings.of(properties("rwe.command.timeout.ms", "2000",
                "rwe.watchdog.ms", "1000", "rwe.x10.safe.state", "on"), Map.of());
        assertEquals(Duration.ofMillis(800), everyModule.commandTimeout("Bot", "Motor", described,
                everyModule.defaultCommandTimeout()));
        assertEquals(Duration.ofMillis(2000), everyModule.commandTimeout("Bot", "Motor", ModuleSafety.NONE,
                everyModule.defaultCommandTimeout()));
        assertEquals(300, everyModule.watchdogMillis("Bot", "Motor", described, 500));
        assertEquals(1000, everyModule.watchdogMillis("Bot", "Motor", ModuleSafety.NONE, 500));
        assertEquals(0, everyModule.watchdogMillis("Bot", "Servo", ModuleSafety.NONE, 0),
                "the setting for every module does not arm what needs no watchdog");
        assertEquals(X10SafeState.OFF, everyModule.x10SafeState("Room", "Lamp", described));
        assertEquals(X10SafeState.ON, everyModule.x10SafeState("Room", "Lamp", ModuleSafety.NONE));

        SafetySettings perModule = SafetySettings.of(properties("rwe.command.timeout.ms.Bot.Motor-1", "150"),
                Map.of("RWE_WATCHDOG_MS_BOT_MOTOR_1", "0", "RWE_X10_SAFE_STATE_ROOM_LAMP", "unchanged"));
        assertEquals(Duration.ofMillis(150), perModule.commandTimeout("Bot", "Motor-1", described,
                perModule.defaultCommandTimeout()));
        assertEquals(0, perModule.watchdogMillis("Bot", "Motor-1", described, 500), "0 switches it off");
        assertEquals(X10SafeState.UNCHANGED, perModule.x10SafeState("Room", "Lamp", described));
    }

    @Test
    void badValuesAreRefusedNamingTheSetting() {
        IllegalArgumentException notANumber = assertThrows(IllegalArgumentException.class,
                () -> SafetySettings.of(properties("rwe.command.timeout.ms", "soon"), Map.of()).defaultCommandTimeout());
        assertTrue(notANumber.getMessage().contains("rwe.command.timeout.ms"), notANumber.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> SafetySettings.of(properties("rwe.command.timeout.ms", "20"), Map.of()).defaultCommandTimeout());
        assertThrows(IllegalArgumentException.class, () -> SafetySettings.of(properties("rwe.watchdog.ms.B.M", "5"),
                Map.of()).watchdogMillis("B", "M", ModuleSafety.NONE, 500));
        assertThrows(IllegalArgumentException.class, () -> SafetySettings.of(properties("rwe.x10.safe.state", "dim"),
                Map.of()).x10SafeState("R", "L", ModuleSafety.NONE));
        assertThrows(IllegalArgumentException.class, () -> new ModuleSafety(null, 70_000, null));
        assertEquals(Duration.ZERO, SafetySettings.of(properties("rwe.heartbeat.ms", "0"), Map.of()).heartbeatPeriod());
    }

    @Test
    void losingTheSpaceStopsEveryActuatorUnlessSetToRemotePerModuleOrForAll() {
        assertTrue(SafetySettings.of(new Properties(), Map.of()).spaceLossStopsAll("Bot", "Motor"), "the default");
        SafetySettings remote = SafetySettings.of(properties("rwe.space.loss.stops", "remote",
                "rwe.space.loss.stops.Bot.Winch", "all"), Map.of());
        assertFalse(remote.spaceLossStopsAll("Bot", "Motor"));
        assertTrue(remote.spaceLossStopsAll("Bot", "Winch"), "the module's own setting wins");
        assertFalse(SafetySettings.of(new Properties(), Map.of("RWE_SPACE_LOSS_STOPS", "REMOTE"))
                .spaceLossStopsAll("Bot", "Motor"), "from the environment, in any case");
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class, () -> SafetySettings.of(
                properties("rwe.space.loss.stops", "some"), Map.of()).spaceLossStopsAll("Bot", "Motor"));
        assertTrue(bad.getMessage().contains("rwe.space.loss.stops is 'all' or 'remote'"), bad.getMessage());
    }
}
