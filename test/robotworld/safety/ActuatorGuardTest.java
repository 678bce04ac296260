package robotworld.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** The guard's bookkeeping: admissions, notices, engagers, the end of the program, races and failed stops. */
class ActuatorGuardTest {

    /** A motor-like actuator: engaged while its speed is not 0; counts how often it was stopped. */
    private static final class FakeMotor implements Actuator {
        volatile int speed;
        final AtomicInteger stops = new AtomicInteger();
        volatile RuntimeException failure;

        @Override
        public String enterSafeState() {
            if (failure != null) {
                throw failure;
            }
            stops.incrementAndGet();
            speed = 0;
            return "speed 0";
        }

        @Override
        public boolean isEngaged() {
            return speed != 0;
        }
    }

    private final FakeMotor motor = new FakeMotor();
    private final List<StopRecord> told = new ArrayList<>();
    private final ActuatorGuard guard = new ActuatorGuard("Bot", "Motor", motor, "robot-pc#own",
            Duration.ofMillis(500), told::add);

    private void command(String commander, boolean canBeTold, int speed) {
        ActuatorGuard.Admission admission = guard.admit(commander, canBeTold);
        assertTrue(admission.admitted(), () -> "refused: " + admission.refusal());
        motor.speed = speed;
        guard.performed(commander, admission);
    }

    @Test
    void commandsAreAdmittedAndTheirCommandersKeepTheActuatorEngaged() {
        command("laptop#a", true, 300);
        command("robot-pc#own", true, 400);
        assertEquals(List.of("laptop#a"), guard.remoteEngagers(), "the serving program itself is not remote");
        command("laptop#a", true, 0);
        assertEquals(List.of(), guard.remoteEngagers(), "at rest, nobody keeps it engaged");
    }

    @Test
    void afterAStopEveryKnownCommanderIsToldOnceOnItsNextCall() {
        command("laptop#a", true, 300);
        command("desk#b", true, 0);
        StopRecord stop = guard.stop(StopCause.STOP_REQUEST, "asked by ops", null, "stop-1");
        assertEquals("speed 0", stop.action());
        assertEquals(List.of(stop), told);
        ActuatorGuard.Admission refused = guard.admit("laptop#a", true);
        assertFalse(refused.admitted());
        assertSame(stop, refused.refusal(), "the notice says what was done");
        assertTrue(guard.admit("laptop#a", true).admitted(), "told once: commands again");
        assertFalse(guard.admit("desk#b", true).admitted(), "every known commander is told");
        assertTrue(guard.admit("newcomer#c", true).admitted(), "a commander unknown before the stop is not");
    }

    @Test
    void aQuietCallCannotCarryTheNoticeSoItIsRefusedUntilAWaitingCallIsTold() {
        command("laptop#a", true, 300);
        guard.stop(StopCause.SPACE_LOST, "no space", null, null);
        assertFalse(guard.admit("laptop#a", false).admitted());
        assertFalse(guard.admit("laptop#a", false).admitted(), "still owed");
        assertFalse(guard.admit("laptop#a", true).admitted(), "told");
        assertTrue(guard.admit("laptop#a", false).admitted());
    }

    @Test
    void aStopForASilentCommanderIsOwedToTheEngagersOnly() {
        command("desk#b", true, 0);
        command("laptop#a", true, 300);
        StopRecord stop = guard.stop(StopCause.COMMANDER_SILENT, "laptop#a silent", "laptop#a", null);
        assertEquals("laptop#a", stop.commander());
        assertFalse(guard.admit("laptop#a", true).admitted());
        assertTrue(guard.admit("desk#b", true).admitted(), "its command had not engaged the motor");
    }

