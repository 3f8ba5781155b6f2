package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertColor;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import geometries.Polygon;
import geometries.Sphere;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;
import testutil.TestMeshes;

/**
 * Unit tests for {@link Refraction}: Snell's law, total internal reflection and Schlick's approximation
 * in closed form, and through {@link RayTracerBasic}: the offset of a ray through a slab, the critical
 * angle, the reflected share, and a ball lens turning the floor upside down.
 */
class RefractionTest {
    private static final double DELTA = 1e-12;
    private static final double GLASS = 1.5;
    /** The outward normal of a surface facing up. */
    private static final Vector UP = new Vector(0, 1, 0);

    /** The unit direction going down at an angle from the vertical, toward +x. */
    private static Vector down(double degrees) {
        double angle = Math.toRadians(degrees);
        return new Vector(Math.sin(angle), -Math.cos(angle), 0);
    }

    /** Test method for {@link Refraction#direction()}: Snell's law, entering and leaving. */
    @Test
    void testDirection() {
        // ===== Equivalence Partitions Tests =====
        // TC01: entering glass at 30°: sin θ2 = sin 30° / 1.5 = 1/3, the ray bends toward the normal
        Refraction entering = new Refraction(down(30), UP, GLASS);
        assertFalse(entering.isTotal(), "TC01: entering glass is never total reflection");
        Vector t = entering.direction();
        assertEquals(1.0 / 3, t.getX(), DELTA, "TC01: sin θ2 must be 1/3");
        assertEquals(-Math.sqrt(8.0 / 9), t.getY(), DELTA, "TC01: cos θ2 must be √(8/9)");
        assertEquals(0, t.getZ(), DELTA, "TC01: the ray stays in its plane of incidence");
        // TC02: leaving the glass at that angle (the ray going down, the outward normal of the bottom face
        // down): sin θ = 1.5 · 1/3 = 1/2, the ray is parallel to the one that entered
        Vector out = new Refraction(t, new Vector(0, -1, 0), GLASS).direction();
        assertEquals(down(30).getX(), out.getX(), DELTA, "TC02: a slab's exit ray is parallel to its entry (x)");
        assertEquals(down(30).getY(), out.getY(), DELTA, "TC02: a slab's exit ray is parallel to its entry (y)");
        // TC03: a ray from inside the body meeting the surface from its inner side leaves: away from the normal
        assertTrue(new Refraction(new Vector(1.0 / 3, Math.sqrt(8.0 / 9), 0), UP, GLASS).direction().getX() > 0.49,
                "TC03: leaving, the ray bends away from the normal");

        // ===== Boundary Values Tests =====
        // TC11: at normal incidence the ray goes straight on
        Vector straight = new Refraction(down(0), UP, GLASS).direction();
        assertEquals(-1, straight.getY(), DELTA, "TC11: normal incidence does not bend");
        // TC12: ior 1 does not bend a ray at any angle
        Vector same = new Refraction(down(70), UP, 1).direction();
        assertEquals(down(70).getX(), same.getX(), DELTA, "TC12: ior 1 must not bend (x)");
        assertEquals(down(70).getY(), same.getY(), DELTA, "TC12: ior 1 must not bend (y)");
        // TC13: a ray along the surface neither enters nor leaves
        assertThrows(IllegalArgumentException.class, () -> new Refraction(new Vector(1, 0, 0), UP, GLASS),
                "TC13: a ray along the surface");
    }

