package robotworld.cluster;

import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

import robotworld.space.CallReceipts;
import robotworld.space.Entry;
import robotworld.space.Removal;
import robotworld.space.SpaceException;

/**
 * The receipts of a server's clients for a clustered space, kept in the containers ({@link Receipt}), so that a
 * client whose server (or member) failed settles its calls with another member's server: a take's removal is held
 * in its container until the client confirms it from anywhere, and a cancel learns from the container whether a
 * write happened, puts a held removal back, or makes sure a late call is refused.
 *
 * <p>A member knows the containers of the calls that came through it. A client that failed over from another
 * member names the container of each call it settles ({@link #hint}); for a call id it still does not know, it
 * asks every container of the space which one knows the call.
 */
final class ClusterReceipts implements CallReceipts {

    private static final System.Logger LOG = System.getLogger(ClusterReceipts.class.getName());
    /** Calls remembered per member: their container, so acknowledgements and cancels go straight there. */
    private static final int MAX_KNOWN = 100_000;

    private final ClusterSpace space;
    private final Map<String, String> containerOf = new ConcurrentHashMap<>();
    /** Takes and destroys held for their client's confirmation, made through this member. */
    private final Set<String> held = ConcurrentHashMap.newKeySet();
    /** Calls no container knew when they were cancelled: refused here if they still come. */
    private final Map<String, Long> tombstones = new LinkedHashMap<>();

    ClusterReceipts(ClusterSpace space) {
        this.space = space;
    }

    /** A call of a client ran through this member on {@code container}; {@code removal}: it holds entries. */
    void made(String call, String container, boolean removal) {
        remember(call, container);
        if (removal) {
            held.add(call);
        }
    }

    /**
     * A failed-over client names the container of a call it settles: no need to ask every container (which,
     * while partitions move after a member died, held up every serving thread for seconds).
     */
    @Override
    public void hint(String callId, String containerId) {
        if (!containerOf.containsKey(callId)) { // what this member saw itself beats what a client says
            remember(callId, containerId);
        }
    }

    private void remember(String callId, String container) {
        if (containerOf.size() >= MAX_KNOWN) {
            containerOf.clear(); // forgotten ones are found again by asking the containers
        }
        containerOf.put(callId, container);
    }

    /** The container holds the removal since the call itself. */
    @Override
    public void hold(String callId, Removal removal, long leaseMillis) {
    }

    @Override
    public void acknowledge(String callId) {
        acknowledge(List.of(callId));
    }

    /**
     * Drops the held removals of these calls in their containers, one call per container, before returning: the
     * server answers the request that carried the confirmations only after that, so a member failing right after
     * cannot lose a confirmation (which would bring the entries back to be taken again).
     */
    @Override
    public void acknowledge(List<String> callIds) {
        Map<String, List<String>> byContainer = new LinkedHashMap<>();
        for (String callId : callIds) {
            held.remove(callId);
            String container = containerOf.remove(callId);
            if (container == null) {
                container = locate(callId);
            }
            if (container != null) {
                byContainer.computeIfAbsent(container, key -> new ArrayList<>()).add(callId);
            }
        }
        for (Map.Entry<String, List<String>> batch : byContainer.entrySet()) {
            space.receiptsCall(batch.getKey(), ContainerCall.Kind.ACK_RECEIPTS, batch.getValue());
        }
    }

    @Override
    public boolean restore(String callId) {
        held.remove(callId);
        String container = locate(callId);
        if (container == null) {
            return false;
        }
        boolean restored = space.receiptCall(container, ContainerCall.Kind.RESTORE_RECEIPT, callId).happened;
        if (restored) {
            containerOf.remove(callId); // settled; otherwise a cancel goes on to forbid it there
        }
        return restored;
    }

    /** The container keeps it since the call itself. */
    @Override
    public void completed(String callId, List<Entry> displaced) {
    }

    @Override
    public List<Entry> takeCompleted(String callId) {
        String container = locate(callId);
        if (container == null) {
            return null;
        }
        Outcome outcome = space.receiptCall(container, ContainerCall.Kind.TAKE_COMPLETED, callId);
        return outcome.happened ? outcome.entries : null;
    }

    @Override
    public List<Entry> forbid(String callId) {
        held.remove(callId);
        String container = locate(callId);
        if (container == null) {
            synchronized (tombstones) {
                if (tombstones.size() >= MAX_KNOWN) {
                    tombstones.remove(tombstones.keySet().iterator().next());
                }
                tombstones.put(callId, System.nanoTime());
            }
            return null;
        }
        containerOf.remove(callId);
        Outcome outcome = space.receiptCall(container, ContainerCall.Kind.FORBID, callId);
        return outcome.happened ? outcome.entries : null;
    }

    @Override
    public boolean isForbidden(String callId) {
        synchronized (tombstones) {
            return !tombstones.isEmpty() && tombstones.remove(callId) != null;
        }
    }

    @Override
    public int held() {
        return held.size();
    }

    /** The container of a client call: known here, or found by asking the space's containers; null if none knows it. */
    private String locate(String callId) {
        String known = containerOf.get(callId);
        if (known != null) {
            return known;
        }
        try {
            String found = space.findReceipt(callId);
            if (found != null) {
                remember(callId, found); // a cancel asks up to three times: look once
            }
            return found;
        } catch (SpaceException e) {
            LOG.log(Level.WARNING, "could not look for call " + callId + " in the cluster: " + e.getMessage());
            return null;
        }
    }
}
