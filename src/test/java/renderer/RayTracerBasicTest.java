package renderer;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertColor;

import org.junit.jupiter.api.Test;

import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * Unit tests for {@link RayTracerBasic}: exact colours of single rays under the Phong model, shadows,
 * transparency, reflection and refraction.
 */
class RayTracerBasicTest {
    private static final Vector DOWN = new Vector(0, 0, -1);
    /** A ray from above straight down onto the origin. */
    private static final Ray RAY_DOWN = new Ray(new Point3D(0, 0, 100), DOWN);

    /** A floor plane z = 0 facing up, with the given material and emission. */
    private static Plane floor(Material material, Color emission) {
        Plane plane = new Plane(Point3D.ZERO, new Vector(0, 0, 1));
        plane.setMaterial(material).setEmission(emission);
        return plane;
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: background, emission and ambient light. */
    @Test
    void testTraceRayNoLights() {
        Color background = new Color(10, 20, 30);
        Scene scene = new Scene("no lights").setBackground(background)
                .setAmbientLight(new AmbientLight(new Color(100, 50, 20), 0.5));
        scene.geometries.add(floor(new Material(), new Color(1, 2, 3)));
        RayTracerBasic tracer = new RayTracerBasic(scene);

        // ===== Equivalence Partitions Tests =====
        // TC01: a ray that hits nothing sees the background (10, 20, 30)
        assertColor(background, tracer.traceRay(new Ray(new Point3D(0, 0, 100), new Vector(0, 0, 1))),
                "TC01: a ray that hits nothing must see the background");
        // TC02: a ray hitting the floor sees emission + ambient = (1+50, 2+25, 3+10)
        assertColor(new Color(51, 27, 13), tracer.traceRay(RAY_DOWN),
                "TC02: with no lights the colour is emission plus ambient");
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: the Phong diffuse and specular terms. */
    @Test
    void testTraceRayPhong() {
        // ===== Equivalence Partitions Tests =====
        // TC01: diffuse only, light at 60° from the normal: kD·|n·l|·I = 0.5·0.5·(200,100,40) = (50,25,10)
        Scene diffuse = new Scene("diffuse");
        diffuse.geometries.add(floor(new Material().setKd(0.5), Color.BLACK));
        diffuse.lights.add(new DirectionalLight(new Color(200, 100, 40), new Vector(0, Math.sqrt(3), -1)));
        assertColor(new Color(50, 25, 10), new RayTracerBasic(diffuse).traceRay(RAY_DOWN),
                "TC01: wrong diffuse colour");

        // TC02: specular only, light straight down so r points straight up and −v·r = 1:
        // kS·1^n·I = 0.25·(200,100,40) = (50,25,10)
        Scene specular = new Scene("specular");
        specular.geometries.add(floor(new Material().setKs(0.25).setShininess(20), Color.BLACK));
        specular.lights.add(new DirectionalLight(new Color(200, 100, 40), DOWN));
        assertColor(new Color(50, 25, 10), new RayTracerBasic(specular).traceRay(RAY_DOWN),
                "TC02: wrong specular colour");

        // TC03: specular with the light at 60° from the normal: r = l − 2(l·n)n leaves at 60° too, so
        // −v·r = 0.5 and the highlight is kS·0.5^2·I = 0.25·0.25·(200,100,40) = (12.5,6.25,2.5)
        Scene oblique = new Scene("oblique specular");
        oblique.geometries.add(floor(new Material().setKs(0.25).setShininess(2), Color.BLACK));
        oblique.lights.add(new DirectionalLight(new Color(200, 100, 40), new Vector(0, Math.sqrt(3), -1)));
        assertColor(new Color(12.5, 6.25, 2.5), new RayTracerBasic(oblique).traceRay(RAY_DOWN),
                "TC03: wrong oblique specular colour");

        // ===== Boundary Values Tests =====
        // TC11: light on the other side of the surface from the viewer contributes nothing (black)
        Scene behind = new Scene("light behind");
        behind.geometries.add(floor(new Material().setKd(1).setKs(1).setShininess(1), Color.BLACK));
        behind.lights.add(new DirectionalLight(new Color(200, 100, 40), new Vector(0, 0, 1)));
        assertColor(Color.BLACK, new RayTracerBasic(behind).traceRay(RAY_DOWN),
                "TC11: a light behind the surface must not light it");
        // TC12: light grazing the surface (n·l = 0) contributes nothing (black)
        Scene grazing = new Scene("grazing light");
        grazing.geometries.add(floor(new Material().setKd(1).setKs(1).setShininess(1), Color.BLACK));
        grazing.lights.add(new DirectionalLight(new Color(200, 100, 40), new Vector(1, 0, 0)));
        assertColor(Color.BLACK, new RayTracerBasic(grazing).traceRay(RAY_DOWN),
                "TC12: a grazing light must not light the surface");
    }

    /** Builds a floor lit straight from above by a point light, with an optional blocker between. */
    private static Scene shadowScene(Material blockerMaterial) {
        Scene scene = new Scene("shadow");
        scene.geometries.add(floor(new Material().setKd(1), Color.BLACK));
        if (blockerMaterial != null)
            scene.geometries.add(new Sphere(new Point3D(0, 0, 50), 10).setMaterial(blockerMaterial));
        scene.lights.add(new PointLight(new Color(100, 100, 100), new Point3D(0, 0, 200)));
        return scene;
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: shadows by opaque and transparent bodies. */
    @Test
    void testTraceRayShadows() {
        // a ray to the floor point (0,0,0) that passes beside the blocker sphere
        Ray ray = new Ray(new Point3D(100, 0, 100), new Point3D(0, 0, 0).subtract(new Point3D(100, 0, 100)));

        // ===== Equivalence Partitions Tests =====
        // TC01: nothing between the floor and the light: full light kD·1·I = (100,100,100)
        assertColor(new Color(100, 100, 100), new RayTracerBasic(shadowScene(null)).traceRay(ray),
                "TC01: an unblocked point must get the whole light");
        // TC02: an opaque sphere between: black
        assertColor(Color.BLACK, new RayTracerBasic(shadowScene(new Material())).traceRay(ray),
                "TC02: an opaque blocker must cast a full shadow");
        // TC03: a transparent sphere kT 0.5 is crossed twice: 0.5·0.5·I = (25,25,25)
        assertColor(new Color(25, 25, 25), new RayTracerBasic(shadowScene(new Material().setKt(0.5))).traceRay(ray),
                "TC03: light through a transparent sphere must be kT squared");

        // ===== Boundary Values Tests =====
        // TC11: a body beyond the light does not shadow: full light (100,100,100)
        Scene beyond = shadowScene(null);
        beyond.geometries.add(new Sphere(new Point3D(0, 0, 300), 10));
        assertColor(new Color(100, 100, 100), new RayTracerBasic(beyond).traceRay(ray),
                "TC11: a body beyond the light must not cast a shadow");
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: reflection and refraction. */
    @Test
    void testTraceRayGlobalEffects() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a mirror floor (kR 0.5) reflects a red emitting triangle above it: 0.5·(200,0,0)
        Scene mirror = new Scene("mirror");
        mirror.geometries.add(floor(new Material().setKr(0.5), Color.BLACK),
                new Triangle(new Point3D(-50, -50, 200), new Point3D(50, -50, 200), new Point3D(0, 50, 200))
                        .setEmission(new Color(200, 0, 0)));
        Ray up = new Ray(new Point3D(0, 0, 100), DOWN);
        assertColor(new Color(100, 0, 0), new RayTracerBasic(mirror).traceRay(up),
                "TC01: the mirror must show half the reflected triangle's colour");

        // TC02: a transparent floor (kT 0.4) shows 0.4 of the green emitter under it
        Scene glass = new Scene("glass");
        glass.geometries.add(floor(new Material().setKt(0.4), Color.BLACK),
                new Triangle(new Point3D(-50, -50, -50), new Point3D(50, -50, -50), new Point3D(0, 50, -50))
                        .setEmission(new Color(0, 100, 0)));
        assertColor(new Color(0, 40, 0), new RayTracerBasic(glass).traceRay(RAY_DOWN),
                "TC02: the transparent floor must show 0.4 of the colour behind it");

        // ===== Boundary Values Tests =====
        // TC11: a mirror that reflects nothing shows kR times the background: 0.5·(0,0,80)
        Scene empty = new Scene("mirror to the sky").setBackground(new Color(0, 0, 80));
        empty.geometries.add(floor(new Material().setKr(0.5), Color.BLACK));
        assertColor(new Color(0, 0, 40), new RayTracerBasic(empty).traceRay(RAY_DOWN),
                "TC11: a mirror facing nothing must show the background scaled by kR");
        // TC12: two facing mirrors (kR 1) stop at the recursion limit and stay finite: the result is
        // the emission (1,1,1) of each of the 10 levels summed
        Scene facing = new Scene("facing mirrors");
        facing.geometries.add(
                new Plane(new Point3D(0, 0, 0), new Vector(0, 0, 1)).setEmission(new Color(1, 1, 1))
                        .setMaterial(new Material().setKr(1)),
                new Plane(new Point3D(0, 0, 200), new Vector(0, 0, -1)).setEmission(new Color(1, 1, 1))
                        .setMaterial(new Material().setKr(1)));
        assertColor(new Color(10, 10, 10), new RayTracerBasic(facing).traceRay(RAY_DOWN),
                "TC12: the recursion must stop after 10 levels");
    }

    /** Test method for {@link RayTracerBasic#RayTracerBasic(Scene)}. */
    @Test
    void testConstructor() {
        // ===== Boundary Values Tests =====
        // TC11: a null scene is rejected with a message naming the scene
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new RayTracerBasic(null),
                "TC11: a null scene must be rejected");
        assertTrue(e.getMessage().contains("scene"), "TC11: the message must name the scene");
    }
}
