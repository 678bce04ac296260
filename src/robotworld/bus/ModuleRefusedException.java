package robotworld.bus;

import robotworld.bus.modbus.ExceptionCodes;

/** The module answered with a Modbus exception response: it understood the request and refused it. */
public class ModuleRefusedException extends BusException {

    private final int functionCode;
    private final int exceptionCode;

    public ModuleRefusedException(String port, int address, String message, int functionCode, int exceptionCode) {
        super(port, address, message);
        this.functionCode = functionCode;
        this.exceptionCode = exceptionCode;
    }

    /** The function code of the refused request (without the exception bit). */
    public int functionCode() {
        return functionCode;
    }

    /** The Modbus exception code, e.g. 2 for "illegal data address"; see {@link ExceptionCodes}. */
    public int exceptionCode() {
        return exceptionCode;
    }
}
