package robotworld.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.net.ConnectException;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.explorer.cli.Rwe;
import robotworld.recording.SimWorld;
import robotworld.space.server.SpaceServer;
import robotworld.testsupport.RunningRwe;
import robotworld.testsupport.ThreadsLeft;
import robotworld.xvsm.XVSMMotorModuleRemote;

/**
 * {@code rwe bridge WORLD} as a person runs it (in-process, through {@link Rwe#run}, stopped as Ctrl-C stops it),
 * against a running simulated world, with the reference Foxglove client.
 */
class BridgeCommandTest {

    /** SimWorld's robot and modules as a RobotWorld description. */
    private static final String WORLD = """
            <?xml version="1.0" encoding="UTF-8"?>
            <RobotWorld xmlns="urn:robotworld:description">
              <WorldName>SimWorld</WorldName>
              <CommunicationType>xvsm</CommunicationType>
              <PackageName>simworld</PackageName>
              <SpaceURL>http://localhost:9876/space</SpaceURL>
              <RobotDescription>
                <RobotName>SimBot</RobotName>
                <Host>robot-pc</Host>
                <COMPort>/dev/ttyUSB0</COMPort>
                <TalkToBusClass>RS485Bus</TalkToBusClass>
                <Module>
                  <Name>Motor</Name><NodeID>15B63A4</NodeID><NodeNumber>1</NodeNumber>
                  <Class>MotorModule</Class><Version>1.0</Version>
                </Module>
                <Module>
                  <Name>Bumper</Name><NodeID>15B63B2</NodeID><NodeNumber>2</NodeNumber>
                  <Class>BumperModule</Class><Version>1.0</Version>
                </Module>
                <Module>
                  <Name>IR</Name><NodeID>15B63C7</NodeID><NodeNumber>4</NodeNumber>
                  <Class>IRDistanceModule</Class><Version>1.0</Version>
                </Module>
              </RobotDescription>
            </RobotWorld>
            """;
    private static final Pattern ENDPOINT = Pattern.compile("Foxglove endpoint for SimWorld at (ws://\\S+)");
    /** The last line it prints before it waits for Ctrl-C. */
    private static final Pattern READY = Pattern.compile("in Foxglove or Lichtblick: Open connection > Foxglove"
            + " WebSocket > (ws://[^\\s;]+)");

    @TempDir
    Path folder;

    private Path world() throws IOException {
        return Files.writeString(folder.resolve("sim-world.xml"), WORLD);
    }

    @Test
    void theReferenceClientSeesAChannelPerModuleLivenessAndTheLiveCallsInOrderUntilCtrlC() throws Exception {
        try (SimWorld world = SimWorld.start()) {
            XVSMMotorModuleRemote motor = new XVSMMotorModuleRemote(world.host("laptop"), SimWorld.ROBOT, "Motor");
            motor.setMotor(1, 0); // the laptop's connection is up, its threads running
            Set<Thread> before = ThreadsLeft.now();
            URI uri;
            try (RunningRwe bridge = new RunningRwe("bridge", world().toString(), "--space", world.url(), "--port", "0")) {
                uri = started(bridge);
                assertEquals("127.0.0.1", uri.getHost(), "loopback by default" + bridge);
                assertTrue(bridge.out.toString().contains("watching 3 modules in the space at " + world.url()),
                        bridge.toString());
                assertFalse(bridge.out.toString().contains("warning"), bridge.toString());
                assertNotReachableFromOtherHosts(uri.getPort());
                assertFalse(ThreadsLeft.since(before, BridgeCommandTest::ofTheBridge).isEmpty(),
                        "the command's own threads are told apart");

                try (FoxglovePeer client = FoxglovePeer.connect(uri, "/SimBot/Motor", "/rwe/liveness")) {
                    JsonNode info = client.await(e -> e.path("event").asText().equals("serverInfo"), "serverInfo");
                    assertTrue(info.get("name").asText().contains("SimWorld"), info.toString());
                    assertFalse(info.get("name").asText().contains("REPLAY"), "a live world: " + info);
                    JsonNode advertise = client.await(e -> e.path("event").asText().equals("advertise"),
                            "advertise");
                    Set<String> modules = new java.util.TreeSet<>();
                    Set<String> topics = new java.util.TreeSet<>();
                    for (JsonNode channel : advertise.get("channels")) {
                        topics.add(channel.get("topic").asText());
                        if (channel.get("schemaName").asText().equals("rwe.ModuleTraffic")) {
                            modules.add(channel.get("topic").asText());
                        }
                    }
                    assertEquals(Set.of("/SimBot/Motor", "/SimBot/Bumper", "/SimBot/IR"), modules,
                            "one channel per module of the description: " + topics);
                    assertTrue(topics.contains("/rwe/liveness"), topics.toString());
                    // calls until the client has one: from then on its subscription is in place
                    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
                    while (motorAnswers(client).isEmpty()) {
                        assertTrue(System.nanoTime() < deadline, "no motor message reached the client: "
                                + client.events() + bridge);
                        motor.setMotor(1, 0);
                        Thread.sleep(50);
                    }
                    List<Integer> sent = new ArrayList<>();
                    for (int i = 1; i <= 20; i++) {
                        motor.setMotor(1, i / 100.0);
                        sent.add(i * 10);
                    }
                    motor.setMotor(1, -0.2);
                    sent.add(-200);
                    client.await(e -> e.path("topic").asText().equals("/SimBot/Motor")
                            && e.at("/data/kind").asText().equals("answer") && e.at("/data/fields/1").asInt() == -200,
                            "the last motor answer");
                    List<Integer> answers = motorAnswers(client);
                    assertEquals(sent, answers.subList(answers.size() - sent.size(), answers.size()),
                            "every call's answer, in the order of the calls");
                    List<Integer> requests = client.events("message").stream()
                            .filter(e -> e.get("topic").asText().equals("/SimBot/Motor")
                                    && e.at("/data/kind").asText().equals("request"))
                            .map(e -> e.at("/data/fields/1").asInt()).toList();
                    assertEquals(sent, requests.subList(requests.size() - sent.size(), requests.size()),
                            "every call's request, in order");
                    JsonNode alive = client.await(e -> e.path("topic").asText().equals("/rwe/liveness")
                            && e.at("/data/participant").asText().equals("SimBot")
                            && e.at("/data/state").asText().equals("ALIVE"), "the robot alive");
                    assertEquals(1, alive.at("/data/alive").asInt(), alive.toString());
                }

                long stopping = System.nanoTime();
                assertEquals(0, bridge.stop(10_000), bridge.toString());
                long stoppedMillis = (System.nanoTime() - stopping) / 1_000_000;
                assertTrue(stoppedMillis < 5_000, "Ctrl-C took " + stoppedMillis + " ms" + bridge);
                Matcher published = Pattern.compile("Foxglove endpoint stopped after (\\d+) messages")
                        .matcher(bridge.out.toString());
                assertTrue(published.find(), bridge.toString());
                assertTrue(Long.parseLong(published.group(1)) >= 2 * 21, bridge.toString());
                assertTrue(bridge.err.toString().isEmpty(), bridge.toString());
            }
            assertRefused(uri.getPort());
            ThreadsLeft.assertNoneSince(before, BridgeCommandTest::ofTheBridge);
        }
    }

