package scenefile;

import java.nio.file.Path;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.function.Supplier;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Instance;
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
import primitives.FileNames;
import primitives.ImageTexture;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;
import renderer.JitteredGrid;
import scene.Scene;

import static primitives.Util.requireNonNull;

/**
 * Loads a scene file — XML checked against the scene schema {@code scenefile/scene.xsd} — into a
 * {@link Picture}: the scene, its camera, the image's size and the render settings.
 *
 * <pre>{@code
 * Picture picture = SceneLoader.load(Path.of("scenes/sphereOnTriangles.xml"));
 * picture.render(picture.newRender(Path.of("out.png")));
 * }</pre>
 *
 * Every problem with a file — missing, not well-formed, an unknown element or attribute, a bad
 * number, a body the library refuses (a zero vector, a concave polygon), a missing OBJ file — is a
 * {@link SceneFileException} whose one-line message names the file, the line and the column.
 */
public final class SceneLoader {
    /** The image's width and height when a file gives no {@code <image>} (the schema's defaults). */
    private static final int IMAGE_SIZE = 500;

    private SceneLoader() {
    }

    /**
     * Loads a scene file.
     *
     * @param file the scene file; OBJ files it names are found relative to its folder
     * @return the picture the file describes
     * @throws SceneFileException when the file cannot be read or does not describe a valid scene
     */
    public static Picture load(Path file) {
        return loadAnimation(file).at(0);
    }

    /**
     * Loads a scene file whose bodies and camera may move: its pictures at the times of an animation.
     *
     * @param file the scene file; OBJ files it names are found relative to its folder
     * @return the scene at any time of the animation's run
     * @throws SceneFileException when the file cannot be read or does not describe a valid scene (some
     *                            problems, such as a zero scale, only when a picture is asked for)
     */
    public static AnimatedScene loadAnimation(Path file) {
        requireNonNull(file, "scene file");
        SceneElement root = SceneParser.parse(file);
        return build(root, () -> new AnimatedScene(root, file));
    }

    /**
     * The picture a scene file describes at a time of its animation.
     *
     * @param root  the file's root element
     * @param file  the file
     * @param time  the time in the run, 0 for the still picture
     * @param names the file's named bodies
     * @param still the bodies, before their transforms, of the elements whose parts do not move, built at an
     *              earlier time; bodies built now are added
     * @return the picture
     * @throws SceneFileException when the file does not describe a valid scene
     */
    static Picture picture(SceneElement root, Path file, double time, NamedBodies names,
                           Map<SceneElement, Intersectable> still) {
        Bodies bodies = new Bodies(file.toAbsolutePath().getParent(), time, names, still);
        return build(root, () -> picture(root, file, bodies));
    }

    private static Picture picture(SceneElement root, Path file, Bodies bodies) {
        String name = root.has("name") ? root.text("name") : baseName(file);
        Scene scene = new Scene(name).setBackground(root.color("background-color"));
        SceneElement ambient = root.child("ambient-light");
        if (ambient != null)
            scene.setAmbientLight(build(ambient,
                    () -> new AmbientLight(ambient.color("color"), ambient.number("kA"))));
        SceneElement lights = root.child("lights");
        if (lights != null)
            for (SceneElement light : lights.children())
                scene.lights.add(build(light, () -> light(light)));
        SceneElement library = root.child("library");
        if (library != null)
            for (SceneElement element : library.children())
                bodies.body(element);
        SceneElement geometries = root.child("geometries");
        if (geometries != null) {
            Intersectable all = bodies.body(geometries);
            scene.setGeometries(all instanceof Geometries group ? group : new Geometries(all));
        }
        SceneElement image = root.child("image");
        int nX = image == null ? IMAGE_SIZE : image.integer("width");
        int nY = image == null ? IMAGE_SIZE : image.integer("height");
        int grid = image == null ? 0 : image.integer("grid");
        SceneElement animation = root.child("animation");
        Transform orbit = animation == null ? null : build(animation, () -> Placement.orbit(animation, bodies.time));
        Camera camera = camera(root.child("camera"), orbit);
        RenderSettings settings = settings(root.child("render"));
        return build(image == null ? root : image, () -> new Picture(name, nX, nY, scene, camera, grid, settings));
    }

