package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.MissingResourceException;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.UnaryOperator;

import org.junit.jupiter.api.Test;

import accel.BoundingVolumeHierarchy;
import geometries.Geometries;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
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

/**
 * Render tests for {@link Render}: small pictures written under {@code target/}, checked pixel by pixel.
 */
class RenderTest {
    private static final Path FOLDER = Path.of("target", "test-images", "render");
    private static final int SIZE = 100;
    private static final Color BACKGROUND = new Color(20, 40, 60);

    /** A camera above the floor z = 0, looking straight down, the view plane covering 200×200 of it. */
    private static Camera topCamera() {
        return new Camera(new Point3D(0, 0, 1000), new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(200, 200).setVpDistance(1000);
    }

    /** A 200×200 diffuse floor square at z = 0, made of two triangles. */
    private static Scene floorScene(String name) {
        return floorScene(name, new Material().setKd(0.8));
    }

    /** A 200×200 floor square at z = 0 of the given material, made of two triangles. */
    private static Scene floorScene(String name, Material material) {
        Scene scene = new Scene(name).setBackground(BACKGROUND);
        Point3D a = new Point3D(-100, -100, 0);
        Point3D b = new Point3D(100, -100, 0);
        Point3D c = new Point3D(100, 100, 0);
        Point3D d = new Point3D(-100, 100, 0);
        scene.geometries.add(new Triangle(a, b, c).setMaterial(material), new Triangle(a, c, d).setMaterial(material));
        return scene;
    }

    /**
     * Renders a square picture through the top camera with k × k rays per pixel, writing it under target/.
     *
     * @param name    the picture's name
     * @param size    the picture's width and height in pixels
     * @param tracer  the ray tracer
     * @param k       the anti-aliasing rays per pixel side
     * @param threads the thread count
     * @return the render, its picture done
     */
    private static Render render(String name, int size, RayTracerBase tracer, int k, int threads) {
        return render(name, size, render -> render.setRayTracer(tracer).setMultithreading(threads).setAntiAliasing(k));
    }

    /**
     * Renders a square picture through the top camera, writing it under target/.
     *
     * @param name     the picture's name
     * @param size     the picture's width and height in pixels
     * @param settings sets the rest (the ray tracer or the scene, ...) on the render given
     * @return the render, its picture done
     */
    private static Render render(String name, int size, UnaryOperator<Render> settings) {
        Render render = settings.apply(new Render().setImageWriter(new ImageWriter(name, size, size, FOLDER))
                .setCamera(topCamera()));
        render.renderImage();
        render.writeToImage();
        return render;
    }

    private static Render render(String name, Scene scene, int threads) {
        return render(name, SIZE, new RayTracerBasic(scene), 1, threads);
    }

    private static Render render(String name, Scene scene) {
        return render(name, scene, 2);
    }

    /** A pixel of a render's picture. */
    private static java.awt.Color pixel(Render render, int x, int y) {
        return render.getImageWriter().getPixel(x, y);
    }

    /** The brightness of a pixel: the sum of its channels. */
    private static int brightness(Render render, int x, int y) {
        java.awt.Color c = pixel(render, x, y);
        return c.getRed() + c.getGreen() + c.getBlue();
    }

    /** Test method for {@link Render#renderImage()}: background and ambient light. */
    @Test
    void testBackgroundAndAmbient() {
        Scene scene = new Scene("ambient").setBackground(BACKGROUND)
                .setAmbientLight(new AmbientLight(new Color(255, 191, 191), 0.5));
        scene.geometries.add(new Sphere(new Point3D(0, 0, 0), 50).setEmission(new Color(10, 0, 0)));
        Render render = render("ambient", scene);

        // ===== Equivalence Partitions Tests =====
        // TC01: a corner pixel hits nothing: background (20, 40, 60)
        assertEquals(new java.awt.Color(20, 40, 60), pixel(render, 0, 0),
                "TC01: a pixel that hits nothing must be the background");
        // TC02: the centre pixel hits the sphere: emission + ambient = (10+127.5, 95.5, 95.5), truncated
        assertEquals(new java.awt.Color(137, 95, 95), pixel(render, 50, 50),
                "TC02: an unlit body must show emission plus ambient");
    }

    /** Test method for {@link Render#renderImage()}: a lit point against the same point with no light. */
    @Test
    void testLightBrightens() {
        Scene dark = floorScene("dark");
        Scene lit = floorScene("lit");
        lit.lights.add(new PointLight(new Color(300, 300, 300), new Point3D(0, 0, 100)));

        // ===== Equivalence Partitions Tests =====
        // TC01: the centre is black without light and bright (0.8·300 = 240 per channel) with it
        assertEquals(0, brightness(render("dark", dark), 50, 50), "TC01: an unlit floor must be black");
        assertEquals(3 * 240, brightness(render("lit", lit), 50, 50), 3, "TC01: the lit floor must be kD·I");
    }

    /** Test method for {@link Render#renderImage()}: opaque and transparent shadows. */
    @Test
    void testShadows() {
        LightSource light = new PointLight(new Color(300, 300, 300), new Point3D(0, 0, 150));
        Scene opaque = floorScene("opaque shadow");
        opaque.geometries.add(new Sphere(new Point3D(0, 0, 60), 20));
        opaque.lights.add(light);
        Scene transparent = floorScene("transparent shadow");
        transparent.geometries.add(new Sphere(new Point3D(0, 0, 60), 20).setMaterial(new Material().setKt(0.5)));
        transparent.lights.add(light);
        Render opaqueRender = render("shadowOpaque", opaque);
        Render transparentRender = render("shadowTransparent", transparent);

        // ===== Equivalence Partitions Tests =====
        // a floor pixel far from the sphere's shadow, seen past the sphere
        int litOpaque = brightness(opaqueRender, 5, 50);
        // the floor under the sphere is hidden by it from the camera, so look at the shadow's rim region:
        // the shadow of a sphere r20 at height 60 from a light at 150 reaches ~33 units from the centre
        int shadowOpaque = brightness(opaqueRender, 50 + 14, 50);
        int shadowTransparent = brightness(transparentRender, 50 + 14, 50);
        // TC01: a shadowed floor pixel is darker than a lit one (black under an opaque blocker)
        assertTrue(shadowOpaque < litOpaque, "TC01: the shadow must be darker than the lit floor");
        assertEquals(0, shadowOpaque, "TC01: the shadow of an opaque body must be black");
        // TC02: behind a transparent sphere (kT 0.5, crossed twice) the shadow is lighter than behind an opaque one
        assertTrue(shadowTransparent > shadowOpaque, "TC02: a transparent body must cast a lighter shadow");
    }

    /** Test method for {@link Render#renderImage()}: a mirror shows the reflected body's colour. */
    @Test
    void testMirror() {
        Scene scene = floorScene("mirror", new Material().setKr(1));
        // a green sphere hanging over the mirror, off the camera's axis
        scene.geometries.add(new Sphere(new Point3D(60, 0, 300), 10).setEmission(new Color(0, 200, 0)));
        Render render = render("mirror", scene);

        // ===== Equivalence Partitions Tests =====
        // the sphere is seen directly at x = 60·1000/700 ≈ 86 on the view plane (pixel column ≈ 93),
        // and its mirror image, 1300 from the camera, at x = 60·1000/1300 ≈ 46 (pixel column ≈ 73)
        // TC01: the sphere seen directly: green
        assertEquals(new java.awt.Color(0, 200, 0), pixel(render, 93, 50),
                "TC01: the sphere must be seen directly");
        // TC02: the mirror shows the reflected sphere's colour where nothing is in front of it
        assertEquals(new java.awt.Color(0, 200, 0), pixel(render, 73, 50),
                "TC02: the mirror must show the reflected sphere's colour");
        // TC03: elsewhere the mirror reflects the background
        assertEquals(new java.awt.Color(20, 40, 60), pixel(render, 30, 50),
                "TC03: the mirror must reflect the background where nothing is above it");
    }

    /** Test method for {@link Render#renderImage()}: attenuation and the spot's narrow beam. */
    @Test
    void testAttenuationAndNarrowBeam() {
        Scene attenuated = floorScene("attenuation");
        attenuated.lights.add(new PointLight(new Color(600, 600, 600), new Point3D(0, 0, 50)).setKq(0.0002));
        Render render = render("attenuation", attenuated);

        // ===== Equivalence Partitions Tests =====
        // TC01: attenuation lowers intensity with distance from the light: centre > middle > corner
        int centre = brightness(render, 50, 50);
        int middle = brightness(render, 75, 50);
        int corner = brightness(render, 99, 99);
        assertTrue(centre > middle && middle > corner, "TC01: intensity must fall with distance");

        // TC02: a narrow beam lights fewer pixels than a plain spot
        Scene wide = floorScene("wide spot");
        wide.lights.add(new SpotLight(new Color(600, 600, 600), new Point3D(0, 0, 50), new Vector(0, 0, -1)));
        Scene narrow = floorScene("narrow spot");
        narrow.lights.add(new SpotLight(new Color(600, 600, 600), new Point3D(0, 0, 50), new Vector(0, 0, -1))
                .setNarrowBeam(20));
        int wideLit = countBrighterThan(render("spotWide", wide), 150);
        int narrowLit = countBrighterThan(render("spotNarrow", narrow), 150);
        assertTrue(narrowLit > 0 && narrowLit < wideLit,
                "TC02: the narrow beam must light fewer pixels (" + narrowLit + " vs " + wideLit + ")");
    }

    private static int countBrighterThan(Render render, int threshold) {
        int count = 0;
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x)
                if (brightness(render, x, y) > threshold)
                    ++count;
        return count;
    }

