package robotworld.bus.modbus;

/** Modbus exception codes a module sends back when it refuses a request. */
public final class ExceptionCodes {

    public static final int ILLEGAL_FUNCTION = 0x01;
    public static final int ILLEGAL_DATA_ADDRESS = 0x02;
    public static final int ILLEGAL_DATA_VALUE = 0x03;
    public static final int SERVER_DEVICE_FAILURE = 0x04;
    public static final int SERVER_DEVICE_BUSY = 0x06;

    private ExceptionCodes() {
    }

    /** A readable name, e.g. "illegal data address". */
    public static String name(int code) {
        return switch (code) {
            case ILLEGAL_FUNCTION -> "illegal function";
            case ILLEGAL_DATA_ADDRESS -> "illegal data address";
            case ILLEGAL_DATA_VALUE -> "illegal data value";
            case SERVER_DEVICE_FAILURE -> "server device failure";
            case 0x05 -> "acknowledge";
            case SERVER_DEVICE_BUSY -> "server device busy";
            case 0x08 -> "memory parity error";
            case 0x0A -> "gateway path unavailable";
            case 0x0B -> "gateway target failed to respond";
            default -> "unknown exception";
        };
    }
}
