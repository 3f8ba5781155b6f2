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

        // ===== Boundary Values Tests =====
        // TC10: vTo parallel to vUp is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Camera(Point3D.ZERO, new Vector(0, 1, 0), new Vector(0, 2, 0)),
                "TC10: parallel vTo and vUp accepted");
        assertMessage(e, "orthogonal", "TC10");
        // TC11: vTo almost orthogonal (dot product 1e-3 after normalising) is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Camera(Point3D.ZERO, new Vector(0, 0.001, -1), new Vector(0, 1, 0)),
                "TC11: nearly orthogonal vTo and vUp accepted");
        assertMessage(e, "orthogonal", "TC11");
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
}
