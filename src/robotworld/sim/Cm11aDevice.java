package robotworld.sim;

import java.time.DayOfWeek;
import java.time.Duration;
import java.time.LocalTime;
import java.util.Optional;
import robotworld.x10.CM11aClock;
import robotworld.x10.CM11aStatus;
import robotworld.x10.HouseCode;

/**
 * The state inside a simulated CM11A that outlives a serial session: the power line and its modules, the upload
 * queue, the power-fail flag, the clock, pending checksum faults and the wire log. Thread-safe.
 */
final class Cm11aDevice {

    private static final int FIRMWARE_REVISION = 1;
    private static final int BATTERY_TIMER_RESET = 0xFFFF;

    final PowerLine powerLine = new PowerLine();
    final UploadQueue uploads = new UploadQueue();
    final WireLog wire = new WireLog();
    private boolean powerFailed;
    private boolean poweredOff;
    private int badChecksumsToSend;
    private CM11aClock clock;
    private long clockSetAt = System.nanoTime();
    private int batteryTimer = BATTERY_TIMER_RESET;
    private HouseCode monitoredHouse = HouseCode.A;

    synchronized boolean isPowerFailed() {
        return powerFailed;
    }

    /** Power lost and back: the interface forgets addressing and asks for the clock. */
    synchronized void powerFail() {
        powerFailed = true;
        powerLine.clearAddressing();
    }

    synchronized boolean isPoweredOff() {
        return poweredOff;
    }

    /** Unplugged from the mains: the interface answers nothing, its modules keep their state. */
    synchronized void powerOff() {
        poweredOff = true;
    }

    /** Plugged in again: like any return of power, the interface asks for the clock first. */
    synchronized void powerOn() {
        if (poweredOff) {
            poweredOff = false;
            powerFail();
        }
    }

    synchronized void injectBadChecksums(int count) {
        if (count < 0) {
            throw new IllegalArgumentException("count must be zero or more");
        }
        badChecksumsToSend += count;
    }

    /** The checksum to send for {@code sum}: right, or wrong if a fault is pending (never a poll value). */
    synchronized int checksumToSend(int sum) {
        if (badChecksumsToSend == 0) {
            return sum;
        }
        badChecksumsToSend--;
        int wrong = (sum + 1) & 0xFF;
        while (wrong == 0x5A || wrong == 0xA5) {
            wrong = (wrong + 1) & 0xFF;
        }
        return wrong;
    }

    /** The host has set the clock: the power failure is over. */
    synchronized void clockSet(CM11aClock received) {
        clock = received;
        clockSetAt = System.nanoTime();
        monitoredHouse = received.monitoredHouse();
        powerFailed = false;
        if ((received.flags() & CM11aClock.CLEAR_BATTERY_TIMER) != 0) {
            batteryTimer = 0;
        }
        if ((received.flags() & CM11aClock.CLEAR_MONITORED_STATUS) != 0) {
            powerLine.clearAddressing();
        }
    }

    synchronized Optional<CM11aClock> lastClock() {
        return Optional.ofNullable(clock);
    }

    /** The 14-byte status as the interface would report it now. */
    synchronized CM11aStatus status() {
        Duration elapsed = Duration.ofNanos(System.nanoTime() - clockSetAt);
        LocalTime base = clock == null ? LocalTime.MIDNIGHT : clock.time();
        long elapsedSeconds = elapsed.toSeconds();
        long days = (base.toSecondOfDay() + elapsedSeconds) / 86_400;
        int startDay = clock == null ? 1 : clock.dayOfYear();
        DayOfWeek startWeekday = clock == null ? DayOfWeek.SUNDAY : clock.dayOfWeek();
        return new CM11aStatus(batteryTimer, base.plusSeconds(elapsedSeconds),
                (int) ((startDay - 1 + days) % 365) + 1, startWeekday.plus(days), monitoredHouse, FIRMWARE_REVISION,
                powerLine.addressedUnits(monitoredHouse), powerLine.onUnits(monitoredHouse),
                powerLine.dimmedUnits(monitoredHouse));
    }
}
