package robotworld.observe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import robotworld.space.Tuple;

class GroundTruthTuplesTest {

    /** A frame whose values survive the integer layout exactly. */
    static GroundTruth frame(long sequence) {
        return new GroundTruth("Robot1", sequence, Instant.ofEpochMilli(1_700_000_000_123L + sequence), 12.5,
                new GroundTruth.Arena(1600, 1200, List.of(new GroundTruth.Obstacle(700, 400, 200, 400))),
                new GroundTruth.Body(350 + sequence, 600, -12.25, 150),
                List.of(new GroundTruth.Ray(4, 1, 0, 212, 800), new GroundTruth.Ray(4, 2, 30, 800, 800)),
                List.of(new GroundTruth.Bumper(2, 4, 35, 70, true), new GroundTruth.Bumper(2, 6, -35, 70, false)),
                List.of(new GroundTruth.Motor(1, 1, 0.25, 0.125, "left"), new GroundTruth.Motor(1, 3, -1, 0, "")));
    }

    @Test
    void aFrameSurvivesTheTripThroughTheSpaceLayout() {
        GroundTruth frame = frame(7);
        Tuple tuple = GroundTruthTuples.encode(frame);
        assertTrue(GroundTruthTuples.isFrame(tuple));
        assertEquals(frame, GroundTruthTuples.decode(tuple));
        assertEquals("rwe.groundtruth", tuple.stringAt(0));
        assertEquals(-1225, tuple.tupleAt(7).longAt(2), "heading in hundredths of a degree");
        assertEquals(250, tuple.tupleAt(10).tupleAt(0).longAt(2), "speeds travel as per-mille");
        assertTrue(frame.anyContact());
        assertTrue(frame.rays().get(0).hits() && !frame.rays().get(1).hits());
    }

    @Test
    void somethingElseIsRefusedWithAClearMessage() {
        assertThrows(IllegalArgumentException.class, () -> GroundTruthTuples.decode(Tuple.of("rwe.groundtruth", 2L)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> GroundTruthTuples.decode(Tuple.of("x")));
        assertTrue(e.getMessage().contains("not a ground-truth frame"), e.getMessage());
        assertEquals("Robot1GROUNDTRUTH", GroundTruthTuples.containerSpec("Robot1").name());
    }
}
