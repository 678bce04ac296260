package robotworld.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Geometry of the simulated world: driving, collisions, bumper arcs, IR rays. */
class WorldTest {

    /** A 2000 x 1000 arena, robot of radius 100 at (500, 500) facing +x, 200 mm/s at full speed. */
    private static World arena(List<Rect> obstacles) {
        return new World(2000, 1000, obstacles, new Pose(500, 500, 0), 100, 200, 200);
    }

    @Test
    void rayDistanceHitsNearFacesAndMisses() {
        Rect box = new Rect(10, -5, 4, 10);
        assertEquals(10, box.rayDistance(0, 0, 1, 0), 1e-9);
        assertEquals(Double.POSITIVE_INFINITY, box.rayDistance(0, 0, -1, 0));
        assertEquals(Double.POSITIVE_INFINITY, box.rayDistance(0, 20, 1, 0));
        assertEquals(0, box.rayDistance(12, 0, 1, 0), 1e-9, "inside");
        assertEquals(5, new Rect(-1, 5, 2, 2).rayDistance(0, 0, 0, 1), 1e-9);
    }

    @Test
    void equalWheelSpeedsDriveStraightAhead() {
        World world = arena(List.of());
        world.drive(0.5, 0.5, 2.0);
        assertEquals(700, world.pose().x(), 1e-6);
        assertEquals(500, world.pose().y(), 1e-6);
        assertEquals(0, world.pose().heading(), 1e-9);
        assertEquals(200, world.travelled(), 1e-6);
    }

    @Test
    void oppositeWheelSpeedsTurnOnTheSpot() {
        World world = arena(List.of());
        // (vr - vl) / wheelBase = (200 + 200) / 200 = 2 rad/s; a quarter turn takes pi/4 s
        world.drive(-1, 1, Math.PI / 4);
        assertEquals(90, world.pose().heading(), 1e-6);
        assertEquals(500, world.pose().x(), 1e-6);
    }

    @Test
    void drivingIntoAWallStopsAtContactAndClosesOnlyFrontArcs() {
        World world = arena(List.of());
        for (int i = 0; i < 2000; i++) {
            world.drive(1, 1, 0.01);
        }
        assertEquals(1900, world.pose().x(), 0.01, "body touches the wall at x = 2000");
        assertTrue(world.contact(-20, 20), "front arc");
        assertFalse(world.contact(160, 200), "rear arc");
        assertFalse(world.contact(30, 60), "an arc beside the contact point");
        double before = world.pose().x();
        world.drive(1, 1, 1);
        assertEquals(before, world.pose().x(), 1e-9, "no further progress");
    }

    @Test
    void obstaclesBlockAndAreSeenByRays() {
        World world = arena(List.of(new Rect(1000, 400, 100, 200)));
        assertEquals(400, world.rangeAt(0), 1e-9, "from the body edge at x=600 to the box at x=1000");
        assertEquals(400, world.rangeAt(90), 1e-9, "up to the arena wall at y=1000");
        assertEquals(400, world.rangeAt(-90), 1e-9, "down to the arena wall at y=0");
        for (int i = 0; i < 500; i++) {
            world.drive(1, 1, 0.01);
        }
        assertEquals(900, world.pose().x(), 0.01);
        assertEquals(0, world.rangeAt(0), 0.01);
        assertTrue(world.contact(-5, 5));
    }

    @Test
    void contactArcsWrapAroundTheBack() {
        World world = new World(2000, 1000, List.of(), new Pose(101, 500, 0), 100, 200, 200);
        assertTrue(world.contact(170, 190), "wall behind");
        assertFalse(world.contact(-10, 10));
    }

    @Test
    void aRobotThatDoesNotFitIsRefused() {
        assertThrows(IllegalArgumentException.class,
                () -> new World(2000, 1000, List.of(), new Pose(50, 500, 0), 100, 200, 200));
        assertThrows(IllegalArgumentException.class,
                () -> arena(List.of(new Rect(450, 450, 100, 100))));
    }

    @Test
    void anglesAreNormalised() {
        assertEquals(-170, World.normalize(190), 1e-9);
        assertEquals(180, World.normalize(-180), 1e-9);
        assertEquals(10, World.normalize(370), 1e-9);
    }
}
