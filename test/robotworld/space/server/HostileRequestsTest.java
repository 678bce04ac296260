package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Function;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;

/**
 * 1 000 malformed or hostile requests, each answered with a 4xx and a message, while the server keeps serving
 * normal clients; and the server's memory is never at the mercy of a request (oversized bodies are refused
 * before they are read, counts and depths are bounded).
 */
@org.junit.jupiter.api.Timeout(120)
class HostileRequestsTest {

    private static final String JSON = "application/json";

    /** One kind of bad request: makes the raw request for a server and a valid container's cref JSON. */
    private record Attack(String name, Function<Target, RawHttp.Answer> send) {
    }

    private record Target(URI uri, String cref, Random random) {
        RawHttp.Answer post(String path, String body) {
            return post(path, JSON, body);
        }

        RawHttp.Answer post(String path, String type, String body) {
            try {
                return RawHttp.post(uri, path, type, body);
            } catch (IOException e) {
                throw new AssertionError("connection failed on " + path + ": " + e, e);
            }
        }

        RawHttp.Answer raw(String head, byte[] body) {
            try {
                return RawHttp.send(uri, head, body);
            } catch (IOException e) {
                throw new AssertionError("connection failed: " + e, e);
            }
        }
    }

    @Test
    void aThousandHostileRequestsGet4xxAndTheServerKeepsServing() throws Exception {
        List<Attack> attacks = attacks();
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
             RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO).named("queue"));
            String cref = "{\"cref\":\"" + queue.id() + "\",\"space\":\"" + queue.space() + "\"}";
            Target target = new Target(server.uri(), cref, new Random(42));
            List<String> failures = new ArrayList<>();
            int sent = 0;
            for (int round = 0; sent < 1_000; round++) {
                for (Attack attack : attacks) {
                    if (sent++ == 1_000) {
                        break;
                    }
                    RawHttp.Answer answer = attack.send().apply(target);
                    if (answer.status() < 400 || answer.status() > 499) {
                        failures.add(attack.name() + " -> " + answer.status() + " " + answer.body());
                    } else if (answer.body().isBlank()) {
                        failures.add(attack.name() + " -> " + answer.status() + " without a message");
                    }
                }
                // a normal client is served all along
                client.write(queue, Timeout.TRY_ONCE, Entry.of(round));
                assertEquals(List.of(Entry.of(round)), client.take(queue, Timeout.ofMillis(1000)));
            }
            assertTrue(failures.isEmpty(), failures.size() + " requests were not refused properly:\n"
                    + String.join("\n", failures.subList(0, Math.min(20, failures.size()))));
            assertEquals(0, server.space().describeContainer(server.space().lookupContainer("queue")).size());
            assertEquals(0, server.space().describeContainer(server.space().lookupContainer("queue")).blocked(),
                    "no hostile request left a waiting operation behind");
            ContainerRef after = client.createContainer(ContainerSpec.of(Order.LIFO));
            client.write(after, Timeout.TRY_ONCE, Entry.of("still serving"));
            assertEquals(List.of(Entry.of("still serving")), client.read(after, Timeout.TRY_ONCE));
        }
    }

    /**
     * Requests Jetty refuses before the space sees them (it cannot parse them, or they exceed its limits) get the
     * same JSON error answer as every other failure, never an HTML page, and the server keeps serving.
     */
    @Test
    void requestsRefusedBeforeTheSpaceGetJsonErrorsToo() throws IOException {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
             RemoteSpace client = RemoteSpace.open(server.uri())) {
            String path = server.uri().getPath();
            List<String> failures = new ArrayList<>();
            record Refused(String name, int status, String head) {
            }
            List<Refused> cases = List.of(
                    new Refused("garbled request line", 400, "GET\u0001/ HTTP/1.1\r\n"),
                    new Refused("URI too long", 414, "GET " + path + "/" + "u".repeat(70_000) + " HTTP/1.1\r\n"),
                    new Refused("headers too large", 431, "GET " + path + " HTTP/1.1\r\nX-Filler: "
                            + "h".repeat(40_000) + "\r\n"),
                    new Refused("unsupported HTTP version", 505, "GET " + path + " HTTP/3.0\r\n"),
                    new Refused("HTTP/2 preface on an HTTP/1.1 port", 426, "PRI * HTTP/2.0\r\n"),
                    new Refused("headers too large on a PUT", 431, "PUT " + path + " HTTP/1.1\r\nX-Filler: "
                            + "h".repeat(40_000) + "\r\n"),
                    new Refused("body ends before its length", 400, "POST " + path + "/lookup HTTP/1.1\r\n"
                            + "Content-Type: application/json\r\nContent-Length: 400\r\n"));
            for (Refused refused : cases) {
                RawHttp.Answer answer = RawHttp.send(server.uri(), refused.head(), "{\"name\":".getBytes());
                String type = answer.head().toLowerCase(java.util.Locale.ROOT);
                if (answer.status() != refused.status() || !type.contains("content-type: application/json")
                        || !answer.body().startsWith("{\"error\":\"") || !answer.body().contains("\"message\":")) {
                    failures.add(refused.name() + " -> " + answer.status() + " " + answer.head().lines().filter(
                            l -> l.toLowerCase(java.util.Locale.ROOT).startsWith("content-type")).findFirst()
                            .orElse("(no type)") + " " + answer.body().substring(0, Math.min(120,
                            answer.body().length())));
                }
            }
            assertTrue(failures.isEmpty(), String.join("\n", failures));
            ContainerRef still = client.createContainer(ContainerSpec.of(Order.FIFO));
            client.write(still, Timeout.TRY_ONCE, Entry.of("serving"));
            assertEquals(List.of(Entry.of("serving")), client.take(still, Timeout.TRY_ONCE));
        }
    }

    @Test
    void anOversizedBodyIsRefusedBeforeItIsRead() throws IOException {
        try (SpaceServer server = SpaceServer.start(SpaceServer.Options.defaults().port(0).stopGraceMillis(100))) {
            // claims a terabyte and sends nothing: refused on the header alone
            RawHttp.Answer answer = RawHttp.send(server.uri(), "POST " + server.uri().getPath()
                    + "/write HTTP/1.1\r\nContent-Type: application/json\r\nContent-Length: 1000000000000\r\n", new byte[0]);
            assertEquals(413, answer.status());
            assertTrue(answer.body().contains("too-large"), answer.body());
        }
    }

    @Test
    void waitingRequestsAreBoundedAndTheRestAreToldToComeBack() throws Exception {
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100).maxWaitingCalls(2);
        try (SpaceServer server = SpaceServer.start(options); RemoteSpace client = RemoteSpace.open(server.uri())) {
            ContainerRef empty = client.createContainer(ContainerSpec.of(Order.FIFO));
            String body = "{\"container\":{\"cref\":\"" + empty.id() + "\",\"space\":\"" + empty.space()
                    + "\"},\"timeout\":10000}";
            List<java.net.Socket> waiting = new ArrayList<>();
            try {
                for (int i = 0; i < 2; i++) {
                    java.net.Socket socket = new java.net.Socket(server.uri().getHost(), server.port());
                    socket.getOutputStream().write(("POST " + server.uri().getPath() + "/take HTTP/1.1\r\nHost: x\r\n"
                            + "Content-Type: application/json\r\nContent-Length: " + body.length() + "\r\n\r\n" + body)
                            .getBytes(StandardCharsets.US_ASCII));
                    waiting.add(socket);
                }
                long deadline = System.nanoTime() + 5_000_000_000L;
                while (client.describeContainer(empty).blocked() < 2) {
                    assertTrue(System.nanoTime() < deadline, "the two takes never waited");
                    Thread.sleep(2);
                }
                RawHttp.Answer third = RawHttp.post(server.uri(), "/take", JSON, body);
                assertEquals(503, third.status());
                assertTrue(third.body().contains("busy"), third.body());
                assertTrue(third.head().contains("Retry-After"), third.head());
                // a try-once operation needs no waiting slot
                client.write(empty, Timeout.TRY_ONCE, Entry.of(1));
                // nor does a take that may wait but can complete at once (a provider taking the next request
                // while every place is held by callers waiting for answers)
                ContainerRef full = client.createContainer(ContainerSpec.of(Order.FIFO));
                client.write(full, Timeout.TRY_ONCE, Entry.of("ready"));
                String ready = "{\"container\":{\"cref\":\"" + full.id() + "\",\"space\":\"" + full.space()
                        + "\"},\"timeout\":10000}";
                RawHttp.Answer served = RawHttp.post(server.uri(), "/take", JSON, ready);
                assertEquals(200, served.status(), served.body());
                assertTrue(served.body().contains("ready"), served.body());
            } finally {
                for (java.net.Socket socket : waiting) {
                    socket.close();
                }
            }
        }
    }

    private static List<Attack> attacks() {
        List<Attack> attacks = new ArrayList<>();
        // -- bad JSON
        for (String body : List.of("", "{", "}", "[1,2", "{\"container\":}", "nonsense", "{\"timeout\":1,}", "\u0000\u0001",
                "{\"name\":\"x\"}{\"name\":\"y\"}", "{'name':'x'}", "{\"name\":\"x\",\"name\":\"y\"}", "null", "42")) {
            attacks.add(new Attack("bad JSON " + body, t -> t.post("/lookup", body)));
        }
        attacks.add(new Attack("random bytes", t -> {
            byte[] noise = new byte[1 + t.random().nextInt(2000)];
            t.random().nextBytes(noise);
            return t.post("/take", new String(noise, StandardCharsets.ISO_8859_1));
        }));
        attacks.add(new Attack("truncated write", t -> {
            String full = "{\"container\":" + t.cref() + ",\"timeout\":0,\"items\":[{\"entry\":[1,2,3]}]}";
            return t.post("/write", full.substring(0, 1 + t.random().nextInt(full.length() - 1)));
        }));
        // -- wrong types
        attacks.add(new Attack("timeout as string", t -> t.post("/take", "{\"container\":" + t.cref()
                + ",\"timeout\":\"soon\"}")));
        attacks.add(new Attack("container as string", t -> t.post("/take", "{\"container\":\"queue\",\"timeout\":0}")));
        attacks.add(new Attack("selectors as object", t -> t.post("/read", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"selectors\":{\"order\":\"fifo\"}}")));
        attacks.add(new Attack("fractional entry", t -> t.post("/write", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[{\"entry\":1.5}]}")));
        attacks.add(new Attack("boolean entry", t -> t.post("/write", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[{\"entry\":true}]}")));
        attacks.add(new Attack("null entry", t -> t.post("/write", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[{\"entry\":null}]}")));
        attacks.add(new Attack("integer beyond 64 bits", t -> t.post("/write", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[{\"entry\":123456789012345678901234567890}]}")));
        attacks.add(new Attack("unknown order", t -> t.post("/read", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"selectors\":[{\"order\":\"sideways\"}]}")));
        attacks.add(new Attack("two selector kinds", t -> t.post("/read", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"selectors\":[{\"order\":\"fifo\",\"key\":\"k\"}]}")));
        attacks.add(new Attack("unknown field", t -> t.post("/read", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"please\":true}")));
        // requests that would be served if the second field were taken (or the first): a reader must not guess
        attacks.add(new Attack("a field named twice", t -> t.post("/lookup",
                "{\"name\":\"queue\",\"name\":\"queue\"}")));
        attacks.add(new Attack("a nested field named twice", t -> t.post("/describe", "{\"container\":"
                + t.cref().replaceFirst("\\{", "{\"cref\":\"c999999\",") + "}")));
        attacks.add(new Attack("missing timeout", t -> t.post("/take", "{\"container\":" + t.cref() + "}")));
        attacks.add(new Attack("missing items", t -> t.post("/write", "{\"container\":" + t.cref() + ",\"timeout\":0}")));
        attacks.add(new Attack("writeThenTake without its take", t -> t.post("/writeThenTake", "{\"container\":"
                + t.cref() + ",\"timeout\":0,\"items\":[{\"entry\":1}]}")));
        attacks.add(new Attack("take nested in a take", t -> t.post("/shiftThenTake", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[],\"take\":{\"container\":" + t.cref() + ",\"take\":{}}}")));
        attacks.add(new Attack("cref without space", t -> t.post("/take", "{\"container\":{\"cref\":\"c1\"},\"timeout\":0}")));
        attacks.add(new Attack("bad call id", t -> t.post("/take", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"call\":\"../../etc\"}")));
        attacks.add(new Attack("bad ack header", t -> {
            try {
                return RawHttp.post(t.uri(), "/ack", JSON, "{}", "Space-Ack: <script>");
            } catch (IOException e) {
                throw new AssertionError(e);
            }
        }));
        attacks.add(new Attack("bad spec capacity", t -> t.post("/create", "{\"spec\":{\"capacity\":0}}")));
        attacks.add(new Attack("blank name", t -> t.post("/create", "{\"spec\":{\"name\":\"  \"}}")));
        attacks.add(new Attack("lookup-or-create without a name", t -> t.post("/lookupOrCreate", "{\"spec\":{}}")));
        // -- huge counts and negative numbers
        attacks.add(new Attack("huge count", t -> t.post("/take", "{\"container\":" + t.cref()
                + ",\"timeout\":-1,\"selectors\":[{\"order\":\"fifo\",\"count\":2147483647}]}")));
        attacks.add(new Attack("huge count beyond int", t -> t.post("/take", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"selectors\":[{\"order\":\"fifo\",\"count\":99999999999}]}")));
        attacks.add(new Attack("negative count", t -> t.post("/take", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"selectors\":[{\"order\":\"fifo\",\"count\":-5}]}")));
        attacks.add(new Attack("huge vector index", t -> t.post("/read", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"selectors\":[{\"vector\":2000000000}]}")));
        attacks.add(new Attack("negative timeout", t -> t.post("/take", "{\"container\":" + t.cref()
                + ",\"timeout\":" + (-2 - t.random().nextInt(1_000_000)) + "}")));
        attacks.add(new Attack("many selectors", t -> {
            StringBuilder selectors = new StringBuilder("[");
            for (int i = 0; i < 100; i++) {
                selectors.append(i == 0 ? "" : ",").append("{\"order\":\"fifo\",\"count\":\"all\"}");
            }
            return t.post("/read", "{\"container\":" + t.cref() + ",\"timeout\":0,\"selectors\":" + selectors + "]}");
        }));
        // -- unknown containers
        attacks.add(new Attack("unknown container", t -> t.post("/take", "{\"container\":{\"cref\":\"c"
                + (1000 + t.random().nextInt(1_000_000)) + "\",\"space\":\"" + t.uri() + "\"},\"timeout\":0}")));
        attacks.add(new Attack("foreign space", t -> t.post("/write", "{\"container\":{\"cref\":\"c1\","
                + "\"space\":\"http://elsewhere:1/space\"},\"timeout\":0,\"items\":[{\"entry\":1}]}")));
        attacks.add(new Attack("unknown name", t -> t.post("/lookup", "{\"name\":\"nobody-" + t.random().nextInt() + "\"}")));
        attacks.add(new Attack("destroy unknown container", t -> t.post("/destroyContainer",
                "{\"container\":{\"cref\":\"c999999\",\"space\":\"" + t.uri() + "\"}}")));
        attacks.add(new Attack("subscribe without a stream", t -> t.post("/subscribe", "{\"session\":\"nope\","
                + "\"container\":" + t.cref() + ",\"operations\":[\"write\"],\"mode\":\"infinite\",\"timeout\":-1}")));
        // -- oversized bodies and strings
        attacks.add(new Attack("oversized body", t -> t.post("/write", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[{\"entry\":\"" + "x".repeat((1 << 20) + 10) + "\"}]}")));
        attacks.add(new Attack("oversized declared length", t -> t.raw("POST " + t.uri().getPath()
                + "/write HTTP/1.1\r\nContent-Type: application/json\r\nContent-Length: 50000000\r\n", new byte[100])));
        attacks.add(new Attack("oversized string", t -> t.post("/write", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[{\"entry\":\"" + "y".repeat(100_000) + "\"}]}")));
        attacks.add(new Attack("too many items", t -> {
            StringBuilder items = new StringBuilder("[");
            for (int i = 0; i < 10_001; i++) {
                items.append(i == 0 ? "" : ",").append("{\"entry\":1}");
            }
            return t.post("/write", "{\"container\":" + t.cref() + ",\"timeout\":0,\"items\":" + items + "]}");
        }));
        // -- nesting
        attacks.add(new Attack("deep tuple", t -> t.post("/write", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[{\"entry\":" + "[".repeat(40) + "1" + "]".repeat(40) + "}]}")));
        attacks.add(new Attack("very deep JSON", t -> t.post("/write", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"items\":[{\"entry\":" + "[".repeat(50_000) + "]".repeat(50_000) + "}]}")));
        attacks.add(new Attack("deep template", t -> t.post("/read", "{\"container\":" + t.cref()
                + ",\"timeout\":0,\"selectors\":[{\"template\":" + "{\"tuple\":[".repeat(40) + "{\"any\":true}"
                + "]}".repeat(40) + "}]}")));
        // -- content types, methods, paths
        attacks.add(new Attack("text/plain", t -> t.post("/lookup", "text/plain", "{\"name\":\"queue\"}")));
        attacks.add(new Attack("form", t -> t.post("/lookup", "application/x-www-form-urlencoded", "name=queue")));
        attacks.add(new Attack("no content type", t -> t.post("/lookup", null, "{\"name\":\"queue\"}")));
        for (String method : List.of("GET", "PUT", "DELETE", "PATCH")) {
            attacks.add(new Attack(method + " on an operation", t -> t.raw(method + " " + t.uri().getPath()
                    + "/take HTTP/1.1\r\nContent-Type: application/json\r\nContent-Length: 2\r\n", "{}".getBytes())));
        }
        attacks.add(new Attack("POST on the description", t -> t.post("", "{}")));
        attacks.add(new Attack("unknown operation", t -> t.post("/teleport", "{}")));
        attacks.add(new Attack("stream without a session", t -> t.raw("GET " + t.uri().getPath()
                + "/events HTTP/1.1\r\n", new byte[0])));
        attacks.add(new Attack("stream with a bad session", t -> t.raw("GET " + t.uri().getPath()
                + "/events?session=%3Cscript%3E HTTP/1.1\r\n", new byte[0])));
        attacks.add(new Attack("body shorter than declared", t -> t.raw("POST " + t.uri().getPath()
                + "/lookup HTTP/1.1\r\nContent-Type: application/json\r\nContent-Length: 40\r\n",
                "{\"name\":\"queue\"}".getBytes())));
        assertFalse(attacks.isEmpty());
        return attacks;
    }
}
