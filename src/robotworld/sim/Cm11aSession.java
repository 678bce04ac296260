package robotworld.sim;

import java.io.IOException;
import java.time.Duration;
import java.util.Arrays;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robotworld.bus.LinkClosedException;
import robotworld.bus.SerialLink;
import robotworld.x10.CM11aClock;
import robotworld.x10.Hex;
import robotworld.x10.X10Constants;

/**
 * The interface side of the CM11A protocol on one serial link, run by one thread until the host goes away:
 * checksum echo, wait for 0x00, power-line transmission, 0x55; polls (0x5A with upload after 0xC3, 0xA5 until the
 * clock comes) during which host frames are ignored; status request; clock download; ring enable/disable and
 * EEPROM blocks (acknowledged, not executed).
 */
final class Cm11aSession implements Runnable {

    private static final Logger LOG = LoggerFactory.getLogger(Cm11aSession.class);
    private static final int NONE = -1;
    private static final int EEPROM_BLOCK_LENGTH = 18;

    private final Cm11aDevice device;
    private final Cm11aTiming timing;
    private final PacedWire wire;
    private final String name;
    private final Duration idleSlice;
    private volatile boolean ended;

    Cm11aSession(Cm11aDevice device, Cm11aTiming timing, SerialLink link) {
        this.device = device;
        this.timing = timing;
        this.name = link.portName();
        this.wire = new PacedWire(link, timing.characterTime(), name);
        Duration slice = Duration.ofMillis(10);
        this.idleSlice = timing.pollInterval().compareTo(slice) < 0 ? timing.pollInterval() : slice;
    }

    @Override
    public void run() {
        try {
            while (true) {
                if (device.isPoweredOff()) {
                    ignoreWithoutPower();
                } else if (device.isPowerFailed()) {
                    poll(X10Constants.CM11A_POWER_FAIL_POLL);
                } else if (!device.uploads.isEmpty()) {
                    poll(X10Constants.CM11A_POLL);
                } else {
                    int value = wire.receive(idleSlice);
                    if (value != NONE && device.isPoweredOff()) {
                        device.wire.hostIgnored(new byte[] {(byte) value}, "no power"); // unplugged while waiting
                    } else if (value != NONE) {
                        handle(value);
                    }
                }
            }
        } catch (LinkClosedException e) {
            LOG.debug("{}: host gone, session ends", name);
        } catch (IOException | RuntimeException e) {
            LOG.warn("{}: simulated CM11A session failed: {}", name, e.toString());
        } finally {
            ended = true;
            wire.close();
        }
    }

    /** Whether the session is over (host gone or closed). */
    boolean hasEnded() {
        return ended;
    }

    /** Stops the session by closing its link. */
    void close() {
        wire.close();
    }

    private void ignoreWithoutPower() throws IOException {
        int value = wire.receive(idleSlice);
        if (value != NONE) {
            device.wire.hostIgnored(new byte[] {(byte) value}, "no power");
        }
    }

    /** Sends one poll and listens for its answer until the next poll is due; other bytes are ignored. */
    private void poll(int pollByte) throws IOException {
        send(pollByte);
        int answer = pollByte == X10Constants.CM11A_POLL ? X10Constants.CM11A_POLL_ACK : X10Constants.CM11A_SET_CLOCK;
        long deadline = System.nanoTime() + timing.pollInterval().toNanos();
        long left;
        while ((left = deadline - System.nanoTime()) > 0) {
            int value = wire.receive(Duration.ofNanos(left));
            if (value == answer) {
                if (answer == X10Constants.CM11A_POLL_ACK) {
                    device.wire.host(new byte[] {(byte) value});
                    sendUpload();
                } else {
                    receiveClock();
                }
                return;
            }
            if (value != NONE) {
                device.wire.hostIgnored(new byte[] {(byte) value}, "ignored while polling");
            }
        }
    }

    private void sendUpload() throws IOException {
        byte[] upload = device.uploads.take();
        if (upload != null) {
            send(upload);
        }
    }

    /** Handles a byte from an idle interface's point of view; a frame may be followed directly by another. */
    private void handle(int first) throws IOException {
        int value = first;
        while (value != NONE) {
            if ((value & X10Constants.HEADER_SYNC_BIT) != 0) {
                value = transmission(value);
            } else {
                other(value);
                value = NONE;
            }
        }
    }