    private static String baseName(Path file) {
        String name = file.getFileName().toString();
        return name.endsWith(".xml") ? name.substring(0, name.length() - ".xml".length()) : name;
    }

    /** The camera of its element, or the default one, turned by the animation's orbit when there is one. */
    private static Camera camera(SceneElement camera, Transform orbit) {
        if (camera == null) { // the schema's defaults: the course's first camera
            Camera course = new Camera(Point3D.ZERO, new Vector(0, 0, -1), new Vector(0, 1, 0));
            return (orbit == null ? course : Placement.orbited(course, orbit)).setVpSize(500, 500).setVpDistance(100);
        }
        return build(camera, () -> {
            Camera placed = orbit == null ? frame(camera) : Placement.orbited(frame(camera), orbit);
            return lens(placed.setVpSize(camera.number("vp-width"), camera.number("vp-height"))
                    .setVpDistance(camera.number("vp-distance")), camera);
        });
    }

    /** The camera of its element's p0, vTo and vUp; a vUp not orthogonal to vTo is told what it would be. */
    private static Camera frame(SceneElement camera) {
        Vector vTo = camera.vector("vTo");
        Vector vUp = camera.vector("vUp");
        try {
            return new Camera(camera.point("p0"), vTo, vUp);
        } catch (IllegalArgumentException e) {
            String given = "vUp=\"" + triple(vUp) + "\" is not orthogonal to vTo=\"" + triple(vTo) + "\"";
            Vector up;
            try {
                up = Camera.orthogonalUp(vTo, vUp);
            } catch (IllegalArgumentException parallel) {
                throw camera.error(given + ": it is parallel to vTo; use a vUp orthogonal to vTo, such as vUp=\""
                        + triple(vTo.orthogonal()) + "\"", e);
            }
            throw camera.error(given + "; use vUp=\"" + triple(up) + "\", its part orthogonal to vTo", e);
        }
    }

    /** {@return a vector as a scene file writes it, "x y z"} */
    private static String triple(Vector v) {
        return SceneWriter.number(v.getX()) + " " + SceneWriter.number(v.getY()) + " " + SceneWriter.number(v.getZ());
    }

    /** Gives a camera the depth of field of its element. */
    private static Camera lens(Camera camera, SceneElement element) {
        camera.setApertureSize(element.number("aperture"))
                .setSqrtApertureRays(grid(element, "aperture-rays"));
        if (element.has("focal-distance"))
            camera.setFocalDistance(element.number("focal-distance"));
        return camera;
    }

    private static RenderSettings settings(SceneElement render) {
        if (render == null)
            return RenderSettings.DEFAULT;
        return build(render, () -> new RenderSettings(render.flag("soft-shadows"), render.flag("adaptive"),
                grid(render, "beams"), grid(render, "anti-aliasing"), render.longInteger("seed"),
                grid(render, "gloss-rays"), render.flag("adaptive-super-sampling")));
    }

    /** A sample grid's size, named by its attribute when it is out of bounds. */
    private static int grid(SceneElement element, String attribute) {
        return JitteredGrid.requireSqrtSamples(element.integer(attribute), "attribute '" + attribute + "'");
    }

    private static LightSource light(SceneElement light) {
        if (light.name().equals("directional-light"))
            return new DirectionalLight(light.color("color"), light.vector("direction"));
        PointLight point = light.name().equals("spot-light")
                ? new SpotLight(light.color("color"), light.point("position"), light.vector("direction"))
                .setNarrowBeam(light.number("narrow-beam"))
                : new PointLight(light.color("color"), light.point("position"));
        // kC last: a light without constant attenuation needs kL or kQ first (all three 0 are refused)
        point.setKl(light.number("kL")).setKq(light.number("kQ")).setKc(light.number("kC"))
                .setEdgesSize(light.number("edge"));
        if (light.has("u") != light.has("v"))
            throw light.error("give both u and v, or neither", null);
        if (light.has("u"))
            point.setUV(light.vector("u"), light.vector("v"));
        return point;
    }

