package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link SpreadSquare}: where the spread rays of glossy and blurry surfaces go.
 */
class SpreadSquareTest {
    private static final double DELTA = 1e-9;
    private static final Point3D POINT = new Point3D(1, 2, 3);
    /** The floor's normal. */
    private static final Vector UP = new Vector(0, 0, 1);

    /**
     * Where a ray crosses the plane at unit distance along the sharp direction r, as an offset from r:
     * d / (d·r) − r.
     */
    private static Vector offset(Ray ray, Vector r) {
        Vector d = ray.getDir();
        return d.scale(1 / d.dotProduct(r)).subtract(r);
    }

    /** Test method for {@link SpreadSquare#ray(double, double)}: the square's geometry. */
    @Test
    void testRayGeometry() {
        // a reflected ray leaving the floor at 60° from the normal, the square's half-edge 0.2
        Vector r = new Vector(Math.sin(Math.PI / 3), 0, Math.cos(Math.PI / 3));
        Ray sharp = new Ray(POINT, r, UP);
        SpreadSquare square = new SpreadSquare(POINT, sharp, UP, 0.2);

        // ===== Equivalence Partitions Tests =====
        // TC01: the corner (0, 0) is h·√2 = 0.2828 off the sharp ray at unit distance, perpendicular to it
        Ray corner = square.ray(0, 0);
        Vector cornerOffset = offset(corner, r);
        assertEquals(0.2 * Math.sqrt(2), cornerOffset.length(), DELTA, "TC01: the corner must be h·√2 off");
        assertEquals(0, cornerOffset.dotProduct(r), DELTA, "TC01: the square must be perpendicular to the sharp ray");
        // TC02: the opposite corner (1, 1) is the mirror image of (0, 0) through the sharp ray
        Vector opposite = offset(square.ray(Math.nextDown(1.0), Math.nextDown(1.0)), r);
        assertEquals(0, opposite.add(cornerOffset).length(), 1e-6, "TC02: opposite corners must be symmetric");
        // TC03: the corners (1, 0) and (0, 1) make a square: the two edges from (0, 0) are perpendicular and 0.4 long
        Vector edgeU = offset(square.ray(Math.nextDown(1.0), 0), r).subtract(cornerOffset);
        Vector edgeV = offset(square.ray(0, Math.nextDown(1.0)), r).subtract(cornerOffset);
        assertEquals(0.4, edgeU.length(), 1e-6, "TC03: an edge must be 2h = 0.4 long");
        assertEquals(0.4, edgeV.length(), 1e-6, "TC03: an edge must be 2h = 0.4 long");
        assertEquals(0, edgeU.dotProduct(edgeV), 1e-6, "TC03: the edges must be perpendicular");
        // TC04: a spread ray starts DELTA off the surface, on the side it leaves to (up)
        assertEquals(POINT.getZ() + Ray.DELTA, corner.getP0().getZ(), DELTA, "TC04: the head must move DELTA up");

        // ===== Boundary Values Tests =====
        // TC11: the centre (0.5, 0.5) is the sharp direction itself
        assertEquals(1, square.ray(0.5, 0.5).getDir().dotProduct(r), DELTA, "TC11: the centre must be the sharp ray");
    }

    /**
     * Test method for {@link SpreadSquare#ray(double, double)}: rays that would leave on the wrong side
     * of the surface are replaced by the sharp ray.
     */
    @Test
    void testRaySide() {
        // a reflected ray grazing the floor, 10° above it, the square's half-edge 0.5 (26.6° along its axes)
        double grazing = Math.toRadians(10);
        Vector r = new Vector(Math.cos(grazing), 0, Math.sin(grazing));
        Ray sharp = new Ray(POINT, r, UP);
        SpreadSquare square = new SpreadSquare(POINT, sharp, UP, 0.5);
        // ===== Equivalence Partitions Tests =====
        // TC01: the rays of the square's lower part would go into the floor: replaced (some), the rest kept,
        // each kept one going up
        int replaced = 0;
        int kept = 0;
        for (int a = 0; a < 10; ++a)
            for (int b = 0; b < 10; ++b) {
                Ray ray = square.ray((a + 0.5) / 10, (b + 0.5) / 10);
                if (ray == sharp)
                    ++replaced;
                else {
                    ++kept;
                    assertTrue(ray.getDir().getZ() > 0, "TC01: a kept reflected ray must go up, got " + ray);
                }
            }
        assertTrue(replaced > 0 && kept > 0, "TC01: expected both replaced and kept rays, got " + replaced + " and "
                + kept);
        // TC02: a refracted ray going down through a pane: a ray that would come back up is replaced
        Vector down = new Vector(Math.cos(grazing), 0, -Math.sin(grazing));
        Ray through = new Ray(POINT, down, UP);
        SpreadSquare pane = new SpreadSquare(POINT, through, UP, 0.5);
        Vector z = new Vector(0, 0, 1);
        Ray upward = pane.ray(0.5 + 0.45, 0.5);
        Ray downward = pane.ray(0.5 - 0.45, 0.5);
        assertTrue(upward == through || downward == through, "TC02: the ray that would come back up must be replaced");
        Ray keptRay = upward == through ? downward : upward;
        assertNotSame(through, keptRay, "TC02: the ray that goes on down must be kept");
        assertTrue(keptRay.getDir().dotProduct(z) < 0, "TC02: a kept refracted ray must go on down");

        // ===== Boundary Values Tests =====
        // TC11: a sharp ray in the surface's plane (grazing exactly): every ray is the sharp one
        Ray inPlane = new Ray(POINT, new Vector(1, 0, 0));
        SpreadSquare flat = new SpreadSquare(POINT, inPlane, UP, 0.3);
        assertSame(inPlane, flat.ray(0.1, 0.9), "TC11: a grazing sharp ray must be kept for every sample");
    }
}
