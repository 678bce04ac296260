package robotworld.xvsm;

import java.util.function.Function;
import robotworld.space.Capi;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Order;

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
