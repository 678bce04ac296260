package robotworld.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RuntimeSettingsTest {

    private static Properties props(String... keyValues) {
        Properties properties = new Properties();
        for (int i = 0; i < keyValues.length; i += 2) {
            properties.setProperty(keyValues[i], keyValues[i + 1]);
        }
        return properties;
    }

    @Test
    void descriptionValueIsTheDefault() {
        RuntimeSettings settings = RuntimeSettings.of(props(), Map.of());
        assertEquals("http://localhost:9876/space", settings.spaceUrl("http://localhost:9876/space"));
        assertEquals("robot-laptop", settings.hostName("robot-laptop"));
        assertEquals("/dev/ttyUSB0", settings.port("CaterpillarRobot", "bus", "/dev/ttyUSB0"));
        assertNull(settings.spaceToken());
    }

    @Test
    void systemPropertyBeatsEnvironmentBeatsDescription() {
        Map<String, String> env = Map.of("RWE_SPACE_URL", "http://env:1/space",
                "RWE_PORT_CATERPILLARROBOT_BUS", "tcp://127.0.0.1:5020", "RWE_SPACE_TOKEN", "secret");
        RuntimeSettings envOnly = RuntimeSettings.of(props(), env);
        assertEquals("http://env:1/space", envOnly.spaceUrl("http://description/space"));
        assertEquals("tcp://127.0.0.1:5020", envOnly.port("CaterpillarRobot", "bus", "/dev/ttyUSB0"));
        assertEquals("secret", envOnly.spaceToken());

        RuntimeSettings both = RuntimeSettings.of(props("rwe.space.url", "http://prop:2/space",
                "rwe.port.CaterpillarRobot.bus", "tcp://127.0.0.1:6000"), env);
        assertEquals("http://prop:2/space", both.spaceUrl("http://description/space"));
        assertEquals("tcp://127.0.0.1:6000", both.port("CaterpillarRobot", "bus", null));
    }

    @Test
    void theTokenCanComeFromAFileSoThatItIsNotOnTheCommandLine(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("token");
        Files.writeString(file, "  from-a-file \n");
        assertEquals("from-a-file", RuntimeSettings.of(props("rwe.space.tokenFile", file.toString()), Map.of())
                .spaceToken());
        assertEquals("from-a-file", RuntimeSettings.of(props(), Map.of("RWE_SPACE_TOKEN_FILE", file.toString()))
                .spaceToken());
        assertEquals("given", RuntimeSettings.of(props("rwe.space.tokenFile", file.toString()),
                Map.of("RWE_SPACE_TOKEN", "given")).spaceToken(), "the token itself comes first");

        IllegalStateException missing = assertThrows(IllegalStateException.class, () -> RuntimeSettings.of(
                props("rwe.space.tokenFile", dir.resolve("nope").toString()), Map.of()).spaceToken());
        assertTrue(missing.getMessage().contains("does not exist"), missing.getMessage());
        Files.writeString(file, "\n");
        IllegalStateException empty = assertThrows(IllegalStateException.class, () -> RuntimeSettings.of(
                props("rwe.space.tokenFile", file.toString()), Map.of()).spaceToken());
        assertTrue(empty.getMessage().contains("is empty"), empty.getMessage());
    }

    @Test
    void blankOverridesAreIgnored() {
        RuntimeSettings settings = RuntimeSettings.of(props("rwe.host", "  "), Map.of("RWE_HOST", ""));
        assertEquals("room-pc", settings.hostName("room-pc"));
    }

    @Test
    void missingValueNamesTheOverrides() {
        RuntimeSettings settings = RuntimeSettings.of(props(), Map.of());
        IllegalStateException noPort = assertThrows(IllegalStateException.class,
                () -> settings.port("DimRoom", "x10", null));
        assertTrue(noPort.getMessage().contains("-Drwe.port.DimRoom.x10=") && noPort.getMessage().contains(
                "RWE_PORT_DIMROOM_X10"), noPort.getMessage());
        assertThrows(IllegalStateException.class, () -> settings.spaceUrl(null));
    }
}
