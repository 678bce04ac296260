package robotworld.sim;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import robotworld.bus.InvalidPortNameException;
import robotworld.bus.SocatPty;

/** What {@code rwe simulate cm11a} starts. */
class Cm11aSimulatorRunnerTest {

    @Test
    void listensOnLoopbackAndDescribesItself() throws Exception {
        Cm11aSimulatorRunner.Started started =
                Cm11aSimulatorRunner.start("tcp://127.0.0.1:0", "A1=lamp,A3=appliance", Cm11aTiming.fast(), false);
        try (RawHost host = new RawHost(started.portName())) {
            assertTrue(started.describe().matches("simulated CM11A on tcp://127\\.0\\.0\\.1:\\d+ \\(fast timing\\): "
                    + "A1 lamp, A3 appliance"), started.describe());
            host.send("04 62").expect("66").send("00").expect("55");
        } finally {
            started.sim().close();
        }
    }

    @Test
    void startsInPowerFailOnRequest() throws Exception {
        Cm11aSimulatorRunner.Started started =
                Cm11aSimulatorRunner.start("tcp://localhost:0", "A1=lamp", Cm11aTiming.fast(), true);
        try (RawHost host = new RawHost(started.portName())) {
            host.expect("A5");
        } finally {
            started.sim().close();
        }
    }

    @Test
    void servesASerialDeviceSuchAsAPty() throws Exception {
        try (SocatPty pty = SocatPty.start()) {
            Cm11aSimulatorRunner.Started started =
                    Cm11aSimulatorRunner.start(pty.b().toString(), "A3=appliance", Cm11aTiming.fast(), false);
            try (RawHost host = new RawHost(pty.a().toString())) {
                host.send("04 62").expect("66").send("00").expect("55");
            } finally {
                started.sim().close();
            }
        }
    }

    @Test
    void refusesToListenBeyondLoopbackAndBadInput() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Cm11aSimulatorRunner.start("tcp://192.0.2.1:5000", "", Cm11aTiming.fast(), false));
        assertTrue(e.getMessage().contains("127.0.0.1 only"), e.getMessage());
        assertThrows(InvalidPortNameException.class,
                () -> Cm11aSimulatorRunner.start("tcp://127.0.0.1", "", Cm11aTiming.fast(), false));
        assertThrows(IllegalArgumentException.class,
                () -> Cm11aSimulatorRunner.start("tcp://127.0.0.1:0", "A1=toaster", Cm11aTiming.fast(), false));
    }
}
