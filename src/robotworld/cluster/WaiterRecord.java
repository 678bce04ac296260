package robotworld.cluster;

import java.io.IOException;
import java.util.List;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;

import robotworld.space.Item;
import robotworld.space.Selector;
import robotworld.space.internal.PlacedEntry;

/**
 * A blocked operation, queued in its container: enough to try it again whenever the container changes. The thread
 * that waits for it lives on the member named in its id.
 *
 * @param id        the call that queued it (its member holds the waiting thread)
 * @param kind      what it does
 * @param selectors for a read, take or destroy
 * @param items     for a write
 * @param restoring for a restoration, the entries to put back
 * @param expiresAt when the owner may drop it as abandoned (owner's clock; its member gives up well before)
 * @param client    the call id of the server's client it runs for, or null: its receipt is kept under it
 * @param lease     for a client's take or destroy: how long its removal is held for confirmation, in ms
 */
record WaiterRecord(OpId id, Kind kind, Selector[] selectors, List<Item> items, List<PlacedEntry> restoring,
                    long expiresAt, String client, long lease) {

    /** What a waiter does when it is served. */
    enum Kind {
        READ, TAKE, DESTROY, WRITE,
        /** Puts removed entries back (an undone take); no thread waits for it. */
        RESTORE;

        boolean mutates() {
            return this != READ;
        }
    }

    void write(ObjectDataOutput out) throws IOException {
        id.write(out);
        out.writeByte(kind.ordinal());
        Codec.writeSelectors(out, selectors);
        Codec.writeItems(out, items);
        Codec.writePlacedList(out, restoring);
        out.writeLong(expiresAt);
        out.writeString(client);
        out.writeLong(lease);
    }

    static WaiterRecord read(ObjectDataInput in) throws IOException {
        OpId id = OpId.read(in);
        Kind kind = Kind.values()[in.readByte()];
        Selector[] selectors = Codec.readSelectors(in);
        List<Item> items = Codec.readItems(in);
        List<PlacedEntry> restoring = Codec.readPlacedList(in);
        long expiresAt = in.readLong();
        String client = in.readString();
        return new WaiterRecord(id, kind, selectors, items, restoring, expiresAt, client, in.readLong());
    }
}
