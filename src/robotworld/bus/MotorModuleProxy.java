package robotworld.bus;

import robotworld.bus.modbus.Pdus;
import robotworld.core.ModuleArguments;
import robotworld.core.MotorModule;

/**
 * A motor module on the bus. Register map: holding register {@code n-1} = speed of motor {@code n} in signed
 * per-mille of full speed (-1000..1000); discrete input {@code n-1} = motor {@code n} still ramping.
 */
public class MotorModuleProxy extends ModuleProxy implements MotorModule {

    public MotorModuleProxy(RS485Bus bus, int address) {
        this(bus, address, null);
    }

    public MotorModuleProxy(RS485Bus bus, int address, String name) {
        super("MotorModule", bus, address, name);
    }

    @Override
    public void setMotor(int motor, double speed) {
        ModuleArguments.motorNumber(motor);
        bus().writeRegister(address(), motor - 1, ModuleArguments.speedToPerMille(speed) & 0xFFFF);
    }

    @Override
    public void setMotorQuiet(int motor, double speed) {
        ModuleArguments.motorNumber(motor);
        bus().writeRegisterQuietly(address(), motor - 1, ModuleArguments.speedToPerMille(speed) & 0xFFFF);
    }

    /** The speed the module was last set to, -1.0..1.0 (beyond the thesis interface: for monitors and tests). */
    public double getMotor(int motor) {
        ModuleArguments.motorNumber(motor);
        return Pdus.signed(bus().readHoldingRegisters(address(), motor - 1, 1)[0]) / 1000.0;
    }

    /** Whether the motor is still ramping towards its set speed. */
    public boolean isRamping(int motor) {
        ModuleArguments.motorNumber(motor);
        return bus().readDiscreteInputs(address(), motor - 1, 1)[0];
    }
}
