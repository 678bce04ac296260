package robotworld.bus;

/** The module bus acceptance over {@code tcp://}. */
class ModuleBusOverTcpTest extends ModuleBusContract {

    @Override
    BusRig connect(String configXml, BusTiming timing) throws Exception {
        return BusRig.tcp(configXml, timing);
    }
}
