package scenefile;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestImages.differentPixels;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import geometries.Tube;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.CheckerTexture;
import primitives.Color;
import primitives.ImageTexture;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import scene.Scene;
import testutil.TestFiles;

/**
 * Tests for {@link SceneWriter}: the text it writes, and the round trip Java scene → file → {@link SceneLoader}
 * → the same values and the same pixels. Files go to {@code target/test-scenes/}.
 */
class SceneWriterTest {
    private static final Path FOLDER = Path.of("target", "test-scenes");

    /** A body the file format does not know: a sphere of the user's own class. */
    private static final class OwnSphere extends Sphere {
        OwnSphere() {
            super(new Point3D(0, 0, -100), 10);
        }
    }

    /** A light the file format does not know: a directional light of the user's own class. */
    private static final class OwnLight extends DirectionalLight {
        OwnLight() {
            super(new Color(100, 100, 100), new Vector(0, 0, -1));
        }
    }

    /**
     * A picture with every body and light type of the library, materials, emission, a nested group, its
     * own camera, size, grid and non-default render settings: 60 × 60 pixels, quick to render.
     */
    private static Picture everything() {
        Scene scene = new Scene("everything").setBackground(new Color(10, 20, 30))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(
                new Sphere(new Point3D(0, 0, -100), 30).setEmission(new Color(0, 0, 100))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(30)),
                new Triangle(new Point3D(-100, -60, -150), new Point3D(100, -60, -150), new Point3D(0, 80, -200))
                        .setEmission(new Color(20, 20, 20)).setMaterial(new Material().setKd(0.3).setKr(0.4)),
                new Polygon(new Point3D(40, 30, -60), new Point3D(70, 30, -60), new Point3D(70, 60, -70),
                        new Point3D(40, 60, -70)).setEmission(new Color(80, 0, 0))
                        .setMaterial(new Material().setKd(0.4).setKs(0.2).setShininess(10).setKt(0.5)),
                new Plane(new Point3D(0, -70, 0), new Vector(0, 1, 0.1)).setEmission(new Color(30, 40, 30))
                        .setMaterial(new Material().setKd(0.6).setKr(0.2)),
                new Tube(new Ray(new Point3D(60, 0, -150), new Vector(0, 1, 1)), 10)
                        .setEmission(new Color(0, 60, 0))
                        .setMaterial(new Material().setKd(0.5).setKs(0.3).setShininess(20)),
                new Cylinder(new Ray(new Point3D(-60, -40, -120), new Vector(0, 1, 0)), 15, 40)
                        .setEmission(new Color(60, 60, 0))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(50)),
                new Geometries(
                        new Sphere(new Point3D(-30, 40, -80), 12).setEmission(new Color(90, 0, 90)),
                        new Triangle(new Point3D(-90, 20, -90), new Point3D(-60, 20, -90), new Point3D(-75, 50, -95))));
        scene.lights.add(new DirectionalLight(new Color(100, 80, 60), new Vector(1, -1, -1)));
        scene.lights.add(new PointLight(new Color(400, 300, 200), new Point3D(-50, 50, 50)).setKl(0.001).setKq(0.0001));
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point3D(50, 80, 0)).setKl(0.002)
                .setEdgesSize(10).setUV(new Vector(1, 0, 0), new Vector(0, 0, 1)));
        scene.lights.add(new PointLight(new Color(200, 100, 100), new Point3D(0, 100, -50)).setKq(0.00005)
                .setEdgesSize(8));
        scene.lights.add(new SpotLight(new Color(500, 400, 300), new Point3D(40, 40, 60), new Vector(-1, -1, -4))
                .setNarrowBeam(4).setKc(0.5).setKl(0.0004).setKq(0.00002).setEdgesSize(12)
                .setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        scene.lights.add(new SpotLight(new Color(300, 300, 500), new Point3D(-40, 60, 30), new Vector(0, -0.2, -1))
                .setKl(0.001).setEdgesSize(6));
        Camera camera = new Camera(new Point3D(10, 20, 600), new Vector(0, -0.1, -1), new Vector(0, 1, -0.1))
                .setVpSize(220, 200).setVpDistance(500);
        return new Picture("everything", 60, 60, scene, camera, 20, new RenderSettings(true, true, 3, 2, 7));
    }

    /** Renders a picture into target/test-scenes under a file name. */
    private static ImageWriter render(Picture picture, String fileName) {
        return picture.render(picture.newRender(FOLDER.resolve(fileName + ImageWriter.EXTENSION))).getImageWriter();
    }

    private static void assertSame(Point3D expected, Point3D actual, String message) {
        assertEquals(expected.getX(), actual.getX(), message);
        assertEquals(expected.getY(), actual.getY(), message);
        assertEquals(expected.getZ(), actual.getZ(), message);
    }

    private static void assertSame(Vector expected, Vector actual, String message) {
        assertSame(expected.getHead(), actual.getHead(), message);
    }

    private static void assertSame(Color expected, Color actual, String message) {
        assertEquals(expected.getR(), actual.getR(), message);
        assertEquals(expected.getG(), actual.getG(), message);
        assertEquals(expected.getB(), actual.getB(), message);
    }

    /** Checks that two bodies (and, for groups, their bodies) have exactly the same values. */
    private static void assertSameBody(Intersectable expected, Intersectable actual, String message) {
        assertEquals(expected.getClass(), actual.getClass(), message + ": type");
        if (expected instanceof Geometries group) {
            List<Intersectable> bodies = group.getGeometries();
            List<Intersectable> loaded = ((Geometries) actual).getGeometries();
            assertEquals(bodies.size(), loaded.size(), message + ": number of bodies");
            for (int k = 0; k < bodies.size(); ++k)
                assertSameBody(bodies.get(k), loaded.get(k), message + " / body " + k);
            return;
        }
        Geometry body = (Geometry) expected;
        Geometry other = (Geometry) actual;
        assertSame(body.getEmission(), other.getEmission(), message + ": emission");
        Material m = body.getMaterial();
        Material n = other.getMaterial();
        assertEquals(m.getKd(), n.getKd(), message + ": kD");
        assertEquals(m.getKs(), n.getKs(), message + ": kS");
        assertEquals(m.getKt(), n.getKt(), message + ": kT");
        assertEquals(m.getKr(), n.getKr(), message + ": kR");
        assertEquals(m.getShininess(), n.getShininess(), message + ": nShininess");
        assertEquals(m.getKg(), n.getKg(), message + ": kG");
        assertEquals(m.getKb(), n.getKb(), message + ": kB");
        assertEquals(m.getIor(), n.getIor(), message + ": ior");
        assertEquals(m.isFresnel(), n.isFresnel(), message + ": fresnel");
        if (body instanceof Sphere sphere) {
            assertSame(sphere.getCenter(), ((Sphere) other).getCenter(), message + ": centre");
            assertEquals(sphere.getRadius(), ((Sphere) other).getRadius(), message + ": radius");
        } else if (body instanceof Polygon polygon) { // and triangles
            List<Point3D> vertices = polygon.getVertices();
            List<Point3D> loaded = ((Polygon) other).getVertices();
            assertEquals(vertices.size(), loaded.size(), message + ": number of vertices");
            for (int k = 0; k < vertices.size(); ++k)
                assertSame(vertices.get(k), loaded.get(k), message + ": vertex " + k);
        } else if (body instanceof Plane plane) {
            assertSame(plane.getQ0(), ((Plane) other).getQ0(), message + ": q0");
            assertSame(plane.getNormal(), ((Plane) other).getNormal(), message + ": normal");
        } else if (body instanceof Tube tube) { // and cylinders
            assertSame(tube.getAxisRay().getP0(), ((Tube) other).getAxisRay().getP0(), message + ": axis p0");
            assertSame(tube.getAxisRay().getDir(), ((Tube) other).getAxisRay().getDir(), message + ": axis dir");
            assertEquals(tube.getRadius(), ((Tube) other).getRadius(), message + ": radius");
            if (body instanceof Cylinder cylinder)
                assertEquals(cylinder.getHeight(), ((Cylinder) other).getHeight(), message + ": height");
        }
    }

    /** Checks that two lights have exactly the same values. */
    private static void assertSameLight(LightSource expected, LightSource actual, String message) {
        assertEquals(expected.getClass(), actual.getClass(), message + ": type");
        if (expected instanceof DirectionalLight directional) {
            assertSame(directional.getIntensity(), ((DirectionalLight) actual).getIntensity(), message + ": colour");
            assertSame(directional.getDirection(), ((DirectionalLight) actual).getDirection(), message + ": direction");
            return;
        }
        PointLight point = (PointLight) expected;
        PointLight other = (PointLight) actual;
        assertSame(point.getIntensity(), other.getIntensity(), message + ": colour");
        assertSame(point.getPosition(), other.getPosition(), message + ": position");
        assertEquals(point.getKc(), other.getKc(), message + ": kC");
        assertEquals(point.getKl(), other.getKl(), message + ": kL");
        assertEquals(point.getKq(), other.getKq(), message + ": kQ");
        assertEquals(point.getEdges(), other.getEdges(), message + ": edge");
        if (point.getU() == null) {
            assertNull(other.getU(), message + ": U should not be set");
            assertNull(other.getV(), message + ": V should not be set");
        } else {
            assertSame(point.getU(), other.getU(), message + ": U");
            assertSame(point.getV(), other.getV(), message + ": V");
        }
        if (point instanceof SpotLight spot) {
            assertSame(spot.getDirection(), ((SpotLight) other).getDirection(), message + ": direction");
            assertEquals(spot.getNarrowBeam(), ((SpotLight) other).getNarrowBeam(), message + ": narrow beam");
        }
    }

    /** Checks that a loaded picture has exactly the values of the original. */
    private static void assertSamePicture(Picture expected, Picture actual, String message) {
        assertEquals(expected.name(), actual.name(), message + ": name");
        assertEquals(expected.nX(), actual.nX(), message + ": width");
        assertEquals(expected.nY(), actual.nY(), message + ": height");
        assertEquals(expected.gridInterval(), actual.gridInterval(), message + ": grid");
        assertEquals(expected.settings(), actual.settings(), message + ": render settings");
        Camera camera = expected.camera();
        Camera loaded = actual.camera();
        assertSame(camera.getP0(), loaded.getP0(), message + ": camera p0");
        assertSame(camera.getVTo(), loaded.getVTo(), message + ": camera vTo");
        assertSame(camera.getVUp(), loaded.getVUp(), message + ": camera vUp");
        assertSame(camera.getVRight(), loaded.getVRight(), message + ": camera vRight");
        assertEquals(camera.getWidth(), loaded.getWidth(), message + ": view plane width");
        assertEquals(camera.getHeight(), loaded.getHeight(), message + ": view plane height");
        assertEquals(camera.getDistance(), loaded.getDistance(), message + ": view plane distance");
        assertEquals(camera.getApertureSize(), loaded.getApertureSize(), message + ": aperture");
        assertEquals(camera.getFocalDistance(), loaded.getFocalDistance(), message + ": focal distance");
        assertEquals(camera.getSqrtApertureRays(), loaded.getSqrtApertureRays(), message + ": aperture rays");
        Scene scene = expected.scene();
        Scene other = actual.scene();
        assertSame(scene.background, other.background, message + ": background");
        assertSame(scene.ambientLight.getIntensity(), other.ambientLight.getIntensity(), message + ": ambient light");
        assertEquals(scene.lights.size(), other.lights.size(), message + ": number of lights");
        for (int k = 0; k < scene.lights.size(); ++k)
            assertSameLight(scene.lights.get(k), other.lights.get(k), message + ": light " + k);
        assertSameBody(scene.geometries, other.geometries, message + ": geometries");
    }

    /** Test method for {@link SceneWriter#toXml(Picture)}: the text, its defaults and its numbers. */
    @Test
    void testToXml() {
        String xml = SceneWriter.toXml(everything());
        // ===== Equivalence Partitions Tests =====
        // TC01: the scene's header, camera, image and settings, one per line in a fixed order
        assertTrue(xml.startsWith("""
                <?xml version="1.0" encoding="UTF-8"?>
                <scene name="everything" background-color="10 20 30">
                    <camera p0="10 20 600" vTo="0 -0.1 -1" vUp="0 1 -0.1" vp-width="220" vp-height="200" vp-distance="500"/>
                    <image width="60" height="60" grid="20"/>
                    <render soft-shadows="true" adaptive="true" beams="3" anti-aliasing="2" seed="7"/>
                    <ambient-light color="25.5 25.5 25.5"/>
                    <lights>
                """), "TC01: wrong header:\n" + xml);
        // TC02: each light with the attributes that differ from the schema's defaults; U and V only when set
        assertTrue(xml.contains("""
                    <lights>
                        <directional-light color="100 80 60" direction="1 -1 -1"/>
                        <point-light color="400 300 200" position="-50 50 50" kL="0.001" kQ="0.0001"/>
                        <point-light color="300 300 300" position="50 80 0" kL="0.002" edge="10" u="1 0 0" v="0 0 1"/>
                        <point-light color="200 100 100" position="0 100 -50" kQ="0.00005" edge="8"/>
                        <spot-light color="500 400 300" position="40 40 60" direction="-1 -1 -4" narrow-beam="4" kC="0.5" kL="0.0004" kQ="0.00002" edge="12" u="1 0 0" v="0 1 0"/>
                        <spot-light color="300 300 500" position="-40 60 30" direction="0 -0.2 -1" kL="0.001" edge="6"/>
                    </lights>
                """), "TC02: wrong lights:\n" + xml);
        // TC03: every body with its emission and material, the nested group indented one step more
        assertTrue(xml.endsWith("""
                    <geometries>
                        <sphere center="0 0 -100" radius="30" emission="0 0 100" kD="0.5" kS="0.5" nShininess="30"/>
                        <triangle p0="-100 -60 -150" p1="100 -60 -150" p2="0 80 -200" emission="20 20 20" kD="0.3" kR="0.4"/>
                        <polygon vertices="40 30 -60 70 30 -60 70 60 -70 40 60 -70" emission="80 0 0" kD="0.4" kS="0.2" kT="0.5" nShininess="10"/>
                        <plane q0="0 -70 0" normal="0 1 0.1" emission="30 40 30" kD="0.6" kR="0.2"/>
                        <tube p0="60 0 -150" dir="0 1 1" radius="10" emission="0 60 0" kD="0.5" kS="0.3" nShininess="20"/>
                        <cylinder p0="-60 -40 -120" dir="0 1 0" radius="15" height="40" emission="60 60 0" kD="0.5" kS="0.5" nShininess="50"/>
                        <geometries>
                            <sphere center="-30 40 -80" radius="12" emission="90 0 90"/>
                            <triangle p0="-90 20 -90" p1="-60 20 -90" p2="-75 50 -95"/>
                        </geometries>
                    </geometries>
                </scene>
                """), "TC03: wrong bodies:\n" + xml);
        // TC04: writing is deterministic: the same text twice
        assertEquals(xml, SceneWriter.toXml(everything()), "TC04: writing twice gave different texts");

        // ===== Boundary Values Tests =====
        // TC11: a picture of nothing but the schema's defaults is the bare scene element
        Camera courseCamera = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(500, 500).setVpDistance(100);
        assertEquals("""
                <?xml version="1.0" encoding="UTF-8"?>
                <scene name="empty">
                </scene>
                """, SceneWriter.toXml(new Picture("empty", 500, 500, new Scene("empty"), courseCamera)),
                "TC11: a picture of defaults should write no attributes or elements but its name");
        // TC12: the markup characters of a name are escaped, tabs and line breaks kept as references
        String name = "a \"b\" & <c>\tline\nbreak";
        assertTrue(SceneWriter.toXml(new Picture(name, 500, 500, new Scene("x"), courseCamera))
                        .contains("<scene name=\"a &quot;b&quot; &amp; &lt;c&gt;&#9;line&#10;break\">"),
                "TC12: wrong escaping of the name");
    }

    /**
     * Test method for {@link SceneWriter#write(Picture, Path)} and {@link SceneLoader#load(Path)}: every body
     * and light type, written and loaded, has the same values and renders the same pixels.
     */
    @Test
    void testRoundTrip() {
        Picture picture = everything();
        Path file = FOLDER.resolve("everything.xml");
        SceneWriter.write(picture, file);
        Picture loaded = SceneLoader.load(file);

        // ===== Equivalence Partitions Tests =====
        // TC01: the loaded picture has exactly the values of the Java one (camera, settings, lights, bodies)
        assertSamePicture(picture, loaded, "TC01");
        assertEquals(0.0004, ((PointLight) loaded.scene().lights.get(4)).getKl(), "TC01: wrong spot light kL");
        assertEquals(30, ((Sphere) loaded.scene().geometries.getGeometries().get(0)).getRadius(),
                "TC01: wrong sphere radius");
        // TC02: the loaded picture renders exactly the pixels of the Java one
        ImageWriter java = render(picture, "everything-java");
        ImageWriter fromFile = render(loaded, "everything-file");
        assertEquals(0, differentPixels(java, fromFile), "TC02: the loaded picture renders other pixels");
        // TC03: the picture shows something: more than 10 colours
        java.util.Set<java.awt.Color> colours = new java.util.HashSet<>();
        for (int y = 0; y < 60; ++y)
            for (int x = 0; x < 60; ++x)
                colours.add(java.getPixel(x, y));
        assertTrue(colours.size() > 10, "TC03: the test picture is nearly flat: " + colours.size() + " colours");
        // TC04: writing the loaded picture gives the same text again
        assertEquals(SceneWriter.toXml(picture), SceneWriter.toXml(loaded), "TC04: the round trip changed the text");

        // ===== Boundary Values Tests =====
        // TC11: a name with markup characters, a tab and a line break comes back unchanged
        String name = "a \"b\" & <c>\tline\nbreak";
        Path odd = FOLDER.resolve("odd-name.xml");
        SceneWriter.write(picture.withSize(10, 10).withSettings(RenderSettings.DEFAULT), odd);
        Picture oddLoaded = SceneLoader.load(odd);
        assertEquals("everything", oddLoaded.name(), "TC11: wrong name before renaming");
        SceneWriter.write(new Picture(name, 10, 10, picture.scene(), picture.camera()), odd);
        assertEquals(name, SceneLoader.load(odd).name(), "TC11: the name did not come back unchanged");
        // TC12: write creates missing folders
        Path deep = FOLDER.resolve("new-folder").resolve("deeper").resolve("everything.xml");
        SceneWriter.write(picture, deep);
        assertTrue(Files.isRegularFile(deep), "TC12: the file in new folders was not written");
    }

    /**
     * Test method for {@link SceneWriter#write(Picture, Path)} and {@link SceneLoader#load(Path)}: glossy
     * and blurry materials and the gloss grid, written and loaded, have the same values and render the
     * same pixels.
     */
    @Test
    void testRoundTripGlossAndBlur() {
        Scene scene = new Scene("gloss").setBackground(new Color(40, 60, 90));
        scene.geometries.add(
                new Plane(new Point3D(0, -40, 0), new Vector(0, 1, 0)).setEmission(new Color(30, 30, 30))
                        .setMaterial(new Material().setKd(0.4).setKr(0.5).setKg(0.07)),
                new Polygon(new Point3D(-30, -40, 20), new Point3D(30, -40, 20), new Point3D(30, 40, 20),
                        new Point3D(-30, 40, 20)).setMaterial(new Material().setKt(0.8).setKb(0.03)),
                new Sphere(new Point3D(0, 0, -40), 25).setEmission(new Color(150, 40, 20)));
        scene.lights.add(new DirectionalLight(new Color(200, 200, 200), new Vector(1, -1, -1)));
        Camera camera = new Camera(new Point3D(0, 10, 300), new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(150, 150).setVpDistance(300);
        Picture picture = new Picture("gloss", 40, 40, scene, camera, 0, RenderSettings.DEFAULT.withSqrtGlossRays(3));
        Path file = FOLDER.resolve("gloss.xml");
        SceneWriter.write(picture, file);
        Picture loaded = SceneLoader.load(file);
        String xml = SceneWriter.toXml(picture);

        // ===== Equivalence Partitions Tests =====
        // TC01: the loaded picture has exactly the values of the Java one, kG, kB and gloss-rays included
        assertSamePicture(picture, loaded, "TC01");
        assertEquals(3, loaded.settings().sqrtGlossRays(), "TC01: wrong gloss-rays");
        // TC02: the text carries kG="0.07", kB="0.03" and gloss-rays="3"
        for (String attribute : List.of("kG=\"0.07\"", "kB=\"0.03\"", "gloss-rays=\"3\""))
            assertTrue(xml.contains(attribute), "TC02: the text lacks " + attribute + ":\n" + xml);
        // TC03: the loaded picture renders exactly the pixels of the Java one
        assertEquals(0, differentPixels(render(picture, "gloss-java"), render(loaded, "gloss-file")),
                "TC03: the loaded picture renders other pixels");

        // ===== Boundary Values Tests =====
        // TC11: kG and kB 0 and the default gloss-rays are not written (the schema's defaults)
        String plain = SceneWriter.toXml(picture.withSettings(RenderSettings.DEFAULT));
        assertFalse(plain.contains("gloss-rays"), "TC11: the default gloss-rays must not be written");
        assertEquals(1, plain.split("kG=", -1).length - 1, "TC11: only the glossy floor may have a kG");
        assertEquals(1, plain.split("kB=", -1).length - 1, "TC11: only the blurry pane may have a kB");
    }

    /**
     * Test method for {@link SceneWriter#write(Picture, Path)} and {@link SceneLoader#load(Path)}: depth of field
     * and adaptive super-sampling are written, read back and render the same pixels.
     */
    @Test
    void testRoundTripDepthOfFieldAndAdaptive() {
        Picture base = everything().withSize(30, 30);
        base.camera().setApertureSize(4).setFocalDistance(450).setSqrtApertureRays(2);
        Picture picture = base.withSettings(new RenderSettings(true, false, 2, 2, 7).withAdaptiveSuperSampling(true));
        Path file = FOLDER.resolve("lens.xml");
        SceneWriter.write(picture, file);
        Picture loaded = SceneLoader.load(file);

        // ===== Equivalence Partitions Tests =====
        // TC01: the camera's lens and the adaptive flag are written with the camera and the render settings
        String xml = SceneWriter.toXml(picture);
        assertTrue(xml.contains(" vp-distance=\"500\" aperture=\"4\" focal-distance=\"450\" aperture-rays=\"2\"/>"),
                "TC01: wrong camera:\n" + xml);
        assertTrue(xml.contains(" seed=\"7\" adaptive-super-sampling=\"true\"/>"), "TC01: wrong render:\n" + xml);
        // TC02: read back with the same values, rendering the same pixels
        assertSamePicture(picture, loaded, "TC02");
        assertEquals(0, differentPixels(render(picture, "lens-java"), render(loaded, "lens-file")),
                "TC02: the loaded picture renders other pixels");

        // ===== Boundary Values Tests =====
        // TC11: a focal distance without an aperture is kept (it is a setting of its own)
        Camera focusedPinhole = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(500, 500).setVpDistance(100).setFocalDistance(300);
        String pinholeXml = SceneWriter.toXml(new Picture("focus", 500, 500, new Scene("focus"), focusedPinhole));
        assertTrue(pinholeXml.contains("<camera focal-distance=\"300\"/>"), "TC11: wrong camera:\n" + pinholeXml);
        // TC12: the defaults (no aperture, the view plane in focus, 9 rays, not adaptive) write nothing
        assertFalse(SceneWriter.toXml(everything()).contains("aperture"), "TC12: a pinhole camera writes no lens");
        assertFalse(SceneWriter.toXml(everything()).contains("adaptive-super"), "TC12: adaptive off writes nothing");
    }

    /**
     * Test method for {@link SceneWriter#toXml(Picture)} on a {@link TriangleMesh}: a scene file names no
     * OBJ file for it, so it is written as a group of its triangles, each with the mesh's surface, and
     * loaded back it renders the same pixels.
     */
    @Test
    void testMesh() {
        Scene scene = new Scene("mesh").setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(new TriangleMesh(new double[] { -50, -50, -100, 50, -50, -100, 50, 50, -100, -50, 50, -120 },
                new int[] { 0, 1, 2, 0, 2, 3 }).setEmission(new Color(40, 0, 0)).setMaterial(new Material().setKd(0.5)));
        scene.lights.add(new DirectionalLight(new Color(200, 200, 200), new Vector(0, 0, -1)));
        Picture picture = new Picture("mesh", 20, 20, scene,
                new Camera(new Point3D(0, 0, 500), new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpSize(150, 150)
                        .setVpDistance(500));
        String xml = SceneWriter.toXml(picture);
        // ===== Equivalence Partitions Tests =====
        // TC01: the mesh is a group of its two triangles, in its order, each with its emission and kD
        assertTrue(xml.contains("""
                    <geometries>
                        <geometries>
                            <triangle p0="-50 -50 -100" p1="50 -50 -100" p2="50 50 -100" emission="40 0 0" kD="0.5"/>
                            <triangle p0="-50 -50 -100" p1="50 50 -100" p2="-50 50 -120" emission="40 0 0" kD="0.5"/>
                        </geometries>
                    </geometries>
                """), "TC01: wrong mesh:\n" + xml);
        // TC02: loaded back, the triangles render the mesh's pixels
        Path file = FOLDER.resolve("mesh.xml");
        SceneWriter.write(picture, file);
        ImageWriter java = render(picture, "mesh-java");
        ImageWriter fromFile = render(SceneLoader.load(file), "mesh-file");
        assertEquals(0, differentPixels(java, fromFile), "TC02: the loaded mesh renders other pixels");

        // ===== Boundary Values Tests =====
        // TC11: the pixel in the middle shows the mesh: its emission and its diffuse light, red 40 + 0.5·200 + 25.5
        assertEquals(166, java.getPixel(10, 10).getRed(), 1, "TC11: the middle pixel must show the mesh");
    }

    /**
     * Test method for {@link SceneWriter#write(Picture, Path)} and {@link SceneLoader#load(Path)}: real glass,
     * textures and a smooth textured mesh, written and loaded, render the same pixels; the image's file is
     * named relative to the scene file's folder.
     */
    @Test
    void testRoundTripGlassTexturesAndSmoothMesh() {
        Path png = TestFiles.writePng(FOLDER.resolve("textures"), "four.png", 2, 0xFF0000, 0x00FF00, 0x0000FF, 0xFFFFFF);
        Scene scene = new Scene("glass").setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        TriangleMesh tent = new TriangleMesh(new double[] { -40, -30, -60, 40, -30, -60, 40, 10, -90, -40, 10, -90 },
                new int[] { 0, 1, 2, 0, 2, 3 }).smoothNormals().setUVs(new double[] { 0, 0, 1, 0, 1, 1, 0, 1 });
        scene.geometries.add(
                new Sphere(new Point3D(0, 0, -50), 20).setMaterial(new Material().setKt(0.9).setIor(1.5).setFresnel(true)),
                new Plane(new Point3D(0, -30, 0), new Vector(0, 1, 0)).setMaterial(new Material().setKd(0.6))
                        .setTexture(new CheckerTexture(new Color(255, 255, 255), new Color(30, 30, 30), 15)),
                tent.setEmission(new Color(60, 60, 60)).setMaterial(new Material().setKd(0.5))
                        .setTexture(new ImageTexture(png)));
        scene.lights.add(new DirectionalLight(new Color(200, 200, 200), new Vector(-1, -2, -1)));
        Picture picture = new Picture("glass", 40, 40, scene, new Camera(new Point3D(0, 20, 300),
                new Vector(0, -0.1, -1), new Vector(0, 1, -0.1)).setVpSize(120, 120).setVpDistance(300));
        Path file = FOLDER.resolve("glass.xml");
        SceneWriter.write(picture, file);
        Picture loaded = SceneLoader.load(file);
        // ===== Equivalence Partitions Tests =====
        // TC01: the same values: the glass, the textures, the mesh's normals and UVs
        Material glass = ((Geometry) loaded.scene().geometries.getGeometries().get(0)).getMaterial();
        assertEquals(1.5, glass.getIor(), "TC01: wrong ior");
        assertTrue(glass.isFresnel(), "TC01: Fresnel must be on");
        TriangleMesh mesh = (TriangleMesh) loaded.scene().geometries.getGeometries().get(2);
        assertArrayEquals(tent.getNormals(), mesh.getNormals(), "TC01: wrong normals");
        assertArrayEquals(tent.getUVs(), mesh.getUVs(), "TC01: wrong UVs");
        assertSamePicture(picture, loaded, "TC01");
        // TC02: the loaded picture renders exactly the Java one's pixels
        assertEquals(0, differentPixels(render(picture, "glass-java"), render(loaded, "glass-file")),
                "TC02: the loaded picture renders other pixels");
        // ===== Boundary Values Tests =====
        // TC11: the image is named relative to the scene file's folder by write, absolutely by toXml
        String xml = SceneWriter.toXml(picture);
        assertTrue(xml.contains("<image-texture file=\"" + png.toAbsolutePath().normalize() + "\"/>"),
                "TC11: toXml names the absolute path:\n" + xml);
        assertTrue(assertDoesNotThrow(() -> Files.readString(file)).contains("<image-texture file=\"textures/four.png\"/>"),
                "TC11: write names the file relative to the scene's folder");
        // TC12: a texture of the user's own class cannot be written
        Scene own = new Scene("own");
        own.geometries.add(new Sphere(Point3D.ZERO, 1).setTexture((u, v) -> Color.BLACK));
        assertMessage(assertThrows(IllegalArgumentException.class, () -> SceneWriter.toXml(new Picture("own", 10, 10,
                own, picture.camera())), "TC12: an unknown texture"), "texture type", "TC12");
    }

    /**
     * Test method for {@link SceneWriter#toXml(Picture)}: numbers are written in their shortest text and read
     * back as the same doubles; directions in their simplest form normalise back to the same unit vectors.
     */
    @Test
    void testNumbers() {
        Camera camera = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpSize(100, 100)
                .setVpDistance(100);
        double[] radii = { 0.3, 0.1 + 0.2, 1E-5, 1.5E-7, 1E-12, 1234.5678, 1E22, 1.0 / 3 };
        Scene scene = new Scene("numbers");
        for (double radius : radii)
            scene.geometries.add(new Sphere(new Point3D(-0.7, 2.5E-9, 1E-3), radius));
        Random random = new Random(20210621);
        int planes = 200;
        for (int k = 0; k < planes; ++k)
            scene.geometries.add(new Plane(new Point3D(0, 0, -100), new Vector(random.nextGaussian(),
                    random.nextGaussian(), random.nextGaussian())));
        Picture picture = new Picture("numbers", 10, 10, scene, camera);
        String xml = SceneWriter.toXml(picture);
        Path file = FOLDER.resolve("numbers.xml");
        SceneWriter.write(picture, file);
        List<Intersectable> loaded = SceneLoader.load(file).scene().geometries.getGeometries();

        // ===== Equivalence Partitions Tests =====
        // TC01: each number in its shortest text, no noise digits, no ".0"
        assertTrue(xml.contains("<sphere center=\"-0.7 0.0000000025 0.001\" radius=\"0.3\"/>"),
                "TC01: wrong 0.3:\n" + xml);
        assertTrue(xml.contains("radius=\"0.30000000000000004\""), "TC01: 0.1 + 0.2 is not 0.3 and must stay so");
        assertTrue(xml.contains("radius=\"0.00001\""), "TC01: wrong 1E-5");
        assertTrue(xml.contains("radius=\"0.00000015\""), "TC01: wrong 1.5E-7");
        assertTrue(xml.contains("radius=\"1E-12\""), "TC01: wrong 1E-12 (plain would be long)");
        assertTrue(xml.contains("radius=\"1234.5678\""), "TC01: wrong 1234.5678");
        assertTrue(xml.contains("radius=\"1E22\""), "TC01: wrong 1E22");
        String body = xml.substring(xml.indexOf("<scene")); // after the declaration's version="1.0"
        assertFalse(body.contains(".0\"") || body.contains(".0 "), "TC01: a number was written with .0");
        // TC02: every number reads back as exactly the same double
        for (int k = 0; k < radii.length; ++k)
            assertEquals(radii[k], ((Sphere) loaded.get(k)).getRadius(), "TC02: radius " + radii[k] + " changed");
        // TC03: arbitrary directions read back to the same unit vectors: exactly for (nearly) all, within 1e-15
        // for the odd one no short text normalises to exactly
        int exact = 0;
        for (int k = 0; k < planes; ++k) {
            Vector normal = ((Plane) scene.geometries.getGeometries().get(radii.length + k)).getNormal();
            Vector back = ((Plane) loaded.get(radii.length + k)).getNormal();
            if (normal.getX() == back.getX() && normal.getY() == back.getY() && normal.getZ() == back.getZ())
                ++exact;
            else {
                assertEquals(normal.getX(), back.getX(), 1e-15, "TC03: normal " + k + " moved");
                assertEquals(normal.getY(), back.getY(), 1e-15, "TC03: normal " + k + " moved");
                assertEquals(normal.getZ(), back.getZ(), 1e-15, "TC03: normal " + k + " moved");
            }
        }
        assertTrue(exact >= planes * 99 / 100, "TC03: only " + exact + " of " + planes + " normals read back exactly");

        // ===== Boundary Values Tests =====
        // TC11: directions given with small numbers are written as given: 1 1 -2, 0 0.2 -1, 0 0 -1
        Scene spots = new Scene("spots");
        spots.lights.add(new SpotLight(new Color(1, 1, 1), Point3D.ZERO, new Vector(1, 1, -2)));
        spots.lights.add(new SpotLight(new Color(1, 1, 1), Point3D.ZERO, new Vector(0, 0.2, -1)));
        spots.lights.add(new DirectionalLight(new Color(1, 1, 1), new Vector(0, 0, -7)));
        String lights = SceneWriter.toXml(new Picture("spots", 10, 10, spots, camera));
        assertTrue(lights.contains("direction=\"1 1 -2\""), "TC11: wrong direction 1 1 -2:\n" + lights);
        assertTrue(lights.contains("direction=\"0 0.2 -1\""), "TC11: wrong direction 0 0.2 -1:\n" + lights);
        assertTrue(lights.contains("direction=\"0 0 -1\""), "TC11: wrong direction 0 0 -7:\n" + lights);
        // TC12: zero and negative zero are both written as 0
        Scene zeros = new Scene("zeros");
        zeros.geometries.add(new Sphere(new Point3D(-0.0, 0, -100), 1));
        assertTrue(SceneWriter.toXml(new Picture("zeros", 10, 10, zeros, camera)).contains("center=\"0 0 -100\""),
                "TC12: wrong zeros");
    }

    /**
     * Test method for {@link SceneWriter#toXml(Picture)}: a light's u and v are written only when they
     * were set, never the square a spot light chooses around its direction.
     */
    @Test
    void testLightSquareSides() {
        Camera camera = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpSize(100, 100)
                .setVpDistance(100);
        Random random = new Random(4711);
        Scene unset = new Scene("unset");
        for (int k = 0; k < 200; ++k)
            unset.lights.add(new SpotLight(new Color(1, 1, 1), Point3D.ZERO,
                    new Vector(random.nextGaussian(), random.nextGaussian(), random.nextGaussian())).setEdgesSize(2));
        unset.lights.add(new PointLight(new Color(1, 1, 1), Point3D.ZERO).setEdgesSize(2));
        Scene set = new Scene("set");
        set.lights.add(new SpotLight(new Color(1, 1, 1), Point3D.ZERO, new Vector(0, 0, -1)).setEdgesSize(2)
                .setUV(new Vector(0, 1, 0), new Vector(1, 0, 0)));
        set.lights.add(new PointLight(new Color(1, 1, 1), Point3D.ZERO).setEdgesSize(2)
                .setUV(new Vector(1, 0, 0), new Vector(0, 0, 1)));

        // ===== Equivalence Partitions Tests =====
        // TC01: 200 spot lights in random directions and a point light, none with u and v set: no u, no v
        String xml = SceneWriter.toXml(new Picture("unset", 10, 10, unset, camera));
        assertFalse(xml.contains(" u=") || xml.contains(" v="), "TC01: a chosen square must not be written:\n" + xml);
        // TC02: a spot light and a point light with u and v set: both written as set
        String written = SceneWriter.toXml(new Picture("set", 10, 10, set, camera));
        assertTrue(written.contains("u=\"0 1 0\" v=\"1 0 0\""), "TC02: the spot light's set square:\n" + written);
        assertTrue(written.contains("u=\"1 0 0\" v=\"0 0 1\""), "TC02: the point light's set square:\n" + written);

        // ===== Boundary Values Tests =====
        // TC11: a spot light whose set u and v equal the square it would choose: still written, as set
        SpotLight chosen = new SpotLight(new Color(1, 1, 1), Point3D.ZERO, new Vector(0, 0, -1)).setEdgesSize(2);
        Scene same = new Scene("same");
        same.lights.add(chosen.setUV(chosen.getU(), chosen.getV()));
        assertTrue(SceneWriter.toXml(new Picture("same", 10, 10, same, camera)).contains(" u="),
                "TC11: a square set with setUV must be written even when it equals the chosen one");
    }

    /** Test method for {@link SceneWriter#toXml(Picture)} and {@link SceneWriter#write(Picture, Path)}: bad input. */
    @Test
    void testErrors() throws IOException {
        Camera camera = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpSize(100, 100)
                .setVpDistance(100);
        // ===== Equivalence Partitions Tests =====
        // TC01: a body of a type the format cannot express
        Scene ownBody = new Scene("own body");
        ownBody.geometries.add(new Sphere(new Point3D(0, 0, -50), 5), new Geometries(new OwnSphere()));
        Picture bodyPicture = new Picture("ownBody", 10, 10, ownBody, camera);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SceneWriter.toXml(bodyPicture),
                "TC01: an unknown body type should be refused");
        assertMessage(e, "body type", "TC01");
        assertMessage(e, "OwnSphere", "TC01");
        // TC02: a light of a type the format cannot express
        Scene ownLight = new Scene("own light");
        ownLight.lights.add(new OwnLight());
        Picture lightPicture = new Picture("ownLight", 10, 10, ownLight, camera);
        e = assertThrows(IllegalArgumentException.class, () -> SceneWriter.toXml(lightPicture),
                "TC02: an unknown light type should be refused");
        assertMessage(e, "light type", "TC02");
        assertMessage(e, "OwnLight", "TC02");
        // TC03: a file in a place that cannot be written: below a regular file
        Path blocker = TestFiles.write(FOLDER, "not-a-folder.txt", "a file, not a folder");
        Path unwritable = blocker.resolve("scene.xml");
        Picture picture = new Picture("unwritable", 10, 10, new Scene("s"), camera);
        UncheckedIOException io = assertThrows(UncheckedIOException.class, () -> SceneWriter.write(picture, unwritable),
                "TC03: an unwritable file should fail");
        assertMessage(io, unwritable.toString(), "TC03");
        // TC04: nothing is written for a picture that cannot be expressed
        Path refused = FOLDER.resolve("refused.xml");
        Files.deleteIfExists(refused);
        assertThrows(IllegalArgumentException.class, () -> SceneWriter.write(bodyPicture, refused),
                "TC04: an unknown body type should be refused by write too");
        assertFalse(Files.exists(refused), "TC04: a refused picture left a file");

        // ===== Boundary Values Tests =====
        // TC11: an empty name cannot be written (the file's name would replace it)
        Picture unnamed = new Picture("", 10, 10, new Scene("s"), camera);
        e = assertThrows(IllegalArgumentException.class, () -> SceneWriter.toXml(unnamed),
                "TC11: an empty name should be refused");
        assertMessage(e, "empty picture name", "TC11");
        // TC12: a name with a control character XML cannot hold
        Picture control = new Picture("bell\u0007", 10, 10, new Scene("s"), camera);
        e = assertThrows(IllegalArgumentException.class, () -> SceneWriter.toXml(control),
                "TC12: a control character should be refused");
        assertMessage(e, "U+0007", "TC12");
        // TC13: a camera without its view plane size cannot be written
        Picture noSize = new Picture("noSize", 10, 10, new Scene("s"),
                new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0)));
        e = assertThrows(IllegalArgumentException.class, () -> SceneWriter.toXml(noSize),
                "TC13: a camera without a view plane should be refused");
        assertMessage(e, "view plane", "TC13");
    }
}
