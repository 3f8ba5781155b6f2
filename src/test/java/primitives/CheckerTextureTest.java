package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

import geometries.Plane;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * Unit tests for {@link CheckerTexture}: the colour at known points, the squares' edges, and a
 * chequered floor through the ray tracer (the texture tints the diffuse light and the emission).
 */
class CheckerTextureTest {
    private static final Color LIGHT = new Color(200, 150, 100);
    private static final Color DARK = new Color(51, 0, 255);
    private final CheckerTexture checker = new CheckerTexture(LIGHT, DARK, 10);

    /** Test method for {@link CheckerTexture#CheckerTexture(Color, Color, double)}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the colours and the size are kept
        assertSame(LIGHT, checker.getColor1(), "TC01: wrong first colour");
        assertSame(DARK, checker.getColor2(), "TC01: wrong second colour");
        assertEquals(10, checker.getSize(), 0, "TC01: wrong size");
        // TC02: a null colour, a negative or NaN size are refused
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new CheckerTexture(null, DARK, 1),
                "TC02: null colour"), "first colour", "TC02");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new CheckerTexture(LIGHT, DARK, -1),
                "TC02: negative size"), "size", "TC02");
        assertThrows(IllegalArgumentException.class, () -> new CheckerTexture(LIGHT, DARK, Double.NaN),
                "TC02: NaN size");
        // ===== Boundary Values Tests =====
        // TC11: size 0 is refused
        assertThrows(IllegalArgumentException.class, () -> new CheckerTexture(LIGHT, DARK, 0), "TC11: size 0");
    }

    /** Test method for {@link CheckerTexture#getColor(double, double)}. */
    @Test
    void testGetColor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: inside the square at the origin: the first colour
        assertSame(LIGHT, checker.getColor(5, 5), "TC01: square (0, 0)");
        // TC02: one square along u or along v: the second colour; one along both: the first
        assertSame(DARK, checker.getColor(15, 5), "TC02: square (1, 0)");
        assertSame(DARK, checker.getColor(5, 15), "TC02: square (0, 1)");
        assertSame(LIGHT, checker.getColor(15, 15), "TC02: square (1, 1)");
        // TC03: negative coordinates continue the pattern: (−5, 5) is square (−1, 0)
        assertSame(DARK, checker.getColor(-5, 5), "TC03: square (-1, 0)");
        assertSame(LIGHT, checker.getColor(-5, -5), "TC03: square (-1, -1)");
        // ===== Boundary Values Tests =====
        // TC11: a square's low edges belong to it, its high edges to the next
        assertSame(LIGHT, checker.getColor(0, 0), "TC11: the origin");
        assertSame(DARK, checker.getColor(10, 0), "TC11: u = 10 starts square (1, 0)");
        assertSame(LIGHT, checker.getColor(Math.nextDown(10.0), 0), "TC11: just below u = 10");
        assertSame(DARK, checker.getColor(-1e-12, 0), "TC11: just below u = 0");
    }

    /**
     * Test method for {@link CheckerTexture} through {@link RayTracerBasic}: a chequered floor (kD 0.5,
     * emission 100) under a light of 100 straight down and no ambient light; a ray straight down sees
     * (kD · 100 + 100) · colour / 255 on each square.
     */
    @Test
    void testTintsDiffuseAndEmission() {
        Scene scene = new Scene("chequered floor").setAmbientLight(new AmbientLight());
        scene.geometries.add(new Plane(Point3D.ZERO, new Vector(0, 1, 0)).setEmission(new Color(100, 100, 100))
                .setMaterial(new Material().setKd(0.5)).setTexture(checker));
        scene.lights.add(new DirectionalLight(new Color(100, 100, 100), new Vector(0, -1, 0)));
        RayTracerBasic tracer = new RayTracerBasic(scene);
        Vector down = new Vector(0, -1, 0);
        // ===== Equivalence Partitions Tests =====
        // TC01: on a light square (u = x = 5, v = −z = 5): 150 · (200, 150, 100) / 255
        assertColor(150 * 200 / 255.0, 150 * 150 / 255.0, 150 * 100 / 255.0,
                tracer.traceRay(new Ray(new Point3D(5, 10, -5), down)), "TC01: a light square");
        // TC02: on a dark square (x = 15): 150 · (51, 0, 255) / 255
        assertColor(30, 0, 150, tracer.traceRay(new Ray(new Point3D(15, 10, -5), down)), "TC02: a dark square");
        // ===== Boundary Values Tests =====
        // TC11: in shadow (the light blocked by a plane above) only the emission is left, tinted: 100 · colour / 255
        scene.geometries.add(new Plane(new Point3D(0, 20, 0), new Vector(0, 1, 0)));
        assertColor(20, 0, 100, new RayTracerBasic(scene).traceRay(new Ray(new Point3D(15, 10, -5), down)),
                "TC11: in shadow");
    }
}