    /**
     * Builds the bodies of a scene file at a time of its animation: each placed by its {@code <transform>}
     * (in an {@link Instance}), the named ones kept for the instances that follow them. A body whose parts
     * do not move is built once, at the first time asked for, and shared by the pictures of later times
     * (a mesh is read once); only its placement is made again.
     */
    private static final class Bodies {
        private final Path folder;
        private final double time;
        private final NamedBodies names;
        private final Map<SceneElement, Intersectable> still;
        /** The bodies built at this time, by element. */
        private final Map<SceneElement, Intersectable> built = new IdentityHashMap<>();

        Bodies(Path folder, double time, NamedBodies names, Map<SceneElement, Intersectable> still) {
            this.folder = folder;
            this.time = time;
            this.names = names;
            this.still = still;
        }

        /** The body of an element, placed by its transform; a problem is reported at the element's place. */
        Intersectable body(SceneElement element) {
            Intersectable body = build(element, () -> placed(inner(element), element));
            built.put(element, body);
            return body;
        }

        /** The body of an element before its transform: built once when its parts do not move. */
        private Intersectable inner(SceneElement element) {
            if (names.partsMove(element))
                return unplaced(element);
            Intersectable body = still.get(element);
            if (body == null) {
                body = unplaced(element);
                still.put(element, body);
            }
            return body;
        }

        private Intersectable unplaced(SceneElement element) {
            return switch (element.name()) {
                case "geometries" -> geometries(element);
                case "instance" -> instance(element);
                case "mesh" -> texture(surface(mesh(element, folder), element), element, folder);
                case "triangle-mesh" -> texture(surface(triangleMesh(element), element), element, folder);
                default -> texture(surface(shape(element), element), element, folder);
            };
        }

        private Geometries geometries(SceneElement group) {
            Geometries geometries = new Geometries();
            SceneElement transform = null;
            for (SceneElement element : group.children())
                if (!element.name().equals("transform"))
                    geometries.add(body(element));
                else if (transform == null)
                    transform = element;
                else
                    throw element.error("a group has one <transform> at most; the first is at line "
                            + transform.line(), null);
            return geometries;
        }

        /** The named body an instance places (the transform is its element's, as for any body). */
        private Intersectable instance(SceneElement instance) {
            SceneElement target = names.target(instance);
            Intersectable body = built.get(target);
            if (body == null && still.containsKey(target)) // a still body in a group built at an earlier time
                body = build(target, () -> placed(still.get(target), target));
            if (body == null)
                throw instance.error("the body named '" + instance.text("of") + "' is not built yet: an <instance>"
                        + " places a body of <library>, or one before it in <geometries> that does not hold it", null);
            return body;
        }

        /** The body placed by its element's {@code <transform>}, when it has one; an instance always is one. */
        private Intersectable placed(Intersectable body, SceneElement element) {
            SceneElement transform = element.child("transform");
            if (transform == null)
                return element.name().equals("instance") ? new Instance(body, Transform.IDENTITY) : body;
            return new Instance(body, build(transform, () -> Placement.transform(transform, time)));
        }
    }

    private static Geometry shape(SceneElement element) {
        return switch (element.name()) {
            case "sphere" -> new Sphere(element.point("center"), element.number("radius"));
            case "triangle" -> new Triangle(element.point("p0"), element.point("p1"), element.point("p2"));
            case "polygon" -> new Polygon(vertices(element));
            case "plane" -> new Plane(element.point("q0"), element.vector("normal"));
            case "tube" -> new Tube(axis(element), element.number("radius"));
            case "cylinder" -> new Cylinder(axis(element), element.number("radius"), element.number("height"));
            default -> throw element.error("not a body", null);
        };
    }

