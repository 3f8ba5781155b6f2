package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;


import app.Gallery;
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
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.CheckerTexture;
import primitives.Color;
import primitives.ImageTexture;
import primitives.Point3D;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import scene.Scene;
import testutil.TestFiles;

/**
 * Tests for {@link SceneLoader}: the course's original files, every element of the format, the
 * defaults, and a one-line error naming file, line and column for every kind of bad file.
 */
class SceneLoaderTest {
    private static final Path FOLDER = Path.of("target", "test-scenes", "loader");
    private static final Path COURSE_FILE = Path.of("src", "test", "resources", "scenes", "basicRenderTestTwoColors.xml");

    /** Writes a scene file under target/ and returns its path. */
    private static Path file(String name, String xml) {
        return TestFiles.write(FOLDER, name, xml);
    }

    /** The bodies of a picture's scene. */
    private static List<Intersectable> bodies(Picture picture) {
        return picture.scene().geometries.getGeometries();
    }

    /** Test method for {@link SceneLoader#load(Path)}: the course's original two-colour file. */
    @Test
    void testLoadCourseFile() {
        Picture picture = SceneLoader.load(COURSE_FILE);
        Scene scene = picture.scene();
        // ===== Equivalence Partitions Tests =====
        // TC01: background (75, 127, 90), ambient light (255, 191, 191) with kA 1
        assertColor(75, 127, 90, scene.background, "TC01: wrong background");
        assertColor(255, 191, 191, scene.ambientLight.getIntensity(), "TC01: wrong ambient light");
        // TC02: one sphere of radius 50 at (0, 0, -100) and four triangles, no lights
        List<Intersectable> bodies = bodies(picture);
        assertEquals(5, bodies.size(), "TC02: wrong number of bodies");
        Sphere sphere = assertInstanceOf(Sphere.class, bodies.get(0), "TC02: the first body is the sphere");
        assertEquals(new Point3D(0, 0, -100), sphere.getCenter(), "TC02: wrong sphere centre");
        assertEquals(50, sphere.getRadius(), 1e-12, "TC02: wrong sphere radius");
        assertEquals(List.of(new Point3D(-100, 0, -100), new Point3D(0, 100, -100), new Point3D(-100, 100, -100)),
                assertInstanceOf(Triangle.class, bodies.get(1), "TC02: then triangles").getVertices(),
                "TC02: wrong triangle vertices");
        assertTrue(scene.lights.isEmpty(), "TC02: no lights");
        // TC03: no camera, image or render element: the course's camera, 500 × 500, the default settings
        Camera camera = picture.camera();
        assertEquals(Point3D.ZERO, camera.getP0(), "TC03: wrong default camera position");
        assertEquals(new Vector(0, 0, -1), camera.getVTo(), "TC03: wrong default vTo");
        assertEquals(new Vector(0, 1, 0), camera.getVUp(), "TC03: wrong default vUp");
        assertEquals(500, camera.getWidth(), 1e-12, "TC03: wrong default view-plane width");
        assertEquals(100, camera.getDistance(), 1e-12, "TC03: wrong default view-plane distance");
        assertEquals(500, picture.nX(), "TC03: wrong default width");
        assertEquals(500, picture.nY(), "TC03: wrong default height");
        assertEquals(0, picture.gridInterval(), "TC03: no grid by default");
        assertEquals(RenderSettings.DEFAULT, picture.settings(), "TC03: wrong default settings");
        // TC04: the picture is named after the file
        assertEquals("basicRenderTestTwoColors", picture.name(), "TC04: wrong picture name");
    }

    /**
     * Test method for {@link SceneLoader#load(Path)}: the course's two-colour file renders exactly like
     * its Java twin in the gallery (same camera, size and grid).
     */
    @Test
    void testCourseFileRendersLikeJavaTwin() {
        Picture twin = Gallery.pictures().stream().filter(p -> p.name().equals("baseRenderTwoColors"))
                .findFirst().orElseThrow().withSize(250, 250);
        Picture loaded = new Picture("twoColorsFromXml", 250, 250, SceneLoader.load(COURSE_FILE).scene(),
                twin.camera(), twin.gridInterval(), twin.settings());
        ImageWriter expected = twin.render(twin.newRender(FOLDER.resolve("twoColorsFromJava.png"))).getImageWriter();
        ImageWriter actual = loaded.render(loaded.newRender(FOLDER.resolve("twoColorsFromXml.png"))).getImageWriter();
        // ===== Equivalence Partitions Tests =====
        // TC01: every pixel the same, and the picture shows the background, the ambient bodies and the grid
        java.util.Set<java.awt.Color> colours = new java.util.HashSet<>();
        for (int y = 0; y < 250; ++y)
            for (int x = 0; x < 250; ++x) {
                assertEquals(expected.getPixel(x, y), actual.getPixel(x, y), "TC01: pixel (" + x + ", " + y + ") differs");
                colours.add(actual.getPixel(x, y));
            }
        assertEquals(3, colours.size(), "TC01: background, bodies and grid: 3 colours");
    }

