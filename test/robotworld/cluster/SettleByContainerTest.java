package robotworld.cluster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.space.Tuple;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;

/**
 * A client that failed over settles its calls with a server that never saw them: cancels and confirmations that
 * name the call's container ({@code id/containerId}) are settled on that container, without asking every container
 * of the space; those that do not are still settled, by asking them all.
 */
class SettleByContainerTest {

    private LocalCluster cluster;
    private SpaceServer first;
    private SpaceServer second;
    private RemoteSpace client;
    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();

    @BeforeEach
    void start() {
        cluster = LocalCluster.start(2);
        SpaceServer.Options options = SpaceServer.Options.defaults().port(0).stopGraceMillis(100).leaseMillis(500);
        first = SpaceServer.start(cluster.member(0).openSpace("settle"), options);
        second = SpaceServer.start(cluster.member(1).openSpace("settle"), options);
        // the first calls on a fresh cluster create its maps on both members: on a busy machine that can take
        // longer than the default 3 s allowance, which is not what these tests are about
        client = RemoteSpace.open(List.of(first.uri()), RemoteSpace.Options.defaults().networkAllowanceMillis(10_000));
    }

    @AfterEach
    void stop() {
        client.close();
        first.kill();
        second.kill();
        cluster.close();
    }

    @Test
    void aCancelNamingTheContainerPutsTheTakenEntryBackWithoutAskingEveryContainer() throws Exception {
        ContainerRef queue = queueWith("a", "b");
        take(first, queue, "laptop:1");
        assertEquals(1, size(queue), "taken, held for its confirmation");
        long searches = searches(1);
        String answer = post(second, "/cancel", "{\"call\":\"laptop:1/" + queue.id() + "\"}", null);
        assertTrue(answer.contains("cancelled"), answer);
        assertEquals(2, size(queue), "the taken entry is back at once");
        assertEquals(searches, searches(1), "settled on the named container, no search");

        take(first, queue, "laptop:2");
        answer = post(second, "/cancel", "{\"call\":\"laptop:2\"}", null);
        assertTrue(answer.contains("cancelled"), answer);
        assertEquals(2, size(queue), "an unnamed container is found too");
        assertTrue(searches(1) > searches, "by asking every container");
    }

    @Test
    void aConfirmationNamingTheContainerMakesTheTakeStandWithoutAskingEveryContainer() throws Exception {
        ContainerRef queue = queueWith("a", "b");
        take(first, queue, "laptop:3");
        take(first, queue, "laptop:4");
        long searches = searches(1);
        post(second, "/ack", "{\"calls\":[\"laptop:3/" + queue.id() + "\"]}", null);
        post(second, "/describe", "{\"container\":" + cref(queue) + "}", "laptop:4/" + queue.id());
        Thread.sleep(1_500); // three leases: unconfirmed takes would have come back by now
        assertEquals(0, size(queue), "both takes stand");
        assertEquals(searches, searches(1), "settled on the named container, no search");
    }

    @Test
    void aMalformedContainerNameIsRefusedWith400() throws Exception {
        HttpResponse<String> answer = send(second, "/cancel", "{\"call\":\"laptop:5/<script>\"}", null);
        assertEquals(400, answer.statusCode(), answer.body());
        assertTrue(answer.body().contains("call container id"), answer.body());
    }

    private ContainerRef queueWith(String... values) {
        ContainerRef queue = client.createContainer(ContainerSpec.of(Order.FIFO).named("queue"));
        for (String value : values) {
            client.write(queue, Timeout.TRY_ONCE, List.of(Item.of(Tuple.of(value))));
        }
        return queue;
    }

    private int size(ContainerRef queue) {
        return client.read(queue, Timeout.TRY_ONCE, Selector.fifo(Selector.ALL)).size();
    }

    private long searches(int member) {
        return cluster.member(member).node().receiptSearches.sum();
    }

    private void take(SpaceServer server, ContainerRef queue, String call) throws Exception {
        String answer = post(server, "/take", "{\"container\":" + cref(queue)
                + ",\"timeout\":0,\"selectors\":[{\"order\":\"fifo\"}],\"call\":\"" + call + "\"}", null);
        assertTrue(answer.contains("\"ack\":true"), answer);
    }

    private static String cref(ContainerRef queue) {
        return "{\"cref\":\"" + queue.id() + "\",\"space\":\"" + queue.space() + "\"}";
    }

    private String post(SpaceServer server, String path, String body, String ackHeader) throws Exception {
        HttpResponse<String> answer = send(server, path, body, ackHeader);
        assertEquals(200, answer.statusCode(), answer.body());
        return answer.body();
    }

    private HttpResponse<String> send(SpaceServer server, String path, String body, String ackHeader)
            throws Exception {
        URI uri = URI.create(server.uri() + path);
        HttpRequest.Builder request = HttpRequest.newBuilder(uri).timeout(Duration.ofSeconds(20))
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(body));
        if (ackHeader != null) {
            request.header("Space-Ack", ackHeader);
        }
        return http.send(request.build(), HttpResponse.BodyHandlers.ofString());
    }
}
