package robotworld.bus.modbus;

/** A response PDU that passed its CRC but does not have the layout its function code promises. */
public class MalformedPduException extends RuntimeException {

    public MalformedPduException(String message) {
        super(message);
    }
}