    /**
     * Test method for {@link Render#renderImage()}: two triangles sharing an edge leave no seam, although
     * the course's query on them misses every ray through that edge.
     */
    @Test
    void testNoSeam() {
        Scene scene = floorScene("seam").setAmbientLight(new AmbientLight(new Color(100, 100, 100), 1));
        Render render = render("seam", scene);

        // ===== Boundary Values Tests =====
        // TC10: the rays of the pixels (k, 99 − k) meet the floor exactly on the shared diagonal: the
        // course's query (open triangles) misses all 100 of them (null)
        for (int k = 0; k < SIZE; ++k)
            assertNull(scene.geometries.findIntersections(topCamera().constructRayThroughPixel(SIZE, SIZE, k, SIZE - 1 - k)),
                    "TC10: the course's query must miss the shared edge at pixel (" + k + ", " + (SIZE - 1 - k) + ")");
        // TC11: no pixel along the shared diagonal (and next to it) shows the background
        for (int k = 0; k < SIZE; ++k)
            for (int d = -1; d <= 1; ++d) {
                int x = Math.min(SIZE - 1, Math.max(0, k + d));
                assertNotEquals(new java.awt.Color(20, 40, 60), pixel(render, x, SIZE - 1 - k),
                        "TC11: the seam between the triangles shows the background at (" + x + ", " + (SIZE - 1 - k) + ")");
            }
    }

    /**
     * Test method for {@link Render#renderImage()}: the hierarchy over the bodies is built once, and
     * again only when the scene's bodies change.
     */
    @Test
    void testRenderBuildsOnce() {
        Scene scene = floorScene("build once").setAmbientLight(new AmbientLight(new Color(100, 100, 100), 1));
        Geometries extra = new Geometries();
        scene.geometries.add(extra);
        RayTracerBasic tracer = new RayTracerBasic(scene);
        Render render = render("buildOnce1", SIZE, tracer, 1, 2);
        BoundingVolumeHierarchy first = tracer.accelerator();

        // ===== Equivalence Partitions Tests =====
        // TC01: a second render of the unchanged scene keeps the hierarchy (the same object)
        render.renderImage();
        assertSame(first, tracer.accelerator(), "TC01: an unchanged scene must not be built again");
        // TC02: a sphere added to a nested composite: built again, and the sphere is seen in the
        // centre (its emission (255, 0, 0) plus the ambient light (100, 100, 100) saturates red)
        extra.add(new Sphere(new Point3D(0, 0, 50), 20).setEmission(new Color(255, 0, 0)));
        render.renderImage();
        assertNotSame(first, tracer.accelerator(), "TC02: a body added to a nested composite must be seen");
        assertEquals(new java.awt.Color(255, 100, 100), pixel(render, SIZE / 2, SIZE / 2),
                "TC02: the added sphere must be seen in the centre");
    }

