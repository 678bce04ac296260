package robotworld.bus;

/** The module bus acceptance through a socat pty pair, jSerialComm on both ends. */
class ModuleBusOverPtyTest extends ModuleBusContract {

    @Override
    BusRig connect(String configXml, BusTiming timing) throws Exception {
        return BusRig.pty(configXml, timing);
    }
}
