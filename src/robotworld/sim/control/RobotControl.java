package robotworld.sim.control;

import static robotworld.sim.control.CommandWords.arguments;
import static robotworld.sim.control.CommandWords.decimal;
import static robotworld.sim.control.CommandWords.number;

import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import robotworld.sim.robot.ModuleFaults;
import robotworld.sim.robot.Pose;
import robotworld.sim.robot.Rect;
import robotworld.sim.robot.SimulatedRobot;

/**
 * The control commands of the simulated robot: move it, push obstacles into its arena or take them out, and make
 * a bus module fail or slow down (or the line echo, as some RS-485 adapters do).
 */
public final class RobotControl implements ControlCommands {

    private final SimulatedRobot robot;

    public RobotControl(SimulatedRobot robot) {
        this.robot = robot;
    }

    @Override
    public List<String> help() {
        return List.of(
                "pose   where the robot is: x y heading (mm, degrees)",
                "place X Y [HEADING]   puts the robot there",
                "obstacle X Y WIDTH HEIGHT   pushes a box into the arena (mm)",
                "remove-obstacle X Y WIDTH HEIGHT   takes that box out again",
                "modules   the bus modules and their faults",
                "fail ADDRESS silent|stopped|none   the module stops answering / reports 'not running' / is well",
                "fail ADDRESS crc RATE | corrupt N | refuse CODE | mute FUNCTION | answer-as ADDRESS   other faults",
                "slow ADDRESS MS   every reply of the module comes MS later (0: on time)",
                "trickle ADDRESS MS   the module sends its replies one byte every MS (0: as the line goes)",
                "echo on|off   the line echoes each request to the master, as an adapter without echo suppression");
    }

    @Override
    public String execute(List<String> words) {
        String name = words.get(0);
        switch (name) {
            case "pose" -> {
                arguments(words, 0, "pose");
                return pose(robot.pose());
            }
            case "place" -> {
                if (words.size() != 3 && words.size() != 4) {
                    throw new IllegalArgumentException("'place' takes 2 or 3 arguments: place X Y [HEADING]");
                }
                double heading = words.size() == 4 ? decimal(words.get(3), "heading") : robot.pose().heading();
                Pose target = new Pose(decimal(words.get(1), "x"), decimal(words.get(2), "y"), heading);
                robot.simulation().inspect(world -> {
                    world.place(target);
                    return null;
                });
                return pose(robot.pose());
            }
            case "obstacle", "remove-obstacle" -> {
                arguments(words, 4, name + " X Y WIDTH HEIGHT");
                Rect box = new Rect(decimal(words.get(1), "x"), decimal(words.get(2), "y"),
                        decimal(words.get(3), "width"), decimal(words.get(4), "height"));
                boolean changed = robot.simulation().inspect(world -> {
                    if (name.equals("obstacle")) {
                        world.addObstacle(box);
                        return true;
                    }
                    return world.removeObstacle(box);
                });
                if (!changed) {
                    throw new IllegalArgumentException("there is no obstacle " + box);
                }
                return robot.simulation().inspect(world -> world.obstacles().size()) + " obstacles";
            }
            case "modules" -> {
                arguments(words, 0, "modules");
                return robot.simulation().modules().values().stream().map(Object::toString)
                        .collect(Collectors.joining(", "));
            }
            case "slow" -> {
                arguments(words, 2, "slow ADDRESS MS");
                int millis = number(words.get(2), 0, 60_000, "delay (ms)");
                faults(words.get(1)).replyDelay(Duration.ofMillis(millis));
                return "address " + words.get(1) + " replies " + millis + " ms late";
            }
            case "fail" -> {
                if (words.size() < 3) {
                    throw new IllegalArgumentException("'fail' takes ADDRESS and a fault: fail 2 silent");
                }
                return fail(faults(words.get(1)), words.get(1), words.subList(2, words.size()));
            }
            case "trickle" -> {
                arguments(words, 2, "trickle ADDRESS MS");
                int millis = number(words.get(2), 0, 1_000, "gap (ms)");
                faults(words.get(1)).trickle(Duration.ofMillis(millis));
                return "address " + words.get(1) + " sends one byte every " + millis + " ms";
            }
            case "echo" -> {
                arguments(words, 1, "echo on|off");
                boolean on = onOff(words.get(1));
                robot.echoRequests(on);
                return "the line " + (on ? "echoes" : "does not echo") + " requests";
            }
            default -> throw new IllegalArgumentException("unknown command '" + name + "' (try help)");
        }
    }

    private static String fail(ModuleFaults faults, String address, List<String> fault) {
        String kind = fault.get(0).toLowerCase(Locale.ROOT);
        if (fault.size() == 1) {
            switch (kind) {
                case "silent" -> faults.silent(true);
                case "stopped" -> faults.stopped(true);
                case "none" -> faults.silent(false).stopped(false).crcErrorRate(0).corruptNextReplies(0).refuseWith(0)
                        .replyDelay(Duration.ZERO).trickle(Duration.ZERO).unmuteAll().answerAs(0);
                default -> throw new IllegalArgumentException("'" + kind + "' is not a fault: silent, stopped, none, "
                        + "crc RATE, corrupt N, refuse CODE, mute FUNCTION, answer-as ADDRESS");
            }
            return "address " + address + ": " + kind;
        }
        if (fault.size() != 2) {
            throw new IllegalArgumentException("'fail ADDRESS " + kind + "' takes one value");
        }
        String value = fault.get(1);
        switch (kind) {
            case "crc" -> {
                double rate = decimal(value, "CRC error rate");
                if (rate < 0 || rate > 1) {
                    throw new IllegalArgumentException("CRC error rate must be 0..1, not " + value);
                }
                faults.crcErrorRate(rate);
            }
            case "corrupt" -> faults.corruptNextReplies(number(value, 0, 1_000_000, "count"));
            case "refuse" -> faults.refuseWith(number(value, 0, 255, "exception code"));
            case "mute" -> faults.mute(value.toLowerCase(Locale.ROOT).startsWith("0x")
                    ? number(Integer.toString(Integer.parseInt(value.substring(2), 16)), 1, 127, "function code")
                    : number(value, 1, 127, "function code"));
            case "answer-as" -> faults.answerAs(number(value, 1, 247, "address"));
            default -> throw new IllegalArgumentException("'" + kind + "' is not a fault with a value: crc RATE, "
                    + "corrupt N, refuse CODE, mute FUNCTION, answer-as ADDRESS");
        }
        return "address " + address + ": " + kind + " " + value;
    }

    private ModuleFaults faults(String address) {
        int number = number(address, 1, 247, "address");
        if (robot.simulation().module(number) == null) {
            throw new IllegalArgumentException("no simulated module at address " + number + " (modules: "
                    + robot.simulation().modules().keySet() + ")");
        }
        return robot.faults(number);
    }

    private static boolean onOff(String text) {
        return switch (text.toLowerCase(Locale.ROOT)) {
            case "on" -> true;
            case "off" -> false;
            default -> throw new IllegalArgumentException("'" + text + "' is neither on nor off");
        };
    }

    private static String pose(Pose pose) {
        return String.format(Locale.ROOT, "%.1f %.1f %.1f", pose.x(), pose.y(), pose.heading());
    }
}
