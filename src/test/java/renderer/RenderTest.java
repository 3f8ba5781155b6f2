package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.MissingResourceException;

import org.junit.jupiter.api.Test;

import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
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
        Scene scene = new Scene(name).setBackground(BACKGROUND);
        Material material = new Material().setKd(0.8);
        Point3D a = new Point3D(-100, -100, 0);
        Point3D b = new Point3D(100, -100, 0);
        Point3D c = new Point3D(100, 100, 0);
        Point3D d = new Point3D(-100, 100, 0);
        scene.geometries.add(new Triangle(a, b, c).setMaterial(material), new Triangle(a, c, d).setMaterial(material));
        return scene;
    }

    private static Render render(String name, Scene scene, int threads) {
        Render render = new Render().setImageWriter(new ImageWriter(name, SIZE, SIZE, FOLDER))
                .setCamera(topCamera()).setRayTracer(new RayTracerBasic(scene)).setMultithreading(threads);
        render.renderImage();
        render.writeToImage();
        return render;
    }

    private static Render render(String name, Scene scene) {
        return render(name, scene, 2);
    }

    /** The brightness of a pixel: the sum of its channels. */
    private static int brightness(Render render, int x, int y) {
        java.awt.Color c = render.getImageWriter().getPixel(x, y);
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
        assertEquals(new java.awt.Color(20, 40, 60), render.getImageWriter().getPixel(0, 0),
                "TC01: a pixel that hits nothing must be the background");
        // TC02: the centre pixel hits the sphere: emission + ambient = (10+127.5, 95.5, 95.5), truncated
        assertEquals(new java.awt.Color(137, 95, 95), render.getImageWriter().getPixel(50, 50),
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
        Scene scene = new Scene("mirror").setBackground(BACKGROUND);
        Point3D a = new Point3D(-100, -100, 0);
        Point3D c = new Point3D(100, 100, 0);
        Material mirror = new Material().setKr(1);
        scene.geometries.add(new Triangle(a, new Point3D(100, -100, 0), c).setMaterial(mirror),
                new Triangle(a, c, new Point3D(-100, 100, 0)).setMaterial(mirror),
                // a green sphere hanging over the mirror, off the camera's axis
                new Sphere(new Point3D(60, 0, 300), 10).setEmission(new Color(0, 200, 0)));
        Render render = render("mirror", scene);

        // ===== Equivalence Partitions Tests =====
        // the sphere is seen directly at x = 60·1000/700 ≈ 86 on the view plane (pixel column ≈ 93),
        // and its mirror image, 1300 from the camera, at x = 60·1000/1300 ≈ 46 (pixel column ≈ 73)
        // TC01: the sphere seen directly: green
        assertEquals(new java.awt.Color(0, 200, 0), render.getImageWriter().getPixel(93, 50),
                "TC01: the sphere must be seen directly");
        // TC02: the mirror shows the reflected sphere's colour where nothing is in front of it
        assertEquals(new java.awt.Color(0, 200, 0), render.getImageWriter().getPixel(73, 50),
                "TC02: the mirror must show the reflected sphere's colour");
        // TC03: elsewhere the mirror reflects the background
        assertEquals(new java.awt.Color(20, 40, 60), render.getImageWriter().getPixel(30, 50),
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

    /** Test method for {@link Render#renderImage()}: two triangles sharing an edge leave no seam. */
    @Test
    void testNoSeam() {
        Scene scene = floorScene("seam").setAmbientLight(new AmbientLight(new Color(100, 100, 100), 1));
        Render render = render("seam", scene);

        // ===== Boundary Values Tests =====
        // TC11: no pixel along the shared diagonal (and next to it) shows the background
        for (int k = 0; k < SIZE; ++k)
            for (int d = -1; d <= 1; ++d) {
                int x = Math.min(SIZE - 1, Math.max(0, k + d));
                assertNotEquals(new java.awt.Color(20, 40, 60), render.getImageWriter().getPixel(x, SIZE - 1 - k),
                        "TC11: the seam between the triangles shows the background at (" + x + ", " + (SIZE - 1 - k) + ")");
            }
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
                assertEquals(one.getImageWriter().getPixel(x, y), two.getImageWriter().getPixel(x, y),
                        "TC01: pixel (" + x + ", " + y + ") differs between 1 and 2 threads");
        // ===== Boundary Values Tests =====
        // TC11: a negative thread count is rejected
        assertThrows(IllegalArgumentException.class, () -> new Render().setMultithreading(-1),
                "TC11: a negative thread count must be rejected");
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
        assertTrue(e.getMessage().contains("image writer"), "TC01: the message must name the image writer");
        e = assertThrows(MissingResourceException.class,
                () -> new Render().setImageWriter(writer).setRayTracer(new RayTracerBasic(scene)).renderImage(),
                "TC01: a render without a camera must fail");
        assertTrue(e.getMessage().contains("camera"), "TC01: the message must name the camera");
        e = assertThrows(MissingResourceException.class,
                () -> new Render().setImageWriter(writer).setCamera(topCamera()).renderImage(),
                "TC01: a render without a ray tracer must fail");
        assertTrue(e.getMessage().contains("ray tracer"), "TC01: the message must name the ray tracer");
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

        // ===== Boundary Values Tests =====
        // TC11: a grid interval of 0 is rejected
        assertThrows(IllegalArgumentException.class, () -> render.printGrid(0, Color.BLACK),
                "TC11: a zero grid interval must be rejected");
    }
}
