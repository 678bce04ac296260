package robotworld.cluster;

import java.io.IOException;
import java.util.List;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;

import robotworld.space.Entry;
import robotworld.space.internal.PlacedEntry;

/**
 * What a container promised about one call of a server's client (by the client's call id), so that any member's
 * server can settle it: a removal held until the client confirms it (put back when its lease runs out or the call is
 * cancelled), a write or shift that happened (with what the shift displaced), or a call cancelled before it arrived
 * (refused if it still comes).
 *
 * @param kind      which of the three
 * @param held      for a held removal: the entries with their places
 * @param displaced for a completed shift: what it pushed out
 * @param at        when it was made (owner's clock)
 * @param expiresAt for a held removal: when its entries come back (owner's clock)
 */
record Receipt(Kind kind, List<PlacedEntry> held, List<Entry> displaced, long at, long expiresAt) {

    enum Kind { HELD, DONE, FORBIDDEN }

    /** How long receipts of completed and cancelled calls are kept for late confirmations and cancels. */
    static final long KEPT_MILLIS = 120_000;

    static Receipt held(List<PlacedEntry> removed, long now, long leaseMillis) {
        return new Receipt(Kind.HELD, removed, List.of(), now, now + leaseMillis);
    }

    static Receipt done(List<Entry> displaced, long now) {
        return new Receipt(Kind.DONE, List.of(), displaced, now, Long.MAX_VALUE);
    }

    static Receipt forbidden(long now) {
        return new Receipt(Kind.FORBIDDEN, List.of(), List.of(), now, Long.MAX_VALUE);
    }

    /** When it may go (owner's clock): a held removal when its lease runs out, the others once kept long enough. */
    long dueAt() {
        return kind == Kind.HELD ? expiresAt : at + KEPT_MILLIS;
    }

    /** Whether it is due at {@code now}: a held removal from its {@link #dueAt()}, the others only after it. */
    boolean isDue(long now) {
        return kind == Kind.HELD ? expiresAt <= now : now - at > KEPT_MILLIS;
    }

    void write(ObjectDataOutput out) throws IOException {
        out.writeByte(kind.ordinal());
        Codec.writePlacedList(out, held);
        Codec.writeEntries(out, displaced);
        out.writeLong(at);
        out.writeLong(expiresAt);
    }

    static Receipt read(ObjectDataInput in) throws IOException {
        Kind kind = Kind.values()[in.readByte()];
        List<PlacedEntry> held = Codec.readPlacedList(in);
        List<Entry> displaced = Codec.readEntries(in);
        long at = in.readLong();
        return new Receipt(kind, held, displaced, at, in.readLong());
    }
}
