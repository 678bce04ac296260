package robotworld.sim.robot;

import java.time.Duration;
import java.util.Map;

/** One simulated module as configured: common settings plus what its type needs. */
public sealed interface ModuleSpec {

    /** Address, identity and fault settings. */
    Common common();

    /** Builds the module in {@code world} with its fault switches. */
    SimModule build(World world, ModuleFaults faults);

    /**
     * Settings every module has.
     *
     * @param replyDelayMillis extra delay of every reply (slow module)
     * @param refuseWith Modbus exception code to refuse everything with, 0 for none
     * @param stopped report "not running" (run indicator 0x00) as status
     */
    record Common(int address, ModuleIdentity identity, boolean silent, double crcErrorRate, int replyDelayMillis,
            int refuseWith, boolean stopped) {

        /** Fault switches set as configured. */
        ModuleFaults faults(long seed) {
            return new ModuleFaults(seed).silent(silent).crcErrorRate(crcErrorRate)
                    .replyDelay(Duration.ofMillis(replyDelayMillis)).refuseWith(refuseWith).stopped(stopped);
        }
    }

    /** A motor module; {@code left}/{@code right} are the wheel channels (0 = not driving). */
    record Motor(Common common, int left, int right, double rampPerSecond) implements ModuleSpec {
        @Override
        public SimModule build(World world, ModuleFaults faults) {
            return new SimMotorModule(common.address(), common.identity(), faults, rampPerSecond, left, right);
        }
    }

    /** A servo module turning at {@code degreesPerSecond}. */
    record Servo(Common common, double degreesPerSecond) implements ModuleSpec {
        @Override
        public SimModule build(World world, ModuleFaults faults) {
            return new SimServoModule(common.address(), common.identity(), faults, degreesPerSecond);
        }
    }

    /** A bumper module with its mounted bumpers by number. */
    record Bumper(Common common, Map<Integer, SimBumperModule.Mount> mounts) implements ModuleSpec {
        @Override
        public SimModule build(World world, ModuleFaults faults) {
            return new SimBumperModule(common.address(), common.identity(), faults, world, mounts);
        }
    }

    /** An IR distance module with its sensors' angles by number and their range in mm. */
    record IRDistance(Common common, Map<Integer, Double> angles, int range) implements ModuleSpec {
        @Override
        public SimModule build(World world, ModuleFaults faults) {
            return new SimIRDistanceModule(common.address(), common.identity(), faults, world, angles, range);
        }
    }
}
