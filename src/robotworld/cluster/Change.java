package robotworld.cluster;

import java.io.IOException;

import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;

import robotworld.space.internal.PlacedEntry;
import robotworld.space.internal.StoreChange;

/**
 * One change to a {@link ContainerRecord}. The owning member logs the changes a call makes; its backups replay
 * them in the same order ({@link ApplyChanges}), so a backup holds exactly what the owner holds without the
 * whole container being copied on every call, and without repeating decisions (a random choice, the clock).
 */
sealed interface Change {

    void apply(ContainerRecord record);

    void write(ObjectDataOutput out) throws IOException;

    /** An entry placed, removed or touched. */
    record Store(StoreChange change) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.contents().apply(change);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            if (change instanceof StoreChange.Placed placed) {
                out.writeByte(0);
                Codec.writePlaced(out, placed.entry());
            } else if (change instanceof StoreChange.Removed removed) {
                out.writeByte(1);
                out.writeLong(removed.written());
            } else {
                StoreChange.Touched touched = (StoreChange.Touched) change;
                out.writeByte(2);
                out.writeLong(touched.written());
                out.writeLong(touched.used());
            }
        }
    }

    record Sequenced(long sequence) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.setSequence(sequence);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            out.writeLong(sequence);
        }
    }

    record WaiterAdded(WaiterRecord waiter, boolean first) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.addWaiter(waiter, first);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            waiter.write(out);
            out.writeBoolean(first);
        }
    }

    record WaiterRemoved(OpId waiter) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.removeWaiter(waiter);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            waiter.write(out);
        }
    }

    record Completed(OpId waiter, Completion completion) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.putCompletion(waiter, completion);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            waiter.write(out);
            completion.write(out);
        }
    }

    record Collected(OpId waiter) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.removeCompletion(waiter);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            waiter.write(out);
        }
    }

    record Subscribed(OpId subscription) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.addSubscriber(subscription);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            subscription.write(out);
        }
    }

    record Unsubscribed(OpId subscription) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.removeSubscriber(subscription);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            subscription.write(out);
        }
    }

    record Journaled(Event event) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.journal(event);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            event.write(out);
        }
    }

    record Remembered(OpId call, Outcome outcome, long at) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.remember(call, outcome, at);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            call.write(out);
            outcome.writeData(out);
            out.writeLong(at);
        }
    }

    record Forgotten(OpId call) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.forget(call);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            call.write(out);
        }
    }

    record ReceiptPut(String call, Receipt receipt) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.putReceipt(call, receipt);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            out.writeString(call);
            receipt.write(out);
        }
    }

    record ReceiptRemoved(String call) implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.removeReceipt(call);
        }

        @Override
        public void write(ObjectDataOutput out) throws IOException {
            out.writeString(call);
        }
    }

    record Destroyed() implements Change {
        @Override
        public void apply(ContainerRecord record) {
            record.markDestroyed();
        }

        @Override
        public void write(ObjectDataOutput out) {
        }
    }

    // ---- encoding: a tag, then the change's own fields ----

    static void writeTagged(ObjectDataOutput out, Change change) throws IOException {
        out.writeByte(tag(change));
        change.write(out);
    }

    private static int tag(Change change) {
        if (change instanceof Store) {
            return 0;
        } else if (change instanceof Sequenced) {
            return 1;
        } else if (change instanceof WaiterAdded) {
            return 2;
        } else if (change instanceof WaiterRemoved) {
            return 3;
        } else if (change instanceof Completed) {
            return 4;
        } else if (change instanceof Collected) {
            return 5;
        } else if (change instanceof Subscribed) {
            return 6;
        } else if (change instanceof Unsubscribed) {
            return 7;
        } else if (change instanceof Journaled) {
            return 8;
        } else if (change instanceof Remembered) {
            return 9;
        } else if (change instanceof Forgotten) {
            return 10;
        } else if (change instanceof ReceiptPut) {
            return 12;
        } else if (change instanceof ReceiptRemoved) {
            return 13;
        }
        return 11; // Destroyed
    }

    static Change read(ObjectDataInput in) throws IOException {
        byte tag = in.readByte();
        return switch (tag) {
            case 0 -> new Store(readStoreChange(in));
            case 1 -> new Sequenced(in.readLong());
            case 2 -> {
                WaiterRecord waiter = WaiterRecord.read(in);
                yield new WaiterAdded(waiter, in.readBoolean());
            }
            case 3 -> new WaiterRemoved(OpId.read(in));
            case 4 -> {
                OpId waiter = OpId.read(in);
                yield new Completed(waiter, Completion.read(in));
            }
            case 5 -> new Collected(OpId.read(in));
            case 6 -> new Subscribed(OpId.read(in));
            case 7 -> new Unsubscribed(OpId.read(in));
            case 8 -> new Journaled(Event.read(in));
            case 9 -> {
                OpId call = OpId.read(in);
                Outcome outcome = new Outcome();
                outcome.readData(in);
                yield new Remembered(call, outcome, in.readLong());
            }
            case 10 -> new Forgotten(OpId.read(in));
            case 11 -> new Destroyed();
            case 12 -> {
                String call = in.readString();
                yield new ReceiptPut(call, Receipt.read(in));
            }
            case 13 -> new ReceiptRemoved(in.readString());
            default -> throw new IOException("unknown change tag " + tag);
        };
    }

    private static StoreChange readStoreChange(ObjectDataInput in) throws IOException {
        byte kind = in.readByte();
        return switch (kind) {
            case 0 -> {
                PlacedEntry placed = Codec.readPlaced(in);
                yield new StoreChange.Placed(placed);
            }
            case 1 -> new StoreChange.Removed(in.readLong());
            case 2 -> {
                long written = in.readLong();
                yield new StoreChange.Touched(written, in.readLong());
            }
            default -> throw new IOException("unknown store change " + kind);
        };
    }
}