    /** Test method for {@link SceneLoader#load(Path)}: camera, image, render settings and lights. */
    @Test
    void testLoadSettingsAndLights() {
        Picture picture = SceneLoader.load(file("settings.xml", """
                <scene name="settings test" background-color="1 2 3">
                  <render soft-shadows="true" adaptive="1" beams="4" anti-aliasing="3" seed="-7"/>
                  <camera p0="0 0 1000" vTo="0 0 -2" vUp="0 3 0" vp-width="200" vp-height="100" vp-distance="800"/>
                  <image width="60" height="30" grid="10"/>
                  <ambient-light color="100 100 100" kA="0.15"/>
                  <lights>
                    <directional-light color="10 20 30" direction="1 1 -1"/>
                    <point-light color="100 50 0" position="1 2 3" kC="0.5" kL="4E-4" kQ="6e-5" edge="30"
                                 u="2 0 0" v="0 0 5"/>
                    <spot-light color="700 400 400" position="40 40 115" direction="-1 -1 -4" kL="4E-4" kQ="2E-5"
                                edge="30" narrow-beam="10"/>
                  </lights>
                </scene>
                """));
        // ===== Equivalence Partitions Tests =====
        // TC01: name, size, grid and background as given
        assertEquals("settings test", picture.name(), "TC01: wrong name");
        assertEquals("settings test", picture.scene().name, "TC01: wrong scene name");
        assertEquals(60, picture.nX(), "TC01: wrong width");
        assertEquals(30, picture.nY(), "TC01: wrong height");
        assertEquals(10, picture.gridInterval(), "TC01: wrong grid");
        assertColor(1, 2, 3, picture.scene().background, "TC01: wrong background");
        // TC02: render settings: soft, adaptive ("1" is true), 4 beams, 3 × 3 anti-aliasing, seed -7
        assertEquals(new RenderSettings(true, true, 4, 3, -7), picture.settings(), "TC02: wrong settings");
        // TC03: camera: vTo and vUp normalised, view plane 200 × 100 at 800
        Camera camera = picture.camera();
        assertEquals(new Point3D(0, 0, 1000), camera.getP0(), "TC03: wrong camera position");
        assertEquals(new Vector(0, 0, -1), camera.getVTo(), "TC03: wrong vTo");
        assertEquals(new Vector(0, 1, 0), camera.getVUp(), "TC03: wrong vUp");
        assertEquals(200, camera.getWidth(), 1e-12, "TC03: wrong view-plane width");
        assertEquals(100, camera.getHeight(), 1e-12, "TC03: wrong view-plane height");
        assertEquals(800, camera.getDistance(), 1e-12, "TC03: wrong view-plane distance");
        // TC04: ambient light intensity is colour × kA = 15
        assertColor(15, 15, 15, picture.scene().ambientLight.getIntensity(), "TC04: wrong ambient light");
        // TC05: a directional light with its colour and unit direction
        DirectionalLight directional = assertInstanceOf(DirectionalLight.class, picture.scene().lights.get(0),
                "TC05: the first light is directional");
        assertColor(10, 20, 30, directional.getIntensity(), "TC05: wrong directional colour");
        assertEquals(new Vector(1, 1, -1).normalized(), directional.getDirection(), "TC05: wrong direction");
        // TC06: a point light with attenuation, edge 30 and unit U, V
        PointLight point = assertInstanceOf(PointLight.class, picture.scene().lights.get(1), "TC06: then a point light");
        assertFalse(point instanceof SpotLight, "TC06: a point light, not a spot light");
        assertEquals(new Point3D(1, 2, 3), point.getPosition(), "TC06: wrong position");
        assertEquals(0.5, point.getKc(), 1e-15, "TC06: wrong kC");
        assertEquals(4E-4, point.getKl(), 1e-15, "TC06: wrong kL");
        assertEquals(6E-5, point.getKq(), 1e-15, "TC06: wrong kQ");
        assertEquals(30, point.getEdges(), 1e-15, "TC06: wrong edge");
        assertEquals(new Vector(1, 0, 0), point.getU(), "TC06: wrong U");
        assertEquals(new Vector(0, 0, 1), point.getV(), "TC06: wrong V");
        // TC07: a spot light with its direction and narrow beam; U, V not given: the square faces the direction
        SpotLight spot = assertInstanceOf(SpotLight.class, picture.scene().lights.get(2), "TC07: then a spot light");
        assertEquals(new Vector(-1, -1, -4).normalized(), spot.getDirection(), "TC07: wrong spot direction");
        assertEquals(10, spot.getNarrowBeam(), 1e-15, "TC07: wrong narrow beam");
        assertEquals(1, spot.getKc(), 1e-15, "TC07: kC defaults to 1");
        assertEquals(0, spot.getU().dotProduct(spot.getDirection()), 1e-12, "TC07: default U must be ⟂ direction");
        assertEquals(0, spot.getV().dotProduct(spot.getDirection()), 1e-12, "TC07: default V must be ⟂ direction");
        // ===== Boundary Values Tests =====
        // TC11: no <lights>, no <geometries>: an empty scene
        Picture empty = SceneLoader.load(file("empty-scene.xml", "<scene/>"));
        assertTrue(empty.scene().lights.isEmpty(), "TC11: no lights");
        assertTrue(bodies(empty).isEmpty(), "TC11: no bodies");
        assertColor(Color.BLACK, empty.scene().background, "TC11: black background by default");
    }

