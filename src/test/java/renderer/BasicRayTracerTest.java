package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertSameRejection;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Vector;
import scene.Scene;

/**
 * Unit tests for {@link BasicRayTracer}, the course's other name for {@link RayTracerBasic}: a scene
 * built with the course's names (this tracer, {@code Sphere(radius, center)},
 * {@code Camera.setViewPlaneSize} and {@code setDistance}) renders the same picture, bit for bit, as
 * the same scene built with the report's names.
 */
class BasicRayTracerTest {
    private static final Path FOLDER = Path.of("target", "test-images", "basic-ray-tracer");
    private static final int SIZE = 60;

    /**
     * A scene with a shadow, a soft shadow's penumbra, a mirror and a transparent sphere.
     *
     * @param radiusFirst whether to build the spheres radius first (the course's other order)
     * @return the scene
     */
    private static Scene scene(boolean radiusFirst) {
        Scene scene = new Scene("course names").setBackground(new Color(10, 20, 30))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        Point3D solid = new Point3D(-20, 0, 25);
        Point3D glass = new Point3D(25, 10, 15);
        scene.geometries.add(
                new Plane(Point3D.ZERO, new Vector(0, 0, 1)).setMaterial(new Material().setKd(0.6).setKs(0.2).setShininess(20)),
                (radiusFirst ? new Sphere(20, solid) : new Sphere(solid, 20)).setEmission(new Color(40, 0, 0))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(30)),
                (radiusFirst ? new Sphere(12, glass) : new Sphere(glass, 12)).setEmission(new Color(0, 30, 40))
                        .setMaterial(new Material().setKd(0.2).setKs(0.3).setShininess(50).setKt(0.6)),
                new Triangle(new Point3D(-90, 60, 0), new Point3D(90, 60, 0), new Point3D(0, 90, 60))
                        .setMaterial(new Material().setKr(0.8)));
        scene.lights.add(new SpotLight(new Color(300, 270, 240), new Point3D(30, -40, 150), new Vector(-0.2, 0.3, -1))
                .setKl(1E-4).setKq(2E-6).setEdgesSize(40));
        return scene;
    }

    /**
     * Renders a picture with soft shadows under target/.
     *
     * @param name   the picture's name
     * @param camera the camera
     * @param tracer the ray tracer
     * @return the render, its picture done
     */
    private static Render render(String name, Camera camera, RayTracerBase tracer) {
        Render render = new Render().setImageWriter(new ImageWriter(name, SIZE, SIZE, FOLDER)).setCamera(camera)
                .setRayTracer(tracer).setSoftShadows(true).setSqrtBeamNum(4).setMultithreading(2);
        render.renderImage();
        render.writeToImage();
        return render;
    }

    /** A camera above the scene looking down, its view plane set through the report's names. */
    private static Camera reportCamera() {
        return new Camera(new Point3D(0, -300, 400), new Vector(0, 3, -4), new Vector(0, 4, 3))
                .setVpSize(120, 120).setVpDistance(400);
    }

    /** The same camera, its view plane set through the course's names, distance first. */
    private static Camera courseCamera() {
        return new Camera(new Point3D(0, -300, 400), new Vector(0, 3, -4), new Vector(0, 4, 3))
                .setDistance(400).setViewPlaneSize(120, 120);
    }

    /** Test method for {@link BasicRayTracer#BasicRayTracer(Scene)}. */
    @Test
    void testConstructor() {
        Scene scene = scene(false);
        // ===== Equivalence Partitions Tests =====
        // TC01: it is a RayTracerBasic, accepted by Render.setRayTracer, and traces the scene it was given
        BasicRayTracer tracer = new BasicRayTracer(scene);
        assertInstanceOf(RayTracerBasic.class, tracer, "TC01: BasicRayTracer must be a RayTracerBasic");
        Render render = new Render();
        assertSame(render, render.setRayTracer(tracer), "TC01: setRayTracer must take a BasicRayTracer");
        assertSame(tracer, render.getRayTracer(), "TC01: the render must hold the BasicRayTracer");

        // ===== Boundary Values Tests =====
        // TC11: a null scene is rejected with the same message as RayTracerBasic's
        assertSameRejection(() -> new RayTracerBasic(null), () -> new BasicRayTracer(null), "TC11");
    }

    /**
     * Test method for {@link BasicRayTracer#traceRay}: the course's names render the report's picture.
     */
    @Test
    void testSamePictureAsRayTracerBasic() {
        Render report = render("report-names", reportCamera(), new RayTracerBasic(scene(false)));
        Render course = render("course-names", courseCamera(), new BasicRayTracer(scene(true)));
        ImageWriter expected = report.getImageWriter();
        ImageWriter actual = course.getImageWriter();

        // ===== Equivalence Partitions Tests =====
        // TC01: every pixel is the same (0 pixels differ)
        int different = 0;
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x)
                if (!expected.getPixel(x, y).equals(actual.getPixel(x, y)))
                    ++different;
        assertEquals(0, different, "TC01: pixels differ between the course's names and the report's");
        // TC02: the picture is not trivial: more than 10 distinct colours (shading, shadow, penumbra, mirror)
        long colours = java.util.stream.IntStream.range(0, SIZE * SIZE)
                .map(k -> actual.getPixel(k % SIZE, k / SIZE).getRGB()).distinct().count();
        assertTrue(colours > 10, "TC02: the test picture has only " + colours + " colours");
    }
}
