package robotworld.bus.modbus;

/** The Modbus function codes this project uses, with readable names for messages. */
public final class FunctionCodes {

    public static final int READ_COILS = 0x01;
    public static final int READ_DISCRETE_INPUTS = 0x02;
    public static final int READ_HOLDING_REGISTERS = 0x03;
    public static final int READ_INPUT_REGISTERS = 0x04;
    public static final int WRITE_SINGLE_COIL = 0x05;
    public static final int WRITE_SINGLE_REGISTER = 0x06;
    public static final int DIAGNOSTICS = 0x08;
    public static final int WRITE_MULTIPLE_COILS = 0x0F;
    public static final int WRITE_MULTIPLE_REGISTERS = 0x10;
    public static final int REPORT_SERVER_ID = 0x11;
    public static final int ENCAPSULATED_INTERFACE = 0x2B;

    /** Diagnostics sub-function 0x0000: the module returns the request unaltered. */
    public static final int DIAGNOSTICS_RETURN_QUERY_DATA = 0x0000;
    /** MEI type of Read Device Identification within function 0x2B. */
    public static final int MEI_READ_DEVICE_ID = 0x0E;
    /** The bit a module sets in the function code of an exception response. */
    public static final int EXCEPTION_BIT = 0x80;

    private FunctionCodes() {
    }

    /** A readable name for messages, e.g. "read discrete inputs (0x02)". */
    public static String name(int functionCode) {
        String name = switch (functionCode & 0x7F) {
            case READ_COILS -> "read coils";
            case READ_DISCRETE_INPUTS -> "read discrete inputs";
            case READ_HOLDING_REGISTERS -> "read holding registers";
            case READ_INPUT_REGISTERS -> "read input registers";
            case WRITE_SINGLE_COIL -> "write single coil";
            case WRITE_SINGLE_REGISTER -> "write single register";
            case DIAGNOSTICS -> "diagnostics";
            case WRITE_MULTIPLE_COILS -> "write multiple coils";
            case WRITE_MULTIPLE_REGISTERS -> "write multiple registers";
            case REPORT_SERVER_ID -> "report server ID";
            case ENCAPSULATED_INTERFACE -> "read device identification";
            default -> "function";
        };
        return String.format("%s (0x%02X)", name, functionCode & 0x7F);
    }
}