    @Test
    void withATokenFileOnlyAClientThatSendsItConnects() throws Exception {
        Path tokenFile = Files.writeString(folder.resolve("token"), "s3cret-tok3n\n");
        try (SpaceServer space = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
             RunningRwe bridge = new RunningRwe("bridge", world().toString(), "--space", space.uri().toString(), "--port",
                     "0", "--token-file", tokenFile.toString())) {
            URI uri = started(bridge);
            assertEquals("127.0.0.1", uri.getHost(), bridge.toString());
            assertTrue(bridge.out.toString().contains("(token required: add ?token=<token> to the URL)"),
                    bridge.toString());
            assertFalse(bridge.out.toString().contains("s3cret-tok3n"), "the token is not printed" + bridge);

            for (URI refused : List.of(uri, URI.create(uri + "?token=wrong"))) {
                try (FoxglovePeer client = FoxglovePeer.connect(refused)) {
                    assertEquals(2, client.awaitEnd(), "refused: " + client.events() + client.errors());
                    assertTrue(client.events("serverInfo").isEmpty(), client.events().toString());
                    JsonNode error = client.events("error").get(0);
                    assertTrue(error.get("message").asText().contains("401"), error.toString());
                }
            }
            try (FoxglovePeer client = FoxglovePeer.connect(URI.create(uri + "?token=s3cret-tok3n"))) {
                JsonNode info = client.await(e -> e.path("event").asText().equals("serverInfo"), "serverInfo");
                assertTrue(info.get("name").asText().contains("SimWorld"), info.toString());
                JsonNode advertise = client.await(e -> e.path("event").asText().equals("advertise"), "advertise");
                assertTrue(advertise.toString().contains("\"/SimBot/Motor\""), advertise.toString());
            }
            // a client that can set headers (a browser cannot) may send it as a bearer token instead
            java.util.concurrent.LinkedBlockingQueue<String> texts = new java.util.concurrent.LinkedBlockingQueue<>();
            java.net.http.WebSocket socket = java.net.http.HttpClient.newHttpClient().newWebSocketBuilder()
                    .header("Authorization", "Bearer s3cret-tok3n").subprotocols(FoxgloveBridge.SUBPROTOCOL)
                    .buildAsync(uri, new java.net.http.WebSocket.Listener() {
                        @Override
                        public java.util.concurrent.CompletionStage<?> onText(java.net.http.WebSocket webSocket,
                                CharSequence data, boolean last) {
                            texts.add(data.toString());
                            webSocket.request(1);
                            return null;
                        }
                    }).get(30, TimeUnit.SECONDS);
            String first = texts.poll(30, TimeUnit.SECONDS);
            assertTrue(first != null && first.contains("\"op\":\"serverInfo\""), String.valueOf(first));
            socket.abort();
            assertEquals(0, bridge.stop(10_000), bridge.toString());
        }
    }

