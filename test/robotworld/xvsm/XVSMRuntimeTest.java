package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import robotworld.core.HostNames;
import robotworld.space.Capi;
import robotworld.space.EmbeddedSpace;
import robotworld.space.SpaceClosedException;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;

/** The runtime: connecting with description defaults and run-time overrides, owning resources, stopping. */
class XVSMRuntimeTest {

    private static final List<String> PROPERTIES = List.of("rwe.space.url", "rwe.host", "rwe.port.Robot1.bus",
            "rwe.call.timeout.ms", "rwe.publish.local", "rwe.sensor.batching");

    @AfterEach
    void clearProperties() {
        PROPERTIES.forEach(System::clearProperty);
    }

    @Test
    void connectUsesTheDescriptionUnlessOverridden() throws Exception {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(100))) {
            try (XVSMRuntime runtime = XVSMRuntime.connect(server.uri().toString(), "robot-pc")) {
                assertEquals("robot-pc", runtime.hostName());
                assertTrue(runtime.space() instanceof RemoteSpace);
                assertEquals(Duration.ofSeconds(10), runtime.defaultCallTimeout());
                assertTrue(runtime.publishLocalCallsByDefault());
                assertFalse(runtime.adaptiveBatchingByDefault());
            }
            System.setProperty("rwe.space.url", server.uri().toString());
            System.setProperty("rwe.host", "override-pc");
            System.setProperty("rwe.call.timeout.ms", "750");
            System.setProperty("rwe.sensor.batching", "true");
            System.setProperty("rwe.publish.local", "false");
            try (XVSMRuntime runtime = XVSMRuntime.connect("http://127.0.0.1:1/nowhere", "robot-pc")) {
                assertEquals("override-pc", runtime.hostName());
                assertEquals(Duration.ofMillis(750), runtime.defaultCallTimeout());
                assertTrue(runtime.adaptiveBatchingByDefault());
                assertFalse(runtime.publishLocalCallsByDefault());
                Capi space = runtime.space();
                runtime.close();
                assertThrows(SpaceClosedException.class, () -> space.lookupContainer("x"),
                        "a connection the runtime opened is closed with it");
            }
        }
    }

    @Test
    void withoutAHostNameTheComputersNameIsUsed() throws Exception {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
             XVSMRuntime runtime = XVSMRuntime.connect(server.uri().toString(), null)) {
            assertEquals(HostNames.thisComputer(), runtime.hostName());
        }
    }

    @Test
    void badUrlsAndHostNamesAreRefused() {
        IllegalStateException noUrl = assertThrows(IllegalStateException.class,
                () -> XVSMRuntime.connect(null, "h"));
        assertTrue(noUrl.getMessage().contains("rwe.space.url"), noUrl.getMessage());
        IllegalArgumentException notHttp = assertThrows(IllegalArgumentException.class,
                () -> XVSMRuntime.connect("tcp://127.0.0.1:9876", "h"));
        assertTrue(notHttp.getMessage().contains("http://"), notHttp.getMessage());
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            assertThrows(IllegalArgumentException.class, () -> XVSMRuntime.using(space, "a#b"));
            assertThrows(IllegalArgumentException.class, () -> XVSMRuntime.using(space, " "));
        }
    }

    @Test
    void portsComeFromTheDescriptionUnlessOverridden() {
        try (EmbeddedSpace space = EmbeddedSpace.open(); XVSMRuntime runtime = XVSMRuntime.using(space, "h")) {
            assertEquals("/dev/ttyUSB0", runtime.port("Robot1", "bus", "/dev/ttyUSB0"));
            System.setProperty("rwe.port.Robot1.bus", "tcp://127.0.0.1:4000");
            assertEquals("tcp://127.0.0.1:4000", runtime.port("Robot1", "bus", "/dev/ttyUSB0"));
            assertThrows(IllegalStateException.class, () -> runtime.port("Env", "x10", null));
        }
    }

    @Test
    void ownedResourcesCloseInReverseOrderAndASuppliedSpaceStaysOpen() {
        List<String> closed = new ArrayList<>();
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            XVSMRuntime runtime = XVSMRuntime.using(space, "h");
            AutoCloseable bus = () -> closed.add("bus");
            assertSame(bus, runtime.own(bus));
            XVSMBumperModuleLocal bumper = runtime.own(new XVSMBumperModuleLocal(runtime, "R", "B", new FakeBumper()));
            runtime.own(bumper); // once only
            runtime.own(() -> closed.add("last"));
            runtime.close();
            runtime.close();

            assertEquals(List.of("last", "bus"), closed);
            assertFalse(bumper.isServing());
            assertEquals(0, space.describeContainer(space.lookupContainer("RBREQUEST")).size(),
                    "the space is still open");
            assertThrows(IllegalStateException.class, () -> runtime.own(() -> closed.add("too late")));
            assertEquals(List.of("last", "bus", "too late"), closed);
        }
    }

    @Test
    void serveUntilStoppedReturnsWhenTheRuntimeIsClosed() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            XVSMRuntime runtime = XVSMRuntime.using(space, "h");
            CompletableFuture<Void> serving = CompletableFuture.runAsync(() -> {
                try {
                    runtime.serveUntilStopped();
                } catch (InterruptedException e) {
                    throw new IllegalStateException(e);
                }
            }, task -> new Thread(task).start());
            assertThrows(java.util.concurrent.TimeoutException.class, () -> serving.get(100, TimeUnit.MILLISECONDS));
            runtime.close();
            serving.get(5, TimeUnit.SECONDS);
        }
    }

    @Test
    void defaultsReadPropertiesAndEnvironment() {
        Properties properties = new Properties();
        properties.setProperty("rwe.call.timeout.ms", "1234");
        RuntimeDefaults defaults = RuntimeDefaults.of(properties, Map.of("RWE_SENSOR_BATCHING", "yes",
                "RWE_PUBLISH_LOCAL", "off"));
        assertEquals(new RuntimeDefaults(Duration.ofMillis(1234), false, true), defaults);
        properties.setProperty("rwe.call.timeout.ms", "soon");
        assertThrows(IllegalArgumentException.class, () -> RuntimeDefaults.of(properties, Map.of()));
        properties.setProperty("rwe.call.timeout.ms", "0");
        assertThrows(IllegalArgumentException.class, () -> RuntimeDefaults.of(properties, Map.of()));
    }
}