    @Test
    void onceTheProgramEndsEveryCommandIsRefused() {
        command("laptop#a", true, 300);
        StopRecord end = guard.stop(StopCause.SHUTDOWN, "Ctrl-C", null, null);
        assertTrue(guard.hasEnded());
        for (String commander : List.of("laptop#a", "robot-pc#own", "newcomer#c")) {
            ActuatorGuard.Admission admission = guard.admit(commander, true);
            assertFalse(admission.admitted(), commander);
            assertSame(end, admission.refusal());
        }
    }

    @Test
    void aCommandThatWasUnderWayDuringAStopCannotLeaveTheActuatorMoving() {
        ActuatorGuard.Admission admission = guard.admit("laptop#a", true);
        guard.stop(StopCause.STOP_REQUEST, "asked by ops", null, null);
        motor.speed = 300; // the command reaches the hardware after the stop did
        guard.performed("laptop#a", admission);
        assertEquals(0, motor.speed, "stopped once more");
        assertEquals(2, motor.stops.get());
        assertEquals(List.of(), guard.remoteEngagers());
    }

    @Test
    void aFailedStopSaysWhyKeepsTheActuatorEngagedAndIsRetriedAtMostEverySecond() {
        command("laptop#a", true, 300);
        motor.failure = new IllegalStateException("no reply from address 1");
        StopRecord stop = guard.stop(StopCause.COMMANDER_SILENT, "silent", "laptop#a", null);
        assertEquals("failed: no reply from address 1", stop.action());
        assertTrue(guard.isEngaged());
        assertEquals(List.of("laptop#a"), guard.remoteEngagers(), "still the reason to stop it");
        assertFalse(guard.mayRetryStop());
        motor.failure = null;
        assertEquals("speed 0", guard.stop(StopCause.STOP_REQUEST, "again", null, null).action());
        assertTrue(guard.mayRetryStop());
    }

    @Test
    void theCommandTimeoutHasALowerBound() {
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> guard.setCommandTimeout(Duration.ofMillis(10)));
        guard.setCommandTimeout(Duration.ofMillis(50));
        assertEquals(50, guard.commandTimeout().toMillis());
    }

    @Test
    void aHeldActuatorRefusesEveryCommandTellingWhyUntilReleased() {
        command("robot-pc#own", true, 450);
        guard.stop(StopCause.SPACE_LOST, "no contact with the space", null, null, true);
        for (int i = 0; i < 3; i++) {
            ActuatorGuard.Admission refused = guard.admit("robot-pc#own", true);
            assertFalse(refused.admitted(), "held: refused every time, not only once");
            assertTrue(refused.held());
            assertTrue(refused.advice().contains("reaches its space"), refused.advice());
        }
        assertFalse(guard.admit("newcomer#c", true).admitted(), "held for every commander, known or not");
        guard.release();
        assertTrue(guard.admit("robot-pc#own", true).admitted(), "told while held: obeyed once released");
    }

    @Test
    void aCommandUnderWayWhenTheActuatorIsHeldIsUndone() {
        ActuatorGuard.Admission admitted = guard.admit("robot-pc#own", true);
        assertTrue(admitted.admitted());
        guard.hold(new StopRecord(java.time.Instant.now(), "Bot", "Motor", StopCause.SPACE_LOST, "no space",
                "held in its safe state", "robot-pc#own", null, null));
        motor.speed = 450; // the command reaches the hardware after the hold
        guard.performed("robot-pc#own", admitted);
        assertEquals(0, motor.speed, "back in its safe state");
    }

    @Test
    void aStopStillOwedIsToldAfterTheHoldWhenTheCommanderDidNotCallMeanwhile() {
        command("laptop#a", true, 300);
        StopRecord stop = guard.stop(StopCause.SPACE_LOST, "no space", null, null);
        guard.hold(stop);
        guard.release();
        ActuatorGuard.Admission told = guard.admit("laptop#a", true);
        assertFalse(told.admitted());
        assertFalse(told.held());
        assertEquals("command it again to move it", told.advice());
        assertTrue(guard.admit("laptop#a", true).admitted());
    }
}