    /**
     * A header byte arrived: read the rest of the frame, echo the checksum, and on 0x00 transmit it and send 0x55.
     *
     * @return a byte that came instead of 0x00 (the start of a resent frame), or NONE
     */
    private int transmission(int header) throws IOException {
        int length = (header & X10Constants.HEADER_EXTENDED_BIT) != 0 ? 5 : 2;
        byte[] frame = new byte[length];
        frame[0] = (byte) header;
        for (int i = 1; i < length; i++) {
            int value = wire.receive(timing.hostTimeout());
            if (value == NONE) {
                device.wire.hostIgnored(Arrays.copyOf(frame, i), "incomplete frame");
                return NONE;
            }
            frame[i] = (byte) value;
        }
        device.wire.host(frame);
        int sum = 0;
        for (byte b : frame) {
            sum += b & 0xFF;
        }
        send(device.checksumToSend(sum & 0xFF));
        int reply = wire.receive(timing.hostTimeout());
        if (reply == NONE) {
            device.wire.deviceNote("no 00 from the host: " + Hex.of(frame) + " not transmitted");
            return NONE;
        }
        if (reply != X10Constants.CM11A_ACK) {
            return reply; // a new frame in place of the acknowledge: this one is not transmitted
        }
        device.wire.host(new byte[] {0});
        transmitOnPowerLine(frame);
        send(X10Constants.CM11A_READY);
        return NONE;
    }

    private void transmitOnPowerLine(byte[] frame) {
        if (!timing.powerLineTime().isZero()) {
            PacedWire.sleepUntil(System.nanoTime() + timing.powerLineTime().toNanos());
        }
        device.powerLine.transmit(frame);
    }

    /** Bytes without the header sync bit: status request, clock, ring control, EEPROM; anything else is noise. */
    private void other(int value) throws IOException {
        switch (value) {
            case X10Constants.CM11A_STATUS_REQUEST -> {
                device.wire.host(new byte[] {(byte) value});
                send(device.status().encode());
            }
            case X10Constants.CM11A_SET_CLOCK -> receiveClock();
            case X10Constants.CM11A_RING_ENABLE, X10Constants.CM11A_RING_DISABLE -> {
                device.wire.host(new byte[] {(byte) value});
                acknowledged(value);
            }
            case X10Constants.CM11A_EEPROM_DOWNLOAD -> eepromBlock();
            default -> device.wire.hostIgnored(new byte[] {(byte) value}, "ignored");
        }
    }

    /** 0x9B and six clock bytes; the checksum covers the six. */
    private void receiveClock() throws IOException {
        byte[] received = new byte[1 + X10Constants.CM11A_CLOCK_LENGTH];
        received[0] = (byte) X10Constants.CM11A_SET_CLOCK;
        if (!receiveInto(received, 1)) {
            return;
        }
        device.wire.host(received);
        byte[] six = Arrays.copyOfRange(received, 1, received.length);
        CM11aClock clock = CM11aClock.decode(six);
        if (acknowledged(device.checksumToSend(clock.checksum()))) {
            device.clockSet(clock);
        }
    }

    /** An EEPROM block: 0xFB, two address bytes, sixteen data bytes; accepted but not executed. */
    private void eepromBlock() throws IOException {
        byte[] block = new byte[1 + EEPROM_BLOCK_LENGTH];
        block[0] = (byte) X10Constants.CM11A_EEPROM_DOWNLOAD;
        if (!receiveInto(block, 1)) {
            return;
        }
        device.wire.host(block);
        int sum = 0;
        for (int i = 1; i < block.length; i++) {
            sum += block[i] & 0xFF;
        }
        acknowledged(device.checksumToSend(sum & 0xFF));
    }

    /** Sends a checksum, waits for 0x00, sends 0x55; whether the host acknowledged. */
    private boolean acknowledged(int checksum) throws IOException {
        send(checksum);
        int reply = wire.receive(timing.hostTimeout());
        if (reply != X10Constants.CM11A_ACK) {
            if (reply != NONE) {
                device.wire.hostIgnored(new byte[] {(byte) reply}, "expected 00");
            }
            return false;
        }
        device.wire.host(new byte[] {0});
        send(X10Constants.CM11A_READY);
        return true;
    }

    private boolean receiveInto(byte[] buffer, int from) throws IOException {
        for (int i = from; i < buffer.length; i++) {
            int value = wire.receive(timing.hostTimeout());
            if (value == NONE) {
                device.wire.hostIgnored(Arrays.copyOf(buffer, i), "incomplete");
                return false;
            }
            buffer[i] = (byte) value;
        }
        return true;
    }

    private void send(int value) throws IOException {
        send(new byte[] {(byte) value});
    }

    private void send(byte[] bytes) throws IOException {
        device.wire.device(bytes); // logged first, so the log is complete when the host has the bytes
        wire.send(bytes);
    }
}
