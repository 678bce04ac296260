package robotworld.x10;

/** The sixteen X10 functions with their 4-bit codes. */
public enum X10Function {
    ALL_UNITS_OFF(X10Constants.FUNCTION_ALL_UNITS_OFF, "All Units Off"),
    ALL_LIGHTS_ON(X10Constants.FUNCTION_ALL_LIGHTS_ON, "All Lights On"),
    ON(X10Constants.FUNCTION_ON, "On"),
    OFF(X10Constants.FUNCTION_OFF, "Off"),
    DIM(X10Constants.FUNCTION_DIM, "Dim"),
    BRIGHT(X10Constants.FUNCTION_BRIGHT, "Bright"),
    ALL_LIGHTS_OFF(X10Constants.FUNCTION_ALL_LIGHTS_OFF, "All Lights Off"),
    EXTENDED_CODE(X10Constants.FUNCTION_EXTENDED_CODE, "Extended Code"),
    HAIL_REQUEST(X10Constants.FUNCTION_HAIL_REQUEST, "Hail Request"),
    HAIL_ACKNOWLEDGE(X10Constants.FUNCTION_HAIL_ACKNOWLEDGE, "Hail Acknowledge"),
    PRESET_DIM_1(X10Constants.FUNCTION_PRESET_DIM_1, "Preset Dim 1"),
    PRESET_DIM_2(X10Constants.FUNCTION_PRESET_DIM_2, "Preset Dim 2"),
    EXTENDED_DATA_TRANSFER(X10Constants.FUNCTION_EXTENDED_DATA_TRANSFER, "Extended Data Transfer"),
    STATUS_ON(X10Constants.FUNCTION_STATUS_ON, "Status On"),
    STATUS_OFF(X10Constants.FUNCTION_STATUS_OFF, "Status Off"),
    STATUS_REQUEST(X10Constants.FUNCTION_STATUS_REQUEST, "Status Request");

    private static final X10Function[] BY_CODE = new X10Function[16];

    static {
        for (X10Function function : values()) {
            BY_CODE[function.code] = function;
        }
    }

    private final int code;
    private final String label;

    X10Function(int code, String label) {
        this.code = code;
        this.label = label;
    }

    /** The 4-bit function code. */
    public int code() {
        return code;
    }

    /** Whether the number of dim steps in the header means something for this function. */
    public boolean usesDimSteps() {
        return this == DIM || this == BRIGHT;
    }

    /** Whether the function acts on every unit of a house rather than the addressed ones. */
    public boolean isHouseWide() {
        return this == ALL_UNITS_OFF || this == ALL_LIGHTS_ON || this == ALL_LIGHTS_OFF;
    }

    /** The function with 4-bit code {@code code} (only the low nibble counts). */
    public static X10Function ofCode(int code) {
        return BY_CODE[code & 0x0F];
    }

    /** The name as X10 documents write it, e.g. "All Lights Off". */
    @Override
    public String toString() {
        return label;
    }
}
