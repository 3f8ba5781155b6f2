package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.DoubleFunction;

import org.junit.jupiter.api.Test;

import accel.BoundingVolumeHierarchy;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable.GeoPoint;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;
import testutil.TestMeshes;
import scenefile.Picture;

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
        // TC03: a null ray is refused, naming it (not a NullPointerException)
        assertMessage(assertThrows(IllegalArgumentException.class, () -> tracer.traceRay(null),
                "TC03: a null ray must be refused"), "ray to trace must not be null", "TC03");
    }

    /**
     * Test method for {@link RayTracerBasic#prepare(int)}: the hierarchy is built again only when the
     * scene's bodies changed.
     */
    @Test
    void testPrepare() {
        Scene scene = new Scene("prepare");
        Geometries nested = new Geometries(floor(new Material(), new Color(1, 2, 3)));
        scene.geometries.add(nested);
        RayTracerBasic tracer = new RayTracerBasic(scene);
        Color red = new Color(200, 0, 0);
        // a red sphere on the floor under RAY_DOWN
        Sphere sphere = new Sphere(new Point3D(0, 0, 10), 5);
        sphere.setEmission(red);

        // ===== Equivalence Partitions Tests =====
        // TC01: prepared twice (on 2 threads, then 1) with nothing changed: the same hierarchy
        tracer.prepare(2);
        BoundingVolumeHierarchy first = tracer.accelerator();
        tracer.prepare(1);
        assertSame(first, tracer.accelerator(), "TC01: an unchanged scene must not be built again");
        // TC02: a body added to a nested composite: built again, the ray sees it (red)
        nested.add(sphere);
        tracer.prepare(2);
        assertNotSame(first, tracer.accelerator(), "TC02: a body added to a nested composite must be seen");
        assertColor(red, tracer.traceRay(RAY_DOWN), "TC02: the added sphere must be seen");
        // TC03: the scene's composite replaced through the field: built again, the ray sees the floor (1, 2, 3)
        BoundingVolumeHierarchy second = tracer.accelerator();
        scene.geometries = new Geometries(floor(new Material(), new Color(1, 2, 3)));
        tracer.prepare(2);
        assertNotSame(second, tracer.accelerator(), "TC03: a replaced composite must be seen");
        assertColor(new Color(1, 2, 3), tracer.traceRay(RAY_DOWN), "TC03: the new composite has no sphere");
        // TC04: the scene's composite set back with setGeometries: built again, the sphere is seen (red)
        BoundingVolumeHierarchy third = tracer.accelerator();
        scene.setGeometries(new Geometries(nested));
        tracer.prepare(2);
        assertNotSame(third, tracer.accelerator(), "TC04: a composite set by setGeometries must be seen");
        assertColor(red, tracer.traceRay(RAY_DOWN), "TC04: the sphere must be seen again");

        // ===== Boundary Values Tests =====
        // TC11: a ray traced before any preparation builds the hierarchy; preparing then keeps it
        RayTracerBasic lazy = new RayTracerBasic(scene);
        assertColor(red, lazy.traceRay(RAY_DOWN), "TC11: the sphere must be seen without preparation");
        BoundingVolumeHierarchy built = lazy.accelerator();
        lazy.prepare(2);
        assertSame(built, lazy.accelerator(), "TC11: the hierarchy built on first use is up to date");
        // TC12: a new tracer over the unchanged scene (a course test's new tracer per picture): the same hierarchy
        RayTracerBasic next = new RayTracerBasic(scene);
        next.prepare(2);
        assertSame(built, next.accelerator(), "TC12: a new tracer over an unchanged scene must not build again");
        assertColor(red, next.traceRay(RAY_DOWN), "TC12: the new tracer sees the sphere");
        // TC13: a null among the lights, put in through the public field: refused by the preparation (before
        // any pixel of a render), naming the index
        scene.lights = Arrays.asList(new DirectionalLight(red, DOWN), null);
        assertMessage(assertThrows(IllegalArgumentException.class, () -> next.prepare(2),
                "TC13: a null light must be refused"), "scene.lights must not hold null (at index 1)", "TC13");
        // TC14 (own): ... and by the first ray of a tracer no render prepared
        assertThrows(IllegalArgumentException.class, () -> new RayTracerBasic(scene).traceRay(RAY_DOWN),
                "TC14: a null light must be refused at the first ray");
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

    /**
     * Test method for {@link RayTracerBasic#traceRay(Ray)}: points that coincide render. A light that sits
     * at the lit point gives it nothing; a hit where the body has no normal is shaded as facing the ray.
     */
    @Test
    void testTraceRayCoincidingPoints() {
        Material diffuse = new Material().setKd(0.5);
        Color emission = new Color(1, 2, 3);
        DirectionalLight sun = new DirectionalLight(new Color(200, 100, 40), DOWN);
        // the sun alone on the floor: emission + kD·1·I = (1+100, 2+50, 3+20)
        Color sunLit = new Color(101, 52, 23);
        // ===== Equivalence Partitions Tests =====
        // TC01: a point light exactly on the floor at the hit: nothing from it, the sun's light as without it
        Scene onPlane = new Scene("light on a plane");
        onPlane.geometries.add(floor(diffuse, emission));
        onPlane.lights.add(new PointLight(new Color(500, 500, 500), Point3D.ZERO));
        onPlane.lights.add(sun);
        assertColor(sunLit, new RayTracerBasic(onPlane).traceRay(RAY_DOWN), "TC01: the light on the point must add nothing");
        // TC02: a spot light there, pointing up, with soft shadows from its square of edge 10: nothing from it
        Scene spot = new Scene("spot on a plane");
        spot.geometries.add(floor(diffuse, emission));
        spot.lights.add(new SpotLight(new Color(500, 500, 500), Point3D.ZERO, new Vector(0, 0, 1)).setEdgesSize(10));
        spot.lights.add(sun);
        assertColor(sunLit, new RayTracerBasic(spot).setSoftShadows(true).traceRay(RAY_DOWN),
                "TC02: the spot light on the point must add nothing");
        // TC03: a point light on a sphere's surface, at the point the ray hits (its top, (0,0,10)): nothing from it
        Scene onSphere = new Scene("light on a sphere");
        onSphere.geometries.add(new Sphere(new Point3D(0, 0, 5), 5).setEmission(emission).setMaterial(diffuse));
        onSphere.lights.add(new PointLight(new Color(500, 500, 500), new Point3D(0, 0, 10)));
        onSphere.lights.add(sun);
        assertColor(sunLit, new RayTracerBasic(onSphere).traceRay(RAY_DOWN), "TC03: the light on the sphere must add nothing");
        // TC04: a sphere of radius 5e-5, 1e12 away: the hit rounds onto its centre, which has no normal; it is
        // shaded as facing the ray, (0,0,1): the sun's light, as on a sphere of radius 1e-4 whose normal exists
        Ray far = new Ray(Point3D.ZERO, new Vector(0, 0, -1));
        Color[] seen = new Color[2];
        double[] radii = {5e-5, 1e-4};
        for (int k = 0; k < 2; ++k) {
            Scene tiny = new Scene("tiny sphere");
            Sphere sphere = new Sphere(new Point3D(0, 0, -1e12), radii[k]);
            tiny.geometries.add(sphere.setEmission(emission).setMaterial(diffuse));
            tiny.lights.add(new DirectionalLight(new Color(200, 100, 40), DOWN));
            seen[k] = new RayTracerBasic(tiny).traceRay(far);
        }
        assertColor(sunLit, seen[0], "TC04: the hit on the centre must be shaded as facing the ray");
        assertColor(seen[1], seen[0], "TC04: the same colour as a sphere whose hit has a normal");

        // ===== Boundary Values Tests =====
        // TC11: a floor point 0.5 from the light sees it edge-on (n·l = 0): nothing either, as at the light itself
        Ray beside = new Ray(new Point3D(0.5, 0, 100), DOWN);
        assertColor(sunLit, new RayTracerBasic(onPlane).traceRay(beside), "TC11: the light edge-on must add nothing");
        // TC12: a light 1e-11 above the hit (within the points' tolerance) counts as on it: nothing from it
        Scene above = new Scene("light just above");
        above.geometries.add(floor(diffuse, emission));
        above.lights.add(new PointLight(new Color(500, 500, 500), new Point3D(0, 0, 1e-11)));
        above.lights.add(sun);
        assertColor(sunLit, new RayTracerBasic(above).traceRay(RAY_DOWN), "TC12: a light within tolerance adds nothing");
        // TC13 (own): a light 0.001 above the hit is not on it: it lights the point, kD·I/kC = 0.5·500 more
        Scene near = new Scene("light near");
        near.geometries.add(floor(diffuse, emission));
        near.lights.add(new PointLight(new Color(500, 500, 500), new Point3D(0, 0, 0.001)));
        assertColor(new Color(251, 252, 253), new RayTracerBasic(near).traceRay(RAY_DOWN),
                "TC13: a light just above the point must light it fully");
    }

    /**
     * The colour the Phong model gives at the origin of a floor seen straight down, worked out with
     * {@link Color}'s own operations, light after light: the reference the tracer's sums must match bit for bit.
     */
    private static Color phongWithColors(Material material, Color emission, Color ambient, DirectionalLight... lights) {
        Vector n = new Vector(0, 0, 1);
        Color local = Color.BLACK;
        for (DirectionalLight light : lights) {
            Vector l = light.getL(Point3D.ZERO);
            double nl = n.dotProduct(l);
            double minusVR = -(DOWN.dotProduct(l) - 2 * nl * DOWN.dotProduct(n));
            Color intensity = light.getIntensity(Point3D.ZERO).scale(1.0);
            Color specular = minusVR <= 0 ? Color.BLACK
                    : intensity.scale(material.getKs() * Math.pow(minusVR, material.getShininess()));
            local = local.add(intensity.scale(material.getKd() * Math.abs(nl)), specular);
        }
        return emission.add(local).add(Color.BLACK).add(ambient);
    }

    /** Asserts that two colours have the same components, bit for bit. */
    private static void assertSameComponents(Color expected, Color actual, String message) {
        assertEquals(expected.getR(), actual.getR(), 0, message + " (red)");
        assertEquals(expected.getG(), actual.getG(), 0, message + " (green)");
        assertEquals(expected.getB(), actual.getB(), 0, message + " (blue)");
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: the lights add up as their Colors would, bit for bit. */
    @Test
    void testTraceRayLightSum() {
        // ===== Equivalence Partitions Tests =====
        // TC01: two lights at odd angles, diffuse and specular, with emission and ambient light: the
        // components of the sum of Colors, bit for bit
        Material material = new Material().setKd(0.37).setKs(0.61).setShininess(7);
        Color emission = new Color(1.1, 2.3, 0.7);
        DirectionalLight first = new DirectionalLight(new Color(211.3, 97.1, 41.9), new Vector(0.3, 0.7, -1));
        DirectionalLight second = new DirectionalLight(new Color(13.7, 250.9, 77.7), new Vector(-0.9, 0.2, -0.4));
        Scene scene = new Scene("two lights");
        scene.geometries.add(floor(material, emission));
        scene.lights.add(first);
        scene.lights.add(second);
        scene.setAmbientLight(new AmbientLight(new Color(30.3, 20.2, 10.1), 0.3));
        assertSameComponents(phongWithColors(material, emission, scene.ambientLight.getIntensity(), first, second),
                new RayTracerBasic(scene).traceRay(RAY_DOWN), "TC01: the sum must be that of the lights' colours");

        // ===== Boundary Values Tests =====
        // TC11: a light so bright that its diffuse and specular terms overflow: red and green stay at the
        // largest double, blue is kD·I + kS·I = 0.5 + 0.5 = 1
        Material full = new Material().setKd(1).setKs(1).setShininess(1);
        DirectionalLight blinding = new DirectionalLight(new Color(Double.MAX_VALUE, Double.MAX_VALUE / 2, 0.5), DOWN);
        Scene bright = new Scene("blinding light");
        bright.geometries.add(floor(full, Color.BLACK));
        bright.lights.add(blinding);
        Color traced = new RayTracerBasic(bright).traceRay(RAY_DOWN);
        assertColor(Double.MAX_VALUE, Double.MAX_VALUE, 1, traced, "TC11: an overflowing sum must saturate");
        assertSameComponents(phongWithColors(full, Color.BLACK, Color.BLACK, blinding), traced,
                "TC11: the saturated sum must be that of the lights' colours");
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
        assertMessage(e, "scene", "TC11");
    }

    // ---------------------------------------------------------------------------------------------
    // Glossy reflection and blurry transparency. The camera looks straight down on 100 × 6 pixels over
    // 20 × 1.2 units (a column is 0.2 wide, centres at x = −9.9 + 0.2·j). A bright stripe 1 unit wide
    // is seen 50 units away: in a mirror tilted 45° (the reflected rays go along x to the stripe on
    // the wall x = 50, z from −0.48 to 0.52) or through a pane z = 0 (the refracted rays go on down to
    // the stripe on the floor z = −50, as seen from x −0.52 to 0.48). Sharp, it covers exactly 5 columns
    // (centres −0.5 to 0.3, each 0.02 inside). Spread by a square of half-edge h at unit distance, the
    // rays reach ±50·h around it, so the stripe's image is 1 + 100·h units wide.
    // ---------------------------------------------------------------------------------------------

    private static final int SPREAD_COLUMNS = 100;
    private static final int SPREAD_ROWS = 6;
    private static final double SPREAD_DISTANCE = 50;
    private static final double COLUMN_WIDTH = 0.2;
    private static final double STRIPE_WIDTH = 1;
    private static final Color STRIPE_EMISSION = new Color(200, 200, 200);
    private static final Path SPREAD_FOLDER = Path.of("target", "test-images", "glossy");

    /** The stripe seen in a mirror tilted 45° (normal (1, 0, 1)) of the given material. */
    private static Scene mirrorScene(Material mirror) {
        Scene scene = new Scene("glossy mirror");
        double x = SPREAD_DISTANCE;
        scene.geometries.add(new Plane(Point3D.ZERO, new Vector(1, 0, 1)).setMaterial(mirror),
                new Polygon(new Point3D(x, -100, -0.48), new Point3D(x, 100, -0.48), new Point3D(x, 100, 0.52),
                        new Point3D(x, -100, 0.52)).setEmission(STRIPE_EMISSION));
        return scene;
    }

    /**
     * The stripe seen through a pane z = 0 of the given material. The stripe is 1050 units from the
     * camera, not 1000 like the pane: it is placed 1.05 times as wide and as far off the axis.
     */
    private static Scene paneScene(Material pane) {
        Scene scene = new Scene("blurry pane");
        double z = -SPREAD_DISTANCE;
        double left = -0.52 * 1.05;
        double right = 0.48 * 1.05;
        scene.geometries.add(floor(pane, Color.BLACK),
                new Polygon(new Point3D(left, -100, z), new Point3D(right, -100, z), new Point3D(right, 100, z),
                        new Point3D(left, 100, z)).setEmission(STRIPE_EMISSION));
        return scene;
    }

    /** Renders a scene of the stripe with 10 × 10 spread rays and returns the image. */
    private static ImageWriter renderSpread(String name, Scene scene, int threads, long seed) {
        ImageWriter image = new ImageWriter(name, SPREAD_COLUMNS, SPREAD_ROWS, SPREAD_FOLDER);
        Render render = new Render().setImageWriter(image)
                .setCamera(new Camera(new Point3D(0, 0, 1000), DOWN, new Vector(0, 1, 0))
                        .setVpSize(SPREAD_COLUMNS * COLUMN_WIDTH, SPREAD_ROWS * COLUMN_WIDTH).setVpDistance(1000))
                .setRayTracer(new RayTracerBasic(scene)).setSqrtGlossRays(10).setSeed(seed)
                .setMultithreading(threads);
        render.renderImage();
        render.writeToImage();
        return image;
    }

    /** The number of columns of the middle row where the stripe is seen (brighter than 5). */
    private static int stripeWidth(ImageWriter image) {
        int width = 0;
        for (int x = 0; x < SPREAD_COLUMNS; ++x)
            if (image.getPixel(x, SPREAD_ROWS / 2).getRed() > 5)
                ++width;
        return width;
    }

    /** The sum over all pixels of the difference of their red levels. */
    private static long pictureDifference(ImageWriter a, ImageWriter b) {
        long sum = 0;
        for (int y = 0; y < SPREAD_ROWS; ++y)
            for (int x = 0; x < SPREAD_COLUMNS; ++x)
                sum += Math.abs(a.getPixel(x, y).getRed() - b.getPixel(x, y).getRed());
        return sum;
    }

    /**
     * Asserts that the stripe's image widens with the spread as geometry predicts: 1 + 100·h units,
     * within 3 columns (the outermost columns see the stripe in too few of their rays).
     */
    private static void assertSpreadWidens(String name, DoubleFunction<Scene> scene) {
        int[] widths = new int[4];
        double[] spreads = {0, 0.01, 0.02, 0.04};
        for (int s = 0; s < spreads.length; ++s) {
            widths[s] = stripeWidth(renderSpread(name + "-" + spreads[s], scene.apply(spreads[s]), 0, 1));
            double expected = (STRIPE_WIDTH + 2 * SPREAD_DISTANCE * spreads[s]) / COLUMN_WIDTH;
            assertEquals(expected, widths[s], 3, "TC01: the stripe's width with " + name + " " + spreads[s]);
        }
        // ===== Equivalence Partitions Tests =====
        // TC01 (above): with h 0.01, 0.02, 0.04 the stripe is 10, 15 and 25 columns wide, each within 3
        // TC02: the width grows with the spread
        for (int s = 1; s < spreads.length; ++s)
            assertTrue(widths[s] > widths[s - 1], "TC02: the stripe must widen with " + name + ", got "
                    + Arrays.toString(widths));
        // ===== Boundary Values Tests =====
        // TC11: with h 0 the stripe is sharp: exactly 5 columns
        assertEquals(5, widths[0], "TC11: the sharp stripe must be 5 columns wide");
    }

    /**
     * Asserts that the picture converges to the sharp one as the spread goes to 0: the difference
     * shrinks with h, vanishes once 50·h is inside the stripe's 0.02 margin, and h = 0 is the sharp
     * picture bit for bit.
     */
    private static void assertSpreadConverges(String name, DoubleFunction<Scene> scene, Scene sharpScene) {
        ImageWriter sharp = renderSpread(name + "-sharp", sharpScene, 0, 1);
        double[] spreads = {0.016, 0.008, 0.004, 0.002, 0.001};
        long[] differences = new long[spreads.length];
        for (int s = 0; s < spreads.length; ++s)
            differences[s] = pictureDifference(sharp,
                    renderSpread(name + "-converge-" + spreads[s], scene.apply(spreads[s]), 0, 1));
        // ===== Equivalence Partitions Tests =====
        // TC01: the difference from the sharp picture shrinks as h halves from 0.016 to 0.001
        for (int s = 1; s < spreads.length; ++s)
            assertTrue(differences[s] < differences[s - 1], "TC01: the difference must shrink with " + name
                    + ", got " + Arrays.toString(differences));
        assertTrue(differences[0] > 0, "TC01: h 0.016 must differ from the sharp picture");
        // ===== Boundary Values Tests =====
        // TC11: h 0.0002 spreads the rays by 0.01, inside the stripe's margin of 0.02: no difference
        assertEquals(0, pictureDifference(sharp, renderSpread(name + "-converge-tiny", scene.apply(0.0002), 0, 1)),
                "TC11: a spread inside the stripe's margin must give the sharp picture");
        // TC12: h 0 is the sharp picture (a material that never set it) bit for bit
        assertSameImage(sharp, renderSpread(name + "-zero", scene.apply(0), 0, 1),
                "TC12: " + name + " 0 must render the sharp picture");
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: a glossy mirror widens a stripe's reflection. */
    @Test
    void testGlossyReflectionWidth() {
        assertSpreadWidens("kG", kG -> mirrorScene(new Material().setKr(1).setKg(kG)));
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: a glossy mirror converges to the sharp one. */
    @Test
    void testGlossyReflectionConvergence() {
        assertSpreadConverges("kG", kG -> mirrorScene(new Material().setKr(1).setKg(kG)),
                mirrorScene(new Material().setKr(1)));
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: blurry glass widens a stripe seen through it. */
    @Test
    void testBlurryTransparencyWidth() {
        assertSpreadWidens("kB", kB -> paneScene(new Material().setKt(1).setKb(kB)));
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: blurry glass converges to clear glass. */
    @Test
    void testBlurryTransparencyConvergence() {
        assertSpreadConverges("kB", kB -> paneScene(new Material().setKt(1).setKb(kB)),
                paneScene(new Material().setKt(1)));
    }

    /**
     * Test method for {@link RayTracerBasic#traceRay(Ray)}: glossy and blurry pictures are
     * reproducible at any number of threads.
     */
    @Test
    void testSpreadPictureDeterministic() {
        Material both = new Material().setKt(0.6).setKb(0.03).setKr(0.4).setKg(0.05);
        ImageWriter oneThread = renderSpread("spread-1", paneScene(both), 1, 7);
        // ===== Equivalence Partitions Tests =====
        // TC01: 1 and 3 threads render the same picture
        assertSameImage(oneThread, renderSpread("spread-3", paneScene(both), 3, 7),
                "TC01: 1 and 3 threads differ");
        // TC02: another seed moves the noise of the blurred stripe's edges
        assertTrue(pictureDifference(oneThread, renderSpread("spread-other-seed", paneScene(both), 1, 8)) > 0,
                "TC02: another seed must give other noise");
    }

    /**
     * Test method for {@link RayTracerBasic#traceRay(Ray)}: no spread ray is traced into the surface.
     * A floor z = 0 over a bright plane z = −10, a ray grazing the floor at 5.7° (the sky above is
     * black): with kG 1 (rays up to 45° off the mirror direction) about half of the reflected rays
     * would go down into the floor and see the bright plane.
     */
    @Test
    void testSpreadRaysStayOnTheirSide() {
        Ray grazing = new Ray(new Point3D(-100, 0, 10), new Vector(10, 0, -1));
        Plane bright = new Plane(new Point3D(0, 0, -10), new Vector(0, 0, 1));
        bright.setEmission(new Color(200, 200, 200));
        // ===== Equivalence Partitions Tests =====
        // TC01: a glossy mirror floor (kR 1, kG 1) reflects only the black sky: black
        Scene glossy = new Scene("glossy floor over a bright plane");
        glossy.geometries.add(floor(new Material().setKr(1).setKg(1), Color.BLACK), bright);
        RayTracerBasic tracer = new RayTracerBasic(glossy);
        tracer.setSqrtGlossRays(10);
        assertColor(Color.BLACK, tracer.traceRay(grazing), "TC01: a reflected ray went into the floor");
        assertEquals(100, tracer.getSpreadRaysCount(), "TC01: the floor must spread 10 × 10 rays");
        // TC02: a blurry pane there instead (kT 1, kB 1) shows only the bright plane below: no ray comes back up
        Scene blurry = new Scene("blurry pane over a bright plane");
        blurry.geometries.add(floor(new Material().setKt(1).setKb(1), Color.BLACK), bright);
        assertColor(new Color(200, 200, 200), new RayTracerBasic(blurry).setSqrtGlossRays(10).traceRay(grazing),
                "TC02: a refracted ray came back up to the black sky");
    }

    /**
     * Test method for {@link RayTracerBasic#traceRay(Ray)}: the spread rays of a path grow linearly
     * with the recursion's depth. Between two facing glossy mirrors (kR 1) every ray bounces to the
     * recursion limit: the first mirror spreads a beam of k² rays, and each of them spreads one ray at
     * each of the 8 levels below (the last level spreads none): 9·k² rays, not k^18.
     */
    @Test
    void testSpreadRaysCount() {
        Scene facing = new Scene("facing glossy mirrors");
        Material glossy = new Material().setKr(1).setKg(0.1);
        facing.geometries.add(floor(glossy, Color.BLACK),
                new Plane(new Point3D(0, 0, 200), new Vector(0, 0, -1)).setMaterial(glossy));
        // ===== Equivalence Partitions Tests =====
        // TC01: a 3 × 3 grid: 9·9 = 81 spread rays for one primary ray
        RayTracerBasic tracer = new RayTracerBasic(facing);
        tracer.setSqrtGlossRays(3).traceRay(RAY_DOWN);
        assertEquals(81, tracer.getSpreadRaysCount(), "TC01: wrong number of spread rays");
        // ===== Boundary Values Tests =====
        // TC11: a 1 × 1 grid: one ray per level, 9
        RayTracerBasic single = new RayTracerBasic(facing);
        single.setSqrtGlossRays(1).traceRay(RAY_DOWN);
        assertEquals(9, single.getSpreadRaysCount(), "TC11: wrong number of spread rays");
        // TC12: sharp mirrors spread no ray
        Scene sharp = new Scene("facing mirrors");
        sharp.geometries.add(floor(new Material().setKr(1), Color.BLACK));
        RayTracerBasic none = new RayTracerBasic(sharp);
        none.traceRay(RAY_DOWN);
        assertEquals(0, none.getSpreadRaysCount(), "TC12: a sharp mirror must spread no ray");
    }

    // ---------------------------------------------------------------------------------------------
    // Soft shadows. The lit point is the origin of the floor z = 0; the light is a square of edge 20
    // centred 100 above it, its sides along x and y. An opaque half-plane z = 50, x < x0, hides the
    // part of the square with x < 2·x0 (similar triangles), so the visible fraction of the light's
    // area is clamp((10 − 2·x0) / 20, 0, 1).
    // ---------------------------------------------------------------------------------------------

    private static final double SOFT_DELTA = 0.08;
    private static final double LIGHT_EDGE = 20;
    private static final Point3D LIGHT_CENTER = new Point3D(0, 0, 100);
    private static final Vector FLOOR_NORMAL = new Vector(0, 0, 1);

    /** The square light above the origin, its sides along x and y. */
    private static PointLight squareLight() {
        return new PointLight(new Color(100, 100, 100), LIGHT_CENTER).setEdgesSize(LIGHT_EDGE)
                .setUV(new Vector(1, 0, 0), new Vector(0, 1, 0));
    }

    /** A large horizontal square at height z covering x < x0, with the given material. */
    private static Polygon halfPlane(double x0, double z, Material material) {
        Polygon polygon = new Polygon(new Point3D(-1000, -1000, z), new Point3D(x0, -1000, z),
                new Point3D(x0, 1000, z), new Point3D(-1000, 1000, z));
        polygon.setMaterial(material);
        return polygon;
    }

    /** The visible fraction of the square light over the origin with the half-plane edge at x0. */
    private static double visibleFraction(double x0) {
        return Math.max(0, Math.min(1, (LIGHT_EDGE / 2 - 2 * x0) / LIGHT_EDGE));
    }

    /** A ray tracer for the floor and the given blockers, soft shadows on with sqrtBeamNum k. */
    private static RayTracerBasic softTracer(int k, Polygon... blockers) {
        Scene scene = new Scene("soft");
        Plane floor = floor(new Material().setKd(1), Color.BLACK);
        scene.geometries.add(floor);
        scene.geometries.add(blockers);
        RayTracerBasic tracer = new RayTracerBasic(scene);
        tracer.setSoftShadows(true).setSqrtBeamNum(k);
        return tracer;
    }

    /** The shadow factor of a light at the origin of the tracer's floor (its first body), for pixel (j, 0). */
    private static double shadowFactor(RayTracerBasic tracer, LightSource light, int j) {
        ThreadState state = tracer.startPixel(j, 0);
        Plane floor = (Plane) tracer.scene.geometries.getGeometries().get(0);
        return tracer.transparency(light, light.getL(Point3D.ZERO), FLOOR_NORMAL, new GeoPoint(floor, Point3D.ZERO),
                state);
    }

    /**
     * The bytes the calling thread allocates while a light's transparency at the origin of the
     * tracer's floor is asked a number of times (after three times as many calls that warm up).
     *
     * @param tracer the tracer
     * @param light  the light
     * @param calls  how many times
     * @return the bytes allocated
     */
    private static long shadowPathAllocation(RayTracerBasic tracer, LightSource light, int calls) {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        Plane floor = (Plane) tracer.scene.geometries.getGeometries().get(0);
        GeoPoint origin = new GeoPoint(floor, Point3D.ZERO);
        Vector l = light.getL(Point3D.ZERO);
        ThreadState state = tracer.startPixel(0, 0);
        double factor = 0;
        // the first calls make the thread's scratch space (and the JVM may allocate while warming up)
        for (int c = 0; c < 3 * calls; ++c)
            factor += tracer.transparency(light, l, FLOOR_NORMAL, origin, state);
        threads.getCurrentThreadAllocatedBytes(); // its own first call may allocate
        long before = threads.getCurrentThreadAllocatedBytes();
        for (int c = 0; c < calls; ++c)
            factor += tracer.transparency(light, l, FLOOR_NORMAL, origin, state);
        long allocated = threads.getCurrentThreadAllocatedBytes() - before;
        assertTrue(factor >= 0, "the factors must not be negative");
        return allocated;
    }

    /**
     * Test method for {@link RayTracerBasic#transparency}: the shadow path allocates nothing per lit
     * point — soft or hard shadows, open or closed bundles.
     */
    @Test
    void testTransparencyAllocatesNothing() {
        PointLight light = squareLight();
        // ===== Equivalence Partitions Tests =====
        // TC01: soft shadows, a closed bundle (a half-plane over half the light's square): 1000 lit
        // points allocate less than 1000 bytes (one object a point would be 16000 or more)
        RayTracerBasic closed = softTracer(9, halfPlane(0, 10, new Material()));
        assertTrue(shadowPathAllocation(closed, light, 1000) < 1000, "TC01: a closed bundle must allocate nothing");
        // TC02: soft shadows, an open bundle (nothing over the floor)
        RayTracerBasic open = softTracer(9);
        assertTrue(shadowPathAllocation(open, light, 1000) < 1000, "TC02: an open bundle must allocate nothing");
        // TC03: hard shadows (one ray), behind a transparent half-plane
        RayTracerBasic hard = softTracer(9, halfPlane(0, 10, new Material().setKt(0.5)));
        hard.setSoftShadows(false);
        assertTrue(shadowPathAllocation(hard, light, 1000) < 1000, "TC03: a hard shadow ray must allocate nothing");

        // ===== Boundary Values Tests =====
        // TC11: sqrtBeamNum 1 (the centre ray and one more)
        RayTracerBasic single = softTracer(1, halfPlane(0, 10, new Material()));
        assertTrue(shadowPathAllocation(single, light, 1000) < 1000, "TC11: one cell must allocate nothing");
    }

    /**
     * Test method for {@link RayTracerBasic#transparency}: the surface a bundle leaves is set aside
     * only for a point on a triangle (a mesh's or a {@link Triangle}): its frustum gets the back face
     * then, and the shadow factor is the same as over a plane.
     */
    @Test
    void testSurfaceSetAsideOnTriangles() {
        PointLight light = squareLight();
        TriangleMesh mesh = new TriangleMesh(new double[] { -50, -50, 0, 50, -50, 0, 50, 50, 0, -50, 50, 0 },
                new int[] { 0, 1, 2, 0, 2, 3 });
        Triangle triangle = new Triangle(new Point3D(-50, -50, 0), new Point3D(50, -50, 0), new Point3D(0, 50, 0));
        Plane plane = floor(new Material(), Color.BLACK);
        Scene scene = new Scene("facets");
        scene.geometries.add(mesh, triangle, halfPlane(0, 10, new Material()));
        RayTracerBasic tracer = new RayTracerBasic(scene);
        tracer.setSoftShadows(true).setSqrtBeamNum(9);
        tracer.prepare();
        Vector l = light.getL(Point3D.ZERO);
        double[] factors = new double[3];
        boolean[] backFaces = new boolean[3];
        Geometry[] bodies = { mesh, triangle, plane };
        for (int k = 0; k < bodies.length; ++k) {
            ThreadState state = tracer.startPixel(0, 0);
            factors[k] = tracer.transparency(light, l, FLOOR_NORMAL, new GeoPoint(bodies[k], Point3D.ZERO), state);
            backFaces[k] = state.query(tracer.accelerator()).getFrustum().hasBackFace();
        }
        // ===== Equivalence Partitions Tests =====
        // TC01: a point on a mesh and one on a Triangle (expects a back face); on a plane (expects none)
        assertTrue(backFaces[0], "TC01: a point on a mesh must set its surface aside");
        assertTrue(backFaces[1], "TC01: a point on a Triangle must set its surface aside");
        assertFalse(backFaces[2], "TC01: a point on a plane must not pay for the back face");
        // TC02: the same point and pixel: the same shadow factor whatever it lies on (half the light
        // hidden by the half-plane: about 0.5)
        assertEquals(factors[2], factors[0], 0, "TC02: the mesh's point must get the plane's factor");
        assertEquals(factors[2], factors[1], 0, "TC02: the Triangle's point must get the plane's factor");
        assertEquals(0.5, factors[2], 0.1, "TC02: half the light must be hidden");
    }

    /**
     * Test method for {@link RayTracerBasic#calcSoftShadows}: the shadow factor is the visible
     * fraction of the light's area.
     */
    @Test
    void testCalcSoftShadowsVisibleFraction() {
        PointLight light = squareLight();
        // ===== Equivalence Partitions Tests =====
        // TC01..TC03: the half-plane hides 75 %, 50 %, 25 % of the light: factor 0.25, 0.5, 0.75 (± 0.08)
        double[] partialEdges = { 2.5, 0, -2.5 };
        for (int tc = 0; tc < partialEdges.length; ++tc) {
            double x0 = partialEdges[tc];
            for (int j = 0; j < 20; ++j)
                assertEquals(visibleFraction(x0), shadowFactor(softTracer(9, halfPlane(x0, 50, new Material())), light, j),
                        SOFT_DELTA, "TC0" + (tc + 1) + ": wrong shadow factor for the edge at x = " + x0);
        }
        // ===== Boundary Values Tests =====
        // TC11: the edge just past the light's square on the hidden side: the whole light is seen, exactly 1
        assertEquals(1.0, shadowFactor(softTracer(9, halfPlane(-5.5, 50, new Material())), light, 0), 0,
                "TC11: a fully visible light must give exactly 1");
        // TC12: the edge just past the square on the other side: the light is hidden, exactly 0
        assertEquals(0.0, shadowFactor(softTracer(9, halfPlane(5.5, 50, new Material())), light, 0), 0,
                "TC12: a fully hidden light must give exactly 0");
        // TC13: a point light whose U, V were not set faces the point: the same square here, 0.25 (± 0.08)
        PointLight facing = new PointLight(new Color(100, 100, 100), LIGHT_CENTER).setEdgesSize(LIGHT_EDGE);
        assertEquals(0.25, shadowFactor(softTracer(9, halfPlane(2.5, 50, new Material())), facing, 0), SOFT_DELTA,
                "TC13: a square facing the point must hide the same fraction");
    }

    /** Test method for {@link RayTracerBasic#calcSoftShadows}: more shadow rays, smaller error. */
    @Test
    void testCalcSoftShadowsConvergence() {
        PointLight light = squareLight();
        double x0 = 2.2; // the edge off the cell boundaries of every grid below
        int[] grids = { 2, 4, 8, 16 };
        double[] errors = new double[grids.length];
        for (int g = 0; g < grids.length; ++g) {
            RayTracerBasic tracer = softTracer(grids[g], halfPlane(x0, 50, new Material()));
            for (int j = 0; j < 40; ++j)
                errors[g] += Math.abs(shadowFactor(tracer, light, j) - visibleFraction(x0)) / 40;
        }
        // ===== Equivalence Partitions Tests =====
        // TC01: the mean error over 40 pixels shrinks as sqrtBeamNum grows from 2 to 16
        for (int g = 1; g < grids.length; ++g)
            assertTrue(errors[g] < errors[g - 1], "TC01: error with sqrtBeamNum " + grids[g] + " (" + errors[g]
                    + ") must be below the error with " + grids[g - 1] + " (" + errors[g - 1] + ")");
        // ===== Boundary Values Tests =====
        // TC11: with 16 × 16 rays the mean error is under 0.01
        assertTrue(errors[grids.length - 1] < 0.01, "TC11: error with 256 rays too large: " + errors[grids.length - 1]);
    }

    /** Test method for {@link RayTracerBasic#calcSoftShadows}: light through transparent bodies. */
    @Test
    void testCalcSoftShadowsTransparent() {
        PointLight light = squareLight();
        Material half = new Material().setKt(0.5);
        // ===== Equivalence Partitions Tests =====
        // TC01: one kT 0.5 sheet over the whole light: 0.5
        assertEquals(0.5, shadowFactor(softTracer(9, halfPlane(500, 50, half)), light, 0), 1e-12,
                "TC01: one transparent sheet must let half the light through");
        // TC02: two kT 0.5 sheets: 0.25
        assertEquals(0.25, shadowFactor(softTracer(9, halfPlane(500, 50, half), halfPlane(500, 70, half)), light, 0),
                1e-12, "TC02: two transparent sheets must let a quarter of the light through");
        // ===== Boundary Values Tests =====
        // TC11: a sheet beyond the light casts no shadow: 1
        assertEquals(1.0, shadowFactor(softTracer(9, halfPlane(500, 150, new Material())), light, 0), 0,
                "TC11: a body beyond the light must not shadow");
    }

    /**
     * Test method for {@link RayTracerBasic#transparency}: with soft shadows off, a light of edge 0,
     * or a light with no area, the factor is the single ray to the light's centre.
     */
    @Test
    void testTransparencySingleRay() {
        PointLight light = squareLight();
        // the edge at x0 = -2.5 leaves the centre visible (1) though a quarter of the light is hidden
        RayTracerBasic hard = softTracer(9, halfPlane(-2.5, 50, new Material()));
        hard.setSoftShadows(false);
        long before = hard.getShadowRaysCount();
        // ===== Equivalence Partitions Tests =====
        // TC01: soft shadows off: exactly the centre ray's 1, with one shadow ray
        assertEquals(1.0, shadowFactor(hard, light, 0), 0, "TC01: soft shadows off must trace the centre ray only");
        assertEquals(1, hard.getShadowRaysCount() - before, "TC01: soft shadows off must trace one shadow ray");
        // TC02: soft shadows off, the centre hidden (edge at x0 = 2.5): exactly 0
        RayTracerBasic hardHidden = softTracer(9, halfPlane(2.5, 50, new Material()));
        hardHidden.setSoftShadows(false);
        assertEquals(0.0, shadowFactor(hardHidden, light, 0), 0, "TC02: a hidden centre must give 0");
        // TC03: a directional light has no area: one ray, 1
        RayTracerBasic soft = softTracer(9, halfPlane(-2.5, 50, new Material()));
        before = soft.getShadowRaysCount();
        assertEquals(1.0, shadowFactor(soft, new DirectionalLight(new Color(1, 1, 1), DOWN), 0), 0,
                "TC03: a directional light must be seen through one ray");
        assertEquals(1, soft.getShadowRaysCount() - before, "TC03: a directional light must cost one shadow ray");
        // ===== Boundary Values Tests =====
        // TC11: soft shadows on, light of edge 0: the centre ray's 1, with one shadow ray
        before = soft.getShadowRaysCount();
        assertEquals(1.0, shadowFactor(soft, squareLight().setEdgesSize(0), 0), 0,
                "TC11: a light of edge 0 must be a point light");
        assertEquals(1, soft.getShadowRaysCount() - before, "TC11: a light of edge 0 must cost one shadow ray");
    }

    /** Test method for {@link RayTracerBasic#calcSoftShadows}: the number of shadow rays. */
    @Test
    void testCalcSoftShadowsRayCount() {
        PointLight light = squareLight();
        // ===== Equivalence Partitions Tests =====
        // TC01: sqrtBeamNum 9: 81 rays to the square and 1 to its centre
        RayTracerBasic tracer = softTracer(9, halfPlane(0, 50, new Material()));
        long before = tracer.getShadowRaysCount();
        shadowFactor(tracer, light, 0);
        assertEquals(82, tracer.getShadowRaysCount() - before, "TC01: sqrtBeamNum 9 must trace 82 shadow rays");
        // ===== Boundary Values Tests =====
        // TC11: sqrtBeamNum 1: one ray to the square and one to its centre
        tracer.setSqrtBeamNum(1);
        before = tracer.getShadowRaysCount();
        shadowFactor(tracer, light, 0);
        assertEquals(2, tracer.getShadowRaysCount() - before, "TC11: sqrtBeamNum 1 must trace 2 shadow rays");
        // TC12: sqrtBeamNum below 1 is rejected
        assertThrows(IllegalArgumentException.class, () -> tracer.setSqrtBeamNum(0), "TC12: sqrtBeamNum 0 must be rejected");
    }

    /**
     * Test method for {@link RayTracerBase#getOpenShadowRaysCount()}: the rays of bundles nothing can
     * block are counted as open, the others not.
     */
    @Test
    void testOpenShadowRaysCount() {
        PointLight light = squareLight();
        // ===== Equivalence Partitions Tests =====
        // TC01: a sheet far to the side: nothing can block the 82 rays, all open, factor 1
        RayTracerBasic tracer = softTracer(9, halfPlane(-500, 50, new Material()));
        assertEquals(1.0, shadowFactor(tracer, light, 0), 0, "TC01: nothing in the way must give 1");
        assertEquals(82, tracer.getShadowRaysCount(), "TC01: 82 shadow rays");
        assertEquals(82, tracer.getOpenShadowRaysCount(), "TC01: all 82 rays must be open");
        // TC02: a sheet half across the light's square: 82 rays, none open
        RayTracerBasic half = softTracer(9, halfPlane(0, 50, new Material()));
        shadowFactor(half, light, 0);
        assertEquals(82, half.getShadowRaysCount(), "TC02: 82 shadow rays");
        assertEquals(0, half.getOpenShadowRaysCount(), "TC02: no ray may be open when a body is in the way");
        // ===== Boundary Values Tests =====
        // TC11: soft shadows off: one shadow ray, never counted as open
        RayTracerBasic hard = softTracer(9, halfPlane(-500, 50, new Material()));
        hard.setSoftShadows(false);
        shadowFactor(hard, light, 0);
        assertEquals(1, hard.getShadowRaysCount(), "TC11: one shadow ray");
        assertEquals(0, hard.getOpenShadowRaysCount(), "TC11: a single shadow ray is no bundle");
    }

    /**
     * Test method for {@link RayTracerBase#getBundleTracingNanos()}: only bundles whose rays are
     * traced take time on the clock.
     */
    @Test
    void testBundleTracingNanos() {
        PointLight light = squareLight();
        // ===== Equivalence Partitions Tests =====
        // TC01: nothing in the way: the bundle is open, no time counted
        RayTracerBasic open = softTracer(9, halfPlane(-500, 50, new Material()));
        shadowFactor(open, light, 0);
        assertEquals(0, open.getBundleTracingNanos(), "TC01: an open bundle traces no ray");
        // TC02: a sheet half across the light's square: the rays are traced, time counted
        RayTracerBasic half = softTracer(9, halfPlane(0, 50, new Material()));
        shadowFactor(half, light, 0);
        assertTrue(half.getBundleTracingNanos() > 0, "TC02: a traced bundle must take time");
        // ===== Boundary Values Tests =====
        // TC11: soft shadows off: a single shadow ray is no bundle, no time counted
        RayTracerBasic hard = softTracer(9, halfPlane(0, 50, new Material()));
        hard.setSoftShadows(false);
        shadowFactor(hard, light, 0);
        assertEquals(0, hard.getBundleTracingNanos(), "TC11: a single shadow ray is no bundle");
    }

    /**
     * Test method for {@link RayTracerBasic#calcSoftShadows} with adaptive sampling: the outline first,
     * the whole grid only where the outline's rays disagree.
     */
    @Test
    void testCalcSoftShadowsAdaptive() {
        PointLight light = squareLight();
        double[] edges = { -5.5, 5.5, 1.3 }; // lit, hidden, penumbra
        double[] factors = new double[edges.length];
        long[] rays = new long[edges.length];
        for (int e = 0; e < edges.length; ++e) {
            RayTracerBasic adaptive = softTracer(9, halfPlane(edges[e], 50, new Material()));
            adaptive.setAdaptiveSoftShadows(true);
            long before = adaptive.getShadowRaysCount();
            factors[e] = shadowFactor(adaptive, light, 3);
            rays[e] = adaptive.getShadowRaysCount() - before;
        }
        // ===== Equivalence Partitions Tests =====
        // TC01: fully lit: 1 from the centre and the 32 outline rays
        assertEquals(1.0, factors[0], 0, "TC01: a fully visible light must give 1");
        assertEquals(33, rays[0], "TC01: a fully visible light must cost only the outline and the centre");
        // TC02: fully hidden: 0 from the centre and the 32 outline rays
        assertEquals(0.0, factors[1], 0, "TC02: a fully hidden light must give 0");
        assertEquals(33, rays[1], "TC02: a fully hidden light must cost only the outline and the centre");
        // TC03: penumbra: the whole grid, and exactly the full grid's factor for the same pixel
        assertEquals(82, rays[2], "TC03: a partly hidden light must be sampled in full");
        assertEquals(shadowFactor(softTracer(9, halfPlane(1.3, 50, new Material())), light, 3), factors[2], 0,
                "TC03: adaptive sampling must give the full grid's factor in the penumbra");
        // ===== Boundary Values Tests =====
        // TC11: a uniform transparent sheet (all rays 0.5) is not "all 1 or all 0": the whole grid, 0.5
        RayTracerBasic sheet = softTracer(9, halfPlane(500, 50, new Material().setKt(0.5)));
        sheet.setAdaptiveSoftShadows(true);
        long before = sheet.getShadowRaysCount();
        assertEquals(0.5, shadowFactor(sheet, light, 0), 1e-12, "TC11: a transparent sheet must let half through");
        assertEquals(82, sheet.getShadowRaysCount() - before, "TC11: partial transparency must be sampled in full");
    }

    // ---------------------------------------------------------------------------------------------
    // Soft-shadow pictures: a sphere over a floor, lit from above by a square light of edge 20 beside
    // it; the camera looks straight down (floor x from -60 to 60 over 80 columns). Along the middle row
    // the sphere's silhouette ends at column 61, its umbra at column 69 and its penumbra at column 78.
    // ---------------------------------------------------------------------------------------------

    private static final int PICTURE_SIZE = 80;
    private static final Path PICTURE_FOLDER = Path.of("target", "test-images", "soft-shadows");

    /** Renders the sphere's shadow on the floor (soft or hard) and returns the image. */
    private static ImageWriter renderShadow(String name, boolean soft, int threads, long seed) {
        Scene scene = new Scene("soft shadow picture");
        scene.geometries.add(floor(new Material().setKd(1), Color.BLACK),
                new Sphere(new Point3D(20, 0, 40), 10).setMaterial(new Material().setKd(1)));
        scene.lights.add(new PointLight(new Color(200, 200, 200), new Point3D(0, 0, 100)).setEdgesSize(20)
                .setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        ImageWriter image = new ImageWriter(name, PICTURE_SIZE, PICTURE_SIZE, PICTURE_FOLDER);
        Render render = new Render().setImageWriter(image)
                .setCamera(new Camera(new Point3D(0, 0, 1000), DOWN, new Vector(0, 1, 0))
                        .setVpSize(120, 120).setVpDistance(1000))
                .setRayTracer(new RayTracerBasic(scene))
                .setSoftShadows(soft).setSeed(seed).setMultithreading(threads);
        render.renderImage();
        render.writeToImage();
        return image;
    }

    /** The grey level of a pixel (the floor and the sphere are grey). */
    private static int grey(ImageWriter image, int x, int y) {
        return image.getPixel(x, y).getRed();
    }

    /** Asserts two images are identical pixel for pixel. */
    private static void assertSameImage(ImageWriter expected, ImageWriter actual, String message) {
        for (int y = 0; y < expected.getNy(); ++y)
            for (int x = 0; x < expected.getNx(); ++x)
                assertEquals(expected.getPixel(x, y), actual.getPixel(x, y), message + " at (" + x + ", " + y + ")");
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: a soft shadow has a penumbra. */
    @Test
    void testSoftShadowPicture() {
        ImageWriter hard = renderShadow("hard", false, 0, RayTracerBase.DEFAULT_SEED);
        ImageWriter soft = renderShadow("soft", true, 0, RayTracerBase.DEFAULT_SEED);
        int row = PICTURE_SIZE / 2;
        // from the sphere's silhouette to the picture's right edge (lit floor), across the shadow's border
        int lit = grey(hard, PICTURE_SIZE - 1, row);
        int shadow = grey(hard, 64, row);
        int hardBetween = 0;
        int softBetween = 0;
        for (int x = 62; x < PICTURE_SIZE; ++x) {
            if (grey(hard, x, row) > shadow + 10 && grey(hard, x, row) < lit - 40)
                ++hardBetween;
            if (grey(soft, x, row) > shadow + 10 && grey(soft, x, row) < lit - 40)
                ++softBetween;
        }
        // ===== Equivalence Partitions Tests =====
        // TC01: the hard shadow is dark under lit floor (0 in the shadow, the floor lit ~200 around it)
        assertTrue(lit > 150 && shadow == 0, "TC01: the hard render must show a black shadow on a lit floor, got "
                + shadow + " and " + lit);
        // TC02: across the border the hard render jumps: no pixel between shadow and light
        assertEquals(0, hardBetween, "TC02: a hard shadow must have no penumbra");
        // TC03: the soft render has a penumbra of several intermediate grey levels
        assertTrue(softBetween >= 5, "TC03: a soft shadow must have a penumbra, found " + softBetween + " pixels");
        // ===== Boundary Values Tests =====
        // TC11: far from the sphere the soft render equals the hard one (the whole light is seen)
        assertEquals(grey(hard, 0, 0), grey(soft, 0, 0), "TC11: a fully lit corner must not change");
    }

    /** Test method for {@link RayTracerBasic#traceRay(Ray)}: soft-shadow pictures are reproducible. */
    @Test
    void testSoftShadowPictureDeterministic() {
        ImageWriter oneThread = renderShadow("soft-1", true, 1, 7);
        // ===== Equivalence Partitions Tests =====
        // TC01: 1 and 2 threads render the same picture
        assertSameImage(oneThread, renderShadow("soft-2", true, 2, 7), "TC01: 1 and 2 threads differ");
        // TC02: the same seed renders the same picture twice
        assertSameImage(oneThread, renderShadow("soft-1-again", true, 1, 7), "TC02: the same seed gave another picture");
        // ===== Boundary Values Tests =====
        // TC11: another seed moves the penumbra's noise
        ImageWriter otherSeed = renderShadow("soft-other-seed", true, 1, 8);
        int differing = 0;
        for (int x = 0; x < PICTURE_SIZE; ++x)
            if (!oneThread.getPixel(x, PICTURE_SIZE / 2).equals(otherSeed.getPixel(x, PICTURE_SIZE / 2)))
                ++differing;
        assertNotEquals(0, differing, "TC11: another seed must change the penumbra's noise");
    }

    /**
     * How two pictures of the same size differ.
     *
     * @param pixels    the pixels of each picture
     * @param differing the pixels whose colours differ
     * @param worst     the largest difference of a colour channel, in levels
     */
    private record Difference(int pixels, int differing, int worst) {
    }

    /**
     * Compares two pictures of the same size pixel by pixel.
     *
     * @param fast the picture rendered through the hierarchy
     * @param scan the picture rendered by the brute-force scan
     * @return how they differ
     */
    private static Difference difference(ImageWriter fast, ImageWriter scan) {
        int differing = 0;
        int worst = 0;
        for (int y = 0; y < fast.getNy(); ++y)
            for (int x = 0; x < fast.getNx(); ++x) {
                int a = fast.getPixel(x, y).getRGB();
                int b = scan.getPixel(x, y).getRGB();
                if (a != b) {
                    ++differing;
                    for (int shift = 0; shift < 24; shift += 8)
                        worst = Math.max(worst, Math.abs(((a >> shift) & 0xFF) - ((b >> shift) & 0xFF)));
                }
            }
        return new Difference(fast.getNx() * fast.getNy(), differing, worst);
    }

    /** Renders a gallery picture at a quarter of its size, through the hierarchy or a brute-force scan. */
    private static ImageWriter renderQuarter(Picture picture, boolean bruteForce) {
        RayTracerBasic tracer = new RayTracerBasic(picture.scene());
        tracer.setBruteForce(bruteForce);
        ImageWriter image = new ImageWriter(picture.name() + (bruteForce ? "-scan" : "-bvh"), picture.nX() / 4,
                picture.nY() / 4, PICTURE_FOLDER.resolve("acceleration"));
        Render render = new Render().setImageWriter(image).setCamera(picture.camera()).setRayTracer(tracer)
                .setSoftShadows(picture.settings().softShadows());
        render.renderImage();
        return image;
    }

    /**
     * Test method for {@link RayTracerBasic#traceRay(Ray)}: the bounding volume hierarchy changes no
     * picture — every gallery picture renders as through a brute-force scan of every body.
     */
    @Test
    void testAccelerationKeepsPictures() {
        int pixels = 0;
        int differing = 0;
        int worst = 0;
        for (Picture picture : app.Gallery.pictures()) {
            Difference difference = difference(renderQuarter(picture, false), renderQuarter(picture, true));
            pixels += difference.pixels();
            differing += difference.differing();
            worst = Math.max(worst, difference.worst());
        }
        // ===== Equivalence Partitions Tests =====
        // TC01: at most 0.1 % of the pixels differ (floating-point ties on silhouettes)
        assertTrue(differing <= pixels / 1000, "TC01: " + differing + " of " + pixels + " pixels differ");
        // ===== Boundary Values Tests =====
        // TC11: no pixel differs by more than a few levels
        assertTrue(worst <= 4, "TC11: a pixel differs by " + worst + " levels");
    }

    // ---------------------------------------------------------------------------------------------
    // Shadow bundles: the rays of a soft shadow are traced as one bundle (the bodies its pyramid meets
    // are gathered once); the pictures must stay those of a brute-force scan of every body. The scene:
    // a floor, two opaque spheres, a sphere of 484 triangles, a glass sphere (kT 0.5), lit by a square
    // light of edge 30 at height 100; the camera looks straight down (floor x, y from -60 to 60).
    // ---------------------------------------------------------------------------------------------

    private static final int BUNDLE_PICTURE_SIZE = 90;
    private static final Point3D BUNDLE_LIGHT = new Point3D(0, 0, 100);
    private static final double BUNDLE_INTENSITY = 200;

    /** The bundle scene: the floor is its first body. */
    private static Scene bundleScene() {
        Scene scene = new Scene("shadow bundles");
        Material matte = new Material().setKd(0.5);
        scene.geometries.add(floor(new Material().setKd(1), Color.BLACK),
                new Sphere(new Point3D(-25, 15, 15), 8).setMaterial(matte),
                new Sphere(new Point3D(20, -25, 10), 5).setMaterial(matte),
                new Sphere(new Point3D(20, 20, 20), 7).setMaterial(new Material().setKd(0.2).setKt(0.5)));
        for (Triangle triangle : benchmark.SphereMesh.triangles(new Point3D(-10, -20, 25), 9, 12, 22))
            scene.geometries.add(triangle.setMaterial(matte));
        scene.lights.add(new PointLight(new Color(BUNDLE_INTENSITY, BUNDLE_INTENSITY, BUNDLE_INTENSITY), BUNDLE_LIGHT)
                .setEdgesSize(30).setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        return scene;
    }

    /**
     * What a pixel of a square picture sees first: the closest hit of its ray among the scene's bodies.
     *
     * @param scene  the scene
     * @param camera the camera
     * @param size   the picture's width and height
     * @param x      the pixel's column
     * @param y      the pixel's row
     * @return the closest hit, or null when the ray meets nothing
     */
    private static GeoPoint seen(Scene scene, Camera camera, int size, int x, int y) {
        Ray ray = camera.constructRayThroughPixel(size, size, x, y);
        return ray.findClosestGeoPoint(scene.geometries.findGeoIntersections(ray));
    }

    /** The camera of the bundle pictures, straight down onto the floor. */
    private static Camera bundleCamera() {
        return new Camera(new Point3D(0, 0, 1000), DOWN, new Vector(0, 1, 0)).setVpSize(120, 120).setVpDistance(1000);
    }

    /**
     * Renders a scene of the bundle tests (soft shadows, sqrtBeamNum 5) through the hierarchy, with
     * bundles, or through a brute-force scan, and writes it under the pictures' folder.
     *
     * @param scene      the scene
     * @param camera     the camera
     * @param name       the picture's name
     * @param size       the picture's width and height
     * @param bruteForce true for the brute-force scan
     * @param adaptive   whether adaptive sampling is on
     * @return the rendered picture
     */
    private static ImageWriter renderBundleScene(Scene scene, Camera camera, String name, int size,
                                                 boolean bruteForce, boolean adaptive) {
        return renderBundleScene(new RayTracerBasic(scene), camera, name, size, bruteForce, adaptive);
    }

    /**
     * Renders a scene of the bundle tests as {@link #renderBundleScene(Scene, Camera, String, int, boolean,
     * boolean)} does, with a ray tracer of the caller's (whose ray counts it can then read).
     *
     * @param tracer     the ray tracer of the scene
     * @param camera     the camera
     * @param name       the picture's name
     * @param size       the picture's width and height
     * @param bruteForce true for the brute-force scan
     * @param adaptive   whether adaptive sampling is on
     * @return the rendered picture
     */
    private static ImageWriter renderBundleScene(RayTracerBasic tracer, Camera camera, String name, int size,
                                                 boolean bruteForce, boolean adaptive) {
        tracer.setBruteForce(bruteForce);
        ImageWriter image = new ImageWriter(name + (adaptive ? "-adaptive" : "") + (bruteForce ? "-scan" : "-bvh"),
                size, size, PICTURE_FOLDER.resolve("bundles"));
        Render render = new Render().setImageWriter(image).setCamera(camera).setRayTracer(tracer)
                .setSoftShadows(true).setSqrtBeamNum(5).setAdaptiveSoftShadows(adaptive)
                .setSeed(RayTracerBase.DEFAULT_SEED);
        render.renderImage();
        render.writeToImage();
        return image;
    }

    /**
     * Asserts that a picture rendered with bundles is the brute force's: at most 0.1 % of the pixels
     * differ, by at most 2 levels.
     *
     * @param fast the picture rendered with bundles
     * @param scan the picture rendered by the brute-force scan
     * @param tc   the test case's label
     */
    private static void assertSamePicture(ImageWriter fast, ImageWriter scan, String tc) {
        Difference difference = difference(fast, scan);
        int differing = difference.differing();
        int pixels = difference.pixels();
        assertTrue(differing <= pixels / 1000, tc + ": " + differing + " of " + pixels + " pixels differ");
        assertTrue(difference.worst() <= 2, tc + ": a pixel differs by " + difference.worst() + " levels");
    }

    /**
     * Test method for {@link RayTracerBasic#calcSoftShadows}: shadow bundles change no picture — a soft
     * shadow scene of spheres, a triangle mesh and a glass sphere renders, with adaptive sampling off
     * and on, as through a brute-force scan of every body, and it has a penumbra.
     */
    @Test
    void testShadowBundlesKeepPictures() {
        Camera camera = bundleCamera();
        double[][] floorNl = floorNl(bundleScene(), camera, BUNDLE_PICTURE_SIZE);
        for (boolean adaptive : new boolean[] { false, true }) {
            String same = adaptive ? "TC02 (adaptive sampling)" : "TC01";
            String shadow = adaptive ? "TC12 (adaptive sampling)" : "TC11";
            ImageWriter fast = renderBundleScene(bundleScene(), camera, "bundles", BUNDLE_PICTURE_SIZE, false, adaptive);
            ImageWriter scan = renderBundleScene(bundleScene(), camera, "bundles", BUNDLE_PICTURE_SIZE, true, adaptive);
            // ===== Equivalence Partitions Tests =====
            // TC01: adaptive sampling off; TC02: on: at most 0.1 % of the pixels differ from the brute
            // force, by at most 2 levels
            assertSamePicture(fast, scan, same);
            // ===== Boundary Values Tests =====
            // TC11: adaptive sampling off; TC12: on: the floor has an umbra (share < 0.02), fully lit
            // parts (share > 0.98) and a penumbra of at least 50 pixels strictly between them
            assertSoftShadow(fast, floorNl, 50, shadow);
        }
    }

    /**
     * n·l of the bundle scenes' light at each pixel that sees the floor (NaN elsewhere), found by
     * brute force.
     *
     * @param scene  a scene of the bundle tests, the floor its first body
     * @param camera the camera
     * @param size   the picture's width and height
     * @return n·l by row and column
     */
    private static double[][] floorNl(Scene scene, Camera camera, int size) {
        Plane floor = (Plane) scene.geometries.getGeometries().get(0);
        double[][] floorNl = new double[size][size];
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                GeoPoint hit = seen(scene, camera, size, x, y);
                floorNl[y][x] = hit == null || hit.geometry != floor ? Double.NaN
                        : BUNDLE_LIGHT.getZ() / hit.point.distance(BUNDLE_LIGHT);
            }
        return floorNl;
    }

    /**
     * Asserts that the floor of a bundle picture has a soft shadow: the share of the light a floor pixel
     * gets (its grey over the unshadowed kD·I·(n·l)) falls below 0.02 in an umbra and exceeds 0.98 in
     * fully lit parts, and enough pixels lie strictly between the two (by 0.05), in a penumbra.
     *
     * @param picture  the picture
     * @param floorNl  n·l at each pixel that sees the floor, NaN elsewhere ({@link #floorNl})
     * @param penumbra the fewest penumbra pixels
     * @param tc       the test case's label
     */
    private static void assertSoftShadow(ImageWriter picture, double[][] floorNl, int penumbra, String tc) {
        double darkest = Double.POSITIVE_INFINITY;
        double brightest = 0;
        List<Double> shares = new ArrayList<>();
        for (int y = 0; y < floorNl.length; ++y)
            for (int x = 0; x < floorNl.length; ++x) {
                if (Double.isNaN(floorNl[y][x]))
                    continue;
                double share = picture.getPixel(x, y).getRed() / (BUNDLE_INTENSITY * floorNl[y][x]);
                shares.add(share);
                darkest = Math.min(darkest, share);
                brightest = Math.max(brightest, share);
            }
        int between = 0;
        for (double share : shares)
            if (share > darkest + 0.05 && share < brightest - 0.05)
                ++between;
        assertTrue(darkest < 0.02 && brightest > 0.98, tc + ": the floor must have an umbra and lit parts, got "
                + darkest + " to " + brightest);
        assertTrue(between >= penumbra, tc + ": the floor must have a penumbra, found " + between + " pixels");
    }

    // ---------------------------------------------------------------------------------------------
    // Blocked bundles: three opaque closed sphere meshes (one TriangleMesh each, 224 triangles) high over
    // the floor, lit by a square light of edge 12 at the bundle scenes' light's place (height 100), seen
    // by the bundle pictures' camera. Each mesh's umbra lies off its own footprint, in sight: there
    // every ray of a bundle passes through one of the mesh's inner boxes, and the bundle is blocked
    // without a ray traced.
    // ---------------------------------------------------------------------------------------------

    private static final int SOLID_PICTURE_SIZE = 64;

    /** How the closed bodies of the scene of closed meshes are made. */
    private enum SolidForm {
        /** Three sphere meshes. */
        MESHES,
        /** The three spheres' triangles as one mesh, of three closed parts. */
        ONE_MESH,
        /** The three spheres' triangles as course-style {@link Triangle} objects. */
        TRIANGLES
    }

    /**
     * The scene of closed meshes: the floor is its first body.
     *
     * @param form how the spheres are made
     * @param kT   the spheres' transparency
     * @return the scene
     */
    private static Scene solidScene(SolidForm form, double kT) {
        Scene scene = new Scene("closed meshes");
        scene.geometries.add(floor(new Material().setKd(1), Color.BLACK));
        Material matte = new Material().setKd(0.5).setKt(kT);
        Point3D[] centres = { new Point3D(-30, 20, 30), new Point3D(25, -20, 20), new Point3D(20, 25, 35) };
        double[] radii = { 7, 6, 8 };
        TriangleMesh[] spheres = new TriangleMesh[centres.length];
        for (int m = 0; m < centres.length; ++m)
            spheres[m] = benchmark.SphereMesh.mesh(centres[m], radii[m], 8, 16);
        switch (form) {
            case MESHES -> {
                for (TriangleMesh mesh : spheres)
                    scene.geometries.add(mesh.setMaterial(matte));
            }
            case ONE_MESH -> scene.geometries.add(TestMeshes.merge(spheres).setMaterial(matte));
            case TRIANGLES -> {
                for (TriangleMesh mesh : spheres)
                    for (Triangle triangle : mesh.getTriangles())
                        scene.geometries.add(triangle.setMaterial(matte));
            }
        }
        scene.lights.add(new PointLight(new Color(BUNDLE_INTENSITY, BUNDLE_INTENSITY, BUNDLE_INTENSITY), BUNDLE_LIGHT)
                .setEdgesSize(12).setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        return scene;
    }

    /** {@return the scene of closed meshes, three opaque sphere meshes} */
    private static Scene solidScene() {
        return solidScene(SolidForm.MESHES, 0);
    }

    /**
     * Test method for {@link RayTracerBasic#calcSoftShadows} and {@link RayTracerBase#getBlockedShadowRaysCount()}:
     * bundles blocked whole by closed opaque meshes change no picture — the scene of closed meshes
     * renders, with adaptive sampling off and on, as three meshes, as one mesh of three closed parts
     * and as course-style triangles, as through a brute-force scan of every body, which blocks no
     * bundle, while the hierarchy blocks many.
     */
    @Test
    void testBlockedBundlesKeepPictures() {
        Camera camera = bundleCamera();
        double[][] floorNl = floorNl(solidScene(), camera, SOLID_PICTURE_SIZE);
        for (SolidForm form : SolidForm.values())
            for (boolean adaptive : new boolean[] { false, true }) {
                String suffix = " (" + form + (adaptive ? ", adaptive sampling)" : ")");
                String same = (adaptive ? "TC02" : "TC01") + suffix;
                String counted = (adaptive ? "TC04" : "TC03") + suffix;
                String shadow = (adaptive ? "TC12" : "TC11") + suffix;
                RayTracerBasic fastTracer = new RayTracerBasic(solidScene(form, 0));
                RayTracerBasic scanTracer = new RayTracerBasic(solidScene(form, 0));
                ImageWriter fast = renderBundleScene(fastTracer, camera, "solids", SOLID_PICTURE_SIZE, false, adaptive);
                ImageWriter scan = renderBundleScene(scanTracer, camera, "solids", SOLID_PICTURE_SIZE, true, adaptive);
                // ===== Equivalence Partitions Tests =====
                // TC01: adaptive sampling off; TC02: on (each in the three forms): at most 0.1 % of the
                // pixels differ from the brute force, by at most 2 levels
                assertSamePicture(fast, scan, same);
                // TC03: adaptive sampling off; TC04: on: the hierarchy blocks bundles of at least 1000
                // shadow rays (not all of them), the brute force none
                long blocked = fastTracer.getBlockedShadowRaysCount();
                long shadowRays = fastTracer.getShadowRaysCount();
                assertTrue(blocked >= 1000 && blocked < shadowRays, counted + ": " + blocked + " of "
                        + shadowRays + " shadow rays in blocked bundles");
                assertEquals(0, scanTracer.getBlockedShadowRaysCount(),
                        counted + ": the brute force must block no bundle");
                assertTrue(scanTracer.getShadowRaysCount() > 0, counted + ": the brute force traces shadow rays");
                // ===== Boundary Values Tests =====
                // TC11: adaptive sampling off; TC12: on: the floor has an umbra (share < 0.02), fully lit
                // parts (share > 0.98) and a penumbra of at least 30 pixels strictly between them
                assertSoftShadow(fast, floorNl, 30, shadow);
            }
    }

    /**
     * Test method for {@link RayTracerBasic#prepare(int)}: course-style triangles made transparent
     * after the hierarchy was built block no bundle in the next render, whose picture is the brute
     * force's.
     */
    @Test
    void testBlockedBundlesReadMaterials() {
        Camera camera = bundleCamera();
        Scene scene = solidScene(SolidForm.TRIANGLES, 0);
        RayTracerBasic tracer = new RayTracerBasic(scene);
        renderBundleScene(tracer, camera, "solids-opaque", SOLID_PICTURE_SIZE, false, false);
        // ===== Equivalence Partitions Tests =====
        // TC01: opaque: bundles blocked (at least 1000 shadow rays)
        assertTrue(tracer.getBlockedShadowRaysCount() >= 1000, "TC01: the opaque triangles block bundles");
        // TC02: the same triangles' material made transparent (kT 0.5) and rendered again: no bundle
        // blocked, the picture the brute force's over transparent spheres
        ((Triangle) scene.geometries.getGeometries().get(1)).getMaterial().setKt(0.5);
        RayTracerBasic again = new RayTracerBasic(scene);
        ImageWriter fast = renderBundleScene(again, camera, "solids-clear", SOLID_PICTURE_SIZE, false, false);
        ImageWriter scan = renderBundleScene(new RayTracerBasic(solidScene(SolidForm.TRIANGLES, 0.5)), camera,
                "solids-clear-scan", SOLID_PICTURE_SIZE, true, false);
        assertEquals(0, again.getBlockedShadowRaysCount(), "TC02: transparent triangles block no bundle");
        assertSamePicture(fast, scan, "TC02");
        // ===== Boundary Values Tests =====
        // TC11: the triangles' material made opaque again (kT 0): bundles blocked again in the next render
        ((Triangle) scene.geometries.getGeometries().get(1)).getMaterial().setKt(0);
        RayTracerBasic third = new RayTracerBasic(scene);
        renderBundleScene(third, camera, "solids-opaque-again", SOLID_PICTURE_SIZE, false, false);
        assertTrue(third.getBlockedShadowRaysCount() >= 1000, "TC11: opaque again, the triangles block bundles");
    }

    // ---------------------------------------------------------------------------------------------
    // Thick shadow bundles: a big light square (edge 80 at height 25) close above a sphere of 528
    // triangles (radius 10, on a floor at z = −10). For the mesh's points between about 12° and 66°
    // from its top the light's centre is above the tangent plane but part of the square below it: the
    // bundle's rays leave the surface on both sides, and the pyramid starts on the surface, 0.1 thick.
    // The camera looks straight down at x, y from −20 to 20.
    // ---------------------------------------------------------------------------------------------

    private static final int TERMINATOR_PICTURE_SIZE = 60;
    private static final Point3D TERMINATOR_LIGHT = new Point3D(0, 0, 25);
    private static final double TERMINATOR_HALF_EDGE = 40;

    /** The terminator scene: a floor, then the mesh sphere's triangles. */
    private static Scene terminatorScene() {
        return terminatorScene(false);
    }

    /**
     * The terminator scene: a floor, then the mesh sphere, as {@link Triangle} objects or as one closed
     * {@link TriangleMesh} (whose inner boxes then block rays).
     *
     * @param asMesh whether the sphere is one {@link TriangleMesh}
     * @return the scene
     */
    private static Scene terminatorScene(boolean asMesh) {
        Scene scene = new Scene("thick shadow bundles");
        Plane plane = new Plane(new Point3D(0, 0, -10), new Vector(0, 0, 1));
        plane.setMaterial(new Material().setKd(1));
        scene.geometries.add(plane);
        Material matte = new Material().setKd(0.8);
        if (asMesh)
            scene.geometries.add(benchmark.SphereMesh.mesh(Point3D.ZERO, 10, 12, 22).setMaterial(matte));
        else
            for (Triangle triangle : benchmark.SphereMesh.triangles(Point3D.ZERO, 10, 12, 22))
                scene.geometries.add(triangle.setMaterial(matte));
        scene.lights.add(new PointLight(new Color(200, 200, 200), TERMINATOR_LIGHT)
                .setEdgesSize(2 * TERMINATOR_HALF_EDGE).setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        return scene;
    }

    /** The camera of the terminator pictures, straight down onto the sphere. */
    private static Camera terminatorCamera() {
        return new Camera(new Point3D(0, 0, 1000), DOWN, new Vector(0, 1, 0)).setVpSize(40, 40).setVpDistance(1000);
    }

    /**
     * Asserts that the terminator scene is as intended: most pixels that see a point of the sphere lit
     * by the light's centre see one whose tangent plane cuts the light's square, whose bundle is thick.
     *
     * @param asMesh whether the sphere is one {@link TriangleMesh}
     */
    private static void assertManyThickBundles(boolean asMesh) {
        Scene reference = terminatorScene(asMesh);
        Camera camera = terminatorCamera();
        Plane floor = (Plane) reference.geometries.getGeometries().get(0);
        int thick = 0;
        int lit = 0;
        for (int y = 0; y < TERMINATOR_PICTURE_SIZE; ++y)
            for (int x = 0; x < TERMINATOR_PICTURE_SIZE; ++x) {
                GeoPoint hit = seen(reference, camera, TERMINATOR_PICTURE_SIZE, x, y);
                if (hit == null || hit.geometry == floor)
                    continue;
                Vector n = hit.geometry.getNormal(hit.point);
                if (n.dotProduct(TERMINATOR_LIGHT.subtract(hit.point)) <= 0)
                    continue;
                ++lit;
                boolean above = false;
                boolean below = false;
                for (double sx : new double[] { -1, 1 })
                    for (double sy : new double[] { -1, 1 }) {
                        Point3D corner = new Point3D(sx * TERMINATOR_HALF_EDGE, sy * TERMINATOR_HALF_EDGE,
                                TERMINATOR_LIGHT.getZ());
                        double side = n.dotProduct(corner.subtract(hit.point));
                        above |= side > 0;
                        below |= side < 0;
                    }
                if (above && below)
                    ++thick;
            }
        assertTrue(thick >= 300 && thick >= lit / 2, "the scene must have many thick bundles, got " + thick + " of "
                + lit + " lit mesh pixels");
    }

    /**
     * Renders the terminator scene with bundles and by brute force and asserts the pictures the same:
     * at most 0.1 % of the pixels differ, by at most 2 levels.
     *
     * @param asMesh   whether the sphere is one {@link TriangleMesh}
     * @param name     the pictures' name
     * @param adaptive whether adaptive sampling is on
     * @param tc       the test case's label
     * @return the picture rendered with bundles
     */
    private static ImageWriter assertTerminatorKept(boolean asMesh, String name, boolean adaptive, String tc) {
        Camera camera = terminatorCamera();
        ImageWriter fast = renderBundleScene(terminatorScene(asMesh), camera, name, TERMINATOR_PICTURE_SIZE, false,
                adaptive);
        ImageWriter scan = renderBundleScene(terminatorScene(asMesh), camera, name, TERMINATOR_PICTURE_SIZE, true,
                adaptive);
        assertSamePicture(fast, scan, tc);
        return fast;
    }

    /**
     * Test method for {@link RayTracerBasic#calcSoftShadows}: thick shadow bundles (the light's square
     * partly below a lit point's tangent plane) change no picture — the terminator scene renders, with
     * adaptive sampling off and on, as through a brute-force scan of every body.
     */
    @Test
    void testThickShadowBundlesKeepPictures() {
        // the pixels that see a mesh point lit by the light's centre whose tangent plane cuts the square
        assertManyThickBundles(false);
        // ===== Equivalence Partitions Tests =====
        // TC01: adaptive sampling off; TC02: on: at most 0.1 % of the pixels differ from the brute
        // force, by at most 2 levels
        assertTerminatorKept(false, "terminator", false, "TC01");
        assertTerminatorKept(false, "terminator", true, "TC02 (adaptive sampling)");
    }

    /**
     * Test method for {@link RayTracerBasic#calcSoftShadows}: thick shadow bundles leaving a closed
     * {@link TriangleMesh} change no picture — the terminator scene with its sphere as one mesh (whose
     * inner boxes block the rays of a packet that enter them, untested) renders, with adaptive
     * sampling off and on, as through a brute-force scan of every body, and as the same triangles given
     * as {@link Triangle} objects.
     */
    @Test
    void testThickBundlesOnClosedMeshKeepPictures() {
        assertManyThickBundles(true);
        // ===== Equivalence Partitions Tests =====
        // TC01: adaptive sampling off; TC02: on: at most 0.1 % of the pixels differ from the brute
        // force, by at most 2 levels
        ImageWriter mesh = assertTerminatorKept(true, "terminator-mesh", false, "TC01");
        assertTerminatorKept(true, "terminator-mesh", true, "TC02 (adaptive sampling)");
        // ===== Boundary Values Tests =====
        // TC11: rendered with bundles, the mesh's picture is that of the Triangle objects: at most 0.1 % of
        // the pixels differ, by at most 2 levels
        assertSamePicture(mesh, renderBundleScene(terminatorScene(false), terminatorCamera(), "terminator",
                TERMINATOR_PICTURE_SIZE, false, false), "TC11");
    }

    // ---------------------------------------------------------------------------------------------
    // Open bundles: when nothing can block any ray of a bundle, its sample points are skipped, not
    // drawn, and the numbers drawn after them must stay those the brute force draws. Two square lights,
    // each of one colour, over a floor: light A (red, edge 10, at (0, 0, 50)) reaches most floor points
    // through open bundles; light B (green, edge 20, at (60, 0, 50)), traced after A, throws the soft
    // shadow of a sphere (radius 5 at (30, 0, 10)) around (22.5, 0, 0). The camera looks straight down
    // at x from 2 to 42, y from −20 to 20.
    // ---------------------------------------------------------------------------------------------

    private static final int OPEN_PICTURE_SIZE = 60;
    private static final Point3D OPEN_LIGHT_A = new Point3D(0, 0, 50);
    private static final Point3D OPEN_LIGHT_B = new Point3D(60, 0, 50);

    /** The open-bundles scene: the floor, the sphere, light A then light B. */
    private static Scene openScene() {
        Scene scene = new Scene("open bundles");
        scene.geometries.add(floor(new Material().setKd(1), Color.BLACK),
                new Sphere(new Point3D(30, 0, 10), 5).setMaterial(new Material().setKd(1)));
        scene.lights.add(new PointLight(new Color(200, 0, 0), OPEN_LIGHT_A).setEdgesSize(10)
                .setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        scene.lights.add(new PointLight(new Color(0, 200, 0), OPEN_LIGHT_B).setEdgesSize(20)
                .setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        return scene;
    }

    /** The camera of the open-bundles pictures, straight down onto the floor. */
    private static Camera openCamera() {
        return new Camera(new Point3D(22, 0, 1000), DOWN, new Vector(0, 1, 0)).setVpSize(40, 40).setVpDistance(1000);
    }

    /**
     * Test method for {@link RayTracerBasic#calcSoftShadows}: a bundle nothing can block draws no sample
     * points but keeps the random stream where drawing them would leave it — a second light's soft
     * shadow, where the first light's bundles are open, renders as through a brute-force scan (which
     * draws every sample point).
     */
    @Test
    void testOpenBundlesKeepPictures() {
        Scene reference = openScene();
        Camera camera = openCamera();
        Plane floor = (Plane) reference.geometries.getGeometries().get(0);
        for (boolean adaptive : new boolean[] { false, true }) {
            String same = adaptive ? "TC02 (adaptive sampling)" : "TC01";
            String penumbra = adaptive ? "TC12 (adaptive sampling)" : "TC11";
            ImageWriter fast = renderBundleScene(openScene(), camera, "open", OPEN_PICTURE_SIZE, false, adaptive);
            ImageWriter scan = renderBundleScene(openScene(), camera, "open", OPEN_PICTURE_SIZE, true, adaptive);
            // floor pixels fully lit by A (red share > 0.98) in B's penumbra (green share in (0.05, 0.95))
            int openInPenumbra = 0;
            for (int y = 0; y < OPEN_PICTURE_SIZE; ++y)
                for (int x = 0; x < OPEN_PICTURE_SIZE; ++x) {
                    GeoPoint hit = seen(reference, camera, OPEN_PICTURE_SIZE, x, y);
                    if (hit == null || hit.geometry != floor)
                        continue;
                    double shareA = fast.getPixel(x, y).getRed()
                            / (200 * OPEN_LIGHT_A.getZ() / hit.point.distance(OPEN_LIGHT_A));
                    double shareB = fast.getPixel(x, y).getGreen()
                            / (200 * OPEN_LIGHT_B.getZ() / hit.point.distance(OPEN_LIGHT_B));
                    if (shareA > 0.98 && shareB > 0.05 && shareB < 0.95)
                        ++openInPenumbra;
                }
            // ===== Equivalence Partitions Tests =====
            // TC01: adaptive sampling off; TC02: on: at most 0.1 % of the pixels differ from the brute
            // force, by at most 2 levels
            assertSamePicture(fast, scan, same);
            // ===== Boundary Values Tests =====
            // TC11: adaptive sampling off; TC12: on: at least 50 floor pixels get all of A's light (open
            // bundles, sample points skipped) and part of B's (its sample points drawn after the skip)
            assertTrue(openInPenumbra >= 50, penumbra + ": too few pixels lit by A in B's penumbra: " + openInPenumbra);
        }
    }
}
