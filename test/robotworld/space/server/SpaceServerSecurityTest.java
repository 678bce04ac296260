package robotworld.space.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ConnectException;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.Socket;
import java.util.Collections;
import java.util.List;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.SpaceRequestRejectedException;
import robotworld.space.Timeout;
import robotworld.space.remote.RemoteSpace;

/** The bearer token, the loopback default, and what an unauthenticated request gets. */
@org.junit.jupiter.api.Timeout(30)
class SpaceServerSecurityTest {

    private static final String TOKEN = "correct-horse-battery-staple";

    private static SpaceServer.Options options() {
        return SpaceServer.Options.defaults().port(0).stopGraceMillis(100);
    }

    @Test
    void requestsWithoutTheTokenAreRefusedWith401() throws IOException {
        try (SpaceServer server = SpaceServer.start(options().token(TOKEN))) {
            RawHttp.Answer none = RawHttp.post(server.uri(), "/lookup", "application/json", "{\"name\":\"x\"}");
            assertEquals(401, none.status());
            assertTrue(none.head().contains("WWW-Authenticate: Bearer"), none.head());
            assertTrue(none.body().contains("\"error\":\"unauthorized\""), none.body());

            RawHttp.Answer wrong = RawHttp.post(server.uri(), "/lookup", "application/json", "{\"name\":\"x\"}",
                    "Authorization: Bearer correct-horse-battery-stapler");
            assertEquals(401, wrong.status());
            RawHttp.Answer basic = RawHttp.post(server.uri(), "/lookup", "application/json", "{\"name\":\"x\"}",
                    "Authorization: Basic " + TOKEN);
            assertEquals(401, basic.status());
            RawHttp.Answer stream = RawHttp.send(server.uri(), "GET " + server.uri().getPath()
                    + "/events?session=s1 HTTP/1.1\r\n", new byte[0]);
            assertEquals(401, stream.status(), "the notification stream is protected too");

            SpaceRequestRejectedException refused = assertThrows(SpaceRequestRejectedException.class,
                    () -> RemoteSpace.open(server.uri()));
            assertEquals(401, refused.status());
            assertThrows(SpaceRequestRejectedException.class,
                    () -> RemoteSpace.open(server.uri(), RemoteSpace.Options.defaults().token("guess")));
        }
    }

    @Test
    void requestsWithTheTokenAreServed() throws IOException {
        try (SpaceServer server = SpaceServer.start(options().token(TOKEN))) {
            RawHttp.Answer accepted = RawHttp.post(server.uri(), "/lookup", "application/json", "{\"name\":\"x\"}",
                    "Authorization: Bearer " + TOKEN);
            assertEquals(404, accepted.status(), "authenticated, and then simply not found");
            assertTrue(accepted.body().contains("container-not-found"), accepted.body());

            try (RemoteSpace space = RemoteSpace.open(server.uri(), RemoteSpace.Options.defaults().token(TOKEN))) {
                ContainerRef ref = space.createContainer(ContainerSpec.of(Order.FIFO));
                space.write(ref, Timeout.TRY_ONCE, Entry.of(1));
                assertEquals(List.of(Entry.of(1)), space.take(ref, Timeout.TRY_ONCE));
            }
        }
    }

    @Test
    void theServerBindsToLoopbackByDefault() throws IOException {
        assertEquals("127.0.0.1", SpaceServer.Options.defaults().bindAddress());
        try (SpaceServer server = SpaceServer.start(options())) {
            assertEquals("127.0.0.1", server.uri().getHost());
            try (Socket loopback = new Socket("127.0.0.1", server.port())) {
                assertTrue(loopback.isConnected());
            }
            InetAddress external = someNonLoopbackAddress();
            Assumptions.assumeTrue(external != null, "this machine has no non-loopback IPv4 address to try");
            try (Socket outside = new Socket()) {
                assertThrows(ConnectException.class,
                        () -> outside.connect(new InetSocketAddress(external, server.port()), 2000),
                        "reachable on " + external);
            }
        }
    }

    private static InetAddress someNonLoopbackAddress() throws IOException {
        for (NetworkInterface nic : Collections.list(NetworkInterface.getNetworkInterfaces())) {
            if (!nic.isUp() || nic.isLoopback()) {
                continue;
            }
            for (InetAddress address : Collections.list(nic.getInetAddresses())) {
                if (address instanceof Inet4Address && !address.isLoopbackAddress()) {
                    return address;
                }
            }
        }
        return null;
    }

    @Test
    void tokensMustBeUsable() {
        assertThrows(IllegalArgumentException.class, () -> SpaceServer.start(options().token(" padded ")));
        assertThrows(IllegalArgumentException.class, () -> SpaceServer.start(options().token("")));
        assertFalse(new BearerToken("abc").accepts(null));
        assertTrue(new BearerToken("abc").accepts("Bearer abc"));
        assertFalse(new BearerToken("abc").accepts("Bearer abcd"));
    }
}