    /**
     * Test method for {@link SceneLoader#load(Path)}: depth of field on the camera and adaptive super-sampling in
     * the render settings.
     */
    @Test
    void testLoadDepthOfFieldAndAdaptiveSuperSampling() {
        Picture picture = SceneLoader.load(file("lens.xml", """
                <scene>
                  <camera vp-distance="80" aperture="2.5" focal-distance="640" aperture-rays="4"/>
                  <render anti-aliasing="4" adaptive-super-sampling="true"/>
                </scene>
                """));
        // ===== Equivalence Partitions Tests =====
        // TC01: aperture 2.5, focused at 640, 4 × 4 aperture rays
        Camera camera = picture.camera();
        assertEquals(2.5, camera.getApertureSize(), 1e-12, "TC01: wrong aperture");
        assertEquals(640, camera.getFocalDistance(), 1e-12, "TC01: wrong focal distance");
        assertEquals(4, camera.getSqrtApertureRays(), "TC01: wrong aperture rays");
        // TC02: adaptive super-sampling on, with 4 × 4 anti-aliasing
        assertEquals(RenderSettings.DEFAULT.withAntiAliasing(4).withAdaptiveSuperSampling(true), picture.settings(),
                "TC02: wrong settings");
        // TC03: a negative aperture names the setting, at the camera's line
        assertBadFile(file("negative-aperture.xml", "<scene>\n  <camera aperture=\"-1\"/>\n</scene>\n"), 2,
                "aperture size must not be negative", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: no lens attributes: a pinhole camera, the view plane (80) in focus, 9 aperture rays; no adaptive
        Picture plain = SceneLoader.load(file("no-lens.xml", "<scene><camera vp-distance=\"80\"/><render/></scene>"));
        assertFalse(plain.camera().hasAperture(), "TC11: a pinhole camera by default");
        assertEquals(80, plain.camera().getFocalDistance(), 1e-12, "TC11: the view plane is in focus by default");
        assertEquals(Camera.DEFAULT_SQRT_APERTURE_RAYS, plain.camera().getSqrtApertureRays(), "TC11: 9 aperture rays");
        assertFalse(plain.settings().adaptiveSuperSampling(), "TC11: adaptive super-sampling is off by default");
        // TC12: focal distance 0 and 1001 aperture rays are refused, naming them
        assertBadFile(file("zero-focus.xml", "<scene>\n  <camera focal-distance=\"0\"/>\n</scene>\n"), 2,
                "focal distance must be positive", "TC12");
        assertBadFile(file("many-aperture-rays.xml", "<scene>\n  <camera aperture-rays=\"1001\"/>\n</scene>\n"), 2,
                "attribute 'aperture-rays' must be between 1 and 1000", "TC12");
        // TC13: aperture rays 0 is refused by the schema
        assertBadFile(file("no-aperture-rays.xml", "<scene>\n  <camera aperture-rays=\"0\"/>\n</scene>\n"), 2,
                "attribute 'aperture-rays' of <camera> must be a whole number, 1 or more", "TC13");
    }

    /** Test method for {@link SceneLoader#load(Path)}: every body, materials, emission, groups and meshes. */
    @Test
    void testLoadBodies() {
        TestFiles.write(FOLDER.resolve("models"), "cube.obj", """
                v -1 -1 -1
                v 1 -1 -1
                v 1 1 -1
                v -1 1 -1
                v -1 -1 1
                v 1 -1 1
                v 1 1 1
                v -1 1 1
                f 1 4 3 2
                f 5 6 7 8
                f 1 2 6 5
                f 2 3 7 6
                f 3 4 8 7
                f 4 1 5 8
                """);
        Picture picture = SceneLoader.load(file("bodies.xml", """
                <scene>
                  <geometries>
                    <sphere center="0 0 -115" radius="30" emission="0 0 255" kD="0.5" kS="0.4" nShininess="30"
                            kT="0.2" kR="0.1"/>
                    <triangle p0="-150 -150 -115" p1="150 -150 -135" p2="75 75 -150"/>
                    <polygon vertices="0 0 0  1 0 0  1 1 0  0 1 0"/>
                    <plane q0="0 -50 0" normal="0 2 0"/>
                    <tube p0="0 0 0" dir="0 0 1" radius="2"/>
                    <cylinder p0="0 0 0" dir="0 1 0" radius="3" height="4"/>
                    <geometries>
                      <sphere center="1 1 1" radius="1"/>
                    </geometries>
                    <mesh file="models/cube.obj" scale="10" position="100 0 0" emission="20 20 20" kR="1"/>
                  </geometries>
                </scene>
                """));
        List<Intersectable> bodies = bodies(picture);
        // ===== Equivalence Partitions Tests =====
        // TC01: eight bodies in file order
        assertEquals(8, bodies.size(), "TC01: wrong number of bodies");
        // TC02: the sphere's emission and material
        Sphere sphere = assertInstanceOf(Sphere.class, bodies.get(0), "TC02: a sphere first");
        assertColor(0, 0, 255, sphere.getEmission(), "TC02: wrong emission");
        assertEquals(0.5, sphere.getMaterial().getKd(), 1e-15, "TC02: wrong kD");
        assertEquals(0.4, sphere.getMaterial().getKs(), 1e-15, "TC02: wrong kS");
        assertEquals(0.2, sphere.getMaterial().getKt(), 1e-15, "TC02: wrong kT");
        assertEquals(0.1, sphere.getMaterial().getKr(), 1e-15, "TC02: wrong kR");
        assertEquals(30, sphere.getMaterial().getShininess(), "TC02: wrong nShininess");
        // TC03: a triangle with the default surface: black emission, all coefficients 0
        Triangle triangle = assertInstanceOf(Triangle.class, bodies.get(1), "TC03: then a triangle");
        assertColor(Color.BLACK, triangle.getEmission(), "TC03: black emission by default");
        assertEquals(0, triangle.getMaterial().getKd(), 1e-15, "TC03: kD 0 by default");
        // TC04: a square polygon of four vertices
        Polygon polygon = assertInstanceOf(Polygon.class, bodies.get(2), "TC04: then a polygon");
        assertEquals(List.of(Point3D.ZERO, new Point3D(1, 0, 0), new Point3D(1, 1, 0), new Point3D(0, 1, 0)),
                polygon.getVertices(), "TC04: wrong polygon vertices");
        // TC05: a plane through q0 with a unit normal
        Plane plane = assertInstanceOf(Plane.class, bodies.get(3), "TC05: then a plane");
        assertEquals(new Point3D(0, -50, 0), plane.getQ0(), "TC05: wrong q0");
        assertEquals(new Vector(0, 1, 0), plane.getNormal(), "TC05: wrong normal");
        // TC06: a tube and a cylinder around their axis rays
        Tube tube = assertInstanceOf(Tube.class, bodies.get(4), "TC06: then a tube");
        assertEquals(2, tube.getRadius(), 1e-15, "TC06: wrong tube radius");
        assertEquals(new Vector(0, 0, 1), tube.getAxisRay().getDir(), "TC06: wrong tube axis");
        Cylinder cylinder = assertInstanceOf(Cylinder.class, bodies.get(5), "TC06: then a cylinder");
        assertEquals(3, cylinder.getRadius(), 1e-15, "TC06: wrong cylinder radius");
        assertEquals(4, cylinder.getHeight(), 1e-15, "TC06: wrong cylinder height");
        // TC07: a nested <geometries> is a nested composite
        Geometries group = assertInstanceOf(Geometries.class, bodies.get(6), "TC07: then a group");
        assertEquals(1, group.getGeometries().size(), "TC07: one sphere in the group");
        // TC08: the OBJ cube is a mesh of 12 triangles over its 8 corners, scaled by 10 around (100, 0, 0),
        // with the mesh element's surface
        TriangleMesh mesh = assertInstanceOf(TriangleMesh.class, bodies.get(7), "TC08: then the mesh");
        assertEquals(12, mesh.getTrianglesCount(), "TC08: a cube is 12 triangles");
        assertEquals(8, mesh.getVerticesCount(), "TC08: a cube has 8 corners");
        assertColor(20, 20, 20, mesh.getEmission(), "TC08: wrong mesh emission");
        assertEquals(1, mesh.getMaterial().getKr(), 1e-15, "TC08: wrong mesh kR");
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            Triangle face = mesh.getTriangle(t);
            assertColor(20, 20, 20, face.getEmission(), "TC08: wrong emission of a face");
            for (Point3D p : face.getVertices()) {
                assertEquals(10, Math.abs(p.getX() - 100), 1e-12, "TC08: cube corner x must be 100 ± 10");
                assertEquals(10, Math.abs(p.getY()), 1e-12, "TC08: cube corner y must be ± 10");
                assertEquals(10, Math.abs(p.getZ()), 1e-12, "TC08: cube corner z must be ± 10");
            }
        }
    }

