package renderer;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Intersectable;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import primitives.Point3D;
import primitives.Vector;

/**
 * Integration tests of {@link renderer.Camera} ray construction with the geometries' intersections:
 * the course's classic test. A camera looking at −z with up +y casts the 9 rays of a 3×3 image
 * through a 3×3 view plane at distance 1 (so the rays go through (x, y, −1) for x, y ∈ {−1, 0, 1}
 * from the camera), and the test counts all the intersection points with one body.
 */
class CameraIntegrationTest {
    /** The camera at the origin. */
    private final Camera camera = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0))
            .setVpSize(3, 3).setVpDistance(1);
    /** The camera at (0, 0, 0.5), for the big-sphere cases as in the course. */
    private final Camera camera05 = new Camera(new Point3D(0, 0, 0.5), new Vector(0, 0, -1), new Vector(0, 1, 0))
            .setVpSize(3, 3).setVpDistance(1);

    /**
     * Casts the 9 rays of a 3×3 image and counts all their intersection points with a body.
     *
     * @param cam  the camera
     * @param body the body
     * @return the total number of intersection points
     */
    private static int countIntersections(Camera cam, Intersectable body) {
        int count = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                List<Point3D> points = body.findIntersections(cam.constructRayThroughPixel(3, 3, j, i));
                if (points != null) {
                    assertFalse(points.isEmpty(), "an empty list was returned instead of null");
                    count += points.size();
                }
            }
        return count;
    }

    /**
     * Camera rays against spheres.
     */
    @Test
    void testCameraSphereIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: small sphere (0,0,−3) r1 in front: only the centre ray (along −z) hits it; the side and
        // corner rays pass at distance √4.5 and √6 from the centre (> 1) (2 points)
        assertEquals(2, countIntersections(camera, new Sphere(new Point3D(0, 0, -3), 1)),
                "TC01: wrong number of intersection points");
        // TC02: big sphere (0,0,−2.5) r2.5, camera at (0,0,0.5): the centre is 3 from the camera; the
        // corner rays pass at √6 < 2.5 and the side rays at √4.5 < 2.5, so all 9 rays cross it (18 points)
        assertEquals(18, countIntersections(camera05, new Sphere(new Point3D(0, 0, -2.5), 2.5)),
                "TC02: wrong number of intersection points");
        // TC03: medium sphere (0,0,−2) r2, camera at (0,0,0.5): the centre is 2.5 from the camera; the
        // corner rays pass at √(6.25 − 6.25/3) ≈ 2.04 > 2 (miss), the side rays at √3.125 ≈ 1.77 < 2
        // and the centre ray through the centre (5 rays × 2 = 10 points)
        assertEquals(10, countIntersections(camera05, new Sphere(new Point3D(0, 0, -2), 2)),
                "TC03: wrong number of intersection points");
        // TC04: sphere (0,0,−1) r4 containing the camera: every ray leaves it once (9 points)
        assertEquals(9, countIntersections(camera, new Sphere(new Point3D(0, 0, -1), 4)),
                "TC04: wrong number of intersection points");
        // TC05: sphere (0,0,1) r0.5 behind the camera (0 points)
        assertEquals(0, countIntersections(camera, new Sphere(new Point3D(0, 0, 1), 0.5)),
                "TC05: wrong number of intersection points");
    }

    /**
     * Camera rays against planes.
     */
    @Test
    void testCameraPlaneIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: plane z = −5 parallel to the view plane: every ray hits it (9 points)
        assertEquals(9, countIntersections(camera, new Plane(new Point3D(0, 0, -5), new Vector(0, 0, 1))),
                "TC01: wrong number of intersection points");
        // TC02: plane through (0,0,−5) slightly tilted, normal (0,1,2): for a ray (x, y, −1),
        // n·d = y − 2 ≠ 0 and t = −10 / (y − 2) > 0 for y ∈ {−1, 0, 1} (9 points)
        assertEquals(9, countIntersections(camera, new Plane(new Point3D(0, 0, -5), new Vector(0, 1, 2))),
                "TC02: wrong number of intersection points");
        // TC03: plane through (0,0,−5) steeply tilted, normal (0,1,1): n·d = y − 1, so the top row (y = 1)
        // is parallel to the plane and misses it; the other rows hit it at t = −5 / (y − 1) > 0 (6 points)
        assertEquals(6, countIntersections(camera, new Plane(new Point3D(0, 0, -5), new Vector(0, 1, 1))),
                "TC03: wrong number of intersection points");
        // TC04: the plane z = 5 behind the camera (0 points)
        assertEquals(0, countIntersections(camera, new Plane(new Point3D(0, 0, 5), new Vector(0, 0, 1))),
                "TC04: wrong number of intersection points");
    }

    /**
     * Camera rays against triangles. The rays meet the plane z = −2 at (2x, 2y) for x, y ∈ {−1, 0, 1}.
     * The course's query takes a triangle as open: a ray through an edge or a vertex does not count.
     */
    @Test
    void testCameraTriangleIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: small triangle (0,1,−2),(1,−1,−2),(−1,−1,−2): only (0,0) lies inside it; (0,2) is above
        // the apex and (0,−2) below the base, the others beyond the sides (1 point)
        assertEquals(1, countIntersections(camera,
                new Triangle(new Point3D(0, 1, -2), new Point3D(1, -1, -2), new Point3D(-1, -1, -2))),
                "TC01: wrong number of intersection points");
        // TC02: tall triangle (0,20,−2),(1,−1,−2),(−1,−1,−2): at height y its half-width is (20 − y)/21,
        // so (0,0) and (0,2) are inside (half-width 18/21 at y = 2), (±2, y) and (0,−2) are outside (2 points)
        assertEquals(2, countIntersections(camera,
                new Triangle(new Point3D(0, 20, -2), new Point3D(1, -1, -2), new Point3D(-1, -1, -2))),
                "TC02: wrong number of intersection points");

        // ===== Boundary Values Tests =====
        // TC10: triangle (0,2,−2),(2,−2,−2),(−2,−2,−2) whose base edge y = −2 holds the three bottom-row
        // hits (−2,−2), (0,−2), (2,−2) — two of them are vertices — and whose apex is the top-middle hit
        // (0,2); (0,0) is inside, (±2,0) and (±2,2) outside. The course's query takes the triangle as open,
        // so only (0,0) counts (1 point)
        assertEquals(1, countIntersections(camera,
                new Triangle(new Point3D(0, 2, -2), new Point3D(2, -2, -2), new Point3D(-2, -2, -2))),
                "TC10: wrong number of intersection points");
    }
}
