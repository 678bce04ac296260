package robotworld.cluster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** What a member's DEBUG log tells of waiting operations: the troubled ones, with their steps; the others not. */
class WaiterStoryTest {

    private final Logger logger = Logger.getLogger(WaiterStory.class.getName());
    private final List<String> logged = new CopyOnWriteArrayList<>();
    private final Handler capture = new Handler() {
        @Override
        public void publish(LogRecord record) {
            logged.add(record.getMessage());
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    };
    private Level levelBefore;

    @BeforeEach
    void listen() {
        levelBefore = logger.getLevel();
        capture.setLevel(Level.ALL);
        logger.addHandler(capture);
    }

    @AfterEach
    void stopListening() {
        logger.removeHandler(capture);
        logger.setLevel(levelBefore);
    }

    @Test
    void aWaitThatHadTroubleIsToldStepByStep() {
        logger.setLevel(Level.FINE);
        WaiterStory story = WaiterStory.begin();
        story.note("look", null);
        story.trouble("look failed:", "the cluster is recovering");
        story.note("look again in ms", 1000);
        story.ended("container c", "its result");

        assertEquals(1, logged.size(), logged.toString());
        String told = logged.get(0);
        assertTrue(told.startsWith("waiting operation on container c ended after "), told);
        assertTrue(told.contains("with its result:"), told);
        assertTrue(told.matches(".* \\+\\d+ ms look; \\+\\d+ ms look failed: the cluster is recovering; \\+\\d+ ms look"
                + " again in ms 1000;$"), told);
    }

    @Test
    void aWaitWithoutTroubleIsNotLogged() {
        logger.setLevel(Level.FINE);
        WaiterStory story = WaiterStory.begin();
        story.woken();
        story.note("look", null);
        story.note("found", Outcome.Status.DONE);
        story.ended("container c", "its result");

        assertEquals(List.of(), logged);
    }

    @Test
    void aWaitThatEndsLongAfterItsWakeUpIsLogged() throws InterruptedException {
        logger.setLevel(Level.FINE);
        WaiterStory story = WaiterStory.begin();
        story.woken();
        Thread.sleep(ClusterNode.SLOW_CALL_MILLIS + 50);
        story.ended("container c", "its result");

        assertEquals(1, logged.size(), logged.toString());
        assertTrue(logged.get(0).contains("ms woken;"), logged.get(0));
    }

    @Test
    void belowDebugNothingIsKept() {
        logger.setLevel(Level.INFO);
        WaiterStory story = WaiterStory.begin();
        assertSame(WaiterStory.NONE, story);
        story.trouble("queue again", null);
        story.ended("container c", "its result");

        assertEquals(List.of(), logged);
    }
}
