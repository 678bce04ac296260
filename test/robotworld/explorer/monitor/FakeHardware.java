package robotworld.explorer.monitor;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import robotworld.core.BumperModule;
import robotworld.core.IRDistanceModule;
import robotworld.core.MotorModule;
import robotworld.core.ServoModule;
import robotworld.core.X10ApplianceModule;
import robotworld.core.X10LampModule;

/** In-memory modules: what the monitor sees does not depend on real hardware, only on the space. */
final class FakeHardware {

    private FakeHardware() {
    }

    static final class Appliance implements X10ApplianceModule {
        final AtomicBoolean on = new AtomicBoolean();

        @Override
        public void on() {
            on.set(true);
        }

        @Override
        public void off() {
            on.set(false);
        }
    }

    static final class Lamp implements X10LampModule {
        @Override
        public void brighten(int level) {
        }

        @Override
        public void dim(int level) {
        }

        @Override
        public void on() {
        }

        @Override
        public void off() {
        }
    }

    static final class Motor implements MotorModule {
        @Override
        public void setMotor(int motor, double speed) {
        }

        @Override
        public void setMotorQuiet(int motor, double speed) {
        }
    }

    static final class Servo implements ServoModule {
        @Override
        public void setServo(int servoNr, int position) {
        }

        @Override
        public void setServoQuiet(int servoNr, int position) {
        }
    }

    /** Bumpers 4 and 6 touch something; {@link #failing} makes the next reads fail. */
    static final class Bumper implements BumperModule {
        final AtomicBoolean failing = new AtomicBoolean();
        final AtomicInteger mask = new AtomicInteger(1 << 3 | 1 << 5);
        final java.util.concurrent.atomic.AtomicReference<String> message =
                new java.util.concurrent.atomic.AtomicReference<>("bumper module does not answer");

        /** While set, calls wait for it to open (at most 20 s): a call under way. */
        final java.util.concurrent.atomic.AtomicReference<java.util.concurrent.CountDownLatch> gate =
                new java.util.concurrent.atomic.AtomicReference<>();

        @Override
        public int getAllBumper() {
            java.util.concurrent.CountDownLatch closed = gate.get();
            if (closed != null) {
                try {
                    closed.await(20, java.util.concurrent.TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            if (failing.get()) {
                throw new IllegalStateException(message.get());
            }
            return mask.get();
        }

        @Override
        public boolean getSingleBumper(int bumperNumber) {
            return (getAllBumper() & 1 << bumperNumber - 1) != 0;
        }
    }

    static final class IR implements IRDistanceModule {
        static final int[] DISTANCES = {120, 350, 800, 800, 640, 800, 75};

        @Override
        public String getAllSensors() {
            StringBuilder text = new StringBuilder();
            for (int distance : DISTANCES) {
                text.append(text.isEmpty() ? "" : " ").append(distance);
            }
            return text.toString();
        }

        @Override
        public int[] getAllSensors_ByteRep() {
            return new int[] {255, 143, 0, 0, 30, 0, 255};
        }

        @Override
        public int getSingleSensor_Cached(int sensorNr) {
            return DISTANCES[sensorNr - 1];
        }

        @Override
        public int getSingleSensor(int sensorNr) {
            return DISTANCES[sensorNr - 1];
        }
    }
}
