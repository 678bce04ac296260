package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import robotworld.space.ContainerRef;
import robotworld.space.EmbeddedSpace;
import robotworld.space.Entry;
import robotworld.space.Selector;
import robotworld.space.Timeout;
import robotworld.testsupport.ForwardingCapi;

/**
 * A module's serving loop survives any exception, not only the space's own: one thrown while working on requests
 * (a fault of the program), or a space connection that throws something other than a {@code SpaceException}.
 * Serving goes on after a pause, and the module says it is served only while it is.
 */
@org.junit.jupiter.api.Timeout(120)
class ServingSurvivesAnyFailureTest {

    @Test
    void anExceptionWhileWorkingOnRequestsDoesNotEndServing() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            ModuleContainers containers = new ModuleContainers(space, "Bot.Test.REQUEST", "Bot.Test.ANSWER");
            AtomicInteger batches = new AtomicInteger();
            RequestServer server = new RequestServer(containers, "Bot/Test", requests -> {
                if (batches.incrementAndGet() == 1) {
                    throw new IllegalStateException("injected: the first batch cannot be answered");
                }
                List<CallTuple> answers = new ArrayList<>();
                for (CallTuple request : requests) {
                    answers.add(request.withFields(List.of(Entry.of(42))));
                }
                return answers;
            }, () -> false);
            server.start();
            try {
                space.write(containers.requests(), Timeout.TRY_ONCE, CallTuple.of("laptop#1", "get").toTuple());
                awaitBatches(batches, 1);
                CallTuple second = CallTuple.of("laptop#2", "get");
                space.write(containers.requests(), Timeout.TRY_ONCE, second.toTuple());
                List<Entry> answer = space.take(containers.answers(), Timeout.ofMillis(30_000),
                        Selector.key(second.key()));
                assertEquals(List.of(Entry.of(42)), CallTuple.parse(answer.get(0)).fields());
                assertTrue(server.isRunning());
            } finally {
                server.stop();
            }
        }
    }

    @Test
    void aSpaceConnectionThrowingSomethingElseDoesNotEndServing() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            AtomicInteger failures = new AtomicInteger(3);
            // not a SpaceEngine: the module waits for requests on a thread of its own, which meets these
            ForwardingCapi faulty = new ForwardingCapi(space) {
                @Override
                public List<Entry> take(ContainerRef container, Timeout timeout, Selector... selectors) {
                    if (failures.getAndDecrement() > 0) {
                        throw new IllegalStateException("injected: a bug in the space connection");
                    }
                    return super.take(container, timeout, selectors);
                }

                @Override
                public void close() {
                    // the test closes the space
                }
            };
            try (XVSMRuntime provider = XVSMRuntime.using(faulty, "robot-pc", false);
                 XVSMRuntime caller = XVSMRuntime.using(space, "laptop", false)) {
                XVSMBumperModuleLocal bumper = new XVSMBumperModuleLocal(provider, "Bot", "Bumper", new FakeBumper());
                XVSMBumperModuleRemote remote = new XVSMBumperModuleRemote(caller, "Bot", "Bumper");
                remote.setCallTimeout(Duration.ofSeconds(20));
                assertEquals(0, remote.getAllBumper());
                assertTrue(failures.get() < 0, "the injected failures were met");
                assertTrue(bumper.isServing());
            }
        }
    }

    private static void awaitBatches(AtomicInteger batches, int count) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (batches.get() < count) {
            assertTrue(System.nanoTime() < deadline, "the request was never worked on");
            Thread.sleep(5);
        }
    }
}