    /** Test method for {@link Render#setMultithreading(int)}: the picture does not depend on the thread count. */
    @Test
    void testThreadsGiveSamePicture() {
        Scene scene = floorScene("threads");
        scene.geometries.add(new Sphere(new Point3D(10, 10, 30), 20)
                .setMaterial(new Material().setKd(0.4).setKs(0.5).setShininess(40).setKt(0.3).setKr(0.2)));
        scene.lights.add(new SpotLight(new Color(500, 400, 300), new Point3D(-40, 30, 120), new Vector(1, -1, -3)));
        Render one = render("threads1", scene, 1);
        Render two = render("threads2", scene, 2);

        // ===== Equivalence Partitions Tests =====
        // TC01: 1 thread and 2 threads give the same pixels
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x)
                assertEquals(pixel(one, x, y), pixel(two, x, y),
                        "TC01: pixel (" + x + ", " + y + ") differs between 1 and 2 threads");
        // ===== Boundary Values Tests =====
        // TC11: a negative thread count is rejected
        assertThrows(IllegalArgumentException.class, () -> new Render().setMultithreading(-1),
                "TC11: a negative thread count must be rejected");
    }

    /**
     * Test method for {@link Render#renderImage()}: points that coincide (a light on the surface, a hit on
     * a sphere's centre through a large aperture) render to the end, as {@link RayTracerBasic} says.
     */
    @Test
    void testCoincidingPointsRender() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a point light on the floor, where the ray of pixel (50, 50) meets it, (1, -1, 0): the picture is
        // rendered, and that pixel gets nothing from the light, the ambient light's (50, 50, 50) alone; so does
        // the floor around it, which sees the light edge-on
        Scene scene = floorScene("light on the floor").setAmbientLight(new AmbientLight(new Color(50, 50, 50), 1));
        scene.lights.add(new PointLight(new Color(500, 500, 500), new Point3D(1, -1, 0)));
        Render render = render("lightOnFloor", scene);
        assertEquals(new java.awt.Color(50, 50, 50), pixel(render, 50, 50), "TC01: the light on the point adds nothing");
        assertEquals(new java.awt.Color(50, 50, 50), pixel(render, 60, 50), "TC01: the light edge-on adds nothing");
        // TC02: a sphere of radius 5e-5, 1e12 away, seen through an aperture of 1000 focused on its centre: the
        // hits round onto the centre; the picture is rendered, the sphere lit as facing the rays:
        // emission (10, 20, 30) + kD 0.8 · (255, 255, 255) = (214, 224, 234)
        Scene tiny = new Scene("tiny sphere");
        tiny.geometries.add(new Sphere(new Point3D(0, 0, -1e12), 5e-5).setEmission(new Color(10, 20, 30))
                .setMaterial(new Material().setKd(0.8)));
        tiny.lights.add(new DirectionalLight(new Color(255, 255, 255), new Vector(0, 0, -1)));
        Camera lens = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpSize(1, 1)
                .setVpDistance(1).setFocalDistance(1e12).setApertureSize(1000).setSqrtApertureRays(3);
        Render aperture = new Render().setImageWriter(new ImageWriter("tinySphere", 3, 3, FOLDER)).setCamera(lens)
                .setRayTracer(new RayTracerBasic(tiny)).setMultithreading(2);
        aperture.renderImage();
        assertEquals(new java.awt.Color(214, 224, 234), pixel(aperture, 1, 1), "TC02: wrong colour of the centre");

        // ===== Boundary Values Tests =====
        // TC11: a spot light on the floor at that point with soft shadows, 5 x 5 beams: rendered, the pixel as in TC01
        Scene spot = floorScene("spot on the floor").setAmbientLight(new AmbientLight(new Color(50, 50, 50), 1));
        spot.lights.add(new SpotLight(new Color(500, 500, 500), new Point3D(1, -1, 0), new Vector(0, 0, 1))
                .setEdgesSize(20));
        Render soft = render("spotOnFloor", SIZE, new RayTracerBasic(spot).setSoftShadows(true).setSqrtBeamNum(5), 1, 2);
        assertEquals(new java.awt.Color(50, 50, 50), pixel(soft, 50, 50), "TC11: the spot on the point adds nothing");
    }

    /** Test method for {@link Render#renderImage()}, {@link Render#printGrid} and {@link Render#writeToImage()}. */
    @Test
    void testMissingPartsAndGrid() {
        Scene scene = floorScene("grid");
        ImageWriter writer = new ImageWriter("grid", SIZE, SIZE, FOLDER);

        // ===== Equivalence Partitions Tests =====
        // TC01: each missing part is named
        MissingResourceException e = assertThrows(MissingResourceException.class, () -> new Render().renderImage(),
                "TC01: a render without an image writer must fail");
        assertMessage(e, "image writer", "TC01");
        e = assertThrows(MissingResourceException.class,
                () -> new Render().setImageWriter(writer).setRayTracer(new RayTracerBasic(scene)).renderImage(),
                "TC01: a render without a camera must fail");
        assertMessage(e, "camera", "TC01");
        e = assertThrows(MissingResourceException.class,
                () -> new Render().setImageWriter(writer).setCamera(topCamera()).renderImage(),
                "TC01: a render without a ray tracer must fail");
        assertMessage(e, "ray tracer", "TC01");
        assertThrows(MissingResourceException.class, () -> new Render().writeToImage(),
                "TC01: writing without an image writer must fail");

        // TC02: the grid colours every 10th row and column and leaves the rest
        Render render = new Render().setImageWriter(writer);
        render.printGrid(10, new Color(255, 255, 0));
        assertEquals(java.awt.Color.YELLOW, writer.getPixel(20, 7), "TC02: grid column must be yellow");
        assertEquals(java.awt.Color.YELLOW, writer.getPixel(7, 30), "TC02: grid row must be yellow");
        assertEquals(java.awt.Color.BLACK, writer.getPixel(7, 7), "TC02: off the grid the pixel must not change");
        render.writeToImage();
        assertTrue(Files.exists(FOLDER.resolve("grid.png")), "TC02: the picture must be written");
        // TC03: a null among the scene's lights (put in through the public field) stops the render before its
        // first tile: an IllegalArgumentException naming it, no tile reported, no pixel rendered
        Scene unlit = floorScene("null light");
        unlit.lights = java.util.Arrays.asList(new DirectionalLight(new Color(100, 100, 100), new Vector(0, 0, -1)),
                null);
        AtomicInteger tiles = new AtomicInteger();
        ImageWriter blank = new ImageWriter("nullLight", SIZE, SIZE, FOLDER);
        Render refused = new Render().setImageWriter(blank).setCamera(topCamera()).setRayTracer(new RayTracerBasic(unlit))
                .setProgressListener(done -> tiles.incrementAndGet());
        assertMessage(assertThrows(IllegalArgumentException.class, refused::renderImage,
                "TC03: a null light must stop the render"), "scene.lights must not hold null (at index 1)", "TC03");
        assertEquals(0, tiles.get(), "TC03: no tile may be rendered");
        assertEquals(java.awt.Color.BLACK, blank.getPixel(SIZE / 2, SIZE / 2), "TC03: no pixel may be rendered");

        // ===== Boundary Values Tests =====
        // TC11: a grid interval of 0 is rejected
        assertThrows(IllegalArgumentException.class, () -> render.printGrid(0, Color.BLACK),
                "TC11: a zero grid interval must be rejected");
    }

    /**
     * Test method for {@link Render#setScene(Scene)}: the course's early render, with no ray tracer set,
     * traces the scene with a {@link RayTracerBasic}; a ray tracer set explicitly wins.
     */
    @Test
    void testSetScene() throws IOException {
        Scene scene = floorScene("set scene");
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point3D(0, 0, 100)));
        Render viaScene = render("setScene", SIZE, render -> render.setScene(scene));
        render("setSceneTracer", SIZE, render -> render.setRayTracer(new RayTracerBasic(scene)));

        // ===== Equivalence Partitions Tests =====
        // TC01: the scene alone is rendered: the lit floor's centre is kD·I = 240 per channel
        assertEquals(3 * 240, brightness(viaScene, 50, 50), 3, "TC01: the scene set must be rendered");
        assertInstanceOf(RayTracerBasic.class, viaScene.getRayTracer(), "TC01: the scene's tracer is a RayTracerBasic");
        // TC02: the picture is, byte for byte, that of an explicit RayTracerBasic over the same scene (-1: no mismatch)
        assertEquals(-1L, Files.mismatch(FOLDER.resolve("setScene.png"), FOLDER.resolve("setSceneTracer.png")),
                "TC02: setScene must render the picture of a RayTracerBasic over the scene");
        // TC03: a ray tracer set explicitly wins, before or after the scene: its empty scene's background (200, 0, 0)
        RayTracerBase explicit = new RayTracerBasic(new Scene("explicit").setBackground(new Color(200, 0, 0)));
        Render after = render("setSceneThenTracer", SIZE, render -> render.setScene(scene).setRayTracer(explicit));
        Render before = render("setTracerThenScene", SIZE, render -> render.setRayTracer(explicit).setScene(scene));
        assertSame(explicit, after.getRayTracer(), "TC03: the explicit ray tracer set after the scene must win");
        assertSame(explicit, before.getRayTracer(), "TC03: the explicit ray tracer set before the scene must win");
        assertEquals(new java.awt.Color(200, 0, 0), pixel(after, 50, 50), "TC03: the explicit ray tracer's picture");
        assertEquals(new java.awt.Color(200, 0, 0), pixel(before, 50, 50), "TC03: the explicit ray tracer's picture");
        // TC04: the forwarding setters reach the scene's ray tracer: soft shadows on, sqrtBeamNum 3
        RayTracerBase forwarded = new Render().setScene(scene).setSoftShadows(true).setSqrtBeamNum(3).getRayTracer();
        assertTrue(forwarded.isSoftShadows(), "TC04: soft shadows must be on in the scene's ray tracer");
        assertEquals(3, forwarded.getSqrtBeamNum(), "TC04: sqrtBeamNum must be 3 in the scene's ray tracer");

        // ===== Boundary Values Tests =====
        // TC11: a null scene is rejected, the message names the "scene"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Render().setScene(null),
                "TC11: a null scene must be rejected");
        assertMessage(e, "scene", "TC11");
        // TC12: neither a ray tracer nor a scene: rendering and the forwarding setters name setScene as a way out
        Render untraced = new Render().setImageWriter(new ImageWriter("noTracer", SIZE, SIZE, FOLDER))
                .setCamera(topCamera());
        MissingResourceException m = assertThrows(MissingResourceException.class, untraced::renderImage,
                "TC12: a render without a ray tracer or a scene must fail");
        assertMessage(m, "setScene", "TC12");
        m = assertThrows(MissingResourceException.class, () -> new Render().setSeed(1),
                "TC12: setSeed without a ray tracer or a scene must fail");
        assertMessage(m, "setScene", "TC12");
    }

    // ---------------------------------------------------------------------------------------------
    // Sampling settings and anti-aliasing
    // ---------------------------------------------------------------------------------------------

    /** The size of the anti-aliasing pictures: 40×40 pixels of 5×5 units on the view plane. */
    private static final int AA_SIZE = 40;
    /** The emission of the anti-aliasing sphere. */
    private static final Color SPHERE_EMISSION = new Color(200, 100, 50);
    /** The sphere's colour as written to the picture. */
    private static final java.awt.Color SPHERE_RGB = new java.awt.Color(200, 100, 50);
    /**
     * The radius on the view plane of the sphere's silhouette: a sphere of radius 50 at distance
     * 1000 from the camera, seen on a view plane at 1000: 50·1000/√(1000² − 50²) ≈ 50.063.
     */
    private static final double SILHOUETTE = 50 * 1000 / Math.sqrt(1000 * 1000 - 50 * 50);

    /** A sphere of radius 50 at the origin with emission (200, 100, 50), black background, no lights. */
    private static Scene sphereScene(String name) {
        Scene scene = new Scene(name);
        scene.geometries.add(new Sphere(new Point3D(0, 0, 0), 50).setEmission(SPHERE_EMISSION));
        return scene;
    }

    /** Renders the sphere scene at 40×40 with k × k rays per pixel, writing it under target/. */
    private static Render renderAntiAliased(String name, RayTracerBase tracer, int k, int threads) {
        return render(name, AA_SIZE, tracer, k, threads);
    }

    /** The smallest distance on the view plane from the camera axis to pixel (x, y)'s square. */
    private static double nearestDistance(int x, int y) {
        double pixel = 200.0 / AA_SIZE;
        double dx = Math.max(0, Math.max((x - AA_SIZE / 2) * pixel, -(x + 1 - AA_SIZE / 2) * pixel));
        double dy = Math.max(0, Math.max((y - AA_SIZE / 2) * pixel, -(y + 1 - AA_SIZE / 2) * pixel));
        return Math.sqrt(dx * dx + dy * dy);
    }

    /** The largest distance on the view plane from the camera axis to pixel (x, y)'s square. */
    private static double farthestDistance(int x, int y) {
        double pixel = 200.0 / AA_SIZE;
        double dx = Math.max(Math.abs((x - AA_SIZE / 2) * pixel), Math.abs((x + 1 - AA_SIZE / 2) * pixel));
        double dy = Math.max(Math.abs((y - AA_SIZE / 2) * pixel), Math.abs((y + 1 - AA_SIZE / 2) * pixel));
        return Math.sqrt(dx * dx + dy * dy);
    }

    /** Whether a pixel's colour lies strictly between the black background and the sphere's colour. */
    private static boolean intermediate(java.awt.Color c) {
        return c.getRed() > 0 && c.getRed() < 200;
    }

    /** Asserts that two renders wrote the same picture, pixel for pixel. */
    private static void assertSamePicture(Render expected, Render actual, String message) {
        for (int y = 0; y < expected.getImageWriter().getNy(); ++y)
            for (int x = 0; x < expected.getImageWriter().getNx(); ++x)
                assertEquals(pixel(expected, x, y), pixel(actual, x, y),
                        message + " at pixel (" + x + ", " + y + ")");
    }

    /** The number of silhouette pixels in which two renders differ. */
    private static int countDifferent(Render a, Render b) {
        int count = 0;
        for (int y = 0; y < AA_SIZE; ++y)
            for (int x = 0; x < AA_SIZE; ++x)
                if (!pixel(a, x, y).equals(pixel(b, x, y)))
                    ++count;
        return count;
    }

    /**
     * Test method for {@link Render#setSoftShadows(boolean)}, {@link Render#setSqrtBeamNum(int)},
     * {@link Render#setAdaptiveSoftShadows(boolean)}, {@link Render#setSeed(long)} and
     * {@link Render#setSqrtGlossRays(int)}: forwarded to the ray tracer.
     */
    @Test
    void testForwardingSetters() {
        RayTracerBase tracer = new RayTracerBasic(floorScene("forward"));
        Render render = new Render().setRayTracer(tracer);

        // ===== Equivalence Partitions Tests =====
        // TC01: each setter returns the render and changes the ray tracer's getter
        assertSame(render, render.setSoftShadows(true), "TC01: setSoftShadows must return the render");
        assertTrue(tracer.isSoftShadows(), "TC01: soft shadows must be on in the ray tracer");
        assertSame(render, render.setSqrtBeamNum(5), "TC01: setSqrtBeamNum must return the render");
        assertEquals(5, tracer.getSqrtBeamNum(), "TC01: sqrtBeamNum must be 5 in the ray tracer");
        assertEquals(5, tracer.getBeamGrid().getSqrtSamples(), "TC01: the ray tracer's beam grid must be 5 × 5");
        assertSame(render, render.setAdaptiveSoftShadows(true), "TC01: setAdaptiveSoftShadows must return the render");
        assertTrue(tracer.isAdaptiveSoftShadows(), "TC01: adaptive soft shadows must be on in the ray tracer");
        assertSame(render, render.setSeed(77), "TC01: setSeed must return the render");
        assertEquals(77, tracer.getSeed(), "TC01: the seed must be 77 in the ray tracer");
        assertSame(render, render.setSqrtGlossRays(7), "TC01: setSqrtGlossRays must return the render");
        assertEquals(7, tracer.getSqrtGlossRays(), "TC01: sqrtGlossRays must be 7 in the ray tracer");
        // TC02: turning the flags off again is forwarded too
        render.setSoftShadows(false).setAdaptiveSoftShadows(false);
        assertFalse(tracer.isSoftShadows(), "TC02: soft shadows must be off again in the ray tracer");
        assertFalse(tracer.isAdaptiveSoftShadows(), "TC02: adaptive soft shadows must be off again");
        // TC03: a bad sqrtBeamNum (-2) is rejected by the ray tracer through the render
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> render.setSqrtBeamNum(-2),
                "TC03: sqrtBeamNum -2 must be rejected");
        assertMessage(e, "sqrtBeamNum", "TC03");
        assertEquals(5, tracer.getSqrtBeamNum(), "TC03: a rejected sqrtBeamNum must leave 5");
        // TC04: a bad sqrtGlossRays (0) is rejected by the ray tracer through the render
        e = assertThrows(IllegalArgumentException.class, () -> render.setSqrtGlossRays(0),
                "TC04: sqrtGlossRays 0 must be rejected");
        assertMessage(e, "sqrtGlossRays", "TC04");
        assertEquals(7, tracer.getSqrtGlossRays(), "TC04: a rejected sqrtGlossRays must leave 7");

        // ===== Boundary Values Tests =====
        // TC11: before setRayTracer every forwarding setter throws MissingResourceException naming the ray tracer
        Render empty = new Render();
        MissingResourceException m = assertThrows(MissingResourceException.class, () -> empty.setSoftShadows(true),
                "TC11: setSoftShadows without a ray tracer must fail");
        assertMessage(m, "ray tracer", "TC11");
        assertThrows(MissingResourceException.class, () -> empty.setSqrtBeamNum(3),
                "TC11: setSqrtBeamNum without a ray tracer must fail");
        assertThrows(MissingResourceException.class, () -> empty.setAdaptiveSoftShadows(true),
                "TC11: setAdaptiveSoftShadows without a ray tracer must fail");
        assertThrows(MissingResourceException.class, () -> empty.setSeed(1),
                "TC11: setSeed without a ray tracer must fail");
        assertThrows(MissingResourceException.class, () -> empty.setSqrtGlossRays(2),
                "TC11: setSqrtGlossRays without a ray tracer must fail");
        // TC12: sqrtBeamNum 1 is forwarded
        render.setSqrtBeamNum(1);
        assertEquals(1, tracer.getSqrtBeamNum(), "TC12: sqrtBeamNum 1 must be forwarded");
    }

    /** Test method for {@link Render#setAntiAliasing(int)} and {@link Render#getAntiAliasing()}. */
    @Test
    void testSetAntiAliasing() {
        Render render = new Render();

        // ===== Equivalence Partitions Tests =====
        // TC01: the default is 1 (one ray through each pixel's centre)
        assertEquals(1, render.getAntiAliasing(), "TC01: anti-aliasing must default to 1");
        // TC02: k = 4 is kept, and the setter returns the render
        assertSame(render, render.setAntiAliasing(4), "TC02: setAntiAliasing must return the render");
        assertEquals(4, render.getAntiAliasing(), "TC02: anti-aliasing must be 4");
        // TC03: a negative k (-2) is rejected and leaves 4
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> render.setAntiAliasing(-2),
                "TC03: anti-aliasing -2 must be rejected");
        assertMessage(e, "anti-aliasing", "TC03");
        assertEquals(4, render.getAntiAliasing(), "TC03: a rejected anti-aliasing must leave 4");

        // ===== Boundary Values Tests =====
        // TC11: k = 0 is rejected
        e = assertThrows(IllegalArgumentException.class, () -> render.setAntiAliasing(0),
                "TC11: anti-aliasing 0 must be rejected");
        assertMessage(e, "anti-aliasing", "TC11");
        // TC12: k = 1 is accepted and turns anti-aliasing off again
        assertSame(render, render.setAntiAliasing(1), "TC12: setAntiAliasing(1) must return the render");
        assertEquals(1, render.getAntiAliasing(), "TC12: anti-aliasing must be 1 again");
        // TC13: k = 46341 (k² overflows an int) is rejected, naming the bound 1000, and leaves 1
        e = assertThrows(IllegalArgumentException.class, () -> render.setAntiAliasing(46_341),
                "TC13: anti-aliasing 46341 must be rejected");
        assertMessage(e, "between 1 and 1000", "TC13");
        assertEquals(1, render.getAntiAliasing(), "TC13: a rejected anti-aliasing must leave 1");
    }

    /** Test method for {@link Render#setAntiAliasing(int)}: k² rays per pixel smooth the silhouette only. */
    @Test
    void testAntiAliasingPicture() {
        RayTracerBase plainTracer = new RayTracerBasic(sphereScene("aliased"));
        Render plain = renderAntiAliased("antiAliasing1", plainTracer, 1, 2);
        RayTracerBase smoothTracer = new RayTracerBasic(sphereScene("anti-aliased"));
        Render smooth = renderAntiAliased("antiAliasing3", smoothTracer, 3, 2);

        // ===== Equivalence Partitions Tests =====
        // TC01: primary rays: 40·40 = 1600 with k = 1, 9·1600 = 14400 with k = 3
        assertEquals(AA_SIZE * AA_SIZE, plainTracer.getPrimaryRaysCount(), "TC01: k = 1 must trace one ray a pixel");
        assertEquals(9 * AA_SIZE * AA_SIZE, smoothTracer.getPrimaryRaysCount(), "TC01: k = 3 must trace 9 rays a pixel");
        // TC02: with k = 1 every pixel is exactly black or exactly the sphere's colour
        for (int y = 0; y < AA_SIZE; ++y)
            for (int x = 0; x < AA_SIZE; ++x) {
                java.awt.Color c = pixel(plain, x, y);
                assertTrue(c.equals(java.awt.Color.BLACK) || c.equals(SPHERE_RGB),
                        "TC02: pixel (" + x + ", " + y + ") must be black or the sphere's colour without AA, got " + c);
            }
        // TC03: with k = 3 every pixel is m/9 of the sphere's colour (m rays of 9 hit it, truncated to an integer)
        int intermediates = 0;
        for (int y = 0; y < AA_SIZE; ++y)
            for (int x = 0; x < AA_SIZE; ++x) {
                java.awt.Color c = pixel(smooth, x, y);
                boolean found = false;
                for (int m = 0; m <= 9 && !found; ++m)
                    found = c.getRed() == (int) (200.0 * m / 9) && c.getGreen() == (int) (100.0 * m / 9)
                            && c.getBlue() == (int) (50.0 * m / 9);
                assertTrue(found, "TC03: pixel (" + x + ", " + y + ") must be the average of 9 rays, got " + c);
                if (intermediate(c)) {
                    ++intermediates;
                    // TC04: intermediate levels only where the pixel straddles the silhouette
                    assertTrue(nearestDistance(x, y) <= SILHOUETTE && farthestDistance(x, y) >= SILHOUETTE,
                            "TC04: pixel (" + x + ", " + y + ") off the silhouette must not be blended");
                }
            }
        // TC05: the silhouette (about 2π·10 ≈ 63 pixels long) shows many intermediate levels with AA
        assertTrue(intermediates >= 30, "TC05: the anti-aliased silhouette must blend, got " + intermediates + " pixels");

        // ===== Boundary Values Tests =====
        // TC11: pixels wholly inside the silhouette keep the sphere's exact colour, and pixels wholly
        // outside it keep the exact black background, with and without AA
        int inside = 0;
        int outside = 0;
        for (int y = 0; y < AA_SIZE; ++y)
            for (int x = 0; x < AA_SIZE; ++x)
                if (farthestDistance(x, y) < SILHOUETTE - 0.5) {
                    ++inside;
                    assertEquals(SPHERE_RGB, pixel(smooth, x, y),
                            "TC11: inner pixel (" + x + ", " + y + ") must keep the sphere's colour with AA");
                    assertEquals(SPHERE_RGB, pixel(plain, x, y),
                            "TC11: inner pixel (" + x + ", " + y + ") must keep the sphere's colour without AA");
                } else if (nearestDistance(x, y) > SILHOUETTE + 0.5) {
                    ++outside;
                    assertEquals(java.awt.Color.BLACK, pixel(smooth, x, y),
                            "TC11: outer pixel (" + x + ", " + y + ") must keep the background with AA");
                    assertEquals(java.awt.Color.BLACK, pixel(plain, x, y),
                            "TC11: outer pixel (" + x + ", " + y + ") must keep the background without AA");
                }
        assertTrue(inside > 200 && outside > 1000,
                "TC11: the test must cover the inside and the far background (" + inside + ", " + outside + ")");
        // TC12: the exact centre pixel (20, 20) and corner (0, 0)
        assertEquals(SPHERE_RGB, pixel(smooth, 20, 20), "TC12: the centre must be the sphere");
        assertEquals(java.awt.Color.BLACK, pixel(smooth, 0, 0), "TC12: the corner must be black");
    }

    /**
     * Test method for {@link Render#setAntiAliasing(int)} with {@link Render#setMultithreading(int)} and
     * {@link Render#setSeed(long)}: anti-aliased pictures are reproducible.
     */
    @Test
    void testAntiAliasingReproducible() {
        Render oneThread = renderAntiAliased("antiAliasingThreads1", new RayTracerBasic(sphereScene("aa1")), 3, 1);
        Render twoThreads = renderAntiAliased("antiAliasingThreads2", new RayTracerBasic(sphereScene("aa2")), 3, 2);

        // ===== Equivalence Partitions Tests =====
        // TC01: 1 thread and 2 threads give the same anti-aliased picture, pixel for pixel
        assertSamePicture(oneThread, twoThreads, "TC01: 1 and 2 threads must give the same picture");
        // TC02: the same seed (7) gives the same picture twice
        Render seeded = renderAntiAliased("antiAliasingSeed7a",
                new RayTracerBasic(sphereScene("seed 7")).setSeed(7), 3, 2);
        Render seededAgain = renderAntiAliased("antiAliasingSeed7b",
                new RayTracerBasic(sphereScene("seed 7 again")).setSeed(7), 3, 2);
        assertSamePicture(seeded, seededAgain, "TC02: the same seed must give the same picture");
        // TC03: another seed (8) moves the jittered rays: some silhouette pixels change
        Render reseeded = renderAntiAliased("antiAliasingSeed8",
                new RayTracerBasic(sphereScene("seed 8")).setSeed(8), 3, 2);
        assertTrue(countDifferent(seeded, reseeded) > 0, "TC03: another seed must change some silhouette pixels");
        // TC04: the default seed and seed 7 differ too
        assertTrue(countDifferent(oneThread, seeded) > 0, "TC04: the default seed and seed 7 must differ");

        // ===== Boundary Values Tests =====
        // TC11: seed set through the render (forwarded) gives the same picture as seed set on the tracer
        RayTracerBase tracer = new RayTracerBasic(sphereScene("seed 7 forwarded"));
        Render forwarded = new Render().setImageWriter(new ImageWriter("antiAliasingSeed7c", AA_SIZE, AA_SIZE, FOLDER))
                .setCamera(topCamera()).setRayTracer(tracer).setSeed(7).setAntiAliasing(3).setMultithreading(1);
        forwarded.renderImage();
        forwarded.writeToImage();
        assertSamePicture(seeded, forwarded, "TC11: setSeed on the render must act as on the ray tracer");
    }

    /** Test method for {@link Render#setProgressListener(java.util.function.LongConsumer)}. */
    @Test
    void testSetProgressListener() {
        // 50 × 40 pixels in 16 × 16 tiles: 4 columns of tiles (16, 16, 16, 2 wide) and 3 rows (16, 16, 8 high)
        Scene scene = new Scene("progress").setBackground(BACKGROUND);
        java.util.Queue<Long> calls = new java.util.concurrent.ConcurrentLinkedQueue<>();
        Render render = new Render().setImageWriter(new ImageWriter("progress", 50, 40, FOLDER))
                .setCamera(topCamera()).setRayTracer(new RayTracerBasic(scene)).setMultithreading(2);

        // ===== Equivalence Partitions Tests =====
        // TC01: the setter returns the render; 2 threads call the listener once per tile (12 calls)
        assertSame(render, render.setProgressListener(calls::add), "TC01: setProgressListener must return the render");
        render.renderImage();
        java.util.List<Long> values = new java.util.ArrayList<>(calls);
        assertEquals(12, values.size(), "TC01: the listener must be called once per tile (4 × 3)");
        // TC02: every value is in (0, 2000], all distinct, and the largest is 50·40 = 2000
        for (long v : values)
            assertTrue(v > 0 && v <= 2000, "TC02: pixels done must be in (0, 2000], got " + v);
        assertEquals(12, new java.util.HashSet<>(values).size(), "TC02: the values must be distinct: " + values);
        assertEquals(2000L, java.util.Collections.max(values), "TC02: the last count must be 50·40 = 2000");
        // TC03: the steps between the sorted values are the tiles' sizes: 256 ×6, 32 ×2, 128 ×3, 16 ×1
        java.util.Collections.sort(values);
        java.util.List<Long> steps = new java.util.ArrayList<>();
        long previous = 0;
        for (long v : values) {
            steps.add(v - previous);
            previous = v;
        }
        java.util.Collections.sort(steps);
        assertEquals(java.util.List.of(16L, 32L, 32L, 128L, 128L, 128L, 256L, 256L, 256L, 256L, 256L, 256L), steps,
                "TC03: the counts must grow by one tile's pixels at a time");
        // TC04: the picture is rendered: a pixel is the background
        assertEquals(new java.awt.Color(20, 40, 60), pixel(render, 49, 39),
                "TC04: the last pixel must be rendered");

        // ===== Boundary Values Tests =====
        // TC11: 1 thread: the counts are the running sums in tile order
        calls.clear();
        render.setMultithreading(1).renderImage();
        assertEquals(java.util.List.of(256L, 512L, 768L, 800L, 1056L, 1312L, 1568L, 1600L, 1728L, 1856L, 1984L, 2000L),
                new java.util.ArrayList<>(calls), "TC11: with 1 thread the counts must be the running sums");
        // TC12: a null listener is allowed: the render works and the old listener is no longer called
        calls.clear();
        assertSame(render, render.setProgressListener(null), "TC12: setProgressListener(null) must return the render");
        render.setMultithreading(2).renderImage();
        assertTrue(calls.isEmpty(), "TC12: a removed listener must not be called");
        assertEquals(new java.awt.Color(20, 40, 60), pixel(render, 0, 0),
                "TC12: the render must work without a listener");
        // TC13: a 1 × 1 picture: one call with 1 pixel
        java.util.List<Long> one = new java.util.concurrent.CopyOnWriteArrayList<>();
        new Render().setImageWriter(new ImageWriter("progress1", 1, 1, FOLDER)).setCamera(topCamera())
                .setRayTracer(new RayTracerBasic(scene)).setMultithreading(2).setProgressListener(one::add)
                .renderImage();
        assertEquals(java.util.List.of(1L), one, "TC13: a 1 × 1 picture must report 1 pixel once");
    }

    /**
     * Test method for {@link Render#renderImage()}: {@link Thread#interrupt()} of the rendering thread stops
     * the render at once and says so, the flag kept; a picture that was complete is not reported interrupted.
     */
    @Test
    void testInterruption() {
        Thread caller = Thread.currentThread();
        Scene scene = floorScene("interrupted");
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point3D(0, 0, 100)));
        // 100 × 100 pixels: 7 × 7 tiles of 16 × 16 (the last row and column 4 wide), 10,000 pixels
        AtomicInteger tiles = new AtomicInteger();
        try {
            // ===== Equivalence Partitions Tests =====
            // TC01: interrupted after the first tile, on 2 threads: a CancellationException, a tile or two more at
            // the most (each thread ends its own), far from the 49, the flag still set
            Render render = new Render().setImageWriter(new ImageWriter("interrupted", SIZE, SIZE, FOLDER))
                    .setCamera(topCamera()).setRayTracer(new RayTracerBasic(scene)).setMultithreading(2)
                    .setProgressListener(done -> {
                        if (tiles.incrementAndGet() == 1)
                            caller.interrupt();
                    });
            CancellationException e = assertThrows(CancellationException.class, render::renderImage,
                    "TC01: the interrupted render must say so");
            assertMessage(e, "interrupted: the render threads stopped after", "TC01");
            assertTrue(tiles.get() <= 3, "TC01: the render must stop at once, " + tiles.get() + " tiles were done");
            assertTrue(Thread.interrupted(), "TC01: the interrupt flag must stay set");
            // TC02: the same render again, not interrupted: complete (every tile), the floor lit
            tiles.set(0);
            render.setProgressListener(done -> tiles.incrementAndGet()).renderImage();
            assertEquals(49, tiles.get(), "TC02: every tile must be rendered");
            assertTrue(brightness(render, 50, 50) > 100, "TC02: the floor must be lit");

            // ===== Boundary Values Tests =====
            // TC11: interrupted by the last tile: the picture is complete, so it is not reported interrupted
            tiles.set(0);
            Render last = new Render().setImageWriter(new ImageWriter("interruptedLast", SIZE, SIZE, FOLDER))
                    .setCamera(topCamera()).setRayTracer(new RayTracerBasic(scene)).setMultithreading(2)
                    .setProgressListener(done -> {
                        if (done == (long) SIZE * SIZE)
                            caller.interrupt();
                    });
            last.renderImage();
            assertTrue(Thread.interrupted(), "TC11: the interrupt flag must stay set for the caller to see");
            assertSamePicture(render, last, "TC11: the complete picture must be the whole one");
            // TC12 (own): interrupted before the call, on 1 thread: no tile is rendered
            tiles.set(0);
            caller.interrupt();
            Render before = new Render().setImageWriter(new ImageWriter("interruptedBefore", SIZE, SIZE, FOLDER))
                    .setCamera(topCamera()).setRayTracer(new RayTracerBasic(scene)).setMultithreading(1)
                    .setProgressListener(done -> tiles.incrementAndGet());
            assertMessage(assertThrows(CancellationException.class, before::renderImage,
                    "TC12: the interrupted render must say so"), "after 0 of 49 tasks", "TC12");
            assertEquals(0, tiles.get(), "TC12: no tile may be rendered");
        } finally {
            Thread.interrupted(); // the test thread goes on uninterrupted whatever failed
        }
    }

    /** Test method for {@link Render#getRayTracer()}. */
    @Test
    void testGetRayTracer() {
        Render render = new Render();

        // ===== Equivalence Partitions Tests =====
        // TC01: the ray tracer set is returned
        RayTracerBase tracer = new RayTracerBasic(floorScene("get ray tracer"));
        render.setRayTracer(tracer);
        assertSame(tracer, render.getRayTracer(), "TC01: getRayTracer must return the ray tracer set");
        // TC02: setting another one replaces it
        RayTracerBase other = new RayTracerBasic(floorScene("other ray tracer"));
        render.setRayTracer(other);
        assertSame(other, render.getRayTracer(), "TC02: getRayTracer must return the last ray tracer set");

        // ===== Boundary Values Tests =====
        // TC11: before setRayTracer: null
        org.junit.jupiter.api.Assertions.assertNull(new Render().getRayTracer(),
                "TC11: getRayTracer must be null before it is set");
    }

    // ----- depth of field -----

    /** The camera of the depth-of-field tests: at the origin looking down −z, the view plane at distance 100. */
    private static Camera lensCamera(double vpWidth, double vpHeight) {
        return new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpSize(vpWidth, vpHeight)
                .setVpDistance(100);
    }

    /** Renders a picture with a camera, its settings made by the caller on the render returned before rendering. */
    private static Render render(String name, int nX, int nY, Camera camera, RayTracerBase tracer, int k,
                                 boolean adaptive, int threads) {
        Render render = new Render().setImageWriter(new ImageWriter(name, nX, nY, FOLDER)).setCamera(camera)
                .setRayTracer(tracer).setAntiAliasing(k).setAdaptiveSuperSampling(adaptive).setMultithreading(threads);
        render.renderImage();
        render.writeToImage();
        return render;
    }

    /** A square of emission {@code color} at depth z, from (x0, y0) to (x1, y1). */
    private static Polygon square(double x0, double y0, double x1, double y1, double z, Color color) {
        return (Polygon) new Polygon(new Point3D(x0, y0, z), new Point3D(x1, y0, z), new Point3D(x1, y1, z),
                new Point3D(x0, y1, z)).setEmission(color);
    }

    /** Four emissive squares of different colours on the plane z = −500, meeting at the axis. */
    private static Scene checkerScene(String name) {
        Scene scene = new Scene(name);
        scene.geometries.add(square(-300, -300, 0, 0, -500, new Color(200, 0, 0)),
                square(0, -300, 300, 0, -500, new Color(0, 200, 0)),
                square(-300, 0, 0, 300, -500, new Color(0, 0, 200)),
                square(0, 0, 300, 300, -500, new Color(200, 200, 200)));
        return scene;
    }

    /**
     * Test method for {@link Render#renderImage()} with {@link Camera#setApertureSize(double)} and
     * {@link Camera#setFocalDistance(double)}: what lies on the focal plane renders as with a pinhole.
     */
    @Test
    void testDepthOfFieldFocalPlane() {
        Render pinhole = render("dofPinhole", 50, 50, lensCamera(100, 100), new RayTracerBasic(checkerScene("pin")),
                1, false, 2);
        RayTracerBase lensTracer = new RayTracerBasic(checkerScene("lens"));
        Render lens = render("dofFocused", 50, 50, lensCamera(100, 100).setApertureSize(30).setFocalDistance(500)
                .setSqrtApertureRays(4), lensTracer, 1, false, 2);

        // ===== Equivalence Partitions Tests =====
        // TC01: the checkerboard lies on the focal plane (z = −500): every pixel as with the pinhole camera,
        // sharp edges included, though each pixel's 16 rays start 30 units apart
        assertSamePicture(pinhole, lens, "TC01: the focal plane must render as with a pinhole camera");
        // TC02: 16 rays a pixel: 50 · 50 · 16 = 40000 primary rays
        assertEquals(50 * 50 * 16, lensTracer.getPrimaryRaysCount(), "TC02: 4 × 4 aperture rays a pixel");
        // TC03: focused elsewhere (z = −250), the same aperture blurs the checkerboard's edges
        Render blurred = render("dofBlurred", 50, 50, lensCamera(100, 100).setApertureSize(30).setFocalDistance(250)
                .setSqrtApertureRays(4), new RayTracerBasic(checkerScene("blur")), 1, false, 2);
        assertTrue(countDifferent(pinhole, blurred) > 50, "TC03: off the focal plane the edges must blur");

        // ===== Boundary Values Tests =====
        // TC11: without a focal distance the view plane (distance 100) is in focus: the same as focal distance 100
        Render viewPlane = render("dofViewPlane", 50, 50, lensCamera(100, 100).setApertureSize(30)
                .setSqrtApertureRays(4), new RayTracerBasic(checkerScene("vp")), 1, false, 2);
        Render hundred = render("dofHundred", 50, 50, lensCamera(100, 100).setApertureSize(30).setFocalDistance(100)
                .setSqrtApertureRays(4), new RayTracerBasic(checkerScene("100")), 1, false, 2);
        assertSamePicture(hundred, viewPlane, "TC11: the view plane must be in focus by default");
        // TC12: aperture 0 set explicitly (with a focal distance) is the pinhole camera, one ray a pixel
        RayTracerBase zeroTracer = new RayTracerBasic(checkerScene("zero"));
        Render zero = render("dofZero", 50, 50, lensCamera(100, 100).setApertureSize(0).setFocalDistance(250),
                zeroTracer, 1, false, 2);
        assertSamePicture(pinhole, zero, "TC12: aperture 0 must be the pinhole camera");
        assertEquals(50 * 50, zeroTracer.getPrimaryRaysCount(), "TC12: aperture 0 must trace one ray a pixel");
    }

    /** The image width of the blur tests, in pixels, and the view plane's width (0.1 a pixel). */
    private static final int BLUR_NX = 200;
    private static final double BLUR_VP_WIDTH = 20;
    /** The focal distance of the blur tests. */
    private static final double BLUR_FOCUS = 1000;

    /**
     * Renders a white half-plane x &gt; 0 at depth d on black with an aperture focused at {@link #BLUR_FOCUS}
     * and returns the width, in pixels, over which its edge rises from 10 % to 90 % (rows averaged).
     */
    private static double edgeWidth(String name, double aperture, double depth) {
        Scene scene = new Scene(name);
        scene.geometries.add(square(0, -10 * depth, 10 * depth, 10 * depth, -depth, new Color(255, 255, 255)));
        Camera camera = lensCamera(BLUR_VP_WIDTH, 0.8).setApertureSize(aperture).setFocalDistance(BLUR_FOCUS)
                .setSqrtApertureRays(16);
        Render render = render(name, BLUR_NX, 8, camera, new RayTracerBasic(scene), 1, false, 2);
        double[] profile = new double[BLUR_NX];
        for (int x = 0; x < BLUR_NX; ++x)
            for (int y = 0; y < 8; ++y)
                profile[x] += pixel(render, x, y).getRed() / 255.0 / 8;
        return crossing(profile, 0.9) - crossing(profile, 0.1);
    }

    /** Where a rising profile first reaches a level, interpolated between pixel centres. */
    private static double crossing(double[] profile, double level) {
        int x = 1;
        while (profile[x] < level)
            ++x;
        return x - 1 + (level - profile[x - 1]) / (profile[x] - profile[x - 1]);
    }

    /**
     * The predicted 10–90 % width, in pixels, of the blurred edge at depth d: the aperture's rays aimed at a
     * pixel's focal point spread over A·|d − f|/f at depth d, which the view plane (distance 100) sees
     * as A·|d − f|/f · 100/d; the edge rises linearly over that, 80 % of it between 10 % and 90 %.
     */
    private static double predictedWidth(double aperture, double depth) {
        double onViewPlane = aperture * Math.abs(depth - BLUR_FOCUS) / depth * 100 / BLUR_FOCUS;
        return 0.8 * onViewPlane / (BLUR_VP_WIDTH / BLUR_NX);
    }

    /**
     * Test method for {@link Render#renderImage()} with {@link Camera#setApertureSize(double)}: the blur of an
     * edge off the focal plane grows with aperture × |d − f| / d.
     */
    @Test
    void testDepthOfFieldBlurWidth() {
        // ===== Equivalence Partitions Tests =====
        // TC01: aperture 20, edge at d = 2000 behind the focus 1000: 10–90 % width 0.8 · 10 = 8 pixels
        // TC02: aperture 40 at the same depth: twice as wide, 16 pixels
        // TC03: aperture 20, d = 1500: 0.8 · 6.67 = 5.33 pixels
        // TC04: aperture 20, in front of the focus, d = 600: 0.8 · 13.3 = 10.7 pixels
        double[][] cases = {{20, 2000}, {40, 2000}, {20, 1500}, {20, 600}};
        for (int c = 0; c < cases.length; ++c) {
            double predicted = predictedWidth(cases[c][0], cases[c][1]);
            double measured = edgeWidth("dofEdge" + c, cases[c][0], cases[c][1]);
            assertEquals(predicted, measured, 0.25 + 0.02 * predicted, "TC0" + (c + 1) + ": aperture " + cases[c][0]
                    + " at depth " + cases[c][1] + " must blur the edge over " + predicted + " pixels");
        }

        // ===== Boundary Values Tests =====
        // TC11: the edge on the focal plane (d = f = 1000) stays sharp: it rises between two neighbouring
        // pixels (0.8 of a pixel between their centres), whatever the aperture (40)
        assertEquals(0.8, edgeWidth("dofEdgeFocused", 40, BLUR_FOCUS), 0.05, "TC11: the focused edge must be sharp");
    }

    // ----- adaptive super-sampling -----

    /** A lit diffuse floor filling the picture, with a sphere of smooth shading on it. */
    private static Scene shadedScene(String name, boolean sphere) {
        Scene scene = new Scene(name).setBackground(BACKGROUND);
        scene.geometries.add(new Plane(Point3D.ZERO, new Vector(0, 0, 1)).setMaterial(new Material().setKd(0.6)));
        if (sphere)
            scene.geometries.add(new Sphere(new Point3D(10, -5, 30), 45).setEmission(new Color(20, 10, 0))
                    .setMaterial(new Material().setKd(0.5).setKs(0.4).setShininess(30)));
        scene.lights.add(new DirectionalLight(new Color(250, 220, 200), new Vector(0, 0, -1)));
        scene.lights.add(new PointLight(new Color(400, 300, 300), new Point3D(-60, 60, 150)).setKl(0.001));
        return scene;
    }

    /** The largest difference of a channel between two renders' pixels, and the mean over all channels. */
    private static double[] difference(Render a, Render b, int size) {
        double max = 0;
        double sum = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                java.awt.Color p = pixel(a, x, y);
                java.awt.Color q = pixel(b, x, y);
                int[] d = {Math.abs(p.getRed() - q.getRed()), Math.abs(p.getGreen() - q.getGreen()),
                        Math.abs(p.getBlue() - q.getBlue())};
                for (int channel : d) {
                    max = Math.max(max, channel);
                    sum += channel;
                }
            }
        return new double[] {max, sum / (3.0 * size * size)};
    }

    /**
     * Test method for {@link Render#setAdaptiveSuperSampling(boolean)}: the picture of full super-sampling
     * within the tolerance, with fewer rays.
     */
    @Test
    void testAdaptiveSuperSampling() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a flat picture (a floor under a directional light, seen from above, nothing else): 5 rays a
        // pixel (4 corners and the centre) instead of 8 · 8 = 64, and the same pixels
        RayTracerBase flatFull = new RayTracerBasic(floorLitScene("flat full"));
        RayTracerBase flatAdaptive = new RayTracerBasic(floorLitScene("flat adaptive"));
        Render full = render("adaptiveFlatFull", AA_SIZE, AA_SIZE, topCamera(), flatFull, 8, false, 2);
        Render adaptive = render("adaptiveFlat", AA_SIZE, AA_SIZE, topCamera(), flatAdaptive, 8, true, 2);
        assertEquals(64L * AA_SIZE * AA_SIZE, flatFull.getPrimaryRaysCount(), "TC01: 64 rays a pixel in full");
        assertEquals(5L * AA_SIZE * AA_SIZE, flatAdaptive.getPrimaryRaysCount(), "TC01: 5 rays a pixel adaptively");
        assertSamePicture(full, adaptive, "TC01: a flat picture must not change");
        // TC02: a shaded sphere on the floor (silhouette, highlight, gradients): every channel of every pixel
        // within 24 levels of full super-sampling (edge pixels: both are estimates), and on average within 0.25
        // of a level, with under a quarter of the rays
        RayTracerBase shadedFull = new RayTracerBasic(shadedScene("shaded full", true));
        RayTracerBase shadedAdaptive = new RayTracerBasic(shadedScene("shaded adaptive", true));
        full = render("adaptiveShadedFull", 100, 100, topCamera(), shadedFull, 8, false, 2);
        adaptive = render("adaptiveShaded", 100, 100, topCamera(), shadedAdaptive, 8, true, 2);
        double[] difference = difference(full, adaptive, 100);
        assertTrue(difference[0] <= 24, "TC02: a pixel differs by " + difference[0] + " levels");
        assertTrue(difference[1] <= 0.25, "TC02: pixels differ by " + difference[1] + " levels on average");
        assertTrue(shadedAdaptive.getPrimaryRaysCount() < shadedFull.getPrimaryRaysCount() / 4,
                "TC02: adaptive must trace under a quarter of the rays, traced " + shadedAdaptive.getPrimaryRaysCount()
                        + " of " + shadedFull.getPrimaryRaysCount());
        // TC03: the emissive sphere of the anti-aliasing test: pixels wholly inside or outside its silhouette
        // are exact, those on it are blended
        Render sphere = render("adaptiveSphere", AA_SIZE, AA_SIZE, topCamera(),
                new RayTracerBasic(sphereScene("adaptive sphere")), 4, true, 2);
        int blended = 0;
        for (int y = 0; y < AA_SIZE; ++y)
            for (int x = 0; x < AA_SIZE; ++x) {
                if (farthestDistance(x, y) < SILHOUETTE - 0.5)
                    assertEquals(SPHERE_RGB, pixel(sphere, x, y), "TC03: inner pixel (" + x + ", " + y + ")");
                else if (nearestDistance(x, y) > SILHOUETTE + 0.5)
                    assertEquals(java.awt.Color.BLACK, pixel(sphere, x, y), "TC03: outer pixel (" + x + ", " + y + ")");
                blended += intermediate(pixel(sphere, x, y)) ? 1 : 0;
            }
        assertTrue(blended >= 30, "TC03: the silhouette must blend, got " + blended + " pixels");

        // ===== Boundary Values Tests =====
        // TC11: with anti-aliasing off (k = 1) adaptive super-sampling is one ray through the centre: the same bytes
        RayTracerBase single = new RayTracerBasic(shadedScene("single", true));
        Render plain = render("adaptiveOffK1", 100, 100, topCamera(), new RayTracerBasic(shadedScene("k1", true)),
                1, false, 2);
        Render adaptiveOne = render("adaptiveK1", 100, 100, topCamera(), single, 1, true, 2);
        assertSamePicture(plain, adaptiveOne, "TC11: adaptive with k = 1 must be the plain picture");
        assertEquals(100 * 100, single.getPrimaryRaysCount(), "TC11: one ray a pixel with k = 1");
        // TC12: k = 2 never divides a pixel (its smallest squares are two cells wide): 5 rays a pixel even on
        // the sphere's silhouette and highlight
        RayTracerBase two = new RayTracerBasic(shadedScene("k2", true));
        render("adaptiveK2", AA_SIZE, AA_SIZE, topCamera(), two, 2, true, 2);
        assertEquals(5L * AA_SIZE * AA_SIZE, two.getPrimaryRaysCount(), "TC12: 5 rays a pixel with k = 2");
        // TC13: k = 4 divides at most once: at most 3 × 3 corners and 4 centres, 13 rays a pixel (not 16)
        RayTracerBase four = new RayTracerBasic(sphereScene("k4 rays"));
        render("adaptiveK4", AA_SIZE, AA_SIZE, topCamera(), four, 4, true, 2);
        long rays = four.getPrimaryRaysCount();
        assertTrue(rays > 5L * AA_SIZE * AA_SIZE && rays <= 13L * AA_SIZE * AA_SIZE,
                "TC13: between 5 and 13 rays a pixel with k = 4, traced " + rays);
        // TC14: the default is off, and the setter returns the render
        Render render = new Render();
        assertFalse(render.isAdaptiveSuperSampling(), "TC14: adaptive super-sampling must be off by default");
        assertSame(render, render.setAdaptiveSuperSampling(true), "TC14: the setter must return the render");
        assertTrue(render.isAdaptiveSuperSampling(), "TC14: adaptive super-sampling must be on");
    }

    /** A lit diffuse floor filling the picture and nothing else: every ray sees the same colour. */
    private static Scene floorLitScene(String name) {
        return shadedScene(name, false).setLights(java.util.List.of(
                new DirectionalLight(new Color(250, 220, 200), new Vector(0, 0, -1))));
    }

    /**
     * Test method for {@link Render#setAdaptiveSuperSampling(boolean)} and {@link Camera#setApertureSize(double)}
     * with {@link Render#setMultithreading(int)}: pictures are the same whatever the number of threads.
     */
    @Test
    void testPictureImprovementsReproducible() {
        // ===== Equivalence Partitions Tests =====
        // TC01: soft shadows, depth of field and adaptive super-sampling together: 1 and 3 threads give the
        // same pixels
        Render[] renders = new Render[2];
        int[] threads = {1, 3};
        for (int t = 0; t < 2; ++t) {
            RayTracerBase tracer = new RayTracerBasic(shadedScene("threads " + threads[t], true));
            tracer.setSoftShadows(true).setSqrtBeamNum(3);
            ((PointLight) tracer.scene.lights.get(1)).setEdgesSize(20);
            renders[t] = render("improvementsThreads" + threads[t], 60, 60, topCamera().setApertureSize(60)
                    .setFocalDistance(970).setSqrtApertureRays(2), tracer, 4, true, threads[t]);
        }
        assertSamePicture(renders[0], renders[1], "TC01: 1 and 3 threads must give the same picture");
        // TC02: depth of field with full super-sampling: 1 and 3 threads give the same pixels
        for (int t = 0; t < 2; ++t)
            renders[t] = render("dofThreads" + threads[t], 60, 60, topCamera().setApertureSize(60)
                            .setFocalDistance(970).setSqrtApertureRays(2),
                    new RayTracerBasic(shadedScene("dof threads " + threads[t], true)), 3, false, threads[t]);
        assertSamePicture(renders[0], renders[1], "TC02: 1 and 3 threads must give the same picture");
    }

    /**
     * Test method for {@link Render#renderImage()}: the render calls the ray tracer's own
     * {@link RayTracerBase#traceRay(Ray)}, also when a subclass overrides it (to count or mark rays).
     */
    @Test
    void testOverriddenTraceRay() {
        Color marked = new Color(200, 0, 100);
        AtomicInteger calls = new AtomicInteger();
        RayTracerBasic marking = new RayTracerBasic(floorScene("marked")) {
            @Override
            public Color traceRay(Ray ray) {
                calls.incrementAndGet();
                return marked;
            }
        };
        // ===== Equivalence Partitions Tests =====
        // TC01: a 10 × 10 picture, 2 × 2 rays a pixel, 2 threads: 400 calls, every pixel (200, 0, 100)
        Render render = render("overriddenTraceRay", 10, marking, 2, 2);
        assertEquals(400, calls.get(), "TC01: every ray must go through the overriding traceRay");
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 10; ++x)
                assertEquals(new java.awt.Color(200, 0, 100), pixel(render, x, y), "TC01: pixel " + x + ", " + y);
    }
}