    /** Test method for {@link Refraction#isTotal()}: the critical angle arcsin(1/1.5) = 41.81°. */
    @Test
    void testTotalInternalReflection() {
        double critical = Math.toDegrees(Math.asin(1 / GLASS));
        Vector bottom = new Vector(0, -1, 0);
        // ===== Equivalence Partitions Tests =====
        // TC01: leaving glass at 30°: refracted; at 60°: totally reflected, its reflectance 1
        assertFalse(new Refraction(down(30), bottom, GLASS).isTotal(), "TC01: 30° leaves the glass");
        Refraction total = new Refraction(down(60), bottom, GLASS);
        assertTrue(total.isTotal(), "TC01: 60° is past the critical angle");
        assertEquals(1, total.reflectance(), 0, "TC01: total internal reflection reflects everything");

        // ===== Boundary Values Tests =====
        // TC11: just below the critical angle the ray leaves, grazing; just above, it does not
        Refraction below = new Refraction(down(critical - 1e-6), bottom, GLASS);
        assertFalse(below.isTotal(), "TC11: just below the critical angle");
        assertEquals(0, below.direction().getY(), 1e-3, "TC11: the ray leaves along the surface");
        assertTrue(new Refraction(down(critical + 1e-6), bottom, GLASS).isTotal(), "TC11: just above it");
        // TC12: entering, even near grazing, never reflects totally
        assertFalse(new Refraction(down(89.9), UP, GLASS).isTotal(), "TC12: entering near grazing");
    }

    /** Test method for {@link Refraction#schlick} and {@link Refraction#reflectance()}. */
    @Test
    void testSchlick() {
        // ===== Equivalence Partitions Tests =====
        // TC01: R0 = ((n − 1)/(n + 1))²: 0.04 for glass at normal incidence, entering or leaving
        assertEquals(0.04, new Refraction(down(0), UP, GLASS).reflectance(), DELTA, "TC01: R0 entering");
        assertEquals(0.04, new Refraction(down(0), new Vector(0, -1, 0), GLASS).reflectance(), DELTA,
                "TC01: R0 leaving");
        assertEquals(Math.pow(1.42 / 3.42, 2), Refraction.schlick(1, 2.42, 1), DELTA, "TC01: diamond's R0");
        // TC02: at 60° entering: R0 + (1 − R0)(1 − cos 60°)^5 = 0.04 + 0.96/32 = 0.07
        assertEquals(0.07, new Refraction(down(60), UP, GLASS).reflectance(), DELTA, "TC02: at 60°");
        // TC03: leaving, the angle that counts is the refracted one, in the air: leaving at 30° refracts at
        // 48.59° (sin = 0.75), R = 0.04 + 0.96 (1 − √(1 − 0.5625))^5
        assertEquals(0.04 + 0.96 * Math.pow(1 - Math.sqrt(1 - 0.5625), 5),
                new Refraction(down(30), new Vector(0, -1, 0), GLASS).reflectance(), DELTA, "TC03: leaving at 30°");

        // ===== Boundary Values Tests =====
        // TC11: near grazing almost all is reflected: at 89°, 0.04 + 0.96 (1 − cos 89°)^5 = 0.919
        assertEquals(0.04 + 0.96 * Math.pow(1 - Math.cos(Math.toRadians(89)), 5),
                new Refraction(down(89), UP, GLASS).reflectance(), 1e-9, "TC11: near grazing");
        assertTrue(new Refraction(down(89), UP, GLASS).reflectance() > 0.9, "TC11: near grazing, above 90 %");
        // TC12: between equal media nothing is reflected at normal incidence
        assertEquals(0, Refraction.schlick(1, 1, 1), 0, "TC12: R0 of ior 1");
    }

    // ===== through the ray tracer =====

    private static final Color WHITE = new Color(1000, 1000, 1000);
    private static final double THICKNESS = 10;

    /** Clear glass of ior 1.5 (kT 1), with Fresnel or not. */
    private static Material glass(boolean fresnel) {
        return new Material().setKt(1).setIor(GLASS).setFresnel(fresnel);
    }

    /** The colour a ray sees from a point, going down at an angle, by a wide slab of glass (y from 0 to 10) and strips. */
    private static Color trace(Material glass, Point3D start, double degrees, Polygon... strips) {
        Scene scene = new Scene("slab");
        scene.geometries.add(TestMeshes.cuboid(-1000, 0, -1000, 1000, THICKNESS, 1000).setMaterial(glass));
        scene.geometries.add(strips);
        return new RayTracerBasic(scene).traceRay(new Ray(start, down(degrees)));
    }

