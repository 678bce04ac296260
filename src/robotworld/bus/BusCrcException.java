package robotworld.bus;

/** Every reply that came back was corrupted (wrong CRC or cut short): a noisy line or a broken module. */
public class BusCrcException extends BusException {

    public BusCrcException(String port, int address, String message) {
        super(port, address, message);
    }
}
