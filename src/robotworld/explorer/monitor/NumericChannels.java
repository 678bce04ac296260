package robotworld.explorer.monitor;

import java.util.ArrayList;
import java.util.List;
import robotworld.core.BumperModule;
import robotworld.space.IntEntry;
import robotworld.space.Tuple;
import robotworld.xvsm.CallTuple;

/**
 * The numbers in a module's answer, one per channel, in the units the monitor shows everywhere: motor speeds as
 * -1..1 of full speed (they travel as per-mille), servo positions in degrees, IR distances in millimetres, bumper
 * contacts and appliance states as 0/1, lamp levels in percent. Used by the plots, the robot-frame view and the
 * console's compact mode.
 */
public final class NumericChannels {

    /**
     * One value of one channel.
     *
     * @param number the channel's number (motor, servo, sensor, bumper), 0 for a module with one value
     * @param value  in the module type's unit ({@link #unit})
     */
    public record Sample(int number, double value) {
    }

    private NumericChannels() {
    }

    /** The unit the values of {@code moduleClass} are shown in, for axis labels. */
    public static String unit(String moduleClass) {
        return switch (moduleClass) {
            case "MotorModule" -> "speed -1..1";
            case "ServoModule" -> "degrees";
            case "IRDistanceModule" -> "mm";
            case "BumperModule" -> "contact";
            case "X10LampModule" -> "level %";
            case "X10ApplianceModule" -> "on";
            default -> "value";
        };
    }

    /** What a channel is called: {@code motor 2}, {@code sensor 7}, {@code level}. */
    public static String channelName(String moduleClass, int number) {
        return switch (moduleClass) {
            case "MotorModule" -> "motor " + number;
            case "ServoModule" -> "servo " + number;
            case "IRDistanceModule" -> "sensor " + number;
            case "BumperModule" -> "bumper " + number;
            case "X10LampModule" -> "level";
            case "X10ApplianceModule" -> "on";
            default -> "channel " + number;
        };
    }

    /**
     * The samples in {@code answer} of a module of class {@code moduleClass}; none for an error answer or one it
     * cannot read.
     *
     * @param lamp the estimated state of an X10 lamp, updated by this answer (null for other modules)
     */
    public static List<Sample> of(String moduleClass, CallTuple answer, LampLevel lamp) {
        List<Sample> samples = new ArrayList<>();
        if (answer.is("ERROR")) {
            return samples;
        }
        try {
            switch (moduleClass) {
                case "MotorModule" -> samples.add(new Sample(answer.expectFields(2).intAt(0), answer.intAt(1) / 1000.0));
                case "ServoModule" -> samples.add(new Sample(answer.expectFields(2).intAt(0), answer.intAt(1)));
                case "BumperModule" -> bumpers(answer, samples);
                case "IRDistanceModule" -> distances(answer, samples);
                case "X10ApplianceModule" -> {
                    if (answer.function() instanceof IntEntry code) {
                        samples.add(new Sample(0, code.value() >= 0 ? 1 : 0));
                    }
                }
                case "X10LampModule" -> lamp(answer, lamp, samples);
                default -> {
                    // a module type the monitor does not know: no numbers it could name
                }
            }
        } catch (RuntimeException unreadable) {
            samples.clear();
        }
        return samples;
    }

    private static void bumpers(CallTuple answer, List<Sample> samples) {
        answer.expectFields(1);
        if (answer.is("getAllBumper")) {
            int mask = answer.intAt(0);
            for (int bumper = 1; bumper <= BumperModule.BUMPERS; bumper++) {
                samples.add(new Sample(bumper, (mask >> (bumper - 1) & 1)));
            }
        } else if (answer.is("getSingleBumper")) {
            Tuple pair = answer.tupleAt(0);
            samples.add(new Sample((int) pair.longAt(0), pair.longAt(1) != 0 ? 1 : 0));
        }
    }

    private static void distances(CallTuple answer, List<Sample> samples) {
        answer.expectFields(1);
        switch (answer.functionText()) {
            case "getAllSensors" -> {
                String[] parts = answer.stringAt(0).strip().split("\\s+");
                for (int i = 0; i < parts.length; i++) {
                    samples.add(new Sample(i + 1, Integer.parseInt(parts[i])));
                }
            }
            case "getSingleSensor", "getSingleSensor_Cached" -> {
                Tuple pair = answer.tupleAt(0);
                samples.add(new Sample((int) pair.longAt(0), pair.longAt(1)));
            }
            default -> {
                // raw readings (getAllSensors_ByteRep) are not distances
            }
        }
    }

    private static void lamp(CallTuple answer, LampLevel lamp, List<Sample> samples) {
        if (lamp == null) {
            return;
        }
        int change = answer.expectFields(1).intAt(0);
        switch (answer.functionText()) {
            case "on" -> lamp.on();
            case "off" -> lamp.off();
            case "brighten" -> lamp.brighten(change);
            case "dim" -> lamp.dim(change);
            default -> {
                return;
            }
        }
        samples.add(new Sample(0, lamp.isOn() ? lamp.level() : 0));
    }
}