    /** A white square, emission {@link #WHITE}, in the plane y = h, over x from x0 to x1. */
    private static Polygon strip(double h, double x0, double x1) {
        return (Polygon) new Polygon(new Point3D(x0, h, -500), new Point3D(x1, h, -500), new Point3D(x1, h, 500),
                new Point3D(x0, h, 500)).setEmission(WHITE);
    }

    /**
     * Where a ray at 45° from y = 50, going down toward +x, must start to see the edge x = 0 of a white
     * floor at a height under the slab (found by bisection, to 1e-9).
     */
    private static double edgeStart(Material slab, double floor) {
        double dark = -400;
        double lit = 0;
        while (lit - dark > 1e-9) {
            double middle = (dark + lit) / 2;
            if (trace(slab, new Point3D(middle, 50, 0), 45, strip(floor, 0, 1000)).getR() > 500)
                lit = middle;
            else
                dark = middle;
        }
        return lit;
    }

    /**
     * Test method for {@link RayTracerBasic#traceRay(Ray)} through a slab: a ray at 45° from y = 50 through
     * the slab (y from 0 to 10) onto the floor y = −100, white for x &gt; 0. Entering, it bends to
     * sin θ2 = sin 45° / 1.5, and it leaves parallel to itself, shifted: it sees the floor's edge from
     * x = −(139.9 tan 45° + 9.9 tan θ2) (each ray's head moves DELTA = 0.1 into the medium it enters, so it
     * crosses 9.9 units of glass and 139.9 of air).
     */
    @Test
    void testSlabOffset() {
        double sinT = Math.sin(Math.PI / 4) / GLASS;
        double tanT = sinT / Math.sqrt(1 - sinT * sinT);
        double edge = edgeStart(glass(false), -100);
        // ===== Equivalence Partitions Tests =====
        // TC01: the edge is seen from the start Snell's law gives: the shift against unbent glass is
        // 9.9·(tan 45° − tan θ2) = 4.61 units
        assertEquals(-(139.9 + 9.9 * tanT), edge, 1e-6, "TC01: the slab shifts the ray by Snell's law");
        // TC02: the ray leaves parallel to itself: a floor 100 lower is seen 100 · tan 45° farther back
        assertEquals(100, edge - edgeStart(glass(false), -200), 1e-6, "TC02: the exit ray is parallel");

        // ===== Boundary Values Tests =====
        // TC11: without an ior the same slab does not bend the ray: the edge is seen from x = −149.8
        assertEquals(-149.8, edgeStart(new Material().setKt(1), -100), 1e-6, "TC11: straight-through glass");
    }

    /**
     * Test method for {@link RayTracerBasic#traceRay(Ray)} at total internal reflection: a ray inside the
     * slab meets its bottom at 60°; it cannot leave, and its whole share kT = 1 goes to the reflection,
     * which sees a white strip inside the glass (at y = 5, x from 3 to 9, where it rises at 60°).
     */
    @Test
    void testTotalReflectionTakesTheShare() {
        Polygon inside = strip(5, 3, 9);
        Polygon floor = strip(-50, -1000, 1000);
        // from (−5·tan 60°, 5, 0) down at 60°: meets the bottom at x = 0
        Point3D start = new Point3D(-5 * Math.tan(Math.PI / 3), 5 - 1e-3, 0);
        // ===== Equivalence Partitions Tests =====
        // TC01: past the critical angle, the reflection sees the strip: white, weight kT + kR = 1
        assertColor(WHITE, trace(glass(false), start, 60, inside, floor), "TC01: total internal reflection");

        // ===== Boundary Values Tests =====
        // TC11: at 30° the ray leaves the glass and sees the white floor below, not the strip above
        Point3D start30 = new Point3D(-5 * Math.tan(Math.PI / 6), 5 - 1e-3, 0);
        assertColor(WHITE, trace(glass(false), start30, 30, inside, floor), "TC11: below the critical angle");
        assertEquals(0, trace(glass(false), start30, 30, inside).getR(), 0,
                "TC11: without the floor, nothing is seen: the strip is not reflected");
    }

