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
    private static final CM11aConfig CONFIG = Cm11aRig.fastConfig().withChecksumTimeout(Duration.ofMillis(200))
            .withDeadInterfaceTimeout(Duration.ofMillis(600));

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
        assertTrue((System.nanoTime() - start) / 1_000_000 < CONFIG.deadDeviceTimeout().toMillis() + 2_000,
                "failed within its bound");
        assertTrue(lost.getMessage().contains(proxy.portName()), lost.getMessage());
        assertThrows(X10Exception.class, () -> controller.off(A3), "still down");

        proxy.restore();
        controller.off(A3); // reconnects first
        assertFalse(sim.appliance(A3).isOn());
    }

    @Test
    void uploadsResumeAfterADropWithoutAnyCommand() throws Exception {
        proxy.drop();
        Thread.sleep(300); // the controller notices while idle and keeps trying
        proxy.restore();
        sim.remoteControl(X10Address.of('A', 5), X10Function.ON);
        X10Event event = events.poll(10, TimeUnit.SECONDS);
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
        controller.off(A3);
        assertFalse(sim.appliance(A3).isOn());
        assertTrue(proxy.connections() > before, "the controller connected anew");
    }

    @Test
    void theSimulatorBackOnTheSamePortIsFoundAgain() throws Exception {
        controller.on(A3);
        sim.close(); // the simulator ends, and with it the connection
        SimulatedCm11a again = SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp,A3=appliance");
        try {
            proxy.retarget(port(again.listen(0))); // a new one, reached through the same port
            long giveUp = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
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
