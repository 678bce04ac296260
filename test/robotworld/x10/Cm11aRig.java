package robotworld.x10;

import java.io.IOException;
import robotworld.bus.JSerialCommLink;
import robotworld.bus.SerialLink;
import robotworld.bus.SocatPty;
import robotworld.sim.Cm11aTiming;
import robotworld.sim.SimulatedCm11a;

/**
 * A simulated CM11A and a controller connected to it over TCP or over a socat pty pair (jSerialComm on both
 * ends). Closing the rig closes everything it started.
 */
final class Cm11aRig implements AutoCloseable {

    /** How the controller reaches the simulator. */
    enum Transport { TCP, PTY }

    final SimulatedCm11a sim;
    final CM11aController controller;
    private final SocatPty pty;

    private Cm11aRig(SimulatedCm11a sim, CM11aController controller, SocatPty pty) {
        this.sim = sim;
        this.controller = controller;
        this.pty = pty;
    }

    /** Starts the simulator (already set up by the caller) and connects a controller to it. */
    static Cm11aRig connect(Transport transport, SimulatedCm11a sim, CM11aConfig config) throws Exception {
        if (transport == Transport.TCP) {
            String port = sim.listen(0);
            return new Cm11aRig(sim, CM11aController.open(port, config), null);
        }
        SocatPty pty = SocatPty.start();
        try {
            SerialLink deviceEnd = new JSerialCommLink(pty.b().toString(), X10Constants.CM11A_SERIAL);
            deviceEnd.open();
            sim.attach(deviceEnd);
            return new Cm11aRig(sim, CM11aController.open(pty.a().toString(), config), pty);
        } catch (IOException | RuntimeException e) {
            pty.close();
            throw e;
        }
    }

    /** A fast simulator with a lamp at A1 and appliances at A3 and B6. */
    static SimulatedCm11a fastSim() {
        return SimulatedCm11a.withDevices(Cm11aTiming.fast(), "A1=lamp,A3=appliance,B6=appliance,O1=lamp");
    }

    /** No pauses; timeouts that a busy machine does not run out (tests of the timeouts set their own). */
    static CM11aConfig fastConfig() {
        return CM11aConfig.defaults().forFastSimulator();
    }

    @Override
    public void close() throws IOException {
        controller.close();
        sim.close();
        if (pty != null) {
            pty.close();
        }
    }
}
