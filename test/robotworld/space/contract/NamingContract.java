package robotworld.space.contract;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.URI;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.Future;

import org.junit.jupiter.api.Test;

import robotworld.space.ContainerInfo;
import robotworld.space.ContainerNameTakenException;
import robotworld.space.ContainerNotFoundException;
import robotworld.space.ContainerRef;
import robotworld.space.ContainerSpec;
import robotworld.space.Entry;
import robotworld.space.Order;
import robotworld.space.SpaceClosedException;
import robotworld.space.Timeout;
import robotworld.space.Tuple;

/** Containers and the naming service: create, lookup, lookup-or-create, destroy, crefs as values. */
public abstract class NamingContract extends SpaceContract {

    @Test
    void namedContainerIsFoundByName() {
        ContainerRef created = container(ContainerSpec.of(Order.FIFO).named("robot1MotorREQUEST"));
        assertEquals(created, space.lookupContainer("robot1MotorREQUEST"));
        assertEquals(space.spaceUri(), created.space());
    }

    @Test
    void lookupOfUnknownNameFails() {
        assertThrows(ContainerNotFoundException.class, () -> space.lookupContainer("nobody"));
    }

    @Test
    void namesAreUnique() {
        container(ContainerSpec.of(Order.FIFO).named("x"));
        assertThrows(ContainerNameTakenException.class, () -> container(ContainerSpec.of(Order.LIFO).named("x")));
    }

    @Test
    void anonymousContainersAreDistinctAndReachableByCref() {
        ContainerRef first = container(Order.FIFO);
        ContainerRef second = container(Order.FIFO);
        assertNotEquals(first, second);
        space.write(first, Timeout.TRY_ONCE, num(1));
        assertSize(first, 1);
        assertSize(second, 0);
    }

    @Test
    void describeReportsSpecAndState() {
        ContainerSpec spec = ContainerSpec.of(Order.LIFO).named("answers").bounded(5).set().withKeyView();
        ContainerRef ref = container(spec);
        space.write(ref, Timeout.TRY_ONCE, num(1), num(2));
        ContainerInfo info = space.describeContainer(ref);
        assertEquals(ref, info.ref());
        assertEquals(spec, info.spec());
        assertEquals(2, info.size());
        assertEquals(0, info.blocked());
        assertEquals(0, info.subscriptions());
    }

    @Test
    void lookupOrCreateCreatesOnceAndReturnsTheSameContainer() {
        ContainerSpec spec = ContainerSpec.of(Order.FIFO).named("shared");
        ContainerRef first = space.lookupOrCreateContainer(spec);
        ContainerRef second = space.lookupOrCreateContainer(spec);
        assertEquals(first, second);
    }

    @Test
    void lookupOrCreateRejectsADifferentSpec() {
        space.lookupOrCreateContainer(ContainerSpec.of(Order.FIFO).named("shared"));
        assertThrows(ContainerNameTakenException.class,
                () -> space.lookupOrCreateContainer(ContainerSpec.of(Order.LIFO).named("shared")));
    }

    @Test
    void lookupOrCreateNeedsAName() {
        assertThrows(IllegalArgumentException.class, () -> space.lookupOrCreateContainer(ContainerSpec.of(Order.FIFO)));
    }

    @Test
    void racingLookupOrCreateYieldsOneContainer() throws Exception {
        int racers = 8;
        CyclicBarrier start = new CyclicBarrier(racers);
        ContainerSpec spec = ContainerSpec.of(Order.FIFO).named("raced");
        List<Future<ContainerRef>> results = new java.util.ArrayList<>();
        for (int i = 0; i < racers; i++) {
            results.add(async(() -> {
                start.await();
                return space.lookupOrCreateContainer(spec);
            }));
        }
        Set<ContainerRef> distinct = new HashSet<>();
        for (Future<ContainerRef> ref : results) {
            distinct.add(result(ref));
        }
        assertEquals(1, distinct.size());
    }

    @Test
    void destroyRemovesContainerAndFreesItsName() {
        ContainerRef old = container(ContainerSpec.of(Order.FIFO).named("reused"));
        space.write(old, Timeout.TRY_ONCE, num(1));
        space.destroyContainer(old);
        assertThrows(ContainerNotFoundException.class, () -> space.lookupContainer("reused"));
        assertThrows(ContainerNotFoundException.class, () -> space.read(old, Timeout.TRY_ONCE));
        assertThrows(ContainerNotFoundException.class, () -> space.describeContainer(old));
        assertThrows(ContainerNotFoundException.class, () -> space.destroyContainer(old));

        ContainerRef renewed = container(ContainerSpec.of(Order.FIFO).named("reused"));
        assertNotEquals(old, renewed, "a new container never answers to an old cref");
        assertThrows(ContainerNotFoundException.class, () -> space.write(old, Timeout.TRY_ONCE, num(2)));
        assertSize(renewed, 0);
    }

    @Test
    void crefOfAnotherSpaceIsNotFound() {
        ContainerRef foreign = new ContainerRef(URI.create("embedded:elsewhere"), "c1");
        assertThrows(ContainerNotFoundException.class, () -> space.read(foreign, Timeout.TRY_ONCE));
    }

    @Test
    void crefTravelsAsAnEntryAndStillWorks() {
        ContainerRef directory = container(ContainerSpec.of(Order.FIFO).named("directory"));
        ContainerRef inbox = container(Order.FIFO);
        space.write(directory, Timeout.TRY_ONCE, Tuple.of(Entry.of("inbox"), inbox));
        Tuple found = (Tuple) space.read(directory, Timeout.TRY_ONCE).get(0);
        ContainerRef reached = found.crefAt(1);
        assertEquals(inbox, reached);
        space.write(reached, Timeout.TRY_ONCE, Entry.of("hello"));
        assertEquals(List.of(Entry.of("hello")), space.take(inbox, Timeout.TRY_ONCE));
    }

    @Test
    void closedSpaceRefusesEverything() {
        ContainerRef ref = container(Order.FIFO);
        space.close();
        space.close(); // idempotent
        assertThrows(SpaceClosedException.class, () -> space.write(ref, Timeout.TRY_ONCE, num(1)));
        assertThrows(SpaceClosedException.class, () -> space.createContainer(ContainerSpec.of(Order.FIFO)));
        assertThrows(SpaceClosedException.class, () -> space.lookupContainer("x"));
    }
}
