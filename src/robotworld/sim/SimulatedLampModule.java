package robotworld.sim;

import robotworld.x10.DimSteps;
import robotworld.x10.X10Address;
import robotworld.x10.X10Constants;
import robotworld.x10.X10Function;

/**
 * A simulated lamp module (e.g. LM465). Brightness is kept in the 22 X10 steps. Like the real module it goes to
 * full brightness when switched on from off, keeps its level when switched on while on, and when off it first
 * comes on at full brightness before a dim or bright is applied. Preset Dim (level 0..31) and extended code 0x31
 * (preset dim, data 0..63) set the level directly.
 */
public final class SimulatedLampModule extends SimulatedX10Module {

    private static final int EXTENDED_PRESET_DIM = 0x31;
    private static final int PRESET_LEVELS = 63;

    private int level = X10Constants.DIM_STEPS_FULL_RANGE;

    public SimulatedLampModule(X10Address address) {
        super(address);
    }

    @Override
    public Kind kind() {
        return Kind.LAMP;
    }

    /** Brightness when on, in steps 0..22 (22 = full). */
    public synchronized int level() {
        return level;
    }

    /** Brightness in percent: 0 when off, otherwise the level as a percentage of full brightness. */
    public synchronized int brightnessPercent() {
        return isOn() ? DimSteps.toPercent(level) : 0;
    }

    @Override
    synchronized void apply(X10Function function, int dimSteps) {
        switch (function) {
            case ON, ALL_LIGHTS_ON -> switchOn();
            case OFF, ALL_UNITS_OFF, ALL_LIGHTS_OFF -> setOn(false);
            case DIM -> {
                switchOn();
                level = Math.max(0, level - dimSteps);
            }
            case BRIGHT -> {
                switchOn();
                level = Math.min(X10Constants.DIM_STEPS_FULL_RANGE, level + dimSteps);
            }
            default -> {
                // hail, status and preset functions leave a plain lamp module as it is
            }
        }
    }

    private void switchOn() {
        if (!isOn()) {
            level = X10Constants.DIM_STEPS_FULL_RANGE;
            setOn(true);
        }
    }

    /** Preset Dim: the level of 31 becomes the nearest of the 22 steps; level 0 switches the lamp off. */
    @Override
    synchronized void applyPresetDim(int presetLevel) {
        level = Math.round(presetLevel * (float) X10Constants.DIM_STEPS_FULL_RANGE / 31);
        setOn(level > 0);
    }

    @Override
    synchronized void applyExtended(int data, int command) {
        if (command == EXTENDED_PRESET_DIM) {
            level = Math.round((data & 0x3F) * (float) X10Constants.DIM_STEPS_FULL_RANGE / PRESET_LEVELS);
            setOn(level > 0);
        }
    }

    @Override
    synchronized boolean isDimmed() {
        return isOn() && level < X10Constants.DIM_STEPS_FULL_RANGE;
    }

    @Override
    public synchronized String toString() {
        return address() + " lamp " + (isOn() ? "on " + brightnessPercent() + "%" : "off");
    }
}