    /**
     * Test method for {@link SceneLoader#load(Path)}: real glass (ior, fresnel), textures (an image, a
     * checkerboard), an OBJ mesh with texture coordinates made smooth, and a mesh given in the file.
     */
    @Test
    void testLoadGlassTexturesAndSmoothMeshes() {
        TestFiles.writePng(FOLDER.resolve("textures"), "two.png", 2, 0xFF0000, 0x0000FF);
        TestFiles.write(FOLDER.resolve("models"), "quad.obj", """
                v 0 0 0
                v 1 0 0
                v 1 1 1
                v 0 1 1
                vt 0 0
                vt 1 0
                vt 1 1
                vt 0 1
                f 1/1 2/2 3/3 4/4
                """);
        Picture picture = SceneLoader.load(file("glass.xml", """
                <scene>
                  <geometries>
                    <sphere center="0 0 0" radius="10" kT="0.9" ior="1.5" fresnel="true">
                      <checker-texture color1="255 255 255" color2="0 0 0" size="0.125"/>
                    </sphere>
                    <plane q0="0 -10 0" normal="0 1 0" kD="0.5">
                      <image-texture file="textures/two.png" size="20"/>
                    </plane>
                    <mesh file="models/quad.obj" smooth="true" kD="0.4">
                      <image-texture file="textures/two.png"/>
                    </mesh>
                    <triangle-mesh vertices="0 0 0 1 0 0 0 1 0" triangles="0 1 2" normals="0 0 1 0 0 1 0 0 1"
                                   uvs="0 0 1 0 0 1"/>
                    <mesh file="models/quad.obj" smooth="false"/>
                  </geometries>
                </scene>
                """));
        List<Intersectable> bodies = bodies(picture);
        // ===== Equivalence Partitions Tests =====
        // TC01: the sphere's glass: ior 1.5, Fresnel, and its checkerboard of 1/8
        Sphere sphere = (Sphere) bodies.get(0);
        assertEquals(1.5, sphere.getMaterial().getIor(), 0, "TC01: wrong ior");
        assertTrue(sphere.getMaterial().isFresnel(), "TC01: Fresnel must be on");
        CheckerTexture checker = assertInstanceOf(CheckerTexture.class, sphere.getTexture(), "TC01: a checkerboard");
        assertEquals(0.125, checker.getSize(), 0, "TC01: wrong checker size");
        // TC02: the plane's image, found beside the scene file, size 20; no ior, no Fresnel by default
        ImageTexture image = assertInstanceOf(ImageTexture.class, ((Plane) bodies.get(1)).getTexture(), "TC02: image");
        assertEquals(FOLDER.toAbsolutePath().resolve("textures/two.png"), image.getFile(), "TC02: wrong file");
        assertEquals(20, image.getSize(), 0, "TC02: wrong size");
        assertFalse(((Plane) bodies.get(1)).getMaterial().hasIor(), "TC02: no ior by default");
        // TC03: the OBJ quad with vt, smooth="true": UVs, and normals computed from its faces
        TriangleMesh quad = (TriangleMesh) bodies.get(2);
        assertTrue(quad.isSmooth(), "TC03: smooth=\"true\" must compute normals");
        assertEquals(8, quad.getUVs().length, "TC03: the file's texture coordinates");
        assertInstanceOf(ImageTexture.class, quad.getTexture(), "TC03: the mesh's texture");
        // TC04: the mesh given in the file, with its normals and UVs
        TriangleMesh given = (TriangleMesh) bodies.get(3);
        assertEquals(3, given.getVerticesCount(), "TC04: three vertices");
        assertTrue(given.isSmooth(), "TC04: the given normals");
        assertEquals(1, given.getUVs()[2], 0, "TC04: the given UVs");
        // ===== Boundary Values Tests =====
        // TC11: smooth="false" reads the mesh flat
        assertFalse(((TriangleMesh) bodies.get(4)).isSmooth(), "TC11: smooth=\"false\" is flat");
    }

