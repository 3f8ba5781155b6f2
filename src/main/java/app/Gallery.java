package app;

import java.nio.file.Path;
import java.util.List;

import geometries.Geometries;
import geometries.Instance;
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
import primitives.CheckerTexture;
import primitives.Color;
import primitives.ImageTexture;
import primitives.Material;
import primitives.Point3D;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.Render;
import scene.Scene;
import scenefile.ObjMesh;
import scenefile.Picture;
import scenefile.RenderSettings;

/**
 * The example gallery: the course's classic pictures, built in Java.
 */
public final class Gallery {
    private static final Color BLUE = new Color(java.awt.Color.BLUE);
    private static final Color WHITE = new Color(java.awt.Color.WHITE);

    private Gallery() {
    }

    /** {@return every picture of the gallery} */
    public static List<Picture> pictures() {
        return List.of(twoColors(),
                lights("sphereDirectional", sphereScene(), sphereCamera(),
                        new DirectionalLight(new Color(500, 300, 0), new Vector(1, 1, -1))),
                lights("spherePoint", sphereScene(), sphereCamera(),
                        new PointLight(new Color(500, 300, 0), new Point3D(-50, -50, 50)).setKl(0.00001).setKq(0.000001)),
                lights("sphereSpot", sphereScene(), sphereCamera(),
                        new SpotLight(new Color(500, 300, 0), new Point3D(-50, -50, 50), new Vector(1, 1, -2))
                                .setKl(0.00001).setKq(0.00000001)),
                lights("sphereSpotSharp", sphereScene(), sphereCamera(),
                        new SpotLight(new Color(500, 300, 0), new Point3D(-50, -50, 50), new Vector(1, 1, -2))
                                .setNarrowBeam(10).setKl(0.00001).setKq(0.00000001)),
                lights("trianglesDirectional", trianglesScene(), trianglesCamera(),
                        new DirectionalLight(new Color(300, 150, 150), new Vector(0, 0, -1))),
                lights("trianglesPoint", trianglesScene(), trianglesCamera(),
                        new PointLight(new Color(500, 250, 250), new Point3D(10, -10, -130)).setKl(0.0005).setKq(0.0005)),
                lights("trianglesSpot", trianglesScene(), trianglesCamera(),
                        new SpotLight(new Color(500, 250, 250), new Point3D(10, -10, -130), new Vector(-2, -2, -1))
                                .setKl(0.0001).setKq(0.000005)),
                lights("trianglesSpotSharp", trianglesScene(), trianglesCamera(),
                        new SpotLight(new Color(800, 400, 400), new Point3D(10, -10, -130), new Vector(-2, -2, -1))
                                .setNarrowBeam(10).setKl(0.001).setKq(0.00004)),
                shadowSphereTriangle(),
                sphereOnTriangles(), sphereOnTriangles().withSoftShadows("softSphereOnTriangles"),
                eightElements(), eightElements().withSoftShadows("softEightElements"),
                twoSpheres(),
                twoSpheresOnMirrors(),
                trianglesTransparentSphere(),
                glossyFloorFrostedPane(),
                depthOfField(),
                adaptiveSuperSampling(),
                spotSmoothFlat(),
                glassSphereChecker(),
                fresnelPane(),
                instancedMeshes());
    }

    /**
     * Renders a picture into a folder.
     *
     * @param picture the picture
     * @param folder  the folder its PNG file goes to
     * @return the render, its image still in memory for a look at the pixels
     */
    public static Render render(Picture picture, Path folder) {
        return render(picture, folder, 0);
    }

    /**
     * Renders a picture into a folder on some threads.
     *
     * @param picture the picture
     * @param folder  the folder its PNG file goes to
     * @param threads the number of rendering threads, 0 for one per core
     * @return the render, its image still in memory for a look at the pixels
     * @throws IllegalArgumentException when the number of threads is negative
     */
    public static Render render(Picture picture, Path folder, int threads) {
        return picture.render(picture.newRender(folder.resolve(picture.name() + ImageWriter.EXTENSION))
                .setMultithreading(threads));
    }

