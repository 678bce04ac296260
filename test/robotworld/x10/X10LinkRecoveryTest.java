package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;
import robotworld.testsupport.LinkFaultProxy;

/**
 * A controller whose link to the interface drops, or goes silent without being closed, serves again once the
 * interface is back on the same port: commands in between fail within their bound, the next one after the return
 * works, and uploads resume without any command being sent.
 */
class X10LinkRecoveryTest {

    private static final X10Address A3 = X10Address.of('A', 3);
    /**
     * A silent interface is given up on after 3 s (three sends, 1 s each), so the silence costs the tests little;
     * on a busy machine the first command over a new connection may still miss that (the relay and the simulator
     * must first be scheduled), so the tests that need a reopened link to answer retry until {@link #PATIENCE}.
     */
    private static final CM11aConfig CONFIG = Cm11aRig.fastConfig().withChecksumTimeout(Duration.ofSeconds(1))
            .withDeadInterfaceTimeout(Duration.ofSeconds(3));
    /** How long a reopened link may take to serve, however busy the machine. */
    private static final Duration PATIENCE = Duration.ofSeconds(60);

    private SimulatedCm11a sim;
    private LinkFaultProxy proxy;
    private CM11aController controller;
    private final BlockingQueue<X10Event> events = new LinkedBlockingQueue<>();

    @BeforeEach
    void start() throws Exception {
        sim = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp,A3=appliance");
        proxy = new LinkFaultProxy(port(sim.listen(0)));
        controller = CM11aController.open(proxy.portName(), CONFIG);
        controller.addListener(events::add);
        long giveUp = System.nanoTime() + PATIENCE.toNanos();
        while (proxy.connections() < 1) { // connected at once; the relay takes its connection in its own time
            assertTrue(System.nanoTime() < giveUp, "the relay never took the controller's connection");
            Thread.sleep(1);
        }
    }

    @AfterEach
    void stop() throws Exception {
        controller.close();
        proxy.close();
        sim.close();
    }

    private static int port(String portName) {
        return URI.create(portName).getPort();
    }

    @Test
    void aDroppedLinkIsOpenedAgainWhenTheInterfaceIsBack() throws Exception {
        controller.on(A3);
        assertTrue(sim.appliance(A3).isOn());

        proxy.drop();
        long start = System.nanoTime();
        X10Exception lost = assertThrows(X10Exception.class, () -> controller.off(A3));
        // bounded: at most the dead-interface timeout, with room for a busy machine (how fast is for bench-x10)
        long tookMillis = (System.nanoTime() - start) / 1_000_000;
        assertTrue(tookMillis < CONFIG.deadDeviceTimeout().plus(PATIENCE).toMillis(),
                "failed only after " + tookMillis + " ms");
        assertTrue(lost.getMessage().contains(proxy.portName()), lost.getMessage());
        assertThrows(X10Exception.class, () -> controller.off(A3), "still down");

        proxy.restore();
        int before = proxy.connections();
        offOnceTheLinkServes(); // reconnects first
        assertFalse(sim.appliance(A3).isOn());
        assertTrue(proxy.connections() > before, "the controller connected anew");
    }

    @Test
    void uploadsResumeAfterADropWithoutAnyCommand() throws Exception {
        int before = proxy.connections();
        proxy.drop();
        // the controller notices while idle and keeps trying: wait for one of its tries to meet the dropped port
        long giveUp = System.nanoTime() + PATIENCE.toNanos();
        while (proxy.connections() <= before) {
            assertTrue(System.nanoTime() < giveUp, "an idle controller never tried to reconnect");
            Thread.sleep(10);
        }
        proxy.restore();
        sim.remoteControl(X10Address.of('A', 5), X10Function.ON);
        X10Event event = events.poll(PATIENCE.toSeconds(), TimeUnit.SECONDS);
        assertTrue(event != null, "the upload came through the reopened link");
        assertEquals(X10Function.ON, event.function());
    }

    @Test
    void aLinkThatWentSilentIsOpenedAgainWhenTheInterfaceIsBack() throws Exception {
        controller.on(A3);
        proxy.silence(); // the connection stays up, nothing passes: a crashed bridge nobody closed
        assertThrows(X10TimeoutException.class, () -> controller.off(A3));
        assertTrue(sim.appliance(A3).isOn());

        proxy.restore(); // new connections work; the silent one stays dead
        int before = proxy.connections();
        offOnceTheLinkServes();
        assertFalse(sim.appliance(A3).isOn());
        assertTrue(proxy.connections() > before, "the controller connected anew");
    }

    /**
     * Switches A3 off through a link that is back: the first try opens it anew. On a busy machine that try may
     * still fail: it times out because the relay and the simulator have not been scheduled yet, or it meets a
     * connection the controller opened while the link was still down. Either makes the next try open the link
     * anew, so the command is repeated until it goes through, within {@link #PATIENCE}.
     */
    private void offOnceTheLinkServes() {
        long giveUp = System.nanoTime() + PATIENCE.toNanos();
        while (true) {
            try {
                controller.off(A3);
                return;
            } catch (X10Exception e) {
                assertTrue(System.nanoTime() < giveUp, "the link never served again: " + e.getMessage());
            }
        }
    }

    @Test
    void theSimulatorBackOnTheSamePortIsFoundAgain() throws Exception {
        controller.on(A3);
        sim.close(); // the simulator ends, and with it the connection
        SimulatedCm11a again = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp,A3=appliance");
        try {
            proxy.retarget(port(again.listen(0))); // a new one, reached through the same port
            long giveUp = System.nanoTime() + PATIENCE.toNanos();
            while (true) {
                try {
                    controller.on(A3); // the first may still meet the old connection
                    break;
                } catch (X10Exception e) {
                    assertTrue(System.nanoTime() < giveUp, "never reconnected: " + e.getMessage());
                }
            }
            assertTrue(again.appliance(A3).isOn());
        } finally {
            again.close();
        }
    }
}
