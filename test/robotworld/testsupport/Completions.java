package robotworld.testsupport;

import java.util.concurrent.CompletableFuture;
import java.util.function.Function;

import robotworld.space.SpaceEngine;
import robotworld.space.SpaceException;

/** Completions of waits without a thread that put their outcome, a result or the failure, into a future. */
public final class Completions {

    private Completions() {
    }

    /** Completes {@code outcome} with {@code result} of what the wait produced, or with its failure. */
    public static <T> SpaceEngine.Completion<T> into(CompletableFuture<Object> outcome, Function<T, Object> result) {
        return new SpaceEngine.Completion<>() {
            @Override
            public void completed(T value) {
                outcome.complete(result.apply(value));
            }

            @Override
            public void failed(SpaceException failure) {
                outcome.complete(failure);
            }
        };
    }
}