    @Test
    void listeningOnEveryInterfaceIsWarnedOf() throws Exception {
        Path tokenFile = Files.writeString(folder.resolve("token"), "s3cret-tok3n\n");
        try (SpaceServer space = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200))) {
            String url = space.uri().toString();
            try (RunningRwe open = new RunningRwe("bridge", world().toString(), "--space", url, "--port", "0", "--bind",
                    "0.0.0.0", "--for", "30")) {
                started(open);
                assertTrue(open.out.toString().contains("warning: reachable from other hosts without a token"),
                        open.toString());
                assertEquals(0, open.stop(10_000), open.toString());
            }
            try (RunningRwe open = new RunningRwe("bridge", world().toString(), "--space", url, "--port", "0", "--bind",
                    "0.0.0.0", "--token-file", tokenFile.toString(), "--for", "30")) {
                started(open);
                assertTrue(open.out.toString().contains("warning: reachable from other hosts\n"), open.toString());
                assertEquals(0, open.stop(10_000), open.toString());
            }
        }
    }

    @Test
    void mistakesGetAShortErrorNamingTheFix() throws Exception {
        String world = world().toString();
        // no space server there
        RunningRwe unreachable = new RunningRwe("bridge", world, "--space", "http://127.0.0.1:9/space", "--port", "0");
        unreachable.thread.join(30_000);
        assertEquals(1, unreachable.exit.get(), unreachable.toString());
        assertShortWithoutTrace(unreachable);
        assertTrue(unreachable.err.toString().contains("http://127.0.0.1:9/space")
                && unreachable.err.toString().contains("--space URL"), unreachable.toString());
        assertFalse(unreachable.out.toString().contains("Foxglove endpoint"), unreachable.toString());

        try (SpaceServer space = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
             ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            RunningRwe busy = new RunningRwe("bridge", world, "--space", space.uri().toString(), "--port",
                    String.valueOf(taken.getLocalPort()));
            busy.thread.join(30_000);
            assertEquals(1, busy.exit.get(), busy.toString());
            assertShortWithoutTrace(busy);
            // the option of this command that chooses the port (not rwe replay's --foxglove-port)
            assertEquals("rwe bridge: cannot listen on 127.0.0.1:" + taken.getLocalPort() + " for Foxglove: Address"
                    + " already in use\nStop the program that uses it (another rwe bridge or rwe replay?), or choose"
                    + " another port with --port P (0: any free one).\n", busy.err.toString());
            assertFalse(busy.out.toString().contains("Foxglove endpoint"), busy.toString());
        }

        RunningRwe never = new RunningRwe("bridge", world, "--for", "0");
        never.thread.join(30_000);
        assertEquals(2, never.exit.get(), never.toString());
        assertTrue(never.err.toString().contains("--for must be positive"), never.toString());
    }

    /** The endpoint's address, once the bridge has said all it says when it starts. */
    private static URI started(RunningRwe bridge) throws InterruptedException {
        String ready = bridge.await(READY);
        String endpoint = bridge.await(ENDPOINT);
        assertEquals(endpoint, ready, bridge.toString());
        return URI.create(endpoint);
    }

    private static void assertShortWithoutTrace(RunningRwe command) {
        String err = command.err.toString();
        assertTrue(err.startsWith("rwe bridge: "), command.toString());
        assertTrue(err.lines().count() <= 3, "at most three lines" + command);
        assertFalse(err.contains("\tat ") || err.contains("Exception"), "no stack trace" + command);
    }

    private static List<Integer> motorAnswers(FoxglovePeer client) {
        return client.events("message").stream()
                .filter(e -> e.get("topic").asText().equals("/SimBot/Motor")
                        && e.at("/data/kind").asText().equals("answer"))
                .map(e -> e.at("/data/fields/1").asInt()).toList();
    }

    /** Nothing listens on {@code port} of this computer's other (non-loopback) addresses. */
    private static void assertNotReachableFromOtherHosts(int port) throws IOException {
        for (NetworkInterface network : Collections.list(NetworkInterface.getNetworkInterfaces())) {
            if (!network.isUp() || network.isLoopback()) {
                continue;
            }
            for (InetAddress address : Collections.list(network.getInetAddresses())) {
                if (address instanceof Inet4Address && !address.isLoopbackAddress()) {
                    try (Socket socket = new Socket()) {
                        socket.connect(new InetSocketAddress(address, port), 5_000);
                        throw new AssertionError("the endpoint answers on " + address + ":" + port);
                    } catch (ConnectException expected) {
                        // refused: it listens on loopback only
                    }
                }
            }
        }
    }

    private static void assertRefused(int port) throws IOException {
        try (Socket socket = new Socket()) {
            socket.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 5_000);
            throw new AssertionError("something still listens on port " + port);
        } catch (ConnectException expected) {
            // closed
        }
    }

    /**
     * Whether a thread of that name is one rwe bridge starts: its endpoint's, its tap's, and its connection's to the
     * space (the world's own connections were there before, with theirs; their notification pools grow on demand).
     */
    private static boolean ofTheBridge(String name) {
        return name.startsWith("foxglove-bridge") || name.startsWith("world-tap")
                || name.startsWith("space-client") && !name.startsWith("space-client-notify");
    }
}