    /**
     * Test method for {@link RayTracerBasic#traceRay(Ray)} with Fresnel: a ray meeting the slab's top at
     * 30° reflects R(30°) = 0.04 + 0.96 (1 − cos 30°)^5 of its light, onto a narrow white strip above (the
     * second reflection, off the slab's bottom, comes out 7 units aside and misses it).
     */
    @Test
    void testFresnelShare() {
        double r = 0.04 + 0.96 * Math.pow(1 - Math.cos(Math.PI / 6), 5);
        // the ray meets the top (y = 10) at x = 0; its reflection rises to y = 20 at x = 10·tan 30° = 5.77
        Point3D start = new Point3D(-5 * Math.tan(Math.PI / 6), 15, 0);
        Polygon above = strip(20, 4.77, 6.77);
        // ===== Equivalence Partitions Tests =====
        // TC01: the strip is seen with the weight R(30°)
        assertColor(WHITE.scale(r), trace(glass(true), start, 30, above), "TC01: Schlick's share is reflected");
        // ===== Boundary Values Tests =====
        // TC11: without Fresnel, clear glass reflects nothing
        assertEquals(0, trace(glass(false), start, 30, above).getR(), 0,
                "TC11: without Fresnel nothing is reflected");
    }

    /**
     * Test method for {@link RayTracerBasic} in a render: a ball lens. Seen from above, a glass sphere of
     * radius 40 and ior 1.5 (focal length 1.5 · 40 = 60 from its centre) over a floor 100 below its centre,
     * red where x &gt; 0 and blue where x &lt; 0, shows the floor inverted: red left of the centre, blue right.
     */
    @Test
    void testLensInversion() {
        ImageWriter lens = renderLens("lens", new Material().setKt(1).setIor(GLASS));
        ImageWriter course = renderLens("straight", new Material().setKt(1));
        // ===== Equivalence Partitions Tests =====
        // TC01: outside the sphere the floor is as it is: red right, blue left
        assertTrue(lens.getPixel(58, 30).getRed() > 200 && lens.getPixel(1, 30).getBlue() > 200,
                "TC01: the floor outside the lens");
        // TC02: through the lens, 10 and 20 units off its centre, the floor is upside down
        for (int offset : new int[] { 5, 10 }) {
            assertTrue(lens.getPixel(30 + offset, 30).getBlue() > 200, "TC02: right of centre sees blue, " + offset);
            assertTrue(lens.getPixel(29 - offset, 30).getRed() > 200, "TC02: left of centre sees red, " + offset);
        }
        // ===== Boundary Values Tests =====
        // TC11: without an ior the course's straight-through glass shows the floor as it is
        assertTrue(course.getPixel(40, 30).getRed() > 200 && course.getPixel(19, 30).getBlue() > 200,
                "TC11: straight-through glass does not invert");
    }

    /** Renders the ball lens of {@link #testLensInversion} (60 × 60, 120 units wide, from above). */
    private static ImageWriter renderLens(String name, Material glass) {
        Scene scene = new Scene(name);
        scene.geometries.add(new Sphere(Point3D.ZERO, 40).setMaterial(glass),
                new Polygon(new Point3D(0, -100, -500), new Point3D(500, -100, -500), new Point3D(500, -100, 500),
                        new Point3D(0, -100, 500)).setEmission(new Color(255, 0, 0)),
                new Polygon(new Point3D(-500, -100, -500), new Point3D(0, -100, -500), new Point3D(0, -100, 500),
                        new Point3D(-500, -100, 500)).setEmission(new Color(0, 0, 255)));
        ImageWriter image = new ImageWriter(name, 60, 60, Path.of("target", "test-images", "glass"));
        Render render = new Render().setImageWriter(image)
                .setCamera(new Camera(new Point3D(0, 1000, 0), new Vector(0, -1, 0), new Vector(0, 0, -1))
                        .setVpSize(120, 120).setVpDistance(1000))
                .setRayTracer(new RayTracerBasic(scene));
        render.renderImage();
        render.writeToImage();
        return image;
    }
}
