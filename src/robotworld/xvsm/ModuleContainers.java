package robotworld.xvsm;

import java.util.List;
import java.util.function.Function;
import java.util.function.Supplier;
import robotworld.space.Capi;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Item;
import robotworld.space.Order;
import robotworld.space.Selector;
import robotworld.space.Timeout;

/**
 * The two containers of one module: {@code <Participant><Module>REQUEST} (FIFO, unbounded) and
 * {@code <Participant><Module>ANSWER} (LIFO with a KEY view, unbounded). Whoever comes first creates them
 * ({@code lookupOrCreateContainer} is atomic), so the module's host and its callers may start in any order. When
 * a container has gone (destroyed, or a space server restarted without its data) an operation is retried once
 * on the container looked up or created again.
 */
final class ModuleContainers {

    private final Capi space;
    private final ContainerSpec requestSpec;
    private final ContainerSpec answerSpec;
    private volatile ContainerRef requests;
    private volatile ContainerRef answers;

    ModuleContainers(Capi space, String requestName, String answerName) {
        this.space = space;
        this.requestSpec = requestSpec(requestName);
        this.answerSpec = answerSpec(answerName);
        this.requests = space.lookupOrCreateContainer(requestSpec);
        this.answers = space.lookupOrCreateContainer(answerSpec);
    }

    /** The REQUEST container's spec: a FIFO queue without limit. */
    static ContainerSpec requestSpec(String name) {
        return ContainerSpec.of(Order.FIFO).unbounded().named(name);
    }

    /** The ANSWER container's spec: LIFO with a KEY view, without limit. */
    static ContainerSpec answerSpec(String name) {
        return ContainerSpec.of(Order.LIFO).withKeyView().unbounded().named(name);
    }

    Capi space() {
        return space;
    }

    ContainerRef requests() {
        return requests;
    }

    ContainerRef answers() {
        return answers;
    }

    /** Runs {@code operation} on the REQUEST container, once more on a fresh one if it has gone. */
    <T> T onRequests(Function<ContainerRef, T> operation) {
        try {
            return operation.apply(requests);
        } catch (ContainerNotFoundException gone) {
            requests = space.lookupOrCreateContainer(requestSpec);
            return operation.apply(requests);
        }
    }

    /**
     * Writes {@code request} into REQUEST, then takes from ANSWER what {@code selector} selects: one exchange with
     * a remote space ({@link Capi#writeThenTake}). When a container has gone, both are looked up or created again:
     * if REQUEST is the same container, the request is in it and only the take is repeated; otherwise the request
     * went with the old one, and both are repeated.
     *
     * @param timeout what is left of the call's time, asked again for each attempt
     */
    List<Entry> writeThenTake(Item request, Supplier<Timeout> timeout, Selector selector) {
        ContainerRef requestsBefore = requests;
        try {
            return space.writeThenTake(requestsBefore, List.of(request), answers, timeout.get(), selector);
        } catch (ContainerNotFoundException gone) {
            requests = space.lookupOrCreateContainer(requestSpec);
            answers = space.lookupOrCreateContainer(answerSpec);
            if (requests.equals(requestsBefore)) {
                return space.take(answers, timeout.get(), selector);
            }
            return space.writeThenTake(requests, List.of(request), answers, timeout.get(), selector);
        }
    }

    /** Looks both containers up (or creates them) again: after one has gone, e.g. a server that came back empty. */
    void lookUpAgain() {
        requests = space.lookupOrCreateContainer(requestSpec);
        answers = space.lookupOrCreateContainer(answerSpec);
    }

    /** Runs {@code operation} on the ANSWER container, once more on a fresh one if it has gone. */
    <T> T onAnswers(Function<ContainerRef, T> operation) {
        try {
            return operation.apply(answers);
        } catch (ContainerNotFoundException gone) {
            answers = space.lookupOrCreateContainer(answerSpec);
            return operation.apply(answers);
        }
    }
}