    /** Writes a scene file of bodies, which start on its third line. */
    private static Path bodiesFile(String name, String bodies) {
        return file(name, "<scene>\n<geometries>\n" + bodies + "</geometries>\n</scene>\n");
    }

    /** Test method for {@link SceneLoader#load(Path)}: bad glass, textures and meshes, each at its line. */
    @Test
    void testBadGlassAndTextures() {
        TestFiles.write(FOLDER.resolve("models"), "plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        String checker = "<checker-texture color1=\"1 1 1\" color2=\"0 0 0\"/>\n";
        String triangle = "<triangle-mesh vertices=\"0 0 0 1 0 0 0 1 0\" ";
        // ===== Equivalence Partitions Tests =====
        // TC01: an ior below 1; TC02: Fresnel without an ior
        assertBadFile(bodiesFile("ior.xml", "<sphere center=\"0 0 0\" radius=\"1\" ior=\"0.5\"/>\n"), 3,
                "at least 1", "TC01");
        assertBadFile(bodiesFile("fresnel.xml", "<sphere center=\"0 0 0\" radius=\"1\" fresnel=\"true\"/>\n"), 3,
                "needs an index of refraction", "TC02");
        // TC03: a missing image, named with its path
        assertBadFile(bodiesFile("missing.xml", "<sphere center=\"0 0 0\" radius=\"1\">\n"
                + "<image-texture file=\"nowhere.png\"/>\n</sphere>\n"), 4, "nowhere.png", "TC03");
        // TC04: a texture on a mesh without texture coordinates; TC05: on a tube, which the schema refuses (a tube
        // may hold only a <transform>)
        assertBadFile(bodiesFile("no-uv.xml", "<mesh file=\"models/plain.obj\">\n" + checker + "</mesh>\n"), 3,
                "surface coordinates", "TC04");
        assertBadFile(bodiesFile("tube.xml", "<tube p0=\"0 0 0\" dir=\"0 1 0\" radius=\"1\">\n" + checker
                + "</tube>\n"), 4, "element <checker-texture> is unknown or not allowed here; expected one of: transform",
                "TC05");
        // TC06: a given mesh's normals of the wrong number
        assertBadFile(bodiesFile("normals.xml", triangle + "triangles=\"0 1 2\" normals=\"0 0 1\"/>\n"), 3,
                "9 numbers", "TC06");
        // ===== Boundary Values Tests =====
        // TC11: a checkerboard of size 0, and a negative triangle index
        assertBadFile(bodiesFile("size.xml", "<plane q0=\"0 0 0\" normal=\"0 1 0\">\n"
                + checker.replace("/>", " size=\"0\"/>") + "</plane>\n"), 4, "size", "TC11");
        assertBadFile(bodiesFile("index.xml", triangle + "triangles=\"0 1 -2\"/>\n"), 3, "triangles", "TC11");
    }

    /** Asserts that loading a bad file fails with one line naming the file, the line and the problem. */
    private static SceneFileException assertBadFile(Path file, int line, String problem, String tc) {
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneLoader.load(file), tc + ": must fail");
        assertEquals(file, e.getFile(), tc + ": wrong file");
        assertEquals(line, e.getLine(), tc + ": wrong line");
        assertMessage(e, problem, tc);
        String where = line == SceneFileException.UNKNOWN ? file + ": " : file + ":" + line + ":" + e.getColumn() + ": ";
        assertTrue(e.getMessage().startsWith(where), tc + ": message must start with " + where + ", got " + e.getMessage());
        assertFalse(e.getMessage().contains("\n"), tc + ": message must be one line");
        assertFalse(e.getMessage().contains("cvc-"), tc + ": no validator codes in " + e.getMessage());
        return e;
    }

    /** Test method for {@link SceneLoader#load(Path)}: glossy and blurry materials and the gloss grid. */
    @Test
    void testLoadGlossAndBlur() {
        Picture picture = SceneLoader.load(file("gloss.xml", """
                <scene>
                  <render gloss-rays="7"/>
                  <geometries>
                    <sphere center="0 0 0" radius="1" kR="0.8" kG="0.05"/>
                    <plane q0="0 -1 0" normal="0 1 0" kT="0.9" kB="0.2"/>
                    <sphere center="3 0 0" radius="1" kG="1" kB="0"/>
                  </geometries>
                </scene>
                """));
        List<Intersectable> bodies = bodies(picture);
        // ===== Equivalence Partitions Tests =====
        // TC01: the render's gloss-rays 7, the other settings the defaults
        assertEquals(RenderSettings.DEFAULT.withSqrtGlossRays(7), picture.settings(), "TC01: wrong settings");
        // TC02: a glossy mirror (kG 0.05) and blurry glass (kB 0.2)
        assertEquals(0.05, ((Geometry) bodies.get(0)).getMaterial().getKg(), 1e-15, "TC02: wrong kG");
        assertEquals(0, ((Geometry) bodies.get(0)).getMaterial().getKb(), 0, "TC02: kB must default to 0");
        assertEquals(0.2, ((Geometry) bodies.get(1)).getMaterial().getKb(), 1e-15, "TC02: wrong kB");
        assertEquals(0, ((Geometry) bodies.get(1)).getMaterial().getKg(), 0, "TC02: kG must default to 0");
        // TC03: without a render element the gloss grid is the default 5
        Picture plain = SceneLoader.load(file("no-gloss.xml", "<scene/>"));
        assertEquals(5, plain.settings().sqrtGlossRays(), "TC03: the default gloss-rays must be 5");

        // ===== Boundary Values Tests =====
        // TC11: kG 1 (the largest spread) is read
        assertEquals(1, ((Geometry) bodies.get(2)).getMaterial().getKg(), 0, "TC11: kG 1 must be read");
        // TC12: kG just above 1 and a negative kB are errors at their element, naming the factor
        assertBadFile(file("big-kg.xml", "<scene>\n<geometries>\n<sphere center=\"0 0 0\" radius=\"1\" kG=\"1.5\"/>\n"
                + "</geometries>\n</scene>\n"), 3, "kG (glossiness) must be at most 1", "TC12");
        assertBadFile(file("negative-kb.xml", "<scene>\n<geometries>\n<sphere center=\"0 0 0\" radius=\"1\""
                + " kB=\"-0.1\"/>\n</geometries>\n</scene>\n"), 3, "kB (blurriness) must not be negative", "TC12");
        // TC13: gloss-rays 0 and 1001 are errors naming the attribute
        assertBadFile(file("gloss-rays-0.xml", "<scene>\n<render gloss-rays=\"0\"/>\n</scene>\n"), 2, "gloss-rays",
                "TC13");
        assertBadFile(file("gloss-rays-1001.xml", "<scene>\n<render gloss-rays=\"1001\"/>\n</scene>\n"), 2,
                "attribute 'gloss-rays' must be between 1 and 1000", "TC13");
    }

