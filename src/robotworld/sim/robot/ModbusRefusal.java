package robotworld.sim.robot;

/** A simulated module refuses a request with a Modbus exception code. */
final class ModbusRefusal extends Exception {

    private final int exceptionCode;

    ModbusRefusal(int exceptionCode, String why) {
        super(why);
        this.exceptionCode = exceptionCode;
    }

    int exceptionCode() {
        return exceptionCode;
    }
}
