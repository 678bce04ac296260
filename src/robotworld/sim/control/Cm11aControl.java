package robotworld.sim.control;

import static robotworld.sim.control.CommandWords.arguments;
import static robotworld.sim.control.CommandWords.number;

import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import robotworld.sim.SimulatedCm11a;
import robotworld.x10.HouseCode;
import robotworld.x10.X10Address;
import robotworld.x10.X10Function;

/**
 * The control commands of the simulated CM11A: power-line traffic from other transmitters (remote controls,
 * motion sensors), which the modules obey and the interface uploads to the host, and faults of the interface.
 */
public final class Cm11aControl implements ControlCommands {

    private final SimulatedCm11a sim;

    public Cm11aControl(SimulatedCm11a sim) {
        this.sim = sim;
    }

    @Override
    public List<String> help() {
        return List.of(
                "remote A5 on|off|FUNCTION   a remote control sends address and function (e.g. hail-request)",
                "dim A5 STEPS / bright A5 STEPS   a remote dims or brightens by 0..22 steps",
                "house A all-lights-off|all-lights-on|all-units-off   a house-wide function",
                "motion A5 / motion-clear A5   a motion sensor reports motion (On) or its end (Off)",
                "bad-checksums N   the next N checksums the interface sends are wrong",
                "power-fail   the interface lost power: it polls 0xA5 until the host sends the clock",
                "power-off / power-on   the interface goes dead (answers nothing) / comes back (then asks for the clock)",
                "status   the modules and whether the interface waits for its clock");
    }

    @Override
    public String execute(List<String> words) {
        String name = words.get(0);
        switch (name) {
            case "remote" -> {
                arguments(words, 2, "remote A5 on");
                X10Address address = address(words.get(1));
                X10Function function = function(words.get(2));
                sim.receiveFromPowerLine(address, function);
                return address + " " + function;
            }
            case "dim", "bright" -> {
                arguments(words, 2, name + " A5 STEPS");
                X10Address address = address(words.get(1));
                int steps = number(words.get(2), 0, 22, "steps");
                sim.receiveFromPowerLine(address, name.equals("dim") ? X10Function.DIM : X10Function.BRIGHT, steps);
                return address + " " + name + " " + steps;
            }
            case "house" -> {
                arguments(words, 2, "house A all-lights-off");
                HouseCode house = house(words.get(1));
                X10Function function = function(words.get(2));
                sim.receiveHouseFunction(house, function);
                return house + " " + function;
            }
            case "motion", "motion-clear" -> {
                arguments(words, 1, name + " A5");
                X10Address address = address(words.get(1));
                if (name.equals("motion")) {
                    sim.motionDetected(address);
                } else {
                    sim.motionCleared(address);
                }
                return address + (name.equals("motion") ? " On" : " Off");
            }
            case "bad-checksums" -> {
                arguments(words, 1, "bad-checksums N");
                int count = number(words.get(1), 0, 1000, "count");
                sim.injectBadChecksums(count);
                return "the next " + count + " checksums are wrong";
            }
            case "power-fail" -> {
                arguments(words, 0, "power-fail");
                sim.powerFail();
                return "polling 0xA5 until the clock comes";
            }
            case "power-off" -> {
                arguments(words, 0, "power-off");
                sim.powerOff();
                return "the interface answers nothing";
            }
            case "power-on" -> {
                arguments(words, 0, "power-on");
                sim.powerOn();
                return "back; polling 0xA5 until the clock comes";
            }
            case "status" -> {
                arguments(words, 0, "status");
                String modules = sim.modules().stream().map(Object::toString).collect(Collectors.joining(", "));
                return (modules.isEmpty() ? "no modules" : modules) + (sim.isPowerFailed() ? "; waiting for the clock"
                        : "");
            }
            default -> throw new IllegalArgumentException("unknown command '" + name + "' (try help)");
        }
    }

    private static X10Address address(String text) {
        try {
            return X10Address.parse(text.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("'" + text + "' is not an X10 address like A5 (A..P, 1..16)");
        }
    }

    private static HouseCode house(String text) {
        if (text.length() != 1) {
            throw new IllegalArgumentException("'" + text + "' is not a house code A..P");
        }
        try {
            return HouseCode.of(Character.toUpperCase(text.charAt(0)));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("'" + text + "' is not a house code A..P");
        }
    }

    private static X10Function function(String text) {
        String wanted = text.toUpperCase(Locale.ROOT).replace('-', '_');
        for (X10Function function : X10Function.values()) {
            if (function.name().equals(wanted)) {
                return function;
            }
        }
        throw new IllegalArgumentException("'" + text + "' is not an X10 function: " + java.util.Arrays
                .stream(X10Function.values()).map(f -> f.name().toLowerCase(Locale.ROOT).replace('_', '-'))
                .collect(Collectors.joining(", ")));
    }

}