    private static Ray axis(SceneElement element) {
        return new Ray(element.point("p0"), element.vector("dir"));
    }

    private static Point3D[] vertices(SceneElement polygon) {
        double[] xyz = polygon.numbers("vertices");
        if (xyz.length % 3 != 0)
            throw polygon.error("vertices need three numbers (x y z) each, got " + xyz.length + " numbers", null);
        Point3D[] vertices = new Point3D[xyz.length / 3];
        for (int k = 0; k < vertices.length; ++k)
            vertices[k] = new Point3D(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
        return vertices;
    }

    private static TriangleMesh mesh(SceneElement mesh, Path folder) {
        ObjMesh.Normals normals = !mesh.has("smooth") ? ObjMesh.Normals.FILE
                : mesh.flag("smooth") ? ObjMesh.Normals.SMOOTH : ObjMesh.Normals.FLAT;
        Path file = folder.resolve(FileNames.toPath(mesh.text("file")));
        TriangleMesh triangles = ObjMesh.readMesh(file, mesh.number("scale"), mesh.point("position"), normals);
        Point3D farthest = Point3D.ZERO;
        for (int v = 0; v < triangles.getVerticesCount(); ++v) {
            Point3D vertex = triangles.getVertex(v);
            if (vertex.distanceSquared(Point3D.ZERO) > farthest.distanceSquared(Point3D.ZERO))
                farthest = vertex;
        }
        mesh.bounded(farthest.distance(Point3D.ZERO), "the distance of vertex " + farthest + " from the origin");
        return triangles;
    }

    /** A mesh given in the file: its vertices, triangles, and maybe normals and UVs. */
    private static TriangleMesh triangleMesh(SceneElement element) {
        double[] vertices = element.numbers("vertices");
        double[] indices = element.numbers("triangles");
        int[] triangles = new int[indices.length];
        for (int i = 0; i < indices.length; ++i)
            triangles[i] = (int) indices[i]; // whole numbers of the int range: the schema's type
        TriangleMesh mesh = new TriangleMesh(vertices, triangles);
        if (element.has("uvs"))
            mesh.setUVs(element.numbers("uvs"));
        if (element.has("normals"))
            mesh.setNormals(element.numbers("normals"));
        else if (element.flag("smooth"))
            mesh.smoothNormals();
        return mesh;
    }

    /** Gives a body the emission and material of its element. */
    private static Geometry surface(Geometry body, SceneElement element) {
        Material material = new Material().setKd(element.number("kD")).setKs(element.number("kS"))
                .setKt(element.number("kT")).setKr(element.number("kR"))
                .setKg(element.number("kG")).setKb(element.number("kB"))
                .setShininess(element.integer("nShininess"));
        if (element.has("ior"))
            material.setIor(element.number("ior"));
        if (element.flag("fresnel") && !material.hasIor())
            throw element.error("fresnel=\"true\" needs an index of refraction: give the attribute 'ior'", null);
        return body.setEmission(element.color("emission")).setMaterial(material.setFresnel(element.flag("fresnel")));
    }

    /** Gives a body the texture of its element's child, when it has one. */
    private static Geometry texture(Geometry body, SceneElement element, Path folder) {
        SceneElement image = element.child("image-texture");
        SceneElement checker = element.child("checker-texture");
        if (image != null)
            body.setTexture(build(image, () -> new ImageTexture(folder.resolve(FileNames.toPath(image.text("file"))),
                    image.number("size"))));
        else if (checker != null)
            body.setTexture(build(checker, () -> new CheckerTexture(checker.color("color1"), checker.color("color2"),
                    checker.number("size"))));
        return body;
    }

    /** Runs a step that reads an element; a problem it meets is reported at the element's place. */
    private static <T> T build(SceneElement element, Supplier<T> step) {
        try {
            return step.get();
        } catch (SceneFileException e) {
            throw e;
        } catch (IllegalArgumentException e) {
            throw element.error(e.getMessage(), e);
        }
    }
}