    /** Test method for {@link SceneLoader#load(Path)}: each kind of bad file gives its one-line message. */
    @Test
    void testBadFiles() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a missing file: no position
        assertBadFile(FOLDER.resolve("no-such-scene.xml"), SceneFileException.UNKNOWN, "no such scene file", "TC01");
        // TC02: malformed XML: the unclosed <sphere> is found at line 3
        assertBadFile(file("malformed.xml", "<scene>\n<geometries>\n<sphere center=\"0 0 0\" radius=\"1\">\n</geometries>\n</scene>\n"),
                4, "must be terminated by the matching end-tag", "TC02");
        // TC03: an unknown element, with the elements allowed there
        assertBadFile(file("unknown-element.xml", "<scene>\n<geometries>\n<cube center=\"0 0 0\"/>\n</geometries>\n</scene>\n"),
                3, "element <cube> is unknown or not allowed here; expected one of: sphere, triangle", "TC03");
        // TC04: an unknown attribute
        assertBadFile(file("unknown-attribute.xml", "<scene>\n<geometries>\n<sphere center=\"0 0 0\" radius=\"1\" colour=\"1 2 3\"/>\n</geometries>\n</scene>\n"),
                3, "unknown attribute 'colour' on <sphere>", "TC04");
        // TC05: a bad number
        assertBadFile(file("bad-number.xml", "<scene>\n<geometries>\n<sphere center=\"0 0 0\" radius=\"5x\"/>\n</geometries>\n</scene>\n"),
                3, "attribute 'radius' of <sphere> must be a number, got '5x'", "TC05");
        // TC06: a zero vector
        SceneFileException zero = assertBadFile(file("zero-vector.xml", "<scene>\n  <camera vTo=\"0 0 0\"/>\n</scene>\n"),
                2, "<camera>: zero vector", "TC06");
        assertInstanceOf(IllegalArgumentException.class, zero.getCause(), "TC06: the library's exception is the cause");
        // TC07: a concave polygon
        assertBadFile(file("concave.xml", "<scene>\n<geometries>\n<polygon vertices=\"0 0 0  4 0 0  1 1 0  0 4 0\"/>\n</geometries>\n</scene>\n"),
                3, "<polygon>: polygon is not convex", "TC07");
        // TC08: a missing OBJ file
        assertBadFile(file("missing-obj.xml", "<scene>\n<geometries>\n\n<mesh file=\"nothere.obj\"/>\n</geometries>\n</scene>\n"),
                4, "<mesh>: OBJ file not found", "TC08");
        // TC09: a missing attribute
        assertBadFile(file("missing-attribute.xml", "<scene>\n<geometries>\n<sphere center=\"0 0 0\"/>\n</geometries>\n</scene>\n"),
                3, "<sphere> needs the attribute 'radius'", "TC09");
        // TC10: two numbers where a point needs three
        assertBadFile(file("two-numbers.xml", "<scene>\n<lights>\n<point-light color=\"1 1 1\" position=\"0 0\"/>\n</lights>\n</scene>\n"),
                3, "attribute 'position' of <point-light> must be three numbers, got '0 0'", "TC10");
        // TC11: a value the library refuses (negative radius) and one the schema refuses (beams 0)
        assertBadFile(file("negative-radius.xml", "<scene><geometries><sphere center=\"0 0 0\" radius=\"-1\"/></geometries></scene>"),
                1, "<sphere>: sphere radius must be positive", "TC11");
        assertBadFile(file("zero-beams.xml", "<scene><render beams=\"0\"/></scene>"),
                1, "attribute 'beams' of <render> must be a whole number, 1 or more, got '0'", "TC11");
        // TC12: U without V
        assertBadFile(file("u-without-v.xml", "<scene><lights><spot-light color=\"1 1 1\" position=\"0 0 0\" direction=\"0 0 -1\" u=\"1 0 0\"/></lights></scene>"),
                1, "<spot-light>: give both u and v, or neither", "TC12");
        // TC13: U and V not orthogonal
        assertBadFile(file("u-v-skew.xml", "<scene><lights><point-light color=\"1 1 1\" position=\"0 0 0\" u=\"1 0 0\" v=\"1 1 0\"/></lights></scene>"),
                1, "orthogonal", "TC13");
        // TC14: a polygon's numbers not in threes
        assertBadFile(file("vertices.xml", "<scene><geometries><polygon vertices=\"0 0 0 1 0 0 0 1 0 5\"/></geometries></scene>"),
                1, "vertices need three numbers (x y z) each, got 10 numbers", "TC14");
        // TC15: another root element, a namespace, text inside an element, a DOCTYPE
        assertBadFile(file("root.xml", "<scena/>"), 1, "the root element must be <scene>, not <scena>", "TC15");
        assertBadFile(file("namespace.xml", "<scene xmlns=\"http://example.com/x\"/>"), 1, "<scene> must not have a namespace", "TC15");
        assertBadFile(file("text.xml", "<scene><geometries>sphere</geometries></scene>"), 1, "<geometries> must not contain text", "TC15");
        assertBadFile(file("doctype.xml", "<!DOCTYPE scene [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>\n<scene name=\"&x;\"/>"),
                1, "a scene file must not have a DOCTYPE", "TC15");
        // TC16: a second <camera>
        assertBadFile(file("two-cameras.xml", "<scene>\n<camera/>\n<camera/>\n</scene>"), 3,
                "<scene> may have only one <camera>", "TC16");
        // TC17: a boolean that is not true or false
        assertBadFile(file("flag.xml", "<scene><render soft-shadows=\"yes\"/></scene>"),
                1, "attribute 'soft-shadows' of <render> must be true or false, got 'yes'", "TC17");
        // TC18: a misspelt attribute names the nearest valid one
        assertBadFile(file("kd.xml", "<scene>\n<geometries>\n<plane q0=\"0 0 0\" normal=\"0 1 0\" kd=\"0.5\"/>\n"
                + "</geometries>\n</scene>\n"), 3, "unknown attribute 'kd' on <plane>; did you mean 'kD'?", "TC18");
        // ===== Boundary Values Tests =====
        // TC21: an empty file
        assertBadFile(file("empty.xml", ""), 1, "Premature end of file", "TC21");
        // TC22: a folder instead of a file
        assertBadFile(FOLDER, SceneFileException.UNKNOWN, "is a folder, not a scene file", "TC22");
        // TC23: a number too large for a double
        assertBadFile(file("huge.xml", "<scene><geometries><sphere center=\"0 0 1e400\" radius=\"1\"/></geometries></scene>"),
                1, "too large", "TC23");
        // TC24: null
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SceneLoader.load(null),
                "TC24: null must be refused");
        assertMessage(e, "scene file", "TC24");        // TC25: numbers that parse but overflow the render: refused at the element's line
        assertBadFile(file("vp-width.xml", "<scene>\n<camera vp-width=\"1e308\"/>\n</scene>"), 2,
                "<camera>: attribute 'vp-width' is too large (1.0E308)", "TC25");
        assertBadFile(file("vp-distance.xml", "<scene>\n\n<camera vp-distance=\"1e308\"/>\n</scene>"), 3,
                "<camera>: attribute 'vp-distance' is too large", "TC25");
        assertBadFile(file("kS.xml", "<scene><geometries>\n<sphere center=\"0 0 0\" radius=\"1\" kS=\"1e308\"/>"
                + "</geometries></scene>"), 2, "<sphere>: attribute 'kS' is too large", "TC25");
        assertBadFile(file("kQ.xml", "<scene><lights>\n<point-light color=\"1 1 1\" position=\"0 0 0\" "
                + "kQ=\"1.7976931348623157e308\"/></lights></scene>"), 2, "<point-light>: attribute 'kQ' is too large",
                "TC25");
        // TC26: a light whose kC, kL and kQ are all 0
        assertBadFile(file("no-attenuation.xml", "<scene><lights>\n<point-light color=\"1 1 1\" position=\"0 0 0\" "
                + "kC=\"0\" kL=\"0\" kQ=\"0\"/></lights></scene>"), 2, "<point-light>: light attenuation", "TC26");
        // TC27: sample grids past the bound, named by their attributes
        assertBadFile(file("beams.xml", "<scene>\n<render beams=\"46341\"/>\n</scene>"), 2,
                "<render>: attribute 'beams' must be between 1 and 1000, got 46341", "TC27");
        assertBadFile(file("aa.xml", "<scene>\n<render anti-aliasing=\"1001\"/>\n</scene>"), 2,
                "<render>: attribute 'anti-aliasing' must be between 1 and 1000, got 1001", "TC27");
        // TC28: an image too large to hold, at the <image>'s line
        assertBadFile(file("image.xml", "<scene>\n<image width=\"2147483647\" height=\"2\"/>\n</scene>"), 2,
                "<image>: image size 2147483647x2 is too large", "TC28");
    }

    /**
     * Test method for {@link SceneLoader#load(Path)}: a camera whose vUp is not orthogonal to vTo is
     * told the vUp it would take, which then loads.
     */
    @Test
    void testCameraUp() {
        // ===== Equivalence Partitions Tests =====
        // TC01: vUp "0 1 1" looking down -z: its part orthogonal to vTo is "0 1 0"
        assertBadFile(file("up-slanted.xml", "<scene>\n<camera vTo=\"0 0 -1\" vUp=\"0 1 1\"/>\n</scene>"), 2,
                "<camera>: vUp=\"0 1 1\" is not orthogonal to vTo=\"0 0 -1\"; use vUp=\"0 1 0\", its part orthogonal"
                        + " to vTo", "TC01");
        // TC02: a camera looking slightly down with vUp "0 1 0": "0 0.995 -0.0995", which loads
        assertBadFile(file("up-down.xml", "<scene>\n<camera vTo=\"0 -0.1 -1\" vUp=\"0 1 0\"/>\n</scene>"), 2,
                "use vUp=\"0 0.995 -0.0995\"", "TC02");
        Camera camera = SceneLoader.load(file("up-down-fixed.xml", "<scene><camera vTo=\"0 -0.1 -1\""
                + " vUp=\"0 0.995 -0.0995\"/></scene>")).camera();
        assertEquals(0, camera.getVTo().dotProduct(camera.getVUp()), 1e-10, "TC02: the vUp given must be orthogonal");
        // TC03: an oblique vTo "1 2 3": the vUp given has a few decimals, and loads
        SceneFileException e = assertBadFile(file("up-oblique.xml", "<scene>\n<camera vTo=\"1 2 3\" vUp=\"0 1 0\"/>"
                + "\n</scene>"), 2, "use vUp=\"-0.16903 0.84515 -0.50709\"", "TC03");
        assertInstanceOf(IllegalArgumentException.class, e.getCause(), "TC03: the camera's exception is the cause");
        assertEquals("camera", SceneLoader.load(file("up-oblique-fixed.xml", "<scene name=\"camera\"><camera"
                + " vTo=\"1 2 3\" vUp=\"-0.16903 0.84515 -0.50709\"/></scene>")).name(), "TC03: the vUp given must load");

        // ===== Boundary Values Tests =====
        // TC11: vUp parallel to vTo: no part of it is orthogonal; a vUp that is is named
        assertBadFile(file("up-parallel.xml", "<scene>\n<camera vTo=\"0 1 0\" vUp=\"0 2 0\"/>\n</scene>"), 2,
                "<camera>: vUp=\"0 2 0\" is not orthogonal to vTo=\"0 1 0\": it is parallel to vTo; use a vUp"
                        + " orthogonal to vTo, such as vUp=\"0 0 -1\"", "TC11");
        // TC12: a vUp off by 1e-5: the rounded vUp "0 1 0"
        assertBadFile(file("up-almost.xml", "<scene>\n<camera vTo=\"0 0 -1\" vUp=\"0 1 0.00001\"/>\n</scene>"), 2,
                "is not orthogonal to vTo=\"0 0 -1\"; use vUp=\"0 1 0\"", "TC12");
    }

    /** Test method for {@link SceneLoader#load(Path)}: extreme numbers that are meaningful are read. */
    @Test
    void testExtremeNumbers() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a plane normal (0, 1e-200, 0) is not a zero vector: the plane's normal is (0, 1, 0)
        Picture picture = SceneLoader.load(file("tiny-normal.xml",
                "<scene><geometries><plane q0=\"0 0 0\" normal=\"0 1e-200 0\"/></geometries></scene>"));
        Plane plane = assertInstanceOf(Plane.class, bodies(picture).get(0), "TC01: a plane expected");
        assertEquals(new Vector(0, 1, 0), plane.getNormal(), "TC01: wrong normal");
        // TC02: a light with kC 0 and kL 1 (no constant attenuation) is read
        picture = SceneLoader.load(file("kC0.xml", "<scene><lights><point-light color=\"1 1 1\" position=\"0 0 0\" "
                + "kC=\"0\" kL=\"1\"/></lights></scene>"));
        assertEquals(0, ((PointLight) picture.scene().lights.get(0)).getKc(), 0, "TC02: kC must be 0");

        // ===== Boundary Values Tests =====
        // TC11: numbers of magnitude 1e100 (the largest) are read
        picture = SceneLoader.load(file("largest.xml", "<scene><camera vp-width=\"1e100\" vp-distance=\"1e100\"/>"
                + "<geometries><sphere center=\"0 0 -1e100\" radius=\"1e100\"/></geometries></scene>"));
        assertEquals(1e100, picture.camera().getWidth(), 0, "TC11: wrong view plane width");
    }

    /** Test method for {@link SceneLoader#load(Path)}: a loaded body is a real {@link Geometry} of the library. */
    @Test
    void testLoadedBodiesIntersect() {
        Picture picture = SceneLoader.load(file("intersect.xml",
                "<scene><geometries><sphere center=\"0 0 -100\" radius=\"50\"/></geometries></scene>"));
        Geometry sphere = (Geometry) bodies(picture).get(0);
        // ===== Equivalence Partitions Tests =====
        // TC01: a ray from the origin down -z meets the sphere at z = -50 and z = -150
        List<Point3D> points = sphere.findIntersections(new primitives.Ray(Point3D.ZERO, new Vector(0, 0, -1)));
        assertEquals(List.of(new Point3D(0, 0, -50), new Point3D(0, 0, -150)), points, "TC01: wrong intersections");
    }

    /** Test method for {@link SceneLoader#load(Path)}: every example file in {@code scenes/} loads. */
    @Test
    void testExampleScenesLoad() throws IOException {
        List<Path> files;
        try (var listing = Files.list(Path.of("scenes"))) {
            files = listing.filter(f -> f.toString().endsWith(".xml")).sorted().toList();
        }
        // ===== Equivalence Partitions Tests =====
        // TC01: the gallery's 17 pictures and the OBJ example at least, each with bodies and named after its file
        assertTrue(files.size() >= 18, "TC01: expected the gallery's scenes and the OBJ example, got " + files);
        for (Path file : files) {
            Picture picture = SceneLoader.load(file);
            assertFalse(bodies(picture).isEmpty(), "TC01: " + file + " has no bodies");
            assertEquals(file.getFileName().toString().replace(".xml", ""), picture.name(),
                    "TC01: " + file + " must be named after its file");
        }
        // TC02: the OBJ example: a plane, two cubes of 12 triangles each and a sphere
        List<Intersectable> bodies = bodies(SceneLoader.load(Path.of("scenes", "cubesOnFloor.xml")));
        assertEquals(4, bodies.size(), "TC02: wrong number of bodies");
        assertEquals(12, ((TriangleMesh) bodies.get(1)).getTrianglesCount(), "TC02: a cube is 12 triangles");
    }
}
