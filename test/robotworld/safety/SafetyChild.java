package robotworld.safety;

import robotworld.bus.BumperModuleProxy;
import robotworld.bus.BusTiming;
import robotworld.bus.MotorModuleProxy;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.x10.CM11aController;
import robotworld.x10.X10LampModuleLocal;
import robotworld.xvsm.XVSMBumperModuleLocal;
import robotworld.xvsm.XVSMMotorModuleLocal;
import robotworld.xvsm.XVSMMotorModuleRemote;
import robotworld.xvsm.XVSMRuntime;
import robotworld.xvsm.XVSMX10LampModuleLocal;

/**
 * The programs whose ends the safety tests cause, run in JVMs of their own ({@link ChildProgram}). The main
 * method has the shape of a generated one: a runtime in try-with-resources, {@code runtime.failed(...)} for an
 * uncaught exception.
 *
 * <pre>
 * serve  return|throw|exit|wait  SPACE_URL BUS_PORT   the robot's program: serves SafetyBot/Motor and Bumper, sets
 *                                                     motors 1 and 2 to 0.45, prints READY, then returns, throws,
 *                                                     calls System.exit(3) or waits to be killed
 * serve  winch  SPACE_URL BUS_PORT                    as wait, and serves SafetyBot/Winch too (address 4), which it
 *                                                     does not command itself
 * serve  drive  SPACE_URL BUS_PORT                    as winch, and keeps setting motors 1 and 2 to 0.45 every 50 ms,
 *                                                     as a control loop does: prints REFUSED and the message at the
 *                                                     first refused command of a run, DRIVING when one is carried
 *                                                     out again
 * room SPACE_URL X10_PORT                             the room's program: serves SafetyRoom/Lamp, switches it on,
 *                                                     prints READY, waits
 * command SPACE_URL SPEED [GO_FILE]                   a remote commander: sets motors 1 and 2 of SafetyBot/Motor
 *                                                     through the space, prints READY, waits to be killed; with
 *                                                     GO_FILE, once that file exists, commands motor 1 again and
 *                                                     prints TOLD (refused) or CARRIED (not), then once more:
 *                                                     AGAIN
 * </pre>
 */
public final class SafetyChild {

    private SafetyChild() {
    }

    public static void main(String[] args) throws Exception {
        if (args[0].equals("command")) {
            command(args[1], Double.parseDouble(args[2]), args.length > 3 ? java.nio.file.Path.of(args[3]) : null);
            return;
        }
        if (args[0].equals("room")) {
            room(args[1], args[2]);
            return;
        }
        String mode = args[1];
        try (XVSMRuntime runtime = XVSMRuntime.connect(args[2], "robot-pc")) {
            try {
                RS485Bus bus = runtime.own(new RS485Bus(args[3], SerialSettings.eightNoneOne(115_200),
                        BusTiming.defaults().withFrameGap(java.time.Duration.ZERO)));
                XVSMMotorModuleLocal motor = runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT,
                        SafetyRig.MOTOR, new MotorModuleProxy(bus, 1, SafetyRig.MOTOR)));
                runtime.own(new XVSMBumperModuleLocal(runtime, SafetyRig.ROBOT, SafetyRig.BUMPER,
                        new BumperModuleProxy(bus, 2, SafetyRig.BUMPER)));
                if (mode.equals("winch") || mode.equals("drive")) {
                    runtime.own(new XVSMMotorModuleLocal(runtime, SafetyRig.ROBOT, SafetyRig.WINCH,
                            new MotorModuleProxy(bus, 4, SafetyRig.WINCH)));
                }
                motor.setMotor(1, 0.45);
                motor.setMotor(2, 0.45);
                System.out.println("READY " + runtime.programId());
                System.out.flush();
                switch (mode) {
                    case "return" -> {
                        // the program ends normally: the runtime's close stops the motors
                    }
                    case "throw" -> throw new IllegalStateException("the control program failed on purpose");
                    case "exit" -> System.exit(3);
                    case "wait", "winch" -> runtime.serveUntilStopped();
                    case "drive" -> drive(motor);
                    default -> throw new IllegalArgumentException("unknown mode " + mode);
                }
            } catch (Throwable failure) {
                runtime.failed(failure);
                throw failure;
            }
        }
    }

    /** A control loop that keeps driving and says when its commands are refused and when they are carried again. */
    private static void drive(XVSMMotorModuleLocal motor) throws InterruptedException {
        boolean refused = false;
        while (true) {
            try {
                motor.setMotor(1, 0.45);
                motor.setMotor(2, 0.45);
                if (refused) {
                    refused = false;
                    System.out.println("DRIVING");
                    System.out.flush();
                }
            } catch (robotworld.xvsm.ActuatorStoppedException told) {
                if (!refused) {
                    refused = true;
                    System.out.println("REFUSED " + told.getMessage());
                    System.out.flush();
                }
            }
            Thread.sleep(50);
        }
    }

    private static void room(String spaceUrl, String x10Port) throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(spaceUrl, "room-pc")) {
            CM11aController x10 = runtime.own(CM11aController.open(x10Port));
            XVSMX10LampModuleLocal lamp = runtime.own(new XVSMX10LampModuleLocal(runtime, SafetyRig.ROOM,
                    SafetyRig.LAMP, new X10LampModuleLocal(x10, 'A', 1)));
            lamp.on();
            System.out.println("READY " + runtime.programId());
            System.out.flush();
            runtime.serveUntilStopped();
        }
    }

    private static void command(String spaceUrl, double speed, java.nio.file.Path go) throws Exception {
        try (XVSMRuntime runtime = XVSMRuntime.connect(spaceUrl, "laptop")) {
            XVSMMotorModuleRemote motor = runtime.own(new XVSMMotorModuleRemote(runtime, SafetyRig.ROBOT,
                    SafetyRig.MOTOR));
            motor.setCallTimeout(java.time.Duration.ofSeconds(30));
            motor.setMotor(1, speed);
            motor.setMotor(2, speed);
            System.out.println("READY " + runtime.programId());
            System.out.flush();
            if (go == null) {
                Thread.sleep(Long.MAX_VALUE);
            }
            while (!java.nio.file.Files.exists(go)) {
                Thread.sleep(10);
            }
            try {
                motor.setMotor(1, speed);
                System.out.println("CARRIED");
            } catch (robotworld.xvsm.ActuatorStoppedException told) {
                System.out.println("TOLD " + told.getMessage());
            }
            motor.setMotor(1, speed);
            System.out.println("AGAIN");
            System.out.flush();
            Thread.sleep(Long.MAX_VALUE);
        }
    }
}
