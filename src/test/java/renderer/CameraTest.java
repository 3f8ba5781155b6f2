package renderer;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertSameRejection;

import java.util.MissingResourceException;

import org.junit.jupiter.api.Test;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link renderer.Camera}.
 */
class CameraTest {

    /** A camera at the origin looking at −z with up +y, view plane not yet set. */
    private static Camera originCamera() {
        return new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0));
    }

    /**
     * Test method for {@link renderer.Camera#Camera(primitives.Point3D, primitives.Vector, primitives.Vector)}.
     */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: orthogonal non-unit vectors: kept as unit copies, the caller's vectors unchanged
        Vector vTo = new Vector(0, 0, -2);
        Vector vUp = new Vector(0, 3, 0);
        Point3D p0 = new Point3D(1, 2, 3);
        Camera camera = new Camera(p0, vTo, vUp);
        assertEquals(p0, camera.getP0(), "TC01: wrong position");
        assertEquals(new Vector(0, 0, -1), camera.getVTo(), "TC01: wrong vTo");
        assertEquals(new Vector(0, 1, 0), camera.getVUp(), "TC01: wrong vUp");
        assertEquals(new Vector(1, 0, 0), camera.getVRight(), "TC01: wrong vRight");
        assertEquals(new Vector(0, 0, -2), vTo, "TC01: the caller's vTo was modified");
        assertEquals(new Vector(0, 3, 0), vUp, "TC01: the caller's vUp was modified");
        assertEquals(0, camera.getWidth(), 0, "TC01: view plane width should be 0 until set");
        assertEquals(0, camera.getHeight(), 0, "TC01: view plane height should be 0 until set");
        assertEquals(0, camera.getDistance(), 0, "TC01: view plane distance should be 0 until set");
        // TC02: a slanted frame: vTo (1,1,0), vUp (0,0,1) → vRight = vTo × vUp = (1,−1,0)/√2, unit,
        // orthogonal to both
        camera = new Camera(Point3D.ZERO, new Vector(1, 1, 0), new Vector(0, 0, 1));
        double s = 1 / Math.sqrt(2);
        Vector vRight = camera.getVRight();
        assertEquals(new Vector(s, -s, 0), vRight, "TC02: wrong vRight");
        assertEquals(1, vRight.length(), 1e-10, "TC02: vRight is not a unit vector");
        assertEquals(1, camera.getVTo().length(), 1e-10, "TC02: vTo is not a unit vector");
        assertEquals(0, vRight.dotProduct(camera.getVTo()), 1e-10, "TC02: vRight is not orthogonal to vTo");
        assertEquals(0, vRight.dotProduct(camera.getVUp()), 1e-10, "TC02: vRight is not orthogonal to vUp");
        assertEquals(camera.getVTo().crossProduct(camera.getVUp()), vRight, "TC02: vRight is not vTo × vUp");
        // TC03: vTo not orthogonal to vUp is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Camera(Point3D.ZERO, new Vector(0, 1, -1), new Vector(0, 1, 0)),
                "TC03: non-orthogonal vTo and vUp accepted");
        assertMessage(e, "orthogonal", "TC03");
        // TC04: null arguments are rejected with a message naming them (no bare NullPointerException)
        e = assertThrows(IllegalArgumentException.class, () -> new Camera(null, new Vector(0, 0, -1), new Vector(0, 1, 0)),
                "TC04: null position accepted");
        assertMessage(e, "position", "TC04");
        e = assertThrows(IllegalArgumentException.class, () -> new Camera(Point3D.ZERO, null, new Vector(0, 1, 0)),
                "TC04: null vTo accepted");
        assertMessage(e, "vTo", "TC04");
        e = assertThrows(IllegalArgumentException.class, () -> new Camera(Point3D.ZERO, new Vector(0, 0, -1), null),
                "TC04: null vUp accepted");
        assertMessage(e, "vUp", "TC04");
        // TC05: the message says what vUp would be: its part orthogonal to vTo
        e = assertThrows(IllegalArgumentException.class,
                () -> new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 1)),
                "TC05: non-orthogonal vTo and vUp accepted");
        assertMessage(e, "the part of vUp orthogonal to vTo, normalized, is ->(0.0, 1.0, 0.0)", "TC05");

        // ===== Boundary Values Tests =====
        // TC10: vTo parallel to vUp is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Camera(Point3D.ZERO, new Vector(0, 1, 0), new Vector(0, 2, 0)),
                "TC10: parallel vTo and vUp accepted");
        assertMessage(e, "orthogonal", "TC10");
        assertMessage(e, "vUp is parallel to vTo, and one orthogonal to it is", "TC10");
        // TC11: vTo almost orthogonal (dot product 1e-3 after normalising) is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Camera(Point3D.ZERO, new Vector(0, 0.001, -1), new Vector(0, 1, 0)),
                "TC11: nearly orthogonal vTo and vUp accepted");
        assertMessage(e, "orthogonal", "TC11");
    }

    /** Test method for {@link renderer.Camera#orthogonalUp(Vector, Vector)}. */
    @Test
    void testOrthogonalUp() {
        // ===== Equivalence Partitions Tests =====
        // TC01: vUp (0, 1, 1) looking down -z: (0, 1, 0)
        assertEquals(new Vector(0, 1, 0), Camera.orthogonalUp(new Vector(0, 0, -1), new Vector(0, 1, 1)),
                "TC01: wrong up vector");
        // TC02: looking slightly down, vUp (0, 1, 0): (0, 0.995, -0.0995) to 4 decimals, which a camera takes
        Vector vTo = new Vector(0, -0.1, -1);
        Vector up = Camera.orthogonalUp(vTo, new Vector(0, 1, 0));
        assertEquals(0, up.getX(), 0, "TC02: wrong x");
        assertEquals(0.995, up.getY(), 0, "TC02: y must be rounded to 0.995");
        assertEquals(-0.0995, up.getZ(), 0, "TC02: z must be rounded to -0.0995");
        assertEquals(up.normalized(), new Camera(Point3D.ZERO, vTo, up).getVUp(), "TC02: a camera must take it");
        // TC03: an oblique vTo (1, 2, 3): 5 decimals are needed, the camera takes them, the vector is unit to 1e-5
        vTo = new Vector(1, 2, 3);
        up = Camera.orthogonalUp(vTo, new Vector(0, 1, 0));
        assertEquals(new Vector(-0.16903, 0.84515, -0.50709), up, "TC03: wrong up vector");
        assertEquals(-0.16903, up.getX(), 0, "TC03: x must be rounded to 5 decimals");
        assertEquals(1, up.length(), 1e-5, "TC03: not of length 1 up to its rounding");
        assertEquals(0, new Camera(Point3D.ZERO, vTo, up).getVTo().dotProduct(up.normalized()), 1e-10,
                "TC03: a camera must take it");

        // ===== Boundary Values Tests =====
        // TC11: a vUp already orthogonal, of length 2: the unit vector along it
        assertEquals(new Vector(0, 1, 0), Camera.orthogonalUp(new Vector(0, 0, -1), new Vector(0, 2, 0)),
                "TC11: an orthogonal vUp must stay, normalized");
        // TC12: vUp parallel to vTo, either way, or within a millionth of a radian: refused
        for (Vector parallel : new Vector[] { new Vector(0, 0, -3), new Vector(0, 0, 1), new Vector(0, 1e-7, -1) }) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> Camera.orthogonalUp(new Vector(0, 0, -1), parallel), "TC12: parallel vUp accepted");
            assertMessage(e, "is parallel to vTo", "TC12");
        }
        // TC13: a vUp a hundred-thousandth off: (0, 1, 0)
        assertEquals(new Vector(0, 1, 0), Camera.orthogonalUp(new Vector(0, 0, -1), new Vector(0, 1, 1e-5)),
                "TC13: wrong up vector");
        // TC14: null: refused with the vector's name
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Camera.orthogonalUp(null, new Vector(0, 1, 0)),
                "TC14: null vTo accepted"), "vTo", "TC14");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Camera.orthogonalUp(new Vector(0, 0, 1), null),
                "TC14: null vUp accepted"), "vUp", "TC14");
    }

    /** Test method for {@link renderer.Camera#lookAt(Point3D, Point3D, Vector)}. */
    @Test
    void testLookAt() {
        // ===== Equivalence Partitions Tests =====
        // TC01: from (0, 0, 10) at the origin, up (0, 1, 0): vTo (0, 0, −1), vUp (0, 1, 0), vRight (1, 0, 0)
        Camera camera = Camera.lookAt(new Point3D(0, 0, 10), Point3D.ZERO, new Vector(0, 1, 0));
        assertEquals(new Point3D(0, 0, 10), camera.getP0(), "TC01: wrong position");
        assertEquals(new Vector(0, 0, -1), camera.getVTo(), "TC01: wrong vTo");
        assertEquals(new Vector(0, 1, 0), camera.getVUp(), "TC01: wrong vUp");
        assertEquals(new Vector(1, 0, 0), camera.getVRight(), "TC01: wrong vRight");
        // TC02: from (10, 10, 10) at the origin, up (0, 3, 0): vTo −(1, 1, 1)/√3, vUp (−1, 2, −1)/√6,
        // vRight (1, 0, −1)/√2, an orthonormal basis
        camera = Camera.lookAt(new Point3D(10, 10, 10), Point3D.ZERO, new Vector(0, 3, 0));
        double s3 = 1 / Math.sqrt(3);
        double s6 = 1 / Math.sqrt(6);
        double s2 = 1 / Math.sqrt(2);
        assertVector(-s3, -s3, -s3, camera.getVTo(), "TC02: wrong vTo");
        assertVector(-s6, 2 * s6, -s6, camera.getVUp(), "TC02: wrong vUp");
        assertVector(s2, 0, -s2, camera.getVRight(), "TC02: wrong vRight");
        assertOrthonormal(camera, "TC02");
        // TC03: an up leaning toward the direction keeps only its orthogonal part: from the origin to
        // (0, 0, −5), up (0, 1, −1): vUp (0, 1, 0)
        camera = Camera.lookAt(Point3D.ZERO, new Point3D(0, 0, -5), new Vector(0, 1, -1));
        assertVector(0, 1, 0, camera.getVUp(), "TC03: wrong vUp");
        assertOrthonormal(camera, "TC03");
        // TC04: an oblique look from (1, 2, 3) to (4, −2, 3) with up (0, 0, 1): vTo (3, −4, 0)/5, vUp (0, 0, 1),
        // vRight vTo × vUp = (−4, −3, 0)/5
        camera = Camera.lookAt(new Point3D(1, 2, 3), new Point3D(4, -2, 3), new Vector(0, 0, 1));
        assertVector(0.6, -0.8, 0, camera.getVTo(), "TC04: wrong vTo");
        assertVector(0, 0, 1, camera.getVUp(), "TC04: wrong vUp");
        assertVector(-0.8, -0.6, 0, camera.getVRight(), "TC04: wrong vRight");

        // ===== Boundary Values Tests =====
        // TC11: from and to the same point: refused, naming it
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Camera.lookAt(new Point3D(1, 2, 3), new Point3D(1, 2, 3), new Vector(0, 1, 0)),
                "TC11: from = to accepted");
        assertMessage(e, "the same point", "TC11");
        // TC12: up parallel to the direction, either way, or within a millionth of a radian: refused
        for (Vector parallel : new Vector[] { new Vector(0, 0, -2), new Vector(0, 0, 1), new Vector(0, 1e-7, 1) }) {
            e = assertThrows(IllegalArgumentException.class,
                    () -> Camera.lookAt(Point3D.ZERO, new Point3D(0, 0, -1), parallel), "TC12: parallel up accepted");
            assertMessage(e, "is parallel to the direction", "TC12");
        }
        // TC13: an up a hundred-thousandth of a radian off the direction is enough: vUp (0, 1, 0)
        camera = Camera.lookAt(Point3D.ZERO, new Point3D(0, 0, -1), new Vector(0, 1e-5, -1));
        assertVector(0, 1, 0, camera.getVUp(), "TC13: wrong vUp");
        // TC14: nulls: refused, naming the parameter
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> Camera.lookAt(null, Point3D.ZERO, new Vector(0, 1, 0)), "TC14: null from"), "from", "TC14");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> Camera.lookAt(Point3D.ZERO, null, new Vector(0, 1, 0)), "TC14: null to"), "to", "TC14");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> Camera.lookAt(Point3D.ZERO, new Point3D(0, 0, 1), null), "TC14: null up"), "up", "TC14");
    }

    /** Asserts a vector's components within 1e-12. */
    private static void assertVector(double x, double y, double z, Vector v, String message) {
        assertEquals(x, v.getX(), 1e-12, message + " (x)");
        assertEquals(y, v.getY(), 1e-12, message + " (y)");
        assertEquals(z, v.getZ(), 1e-12, message + " (z)");
    }

    /** Asserts that a camera's vTo, vUp and vRight are unit vectors, orthogonal to each other, vRight = vTo × vUp. */
    private static void assertOrthonormal(Camera camera, String tc) {
        Vector[] basis = { camera.getVTo(), camera.getVUp(), camera.getVRight() };
        for (int a = 0; a < 3; ++a) {
            assertEquals(1, basis[a].length(), 1e-12, tc + ": not a unit vector: " + basis[a]);
            for (int b = a + 1; b < 3; ++b)
                assertEquals(0, basis[a].dotProduct(basis[b]), 1e-12, tc + ": not orthogonal: " + basis[a] + ", " + basis[b]);
        }
        assertEquals(camera.getVTo().crossProduct(camera.getVUp()), camera.getVRight(), tc + ": vRight is not vTo × vUp");
    }

    /**
     * Test method for {@link renderer.Camera#setVpSize(double, double)} and
     * {@link renderer.Camera#setVpDistance(double)}.
     */
    @Test
    void testSetters() {
        Camera camera = originCamera();
        // ===== Equivalence Partitions Tests =====
        // TC01: positive values are kept (width 4, height 3, distance 10) and the setters return this camera
        assertSame(camera, camera.setVpSize(4, 3), "TC01: setVpSize does not return this");
        assertSame(camera, camera.setVpDistance(10), "TC01: setVpDistance does not return this");
        assertEquals(4, camera.getWidth(), 1e-10, "TC01: wrong width");
        assertEquals(3, camera.getHeight(), 1e-10, "TC01: wrong height");
        assertEquals(10, camera.getDistance(), 1e-10, "TC01: wrong distance");
        // TC02: negative width, height or distance is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> camera.setVpSize(-1, 3),
                "TC02: negative width accepted");
        assertMessage(e, "width", "TC02");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setVpSize(4, -3), "TC02: negative height accepted");
        assertMessage(e, "height", "TC02");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setVpDistance(-10),
                "TC02: negative distance accepted");
        assertMessage(e, "distance", "TC02");
        // TC03: NaN or infinite values are rejected
        e = assertThrows(IllegalArgumentException.class, () -> camera.setVpSize(Double.NaN, 3), "TC03: NaN width accepted");
        assertMessage(e, "width", "TC03");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setVpSize(4, Double.NaN), "TC03: NaN height accepted");
        assertMessage(e, "height", "TC03");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setVpDistance(Double.NaN),
                "TC03: NaN distance accepted");
        assertMessage(e, "distance", "TC03");
        assertThrows(IllegalArgumentException.class, () -> camera.setVpDistance(Double.POSITIVE_INFINITY),
                "TC03: infinite distance accepted");
        // TC04: a rejected value leaves the earlier settings unchanged (4, 3, 10)
        assertEquals(4, camera.getWidth(), 1e-10, "TC04: width changed by a rejected call");
        assertEquals(3, camera.getHeight(), 1e-10, "TC04: height changed by a rejected call");
        assertEquals(10, camera.getDistance(), 1e-10, "TC04: distance changed by a rejected call");

        // ===== Boundary Values Tests =====
        // TC10: zero width, height or distance is rejected
        e = assertThrows(IllegalArgumentException.class, () -> camera.setVpSize(0, 3), "TC10: zero width accepted");
        assertMessage(e, "width", "TC10");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setVpSize(4, 0), "TC10: zero height accepted");
        assertMessage(e, "height", "TC10");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setVpDistance(0), "TC10: zero distance accepted");
        assertMessage(e, "distance", "TC10");
    }

    /**
     * Test method for {@link renderer.Camera#setViewPlaneSize(double, double)} and
     * {@link renderer.Camera#setDistance(double)}, the course's names of the report's setters.
     */
    @Test
    void testCourseSetterNames() {
        Camera course = originCamera();
        Camera report = originCamera().setVpSize(4, 3).setVpDistance(10);

        // ===== Equivalence Partitions Tests =====
        // TC01: the setters return this camera and set the same view plane (4 × 3 at distance 10)
        assertSame(course, course.setViewPlaneSize(4, 3), "TC01: setViewPlaneSize does not return this");
        assertSame(course, course.setDistance(10), "TC01: setDistance does not return this");
        assertEquals(4, course.getWidth(), 1e-10, "TC01: wrong width");
        assertEquals(3, course.getHeight(), 1e-10, "TC01: wrong height");
        assertEquals(10, course.getDistance(), 1e-10, "TC01: wrong distance");
        // TC02: every pixel ray of a 5 × 4 image is the report-named camera's ray, through centres and corners
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 5; ++j) {
                assertEquals(report.constructRayThroughPixel(5, 4, j, i), course.constructRayThroughPixel(5, 4, j, i),
                        "TC02: different rays through pixel (" + j + ", " + i + ")");
                assertEquals(report.constructRayThroughPixel(5, 4, j, i, 0, 1),
                        course.constructRayThroughPixel(5, 4, j, i, 0, 1),
                        "TC02: different rays through the corner of pixel (" + j + ", " + i + ")");
            }
        // TC03: bad values get the same messages as through the report's names (negative, NaN)
        assertSameRejection(() -> originCamera().setVpSize(-1, 3), () -> originCamera().setViewPlaneSize(-1, 3), "TC03");
        assertSameRejection(() -> originCamera().setVpSize(4, Double.NaN),
                () -> originCamera().setViewPlaneSize(4, Double.NaN), "TC03");
        assertSameRejection(() -> originCamera().setVpDistance(-10), () -> originCamera().setDistance(-10), "TC03");

        // ===== Boundary Values Tests =====
        // TC10: zero width, height or distance is rejected with the same message
        assertSameRejection(() -> originCamera().setVpSize(0, 3), () -> originCamera().setViewPlaneSize(0, 3), "TC10");
        assertSameRejection(() -> originCamera().setVpSize(4, 0), () -> originCamera().setViewPlaneSize(4, 0), "TC10");
        assertSameRejection(() -> originCamera().setVpDistance(0), () -> originCamera().setDistance(0), "TC10");
        // TC11: the course's order, distance before size, gives the same camera
        Camera distanceFirst = originCamera().setDistance(10).setViewPlaneSize(4, 3);
        assertEquals(report.constructRayThroughPixel(5, 4, 0, 0), distanceFirst.constructRayThroughPixel(5, 4, 0, 0),
                "TC11: setting the distance first must give the same rays");
    }

    /**
     * Test method for {@link renderer.Camera#constructRayThroughPixel(int, int, int, int)}.
     */
    @Test
    void testConstructRayThroughPixel() {
        // camera at the origin looking at −z, up +y (so vRight = +x), view plane 3×3 at distance 1
        Camera camera = originCamera().setVpSize(3, 3).setVpDistance(1);
        // ===== Equivalence Partitions Tests =====
        // TC01: 3×3 grid, inner pixel: the centre (1,1) → (0,0,−1)
        Ray ray = camera.constructRayThroughPixel(3, 3, 1, 1);
        assertEquals(new Ray(Point3D.ZERO, new Vector(0, 0, -1)), ray, "TC01: wrong ray");
        assertEquals(1, ray.getDir().length(), 1e-10, "TC01: ray direction is not a unit vector");
        // TC02: 4×4 grid on a 4×4 view plane, inner pixel (column 1, row 2) → (−0.5, −0.5, −1)
        Camera camera4 = originCamera().setVpSize(4, 4).setVpDistance(1);
        assertEquals(new Ray(Point3D.ZERO, new Vector(-0.5, -0.5, -1)), camera4.constructRayThroughPixel(4, 4, 1, 2),
                "TC02: wrong ray");
        // TC03: a rectangular grid, 4 columns × 2 rows on an 8×4 view plane at distance 2:
        // column 3, row 0 (top right) → (3, 1, −2); column 0, row 1 (bottom left) → (−3, −1, −2)
        Camera wide = originCamera().setVpSize(8, 4).setVpDistance(2);
        assertEquals(new Ray(Point3D.ZERO, new Vector(3, 1, -2)), wide.constructRayThroughPixel(4, 2, 3, 0),
                "TC03: wrong ray for the top right pixel");
        assertEquals(new Ray(Point3D.ZERO, new Vector(-3, -1, -2)), wide.constructRayThroughPixel(4, 2, 0, 1),
                "TC03: wrong ray for the bottom left pixel");
        // TC04: the ray starts at the camera's position for a camera off the origin
        Camera moved = new Camera(new Point3D(1, 2, 3), new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(3, 3).setVpDistance(1);
        assertEquals(new Ray(new Point3D(1, 2, 3), new Vector(-1, 1, -1)), moved.constructRayThroughPixel(3, 3, 0, 0),
                "TC04: wrong ray");
        // TC05: the course's camera: looking at +z with up −y (so vRight = +x), distance 10, 4×4 pixels on
        // 8×8: inner pixel (1,1) is −1 along vRight and +1 along vUp → (−1, −1, 10)
        Camera course = new Camera(Point3D.ZERO, new Vector(0, 0, 1), new Vector(0, -1, 0)).setVpDistance(10);
        assertEquals(new Ray(Point3D.ZERO, new Vector(-1, -1, 10)),
                course.setVpSize(8, 8).constructRayThroughPixel(4, 4, 1, 1), "TC05: wrong ray");
        // TC06: a slanted camera: looking at (1,1,0) with up +z, vRight (1,−1,0)/√2, view plane 2×2 at
        // distance √2, 2×2 pixels: top left pixel (0,0) → √2·vTo − 0.5·vRight + 0.5·vUp = (1 − 0.5/√2, 1 + 0.5/√2, 0.5)
        Camera slanted = new Camera(Point3D.ZERO, new Vector(1, 1, 0), new Vector(0, 0, 1))
                .setVpSize(2, 2).setVpDistance(Math.sqrt(2));
        double s = 1 / Math.sqrt(2);
        assertEquals(new Ray(Point3D.ZERO, new Vector(1 - 0.5 * s, 1 + 0.5 * s, 0.5)),
                slanted.constructRayThroughPixel(2, 2, 0, 0), "TC06: wrong ray");

        // ===== Boundary Values Tests =====
        // **** Group: 3×3 grid on a 3×3 view plane (pixel size 1)
        // TC10: corner pixel (0,0), top left → (−1, 1, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-1, 1, -1)), camera.constructRayThroughPixel(3, 3, 0, 0),
                "TC10: wrong ray");
        // TC11: corner pixel (2,2), bottom right → (1, −1, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(1, -1, -1)), camera.constructRayThroughPixel(3, 3, 2, 2),
                "TC11: wrong ray");
        // TC12: corner pixel column 2, row 0, top right → (1, 1, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(1, 1, -1)), camera.constructRayThroughPixel(3, 3, 2, 0),
                "TC12: wrong ray");
        // TC13: side pixel column 1, row 0 (top middle) → (0, 1, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(0, 1, -1)), camera.constructRayThroughPixel(3, 3, 1, 0),
                "TC13: wrong ray");
        // TC14: side pixel column 0, row 1 (middle left) → (−1, 0, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-1, 0, -1)), camera.constructRayThroughPixel(3, 3, 0, 1),
                "TC14: wrong ray");
        // TC15: side pixel column 2, row 1 (middle right) → (1, 0, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(1, 0, -1)), camera.constructRayThroughPixel(3, 3, 2, 1),
                "TC15: wrong ray");
        // TC16: side pixel column 1, row 2 (bottom middle) → (0, −1, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(0, -1, -1)), camera.constructRayThroughPixel(3, 3, 1, 2),
                "TC16: wrong ray");

        // **** Group: 4×4 grid on a 4×4 view plane (pixel size 1), no pixel at the centre
        // TC20: corner pixel (0,0) → (−1.5, 1.5, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-1.5, 1.5, -1)), camera4.constructRayThroughPixel(4, 4, 0, 0),
                "TC20: wrong ray");
        // TC21: corner pixel (3,3) → (1.5, −1.5, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(1.5, -1.5, -1)), camera4.constructRayThroughPixel(4, 4, 3, 3),
                "TC21: wrong ray");
        // TC22: side pixel column 1, row 0 → (−0.5, 1.5, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-0.5, 1.5, -1)), camera4.constructRayThroughPixel(4, 4, 1, 0),
                "TC22: wrong ray");
        // TC23: side pixel column 0, row 2 → (−1.5, −0.5, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-1.5, -0.5, -1)), camera4.constructRayThroughPixel(4, 4, 0, 2),
                "TC23: wrong ray");
        // TC24: the pixels nearest the centre, column 2 row 1 → (0.5, 0.5, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(0.5, 0.5, -1)), camera4.constructRayThroughPixel(4, 4, 2, 1),
                "TC24: wrong ray");

        // **** Group: the course's 4×4 and 3×3 cases (camera looking at +z, up −y, distance 10)
        // TC30: 4×4 on 8×8, corner (0,0) → (−3, −3, 10)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-3, -3, 10)),
                course.setVpSize(8, 8).constructRayThroughPixel(4, 4, 0, 0), "TC30: wrong ray");
        // TC31: 4×4 on 8×8, side column 1 row 0 → (−1, −3, 10)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-1, -3, 10)),
                course.setVpSize(8, 8).constructRayThroughPixel(4, 4, 1, 0), "TC31: wrong ray");
        // TC32: 3×3 on 6×6, centre (1,1) → (0, 0, 10)
        assertEquals(new Ray(Point3D.ZERO, new Vector(0, 0, 10)),
                course.setVpSize(6, 6).constructRayThroughPixel(3, 3, 1, 1), "TC32: wrong ray");
        // TC33: 3×3 on 6×6, middle of the upper side, column 1 row 0 → (0, −2, 10)
        assertEquals(new Ray(Point3D.ZERO, new Vector(0, -2, 10)),
                course.setVpSize(6, 6).constructRayThroughPixel(3, 3, 1, 0), "TC33: wrong ray");
        // TC34: 3×3 on 6×6, middle of the left side, column 0 row 1 → (−2, 0, 10)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-2, 0, 10)),
                course.setVpSize(6, 6).constructRayThroughPixel(3, 3, 0, 1), "TC34: wrong ray");
        // TC35: 3×3 on 6×6, corner (0,0) → (−2, −2, 10)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-2, -2, 10)),
                course.setVpSize(6, 6).constructRayThroughPixel(3, 3, 0, 0), "TC35: wrong ray");

        // **** Group: a one-pixel image
        // TC40: 1×1 grid: the only pixel is the view plane's centre → (0, 0, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(0, 0, -1)), camera.constructRayThroughPixel(1, 1, 0, 0),
                "TC40: wrong ray");
    }

    /**
     * Test method for the bad-input rules of {@link renderer.Camera#constructRayThroughPixel(int, int, int, int)}.
     */
    @Test
    void testConstructRayThroughPixelBadInput() {
        Camera camera = originCamera().setVpSize(3, 3).setVpDistance(1);
        // ===== Equivalence Partitions Tests =====
        // TC01: negative image sizes are rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> camera.constructRayThroughPixel(-3, 3, 0, 0), "TC01: negative nX accepted");
        assertMessage(e, "image size", "TC01");
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, -3, 0, 0),
                "TC01: negative nY accepted");
        assertMessage(e, "image size", "TC01");
        // TC02: pixels far outside the image are rejected
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, 3, 7, 1),
                "TC02: column outside the image accepted");
        assertMessage(e, "outside", "TC02");
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, 3, 1, -5),
                "TC02: row outside the image accepted");
        assertMessage(e, "outside", "TC02");
        // TC03: the view plane size was never set → MissingResourceException naming it
        Camera noSize = originCamera().setVpDistance(1);
        MissingResourceException m = assertThrows(MissingResourceException.class,
                () -> noSize.constructRayThroughPixel(3, 3, 1, 1), "TC03: missing view plane size accepted");
        assertMessage(m, "size", "TC03");
        // TC04: the view plane distance was never set → MissingResourceException naming it
        Camera noDistance = originCamera().setVpSize(3, 3);
        m = assertThrows(MissingResourceException.class, () -> noDistance.constructRayThroughPixel(3, 3, 1, 1),
                "TC04: missing view plane distance accepted");
        assertMessage(m, "distance", "TC04");
        // TC05: neither was set → MissingResourceException
        assertThrows(MissingResourceException.class, () -> originCamera().constructRayThroughPixel(3, 3, 1, 1),
                "TC05: missing view plane accepted");

        // ===== Boundary Values Tests =====
        // TC10: zero image sizes are rejected
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(0, 3, 0, 0),
                "TC10: zero nX accepted");
        assertMessage(e, "image size", "TC10");
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, 0, 0, 0),
                "TC10: zero nY accepted");
        assertMessage(e, "image size", "TC10");
        // TC11: the first index past the image (j = nX, i = nY) is rejected
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, 3, 3, 0),
                "TC11: column nX accepted");
        assertMessage(e, "outside", "TC11");
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, 3, 0, 3),
                "TC11: row nY accepted");
        assertMessage(e, "outside", "TC11");
        // TC12: index −1 is rejected
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, 3, -1, 0),
                "TC12: column −1 accepted");
        assertMessage(e, "outside", "TC12");
        e = assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, 3, 0, -1),
                "TC12: row −1 accepted");
        assertMessage(e, "outside", "TC12");
    }

    /**
     * Test method for {@link renderer.Camera#constructRayThroughPixel(int, int, int, int, double, double)}.
     */
    @Test
    void testConstructRayThroughPixelOffset() {
        Camera camera = originCamera().setVpSize(3, 3).setVpDistance(1);
        // ===== Equivalence Partitions Tests =====
        // TC01: a point inside the centre pixel, a quarter from its left and top edges → (−0.25, 0.25, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-0.25, 0.25, -1)),
                camera.constructRayThroughPixel(3, 3, 1, 1, 0.25, 0.25), "TC01: wrong ray");
        // TC02: offset (0.5, 0.5) is the pixel's centre, as in the four-argument form
        assertEquals(camera.constructRayThroughPixel(3, 3, 0, 2), camera.constructRayThroughPixel(3, 3, 0, 2, 0.5, 0.5),
                "TC02: wrong ray");
        // TC03: offsets outside 0..1 or NaN are rejected, naming the offset
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> camera.constructRayThroughPixel(3, 3, 1, 1, 1.5, 0.5), "TC03: offset 1.5 accepted");
        assertMessage(e, "offset", "TC03");
        e = assertThrows(IllegalArgumentException.class,
                () -> camera.constructRayThroughPixel(3, 3, 1, 1, 0.5, Double.NaN), "TC03: NaN offset accepted");
        assertMessage(e, "offset", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: offset (0, 0) is the top left corner of the pixel: corner pixel (0,0) → (−1.5, 1.5, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(-1.5, 1.5, -1)),
                camera.constructRayThroughPixel(3, 3, 0, 0, 0, 0), "TC10: wrong ray");
        // TC11: offset (1, 1) is the bottom right corner: corner pixel (2,2) → (1.5, −1.5, −1)
        assertEquals(new Ray(Point3D.ZERO, new Vector(1.5, -1.5, -1)),
                camera.constructRayThroughPixel(3, 3, 2, 2, 1, 1), "TC11: wrong ray");
        // TC12: offset just below 0 is rejected
        assertThrows(IllegalArgumentException.class, () -> camera.constructRayThroughPixel(3, 3, 1, 1, -1e-3, 0.5),
                "TC12: negative offset accepted");
    }

    /**
     * Test method for {@link renderer.Camera#setFocalDistance(double)}, {@link renderer.Camera#setApertureSize(double)}
     * and {@link renderer.Camera#setSqrtApertureRays(int)}.
     */
    @Test
    void testDepthOfFieldSetters() {
        Camera camera = originCamera().setVpSize(4, 4).setVpDistance(10);
        // ===== Equivalence Partitions Tests =====
        // TC01: the defaults: a pinhole (aperture 0), the view plane (10) in focus, 9 × 9 aperture rays
        assertEquals(0, camera.getApertureSize(), 0, "TC01: the aperture must default to 0");
        assertFalse(camera.hasAperture(), "TC01: a pinhole camera has no aperture");
        assertEquals(10, camera.getFocalDistance(), 1e-10, "TC01: the view plane must be in focus by default");
        assertEquals(Camera.DEFAULT_SQRT_APERTURE_RAYS, camera.getSqrtApertureRays(), "TC01: 9 aperture rays a side");
        // TC02: values are kept (focus 250, aperture 3.5, 5 rays a side) and the setters return this camera
        assertSame(camera, camera.setFocalDistance(250), "TC02: setFocalDistance does not return this");
        assertSame(camera, camera.setApertureSize(3.5), "TC02: setApertureSize does not return this");
        assertSame(camera, camera.setSqrtApertureRays(5), "TC02: setSqrtApertureRays does not return this");
        assertEquals(250, camera.getFocalDistance(), 1e-10, "TC02: wrong focal distance");
        assertEquals(3.5, camera.getApertureSize(), 1e-10, "TC02: wrong aperture");
        assertTrue(camera.hasAperture(), "TC02: aperture 3.5 must be on");
        assertEquals(5, camera.getSqrtApertureRays(), "TC02: wrong aperture rays");
        assertEquals(5, camera.getApertureGrid().getSqrtSamples(), "TC02: the aperture grid must be 5 × 5");
        // TC03: negative, NaN or infinite values are rejected, naming the setting, and leave the old values
        double[] bad = {-1, Double.NaN, Double.POSITIVE_INFINITY};
        for (double value : bad) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> camera.setFocalDistance(value), "TC03: focal distance " + value + " accepted");
            assertMessage(e, "focal distance", "TC03");
            e = assertThrows(IllegalArgumentException.class, () -> camera.setApertureSize(value),
                    "TC03: aperture " + value + " accepted");
            assertMessage(e, "aperture size", "TC03");
        }
        assertEquals(250, camera.getFocalDistance(), 1e-10, "TC03: focal distance changed by a rejected call");
        assertEquals(3.5, camera.getApertureSize(), 1e-10, "TC03: aperture changed by a rejected call");

        // ===== Boundary Values Tests =====
        // TC11: focal distance 0 is rejected (nothing can be in focus at the camera)
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> camera.setFocalDistance(0),
                "TC11: focal distance 0 accepted");
        assertMessage(e, "focal distance", "TC11");
        // TC12: aperture 0 is accepted: the pinhole camera again
        camera.setApertureSize(0);
        assertFalse(camera.hasAperture(), "TC12: aperture 0 must be a pinhole");
        // TC13: aperture rays 0 and 1001 a side are rejected naming the setting; 1 and 1000 are accepted
        e = assertThrows(IllegalArgumentException.class, () -> camera.setSqrtApertureRays(0), "TC13: 0 accepted");
        assertMessage(e, "sqrtApertureRays", "TC13");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setSqrtApertureRays(1001), "TC13: 1001 accepted");
        assertMessage(e, "between 1 and 1000", "TC13");
        assertEquals(1, camera.setSqrtApertureRays(1).getSqrtApertureRays(), "TC13: 1 must be accepted");
        assertEquals(1000, camera.setSqrtApertureRays(1000).getSqrtApertureRays(), "TC13: 1000 must be accepted");
        // TC14: an aperture and a focal distance of 1e100 are accepted; just above, they are rejected
        // naming the setting and the bound, before any ray could overflow
        assertEquals(1e100, camera.setApertureSize(1e100).getApertureSize(), 0, "TC14: aperture 1e100 accepted");
        assertEquals(1e100, camera.setFocalDistance(1e100).getFocalDistance(), 0, "TC14: focus 1e100 accepted");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setApertureSize(1.1e100), "TC14: 1.1e100");
        assertMessage(e, "aperture size must be at most 1.0E100", "TC14");
        e = assertThrows(IllegalArgumentException.class, () -> camera.setFocalDistance(1e308), "TC14: 1e308");
        assertMessage(e, "focal distance must be at most 1.0E100", "TC14");
    }

    /**
     * Test method for
     * {@link renderer.Camera#constructRayThroughAperture(int, int, int, int, double, double, double, double)}.
     */
    @Test
    void testConstructRayThroughAperture() {
        // a slanted camera, so that every axis matters: at (1,2,3) looking along (1,1,0), up (0,0,1)
        Camera camera = new Camera(new Point3D(1, 2, 3), new Vector(1, 1, 0), new Vector(0, 0, 1)).setVpSize(8, 6)
                .setVpDistance(10).setApertureSize(2).setFocalDistance(40);
        // ===== Equivalence Partitions Tests =====
        // TC01: rays from points all over the aperture through pixel (1, 2) of 4 × 3, at (0.3, 0.8) in it:
        // each starts on the aperture (in the vRight/vUp plane through p0, within 1 of p0 along each) and
        // passes through the point where the pinhole ray meets the focal plane (40 along vTo)
        Ray pinhole = camera.constructRayThroughPixel(4, 3, 1, 2, 0.3, 0.8);
        double t = 40 / pinhole.getDir().dotProduct(camera.getVTo());
        Point3D focal = pinhole.getPoint(t);
        double[][] uv = {{0.2, 0.7}, {0.9, 0.1}, {0.5, 0.5}, {0.35, 0.95}};
        for (double[] point : uv) {
            Ray ray = camera.constructRayThroughAperture(4, 3, 1, 2, 0.3, 0.8, point[0], point[1]);
            assertEquals(0, along(ray.getP0(), camera, camera.getVTo()), 1e-10,
                    "TC01: the ray must start in the aperture's plane");
            assertEquals((point[0] - 0.5) * 2, along(ray.getP0(), camera, camera.getVRight()), 1e-10,
                    "TC01: wrong start along vRight for " + point[0]);
            assertEquals((point[1] - 0.5) * 2, along(ray.getP0(), camera, camera.getVUp()), 1e-10,
                    "TC01: wrong start along vUp for " + point[1]);
            Vector toFocal = focal.subtract(ray.getP0());
            assertEquals(0, ray.getPoint(toFocal.dotProduct(ray.getDir())).distance(focal), 1e-9,
                    "TC01: the ray must pass through the focal point");
            assertTrue(toFocal.dotProduct(ray.getDir()) > 0, "TC01: the focal point must lie ahead");
        }
        // TC02: the aperture's centre (0.5, 0.5) gives the pinhole ray
        Ray centre = camera.constructRayThroughAperture(4, 3, 1, 2, 0.3, 0.8, 0.5, 0.5);
        assertEquals(camera.getP0(), centre.getP0(), "TC02: the centre's ray starts at p0");
        assertEquals(pinhole.getDir(), centre.getDir(), "TC02: the centre's ray is the pinhole ray");

        // ===== Boundary Values Tests =====
        // TC11: aperture points on its corners (0, 0) and (1, 1) are accepted; just outside 0..1 is rejected
        Ray corner = camera.constructRayThroughAperture(4, 3, 1, 2, 0.3, 0.8, 0, 0);
        assertEquals(Math.sqrt(2), corner.getP0().distance(camera.getP0()), 1e-10, "TC11: corner (0, 0) of the aperture");
        corner = camera.constructRayThroughAperture(4, 3, 1, 2, 0.3, 0.8, 1, 1);
        assertEquals(Math.sqrt(2), corner.getP0().distance(camera.getP0()), 1e-10, "TC11: corner (1, 1) of the aperture");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> camera.constructRayThroughAperture(4, 3, 1, 2, 0.3, 0.8, -0.01, 0.5), "TC11: u = −0.01 accepted");
        assertMessage(e, "aperture offset", "TC11");
        assertThrows(IllegalArgumentException.class,
                () -> camera.constructRayThroughAperture(4, 3, 1, 2, 0.3, 0.8, 0.5, 1.01), "TC11: v = 1.01 accepted");
        assertThrows(IllegalArgumentException.class,
                () -> camera.constructRayThroughAperture(4, 3, 1, 2, 0.3, 0.8, 0.5, Double.NaN), "TC11: NaN accepted");
        // TC12: the pixel checks of constructRayThroughPixel apply too: pixel (4, 0) is outside 4 × 3
        e = assertThrows(IllegalArgumentException.class,
                () -> camera.constructRayThroughAperture(4, 3, 4, 0, 0.5, 0.5, 0.5, 0.5), "TC12: pixel (4, 0) accepted");
        assertMessage(e, "outside", "TC12");
        // TC13: without a focal distance the rays meet on the view plane (10 along vTo)
        Camera viewPlane = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpSize(4, 4)
                .setVpDistance(10).setApertureSize(2);
        Ray ray = viewPlane.constructRayThroughAperture(2, 2, 0, 0, 0.5, 0.5, 0, 1);
        assertEquals(new Point3D(-1, 1, 0), ray.getP0(), "TC13: the ray must start at the aperture's corner");
        assertEquals(new Point3D(-1, 1, -10), ray.getPoint(10),
                "TC13: the rays must meet where the pixel's centre is on the view plane");
    }

    /** The offset of a point from the camera's position along one of its axes. */
    private static double along(Point3D point, Camera camera, Vector axis) {
        Point3D p0 = camera.getP0();
        return (point.getX() - p0.getX()) * axis.getX() + (point.getY() - p0.getY()) * axis.getY()
                + (point.getZ() - p0.getZ()) * axis.getZ();
    }
}