    private static Camera frontCamera(double z, double vpSize) {
        return new Camera(new Point3D(0, 0, z), new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(vpSize, vpSize).setVpDistance(z);
    }

    /** The course's first picture: ambient light only, with a grid over it. */
    private static Picture twoColors() {
        Scene scene = new Scene("two colours")
                .setAmbientLight(new AmbientLight(new Color(255, 191, 191), 1))
                .setBackground(new Color(75, 127, 90));
        scene.geometries.add(new Sphere(new Point3D(0, 0, -100), 50),
                new Triangle(new Point3D(-100, 0, -100), new Point3D(0, 100, -100), new Point3D(-100, 100, -100)),
                new Triangle(new Point3D(100, 0, -100), new Point3D(0, 100, -100), new Point3D(100, 100, -100)),
                new Triangle(new Point3D(-100, 0, -100), new Point3D(0, -100, -100), new Point3D(-100, -100, -100)),
                new Triangle(new Point3D(100, 0, -100), new Point3D(0, -100, -100), new Point3D(100, -100, -100)));
        Camera camera = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpDistance(100).setVpSize(500, 500);
        return new Picture("baseRenderTwoColors", 1000, 1000, scene, camera, 100, RenderSettings.DEFAULT);
    }

    private static Picture lights(String name, Scene scene, Camera camera, LightSource light) {
        scene.lights.add(light);
        return new Picture(name, 500, 500, scene, camera);
    }

    private static Scene sphereScene() {
        Scene scene = new Scene("lights on a sphere");
        scene.geometries.add(new Sphere(new Point3D(0, 0, -50), 50)
                .setEmission(new Color(0, 0, 100))
                .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(100)));
        return scene;
    }

    private static Camera sphereCamera() {
        return frontCamera(1000, 150);
    }

    private static Scene trianglesScene() {
        Scene scene = new Scene("lights on triangles");
        Material material = new Material().setKd(0.5).setKs(0.5).setShininess(300);
        scene.geometries.add(
                new Triangle(new Point3D(-150, -150, -150), new Point3D(150, -150, -150), new Point3D(75, 75, -150))
                        .setMaterial(material),
                new Triangle(new Point3D(-150, -150, -150), new Point3D(-70, 70, -50), new Point3D(75, 75, -150))
                        .setMaterial(material));
        return scene;
    }

    private static Camera trianglesCamera() {
        return frontCamera(1000, 200);
    }

    /** A sphere casting a shadow on a small triangle hovering over it... and the triangle on it. */
    private static Picture shadowSphereTriangle() {
        Scene scene = new Scene("shadow: sphere and triangle");
        Material material = new Material().setKd(0.5).setKs(0.5).setShininess(30);
        scene.geometries.add(
                new Sphere(new Point3D(0, 0, -200), 60).setEmission(BLUE).setMaterial(material),
                new Triangle(new Point3D(-70, -40, 0), new Point3D(-40, -70, 0), new Point3D(-68, -68, -4))
                        .setEmission(BLUE).setMaterial(material));
        scene.lights.add(new SpotLight(new Color(400, 240, 0), new Point3D(-100, -100, 200), new Vector(1, 1, -3))
                .setKl(1E-5).setKq(1.5E-7));
        return new Picture("shadowSphereTriangle", 400, 400, scene, frontCamera(1000, 200));
    }

