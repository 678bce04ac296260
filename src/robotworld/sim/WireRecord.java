package robotworld.sim;

import robotworld.x10.Hex;

/**
 * One unit of serial traffic seen by the simulated interface: a frame or byte from the host, or an answer from
 * the interface.
 *
 * @param fromHost true for host-to-interface bytes
 * @param bytes the bytes
 * @param note why the bytes were not used, e.g. "ignored while polling"; empty when they were
 * @param nanos {@link System#nanoTime()} when recorded
 */
public record WireRecord(boolean fromHost, byte[] bytes, String note, long nanos) {

    /**
     * e.g. {@code host 04 62}, {@code cm11a 66}, {@code host 04 (ignored while polling)}; a record without bytes is
     * something the interface did on its own, e.g. {@code cm11a (no 00 from the host: 04 62 not transmitted)}.
     */
    @Override
    public String toString() {
        String note = this.note.isEmpty() ? "" : "(" + this.note + ")";
        String text = bytes.length == 0 ? note : note.isEmpty() ? Hex.of(bytes) : Hex.of(bytes) + " " + note;
        return (fromHost ? "host " : "cm11a ") + text;
    }
}
