package robotworld.cluster;

import java.lang.System.Logger.Level;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

import robotworld.space.Entry;
import robotworld.space.Removal;
import robotworld.space.SpaceException;
import robotworld.space.internal.PlacedEntry;

/**
 * A take or destroy on a cluster that can still be undone: {@link #restore()} puts the entries back where they
 * were in their container (on the member that owns it), waiting first in its queue if they do not fit now.
 */
final class ClusterRemoval implements Removal {

    private static final System.Logger LOG = System.getLogger(ClusterRemoval.class.getName());

    private final ClusterSpace space;
    private final String container;
    private final List<Entry> entries;
    private final List<PlacedEntry> removed;
    /** The call id of the server's client it was made for (the container holds it under that id), or null. */
    private final String client;
    private final AtomicBoolean restored = new AtomicBoolean();

    ClusterRemoval(ClusterSpace space, String container, List<Entry> entries, List<PlacedEntry> removed,
                   String client) {
        this.space = space;
        this.container = container;
        this.entries = entries;
        this.removed = removed;
        this.client = client;
    }

    @Override
    public List<Entry> entries() {
        return entries;
    }

    @Override
    public void restore() {
        if (removed.isEmpty() || !restored.compareAndSet(false, true)) {
            return;
        }
        try {
            if (client != null) {
                space.restoreReceipt(container, client); // the container holds it: put back from there, once
            } else {
                space.restore(container, removed);
            }
        } catch (SpaceException e) {
            LOG.log(Level.WARNING, "could not put " + entries.size() + " entries back into " + container + ": "
                    + e.getMessage());
        }
    }
}