    /** The report's scene A: a sphere over two triangles, lit by a square spot light of edge 30. */
    private static Picture sphereOnTriangles() {
        Scene scene = new Scene("sphere on triangles").setAmbientLight(new AmbientLight(WHITE, 0.15));
        scene.geometries.add(reportFloor(new Material().setKs(0.8).setShininess(60)),
                new Sphere(new Point3D(0, 0, -115), 30).setEmission(BLUE)
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(30)));
        scene.lights.add(reportSquare(new SpotLight(new Color(700, 400, 400), new Point3D(40, 40, 115),
                new Vector(-1, -1, -4)).setKl(4E-4).setKq(2E-5), 30));
        return new Picture("sphereOnTriangles", 600, 600, scene, frontCamera(1000, 200));
    }

    /** The report's scene B: spheres and triangles, transparent and not, a mirror and three square lights. */
    private static Picture eightElements() {
        Scene scene = new Scene("eight elements").setAmbientLight(new AmbientLight(WHITE, 0.15));
        scene.geometries.add(reportFloor(new Material().setKd(0.5).setKs(0.5).setShininess(60)),
                new Sphere(new Point3D(-60, -50, -50), 30).setEmission(new Color(java.awt.Color.RED))
                        .setMaterial(new Material().setKd(0.3).setKs(0.3).setShininess(30).setKt(0.5)),
                new Sphere(new Point3D(10, -20, -100), 25).setEmission(new Color(java.awt.Color.GREEN))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(30).setKt(0.6)),
                new Sphere(new Point3D(-95, -90, -100), 20).setEmission(new Color(java.awt.Color.PINK))
                        .setMaterial(new Material().setKd(0.25).setKs(0.25).setShininess(20)),
                new Triangle(new Point3D(-70, -40, 0), new Point3D(-40, -70, 0), new Point3D(-68, -68, -4))
                        .setEmission(BLUE).setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(30).setKt(0.3)),
                new Triangle(new Point3D(-30, 0, 0), new Point3D(0, -30, 0), new Point3D(-38, -38, -4))
                        .setEmission(new Color(java.awt.Color.CYAN))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(30)),
                new Triangle(new Point3D(150, -150, -150), new Point3D(-150, 150, -150), new Point3D(80, 80, 300))
                        .setEmission(new Color(20, 20, 20)).setMaterial(new Material().setKr(1)));
        scene.lights.add(reportSquare(new SpotLight(new Color(700, 400, 400), new Point3D(60, 50, 0),
                new Vector(0, 0.2, -1)).setKl(4E-5).setKq(2E-7), 50));
        scene.lights.add(reportSquare(new PointLight(new Color(1000, 600, 0), new Point3D(-100, -100, 300))
                .setKl(4E-4).setKq(6E-5), 30));
        scene.lights.add(reportSquare(new SpotLight(new Color(1020, 400, 400), new Point3D(-75, -75, -15),
                new Vector(-1, -1, -4)).setKl(1E-5).setKq(5E-5), 40));
        return new Picture("eightElements", 600, 600, scene, frontCamera(1000, 250));
    }

    /** Gives a light the report's square: this edge, its sides along the camera's vRight and vUp. */
    private static PointLight reportSquare(PointLight light, double edges) {
        return light.setEdgesSize(edges).setUV(new Vector(1, 0, 0), new Vector(0, 1, 0));
    }

    /** The report's floor: two triangles sharing a diagonal, the seam the report's pictures show. */
    private static Geometries reportFloor(Material material) {
        Point3D corner = new Point3D(-150, -150, -115);
        Point3D farCorner = new Point3D(75, 75, -150);
        return new Geometries(
                new Triangle(corner, new Point3D(150, -150, -135), farCorner).setMaterial(material),
                new Triangle(corner, new Point3D(-70, 70, -140), farCorner).setMaterial(material));
    }

    /** A transparent sphere with a smaller one inside. */
    private static Picture twoSpheres() {
        Scene scene = new Scene("two spheres");
        scene.geometries.add(
                new Sphere(new Point3D(0, 0, -50), 50).setEmission(BLUE)
                        .setMaterial(new Material().setKd(0.4).setKs(0.3).setShininess(100).setKt(0.3)),
                new Sphere(new Point3D(0, 0, -50), 25).setEmission(new Color(java.awt.Color.RED))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(100)));
        scene.lights.add(new SpotLight(new Color(1000, 600, 0), new Point3D(-100, -100, 500), new Vector(-1, -1, -2))
                .setKl(0.0004).setKq(0.0000006));
        return new Picture("refractionTwoSpheres", 500, 500, scene, frontCamera(1000, 150));
    }

    /** Two spheres, one in the other, reflected in two mirrors. */
    private static Picture twoSpheresOnMirrors() {
        Scene scene = new Scene("two spheres on mirrors").setAmbientLight(new AmbientLight(WHITE, 0.1));
        scene.geometries.add(
                new Sphere(new Point3D(-950, -900, -1000), 400).setEmission(new Color(0, 0, 100))
                        .setMaterial(new Material().setKd(0.25).setKs(0.25).setShininess(20).setKt(0.5)),
                new Sphere(new Point3D(-950, -900, -1000), 200).setEmission(new Color(100, 20, 20))
                        .setMaterial(new Material().setKd(0.25).setKs(0.25).setShininess(20)),
                new Triangle(new Point3D(1500, -1500, -1500), new Point3D(-1500, 1500, -1500), new Point3D(670, 670, 3000))
                        .setEmission(new Color(20, 20, 20)).setMaterial(new Material().setKr(1)),
                new Triangle(new Point3D(1500, -1500, -1500), new Point3D(-1500, 1500, -1500), new Point3D(-1500, -1500, -2000))
                        .setEmission(new Color(20, 20, 20)).setMaterial(new Material().setKr(0.5)));
        scene.lights.add(new SpotLight(new Color(1020, 400, 400), new Point3D(-750, -750, -150), new Vector(-1, -1, -4))
                .setKl(0.00001).setKq(0.000005));
        return new Picture("reflectionTwoSpheresMirrored", 500, 500, scene, frontCamera(10000, 2500));
    }

    /**
     * Depth of field: a row of spheres receding over a chequered floor, the camera focused on the middle one
     * (aperture 8, 5 × 5 rays through it for each pixel).
     */
    private static Picture depthOfField() {
        Camera camera = new Camera(new Point3D(0, 40, 300), new Vector(0, -0.15, -1), new Vector(0, 1, -0.15))
                .setVpSize(240, 160).setVpDistance(300).setApertureSize(8).setFocalDistance(442)
                .setSqrtApertureRays(5);
        return new Picture("depthOfField", 480, 320, spheresOnChequers("depth of field", 7), camera);
    }

    /**
     * Adaptive super-sampling: chequers receding into the distance, where they alias worst, and spheres;
     * 8 × 8 anti-aliasing, sampled adaptively.
     */
    private static Picture adaptiveSuperSampling() {
        Camera camera = new Camera(new Point3D(0, 30, 400), new Vector(0, -0.1, -1), new Vector(0, 1, -0.1))
                .setVpSize(240, 160).setVpDistance(300);
        return new Picture("adaptiveSuperSampling", 480, 320, spheresOnChequers("adaptive super-sampling", 5),
                camera, 0, RenderSettings.DEFAULT.withAntiAliasing(8).withAdaptiveSuperSampling(true));
    }

    /**
     * A row of coloured spheres of radius 20 on a floor of light and dark square tiles at y = −30, 16 tiles
     * across and 40 deep, under a point light and a dim directional light.
     *
     * @param name    the scene's name
     * @param spheres how many spheres, 80 apart in depth from z = 100
     */
    private static Scene spheresOnChequers(String name, int spheres) {
        Scene scene = new Scene(name).setAmbientLight(new AmbientLight(WHITE, 0.08))
                .setBackground(new Color(20, 25, 45));
        Material light = new Material().setKd(0.7).setKs(0.2).setShininess(20);
        Material dark = new Material().setKd(0.08).setKs(0.2).setShininess(20);
        for (int row = 0; row < 40; ++row)
            for (int column = 0; column < 16; ++column) {
                double x = -320 + 40 * column;
                double z = 400 - 40 * row;
                scene.geometries.add(new Polygon(new Point3D(x, -30, z), new Point3D(x + 40, -30, z),
                        new Point3D(x + 40, -30, z - 40), new Point3D(x, -30, z - 40))
                        .setMaterial((row + column) % 2 == 0 ? light : dark));
            }
        Color[] colours = {new Color(200, 40, 40), new Color(220, 140, 30), new Color(200, 200, 40),
                new Color(40, 180, 60), new Color(40, 120, 220), new Color(110, 60, 200), new Color(200, 60, 160)};
        for (int k = 0; k < spheres; ++k)
            scene.geometries.add(new Sphere(new Point3D(50 - 17 * k, -10, 100 - 80 * k), 20)
                    .setEmission(colours[k % colours.length].scale(0.35))
                    .setMaterial(new Material().setKd(0.4).setKs(0.4).setShininess(60)));
        scene.lights.add(new PointLight(new Color(500, 480, 440), new Point3D(-250, 250, 150)).setKl(1E-3)
                .setKq(2E-6));
        scene.lights.add(new DirectionalLight(new Color(50, 50, 70), new Vector(1, -1, -1)));
        return scene;
    }

    /** Two triangles under a transparent sphere: the sphere's shadow is light. */
    private static Picture trianglesTransparentSphere() {
        Scene scene = new Scene("triangles and a transparent sphere").setAmbientLight(new AmbientLight(WHITE, 0.15));
        scene.geometries.add(reportFloor(new Material().setKs(0.8).setShininess(60)),
                new Sphere(new Point3D(60, 50, -50), 30).setEmission(BLUE)
                        .setMaterial(new Material().setKd(0.2).setKs(0.2).setShininess(30).setKt(0.6)));
        scene.lights.add(new SpotLight(new Color(700, 400, 400), new Point3D(60, 50, 0), new Vector(0, 0, -1))
                .setKl(4E-5).setKq(2E-7));
        return new Picture("refractionShadow", 600, 600, scene, frontCamera(1000, 200));
    }

    /**
     * Glossy reflection and blurry transparency: spheres on a glossy floor (kG 0.03) in front of a
     * brushed-metal mirror (kG 0.02), and a frosted glass pane (kB 0.04) in front of an orange sphere,
     * under a square light with soft shadows.
     */
    private static Picture glossyFloorFrostedPane() {
        Scene scene = new Scene("glossy floor and frosted pane").setBackground(new Color(25, 32, 50))
                .setAmbientLight(new AmbientLight(WHITE, 0.1));
        Material shiny = new Material().setKd(0.5).setKs(0.6).setShininess(80);
        scene.geometries.add(
                new Plane(new Point3D(0, -50, 0), new Vector(0, 1, 0)).setEmission(new Color(20, 16, 14))
                        .setMaterial(new Material().setKd(0.2).setKs(0.3).setShininess(40).setKr(0.6).setKg(0.03)),
                new Polygon(new Point3D(-230, -50, -300), new Point3D(-10, -50, -300), new Point3D(-10, 100, -300),
                        new Point3D(-230, 100, -300)).setEmission(new Color(6, 6, 8))
                        .setMaterial(new Material().setKd(0.05).setKs(0.3).setShininess(100).setKr(0.85)
                                .setKg(0.02)),
                new Sphere(new Point3D(-95, -15, -120), 35).setEmission(new Color(20, 60, 170)).setMaterial(shiny),
                new Sphere(new Point3D(-10, -30, -20), 20).setEmission(new Color(30, 120, 60)).setMaterial(shiny),
                new Sphere(new Point3D(105, -10, -190), 40).setEmission(new Color(200, 80, 10)).setMaterial(shiny),
                new Polygon(new Point3D(40, -50, -80), new Point3D(170, -50, -80), new Point3D(170, 70, -80),
                        new Point3D(40, 70, -80)).setEmission(new Color(10, 12, 14))
                        .setMaterial(new Material().setKd(0.05).setKs(0.5).setShininess(150).setKt(0.85)
                                .setKb(0.04)));
        scene.lights.add(new PointLight(new Color(700, 650, 600), new Point3D(60, 250, 150)).setKl(0.0008)
                .setKq(0.000004).setEdgesSize(60).setUV(new Vector(1, 0, 0), new Vector(0, 0, 1)));
        Camera camera = new Camera(new Point3D(0, 60, 650), new Vector(0, -0.12, -1), new Vector(0, 1, -0.12))
                .setVpSize(300, 200).setVpDistance(500);
        return new Picture("glossyFloorFrostedPane", 600, 400, scene, camera, 0,
                RenderSettings.DEFAULT.withSoftShadows(true).withSqrtBeamNum(4));
    }

    /** The folder of the public-domain model Spot (Keenan Crane): its OBJ file and its texture. */
    private static final Path SPOT = Path.of("scenes", "models", "spot");

    /**
     * Smooth shading and textures: Spot, the cow, read with its texture coordinates and its texture,
     * twice: flat (left, every triangle one shade) and smooth (right, normals computed from its faces).
     */
    private static Picture spotSmoothFlat() {
        Scene scene = new Scene("smooth and flat Spot").setBackground(new Color(30, 36, 52))
                .setAmbientLight(new AmbientLight(WHITE, 0.08));
        ImageTexture texture = new ImageTexture(SPOT.resolve("spot_texture.png"));
        Material matte = new Material().setKd(0.75).setKs(0.15).setShininess(30);
        for (ObjMesh.Normals normals : new ObjMesh.Normals[] { ObjMesh.Normals.FLAT, ObjMesh.Normals.SMOOTH })
            scene.geometries.add(ObjMesh.readMesh(SPOT.resolve("spot_triangulated.obj"), 60,
                    normals == ObjMesh.Normals.FLAT ? new Point3D(34, 0, 25) : new Point3D(-34, 0, -25), normals)
                    .setEmission(new Color(40, 40, 40)).setMaterial(matte).setTexture(texture));
        scene.geometries.add(new Plane(new Point3D(0, -44.3, 0), new Vector(0, 1, 0)).setEmission(new Color(20, 20, 24))
                .setMaterial(new Material().setKd(0.5)));
        scene.lights.add(new PointLight(new Color(600, 580, 540), new Point3D(260, 280, -60)).setKl(0.0005)
                .setKq(0.000001));
        // from the front right, looking at the cows' heads (Spot faces −z)
        Camera camera = new Camera(new Point3D(210, 80, -290), new Vector(-0.6, -0.2, 0.8), new Vector(-0.12, 1, 0.16))
                .setVpSize(180, 120).setVpDistance(360);
        return new Picture("spotSmoothFlat", 600, 400, scene, camera);
    }

    /**
     * Real glass: a glass sphere of ior 1.5 on a checkerboard floor; through it, as through a lens, the
     * floor shows upside down.
     */
    private static Picture glassSphereChecker() {
        Scene scene = new Scene("glass sphere on chequers").setBackground(new Color(60, 80, 120));
        scene.geometries.add(chequeredFloor(-40),
                new Sphere(new Point3D(0, 0, 0), 40).setMaterial(new Material().setKt(0.95).setKs(0.6)
                        .setShininess(300).setIor(1.5)));
        scene.lights.add(new PointLight(new Color(500, 490, 470), new Point3D(-150, 250, 200)).setKl(0.0008));
        Camera camera = new Camera(new Point3D(0, 60, 330), new Vector(0, -0.2, -1), new Vector(0, 1, -0.2))
                .setVpSize(180, 120).setVpDistance(330);
        return new Picture("glassSphereChecker", 600, 400, scene, camera);
    }

    /**
     * Fresnel: a glass pane (ior 1.5, Schlick's split of its transparency) seen along its length. Near the
     * camera the view meets it steeply and sees through it, to the red sphere behind; far off it meets it
     * at grazing angles and the pane mirrors the blue sphere in front of it.
     */
    private static Picture fresnelPane() {
        Scene scene = new Scene("Fresnel pane").setBackground(new Color(60, 80, 120));
        Material glass = new Material().setKt(1).setKs(0.5).setShininess(200).setIor(1.5).setFresnel(true);
        double x0 = -20;
        double x1 = -16;
        Point3D[] low = { new Point3D(x0, -40, 250), new Point3D(x1, -40, 250), new Point3D(x1, -40, -450),
                new Point3D(x0, -40, -450) };
        Point3D[] high = { new Point3D(x0, 60, 250), new Point3D(x1, 60, 250), new Point3D(x1, 60, -450),
                new Point3D(x0, 60, -450) };
        scene.geometries.add(chequeredFloor(-40),
                // the pane's six faces, each counter-clockwise seen from outside
                new Polygon(low[3], low[2], low[1], low[0]).setMaterial(glass),
                new Polygon(high[0], high[1], high[2], high[3]).setMaterial(glass),
                new Polygon(low[0], low[1], high[1], high[0]).setMaterial(glass),
                new Polygon(low[2], low[3], high[3], high[2]).setMaterial(glass),
                new Polygon(low[1], low[2], high[2], high[1]).setMaterial(glass),
                new Polygon(low[3], low[0], high[0], high[3]).setMaterial(glass),
                new Sphere(new Point3D(-75, -15, 150), 25).setEmission(new Color(150, 30, 30))
                        .setMaterial(new Material().setKd(0.5).setKs(0.4).setShininess(60)),
                new Sphere(new Point3D(10, -10, -150), 30).setEmission(new Color(30, 50, 150))
                        .setMaterial(new Material().setKd(0.5).setKs(0.4).setShininess(60)));
        scene.lights.add(new PointLight(new Color(500, 490, 470), new Point3D(100, 250, 200)).setKl(0.0008));
        Camera camera = new Camera(new Point3D(60, 30, 300), new Vector(-0.5, -0.1, -1), new Vector(-0.04, 1, -0.08))
                .setVpSize(240, 160).setVpDistance(300);
        return new Picture("fresnelPane", 600, 400, scene, camera);
    }

    /**
     * Instances: Spot read once and placed five times by transforms (turned, scaled, one squashed),
     * every instance walking the one hierarchy the mesh keeps.
     */
    private static Picture instancedMeshes() {
        Scene scene = new Scene("instances of one mesh").setBackground(new Color(30, 36, 52))
                .setAmbientLight(new AmbientLight(WHITE, 0.08));
        TriangleMesh spot = ObjMesh.readMesh(SPOT.resolve("spot_triangulated.obj"), 1, Point3D.ZERO,
                ObjMesh.Normals.SMOOTH);
        spot.setEmission(new Color(40, 40, 40)).setMaterial(new Material().setKd(0.75).setKs(0.15).setShininess(30))
                .setTexture(new ImageTexture(SPOT.resolve("spot_texture.png")));
        double feet = spot.bounds()[1];
        double[][] placements = { // scale x, y, z, turn about y, then x and z on the floor
                { 24, 24, 24, 35, -62, 10 }, { 32, 32, 32, -25, 8, -60 }, { 17, 17, 17, 160, 58, 40 },
                { 28, 16, 28, 90, -8, 62 }, { 48, 48, 48, -65, 95, -190 } };
        for (double[] p : placements)
            scene.geometries.add(new Instance(spot, Transform.scale(p[0], p[1], p[2]).then(Transform.rotateY(p[3]))
                    .then(Transform.translate(new Vector(p[4], -40 - feet * p[1], p[5])))));
        scene.geometries.add(chequeredFloor(-40));
        scene.lights.add(new PointLight(new Color(600, 580, 540), new Point3D(-150, 250, 200)).setKl(0.0008));
        Camera camera = new Camera(new Point3D(0, 60, 330), new Vector(0, -0.2, -1), new Vector(0, 1, -0.2))
                .setVpSize(180, 120).setVpDistance(330);
        return new Picture("instancedMeshes", 600, 400, scene, camera);
    }

    /** A floor of light and dark squares of 20, a checkerboard texture on a plane at height y. */
    private static Plane chequeredFloor(double y) {
        return (Plane) new Plane(new Point3D(0, y, 0), new Vector(0, 1, 0)).setEmission(new Color(40, 40, 40))
                .setMaterial(new Material().setKd(0.7))
                .setTexture(new CheckerTexture(new Color(235, 230, 220), new Color(60, 60, 70), 20));
    }
}
