package robotworld.bus;

/** The module answered with a correct CRC but not what the request asks for (wrong function, altered echo). */
public class BusProtocolException extends BusException {

    public BusProtocolException(String port, int address, String message) {
        super(port, address, message);
    }
}
