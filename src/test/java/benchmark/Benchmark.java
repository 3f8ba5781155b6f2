package benchmark;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import accel.BoundingVolumeHierarchy;
import geometries.Geometry;
import geometries.Instance;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.Render;
import scene.Scene;
import scenefile.ObjMesh;
import testutil.TestMeshes;

/**
 * The project's speed benchmark (docs/benchmarks.md). It renders the reference scenes: S (three spheres on a
 * floor, one square light of edge 20, soft shadows with 9 × 9 + 1 shadow rays, 800 × 800) and M (the
 * same with every sphere tessellated into a triangle mesh); at mesh scale G10k, G100k and G1M (a
 * bumpy {@link Terrain} of about 10k, 100k and 1M triangles, 400 × 400, a light of edge 60) and F2
 * (a forest of 20 × 60 small spheres, 400 × 400, the same light); for the picture improvements, scene S
 * at 400 × 400 seen through an aperture (SDOF: edge 20, focused on the origin, 3 × 3 aperture rays per
 * pixel), with 4 × 4 anti-aliasing (SAA), with it adaptive (SAAA), and with a glossy floor (SG: kR 0.5
 * and kG 0.05, 5 × 5 spread rays at each floor point); M1 (M's triangles as one mesh) and MS (as course-style
 * triangles); {@code obj:PATH}, an OBJ file's mesh standing on S's floor, and {@code inst:PATH}, the same
 * mesh placed by an {@link Instance} (scaled and moved) instead of built in place. Per scene it prints:
 * <ul>
 * <li>the bodies in the hierarchy, the seconds of building it (the median of {@value #BUILDS}
 * builds on the render's threads, outside any render), and the bytes per body of the scene and its
 * hierarchy: the heap in use after a full collection ({@link System#gc()}, read from the
 * {@link java.lang.management.MemoryMXBean}) once the scene and a hierarchy are built, less the heap
 * in use before, divided by the bodies (for the meshes, bytes per triangle);</li>
 * <li>the primary and shadow rays of a frame (and the share of the shadow rays whose bundle was
 * open: nothing could block them, so no body was tested; and of those whose bundle was blocked
 * whole by a closed opaque mesh, so no ray was tested), the seconds of the first frame (which
 * builds the render's hierarchy), the median seconds of the timed frames (warm: the hierarchy is
 * built once, not per frame), million shadow rays per second, and million rays (primary, shadow and
 * spread) per second;</li>
 * <li>the traced shadow rays of a frame (neither open nor blocked), the median CPU time of a frame (all
 * the process's threads, as the operating system counts it, in steps of 10 ms on Linux: on a shared
 * machine it counts the time the render ran, not the time it waited) and that time per traced ray,
 * an upper bound of a traced ray's cost, since it includes the primary rays and the shading; then
 * the time the threads spent tracing those rays alone (their packets and gathered tests, not the
 * gathers that sorted the bundles; elapsed time on each thread, summed), its share of the CPU time
 * and that time per traced ray;</li>
 * <li>with glossy or blurry surfaces, the spread rays of a frame.</li>
 * </ul>
 * <p>
 * Options: {@code --scene} a scene, several separated by commas, or {@code all} (the default: S and
 * M), {@code --frames N} timed frames (default 5), {@code --warmup N} untimed frames first (default
 * 10: on two cores the JIT's optimising compiler, which shares them with the rendering threads, took
 * 1 to 3.5 seconds after a scene started to settle, and a frame timed earlier is not warm),
 * {@code --threads N} (default 0, all cores). The last frame of each scene is written to
 * {@code target/benchmark/<scene>.png}.
 */
public final class Benchmark {
    /** The scenes, by name. */
    private static final List<String> SCENES = List.of("S", "M", "M1", "MS", "G10k", "G100k", "G1M", "F2", "SDOF",
            "SAA", "SAAA", "SG");
    /** The prefix of a real-mesh scene's name: the rest is the OBJ file's path. */
    private static final String OBJ_PREFIX = "obj:";
    /** The prefix of a real-mesh scene's name whose mesh is placed by an instance. */
    private static final String INSTANCE_PREFIX = "inst:";
    /** A real mesh's largest extent, in scene units: about half the view plane's 150. */
    private static final double OBJ_EXTENT = 75;
    /** The floor's height, which S's bodies and a real mesh stand on. */
    private static final double FLOOR_Y = -50;
    /** The light of the real-mesh scenes: its edge and its centre. */
    private static final double OBJ_LIGHT_EDGE = 40;
    private static final Point3D OBJ_LIGHT = new Point3D(-70, 100, 40);
    /** The width and height of the pictures of S and M, in pixels. */
    private static final int SIZE = 800;
    /** The width and height of the pictures of the terrains and the forest, in pixels. */
    private static final int SMALL_SIZE = 400;
    /** The bands from pole to pole of a sphere's mesh in scene M. */
    private static final int MESH_RINGS = 129;
    /** The slices around the axis of a sphere's mesh in scene M. */
    private static final int MESH_SEGMENTS = 128;
    /** The edge of the light's square in S and M, and in the terrains and the forest. */
    private static final double LIGHT_EDGE = 20;
    private static final double LARGE_LIGHT_EDGE = 60;
    /** The forest's trees along x and along z, their radius and the distance between them. */
    private static final int FOREST_COLUMNS = 20;
    private static final int FOREST_ROWS = 60;
    private static final double TREE_RADIUS = 3;
    private static final double TREE_SPACING = 10;
    /** The builds of the hierarchy timed per scene. */
    private static final int BUILDS = 3;
    /** Where the pictures go. */
    private static final Path OUTPUT = Path.of("target", "benchmark");
    /** SDOF's aperture: its edge, and the rays along each side of it. */
    private static final double APERTURE = 20;
    private static final int APERTURE_RAYS = 3;
    /** SAA's and SAAA's anti-aliasing: rays along each side of a pixel. */
    private static final int ANTI_ALIASING = 4;
    /** The centres and radii of S's spheres. */
    private static final Point3D[] CENTERS = { new Point3D(-40, -20, 0), new Point3D(30, -30, 20),
            new Point3D(5, -35, -50) };
    private static final double[] RADII = { 30, 20, 15 };
    /** The material of every body. */
    private static final Material DIFFUSE = new Material().setKd(0.8);
    /** The floor of scene SG: half diffuse, half a glossy mirror. */
    private static final Material GLOSSY_FLOOR = new Material().setKd(0.5).setKr(0.5).setKg(0.05);

    /** Not instantiable. */
    private Benchmark() {
    }

    /**
     * Runs the benchmark.
     *
     * @param args the options, see the class comment
     */
    public static void main(String[] args) {
        String sceneOption = "all";
        int frames = 5;
        int warmup = 10;
        int threads = 0;
        for (int a = 0; a < args.length; a += 2) {
            if (a + 1 >= args.length)
                usage("option " + args[a] + " needs a value");
            String value = args[a + 1];
            switch (args[a]) {
                case "--scene" -> sceneOption = value;
                case "--frames" -> frames = wholeNumber(value, 1);
                case "--warmup" -> warmup = wholeNumber(value, 0);
                case "--threads" -> threads = wholeNumber(value, 0);
                default -> usage("unknown option " + args[a]);
            }
        }
        List<String> scenes = sceneOption.equals("all") ? List.of("S", "M") : List.of(sceneOption.split(","));
        for (String name : scenes)
            if (!SCENES.contains(name) && objPath(name) == null)
                usage("--scene must be all, among " + String.join(", ", SCENES) + ", obj:PATH or inst:PATH, got "
                        + name);
        int threadsUsed = threads == 0 ? Runtime.getRuntime().availableProcessors() : threads;
        System.out.printf("JVM %s (%s), %d available processors, %d threads, %d warm-up + %d timed frames%n",
                Runtime.version(), System.getProperty("java.vm.name"), Runtime.getRuntime().availableProcessors(),
                threadsUsed, warmup, frames);
        for (String name : scenes) {
            if (objPath(name) != null && !Files.isReadable(objPath(name))) {
                System.out.printf("%s: skipped, no such file%n", name);
                continue;
            }
            run(name, frames, warmup, threadsUsed);
        }
    }

    /**
     * Builds one scene and its hierarchy and prints their line, then renders it: the warm-up frames,
     * then the timed ones, and prints its line.
     *
     * @param name    the scene's name
     * @param frames  the number of timed frames
     * @param warmup  the number of untimed frames first
     * @param threads the number of threads
     */
    private static void run(String name, int frames, int warmup, int threads) {
        long heapBefore = heapUsed();
        long making = System.nanoTime();
        Scene scene = buildScene(name);
        double made = (System.nanoTime() - making) / 1e9;
        double[] builds = new double[BUILDS];
        BoundingVolumeHierarchy bvh = null;
        for (int b = 0; b < BUILDS; ++b) {
            bvh = null; // the last hierarchy is collected while the next one is built
            long start = System.nanoTime();
            bvh = BoundingVolumeHierarchy.build(scene.geometries, threads);
            builds[b] = (System.nanoTime() - start) / 1e9;
        }
        long heapAfter = heapUsed();
        int bodies = bvh.getBoundedCount();
        System.out.printf("%s: scene made in %.3f s; %d bodies in the hierarchy (%d nodes), build median %.3f s"
                        + " (builds %s s), %.0f bytes per body (scene + hierarchy)%n", name, made, bodies,
                bvh.getNodesCount(), median(builds), format(builds), (double) (heapAfter - heapBefore) / bodies);
        bvh = null; // the render builds its own
        render(name, scene, frames, warmup, threads);
    }

    /**
     * Renders a scene: the warm-up frames, then the timed ones, and prints its line.
     *
     * @param name    the scene's name
     * @param scene   the scene
     * @param frames  the number of timed frames
     * @param warmup  the number of untimed frames first
     * @param threads the number of threads
     */
    private static void render(String name, Scene scene, int frames, int warmup, int threads) {
        Frame frame = new Frame(name, scene, threads);
        double first = 0;
        for (int f = 0; f < warmup; ++f) {
            double seconds = frame.timedRender();
            if (f == 0)
                first = seconds;
        }
        double[] seconds = new double[frames];
        double[] cpuSeconds = new double[frames];
        double[] tracingSeconds = new double[frames];
        long[] counts = null;
        for (int f = 0; f < frames; ++f) {
            long cpuStart = processCpuNanos();
            seconds[f] = frame.timedRender();
            cpuSeconds[f] = (processCpuNanos() - cpuStart) / 1e9;
            counts = frame.counts();
            tracingSeconds[f] = counts[5] / 1e9;
        }
        frame.render.writeToImage();
        if (warmup == 0)
            first = seconds[0];
        double median = median(seconds);
        long primary = counts[0];
        long shadow = counts[1];
        long open = counts[2];
        long blocked = counts[3];
        long spread = counts[4];
        long traced = shadow - open - blocked;
        System.out.printf("%s: %d pixels, %d primary rays/frame, %d shadow rays/frame (%.1f %% in open bundles,"
                        + " %.1f %% in blocked ones), first frame %.3f s (with the build), median %.3f s/frame (frames %s s),"
                        + " %.2f M shadow rays/s, %.2f M rays/s%n",
                name, frame.size * frame.size, primary, shadow, 100.0 * open / shadow, 100.0 * blocked / shadow, first,
                median, format(seconds), shadow / median / 1e6, (primary + shadow + spread) / median / 1e6);
        double cpu = median(cpuSeconds);
        double tracing = median(tracingSeconds);
        System.out.printf("%s: %d traced shadow rays/frame, median %.3f s of CPU time/frame, %.0f ns of it per"
                        + " traced shadow ray (shading and primary rays included); %.3f s/frame tracing them"
                        + " (%.0f %% of the CPU time), %.0f ns a ray%n",
                name, traced, cpu, cpu * 1e9 / traced, tracing, 100 * tracing / cpu, tracing * 1e9 / traced);
        if (spread > 0)
            System.out.printf("%s: %d spread rays/frame%n", name, spread);
    }

    /**
     * One scene's frames: its render and ray tracer, made once, or for the course-style scene MS anew
     * every frame (as a student's test makes them), and the counts of the last frame's rays.
     */
    private static final class Frame {
        private final String name;
        private final Scene scene;
        private final int threads;
        private final int size;
        private RayTracerBasic rayTracer;
        private Render render;
        private long[] before = new long[5];

        Frame(String name, Scene scene, int threads) {
            this.name = name;
            this.scene = scene;
            this.threads = threads;
            this.size = sizeOf(name);
            make();
        }

        /** Makes the render and its ray tracer. */
        private void make() {
            rayTracer = new RayTracerBasic(scene);
            Camera camera = new Camera(new Point3D(0, 0, 1000), new Vector(0, 0, -1), new Vector(0, 1, 0))
                    .setVpSize(150, 150).setVpDistance(1000);
            render = new Render().setImageWriter(new ImageWriter(outputName(name), size, size, OUTPUT))
                    .setCamera(camera).setRayTracer(rayTracer).setSoftShadows(true).setSqrtBeamNum(9)
                    .setMultithreading(threads);
            improve(name, camera, render);
        }

        /** {@return the seconds of rendering one frame (for MS, with a new render and ray tracer)} */
        double timedRender() {
            long start = System.nanoTime();
            if (name.equals("MS"))
                make();
            before = totals();
            render.renderImage();
            return (System.nanoTime() - start) / 1e9;
        }

        /** {@return the primary, shadow, open, blocked and spread rays of the last frame, and its bundles' tracing ns} */
        long[] counts() {
            long[] after = totals();
            for (int k = 0; k < after.length; ++k)
                after[k] -= before[k];
            return after;
        }

        private long[] totals() {
            return new long[] { rayTracer.getPrimaryRaysCount(), rayTracer.getShadowRaysCount(),
                    rayTracer.getOpenShadowRaysCount(), rayTracer.getBlockedShadowRaysCount(),
                    rayTracer.getSpreadRaysCount(), rayTracer.getBundleTracingNanos() };
        }
    }

    /** {@return the OBJ file of a real-mesh scene ({@code obj:PATH} or {@code inst:PATH}), or null for another} */
    private static Path objPath(String name) {
        for (String prefix : List.of(OBJ_PREFIX, INSTANCE_PREFIX))
            if (name.startsWith(prefix))
                return Path.of(name.substring(prefix.length()));
        return null;
    }

    /** {@return a file name for a scene's picture: a real mesh's is its OBJ file's name after its kind} */
    private static String outputName(String name) {
        Path obj = objPath(name);
        if (obj == null)
            return name;
        String kind = name.startsWith(OBJ_PREFIX) ? "obj-" : "inst-";
        return kind + obj.getFileName().toString().replaceFirst("\\.obj$", "");
    }

    /**
     * Gives the picture improvements' scenes their settings: an aperture, or anti-aliasing (adaptive or not).
     *
     * @param name   the scene's name
     * @param camera its camera
     * @param render its render
     */
    private static void improve(String name, Camera camera, Render render) {
        switch (name) {
            case "SDOF" -> camera.setApertureSize(APERTURE).setFocalDistance(1000).setSqrtApertureRays(APERTURE_RAYS);
            case "SAA" -> render.setAntiAliasing(ANTI_ALIASING);
            case "SAAA" -> render.setAntiAliasing(ANTI_ALIASING).setAdaptiveSuperSampling(true);
            default -> { } // the reference scenes as docs/benchmarks.md gives them
        }
    }

    /** {@return the heap in use after a full collection, in bytes} */
    private static long heapUsed() {
        for (int i = 0; i < 3; ++i)
            System.gc();
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }

    /**
     * The width and height of a scene's picture.
     *
     * @param name the scene's name
     * @return its size in pixels
     */
    private static int sizeOf(String name) {
        return name.equals("S") || name.startsWith("M") || objPath(name) != null ? SIZE : SMALL_SIZE;
    }

    /**
     * Builds a scene by its name.
     *
     * @param name one of {@link #SCENES}
     * @return the scene
     */
    static Scene buildScene(String name) {
        return switch (name) {
            case "S", "M", "SDOF", "SAA", "SAAA" -> buildScene(name.equals("M"));
            case "M1" -> oneMesh();
            case "MS" -> courseStyle();
            case "F2" -> forest();
            case "SG" -> glossyFloor();
            default -> objPath(name) != null ? realMesh(name) : terrain(name, Integer.parseInt(name.substring(1).replace("k", "000").replace("M", "000000")));
        };
    }

    /**
     * The floor and the light every scene has.
     *
     * @param name      the scene's name
     * @param lightEdge the edge of the light's square
     * @return the scene with them
     */
    private static Scene floorAndLight(String name, double lightEdge) {
        return floorAndLight(name, lightEdge, new Point3D(0, 100, 0));
    }

    /**
     * The floor, and a light of a given edge at a given centre.
     *
     * @param name      the scene's name
     * @param lightEdge the edge of the light's square
     * @param light     the light's centre
     * @return the scene with them
     */
    private static Scene floorAndLight(String name, double lightEdge, Point3D light) {
        Scene scene = new Scene(name);
        scene.geometries.add(new Plane(new Point3D(0, FLOOR_Y, 0), new Vector(0, 1, 0)).setMaterial(DIFFUSE));
        scene.lights.add(new PointLight(new Color(255, 255, 255), light)
                .setEdgesSize(lightEdge).setUV(new Vector(1, 0, 0), new Vector(0, 0, 1)));
        return scene;
    }

    /**
     * Builds scene G&lt;n&gt;: the terrain of about n triangles over the floor.
     *
     * @param name      the scene's name
     * @param triangles about how many triangles
     * @return the scene
     */
    private static Scene terrain(String name, int triangles) {
        Scene scene = floorAndLight(name, LARGE_LIGHT_EDGE);
        TriangleMesh mesh = Terrain.mesh(triangles);
        scene.geometries.add(mesh.setMaterial(DIFFUSE));
        System.out.printf("%s: a terrain of %d x %d cells, %d triangles%n", name, Terrain.cellsAlongX(triangles),
                Terrain.cellsAlongZ(triangles), mesh.getTrianglesCount());
        return scene;
    }

    /** {@return scene F2: 20 × 60 spheres of radius 3, 10 apart, on the floor} */
    private static Scene forest() {
        Scene scene = floorAndLight("F2", LARGE_LIGHT_EDGE);
        for (int i = 0; i < FOREST_COLUMNS; ++i)
            for (int k = 0; k < FOREST_ROWS; ++k)
                scene.geometries.add(new Sphere(new Point3D(-95 + TREE_SPACING * i, -37, 330 - TREE_SPACING * k),
                        TREE_RADIUS).setMaterial(DIFFUSE));
        return scene;
    }

    /** {@return scene M1: M's triangles as one mesh} */
    private static Scene oneMesh() {
        Scene scene = floorAndLight("M1", LIGHT_EDGE);
        TriangleMesh mesh = TestMeshes.merge(sphereMeshes().toArray(TriangleMesh[]::new));
        scene.geometries.add(mesh.setMaterial(DIFFUSE));
        System.out.printf("M1: M's %d triangles as one mesh%n", mesh.getTrianglesCount());
        return scene;
    }

    /** {@return scene MS: M's triangles as course-style {@link Triangle} objects} */
    private static Scene courseStyle() {
        Scene scene = floorAndLight("MS", LIGHT_EDGE);
        int triangles = 0;
        for (TriangleMesh mesh : sphereMeshes())
            for (Triangle triangle : mesh.getTriangles()) {
                scene.geometries.add(triangle.setMaterial(DIFFUSE));
                ++triangles;
            }
        System.out.printf("MS: M's %d triangles as Triangle objects, a new render and ray tracer per frame%n",
                triangles);
        return scene;
    }

    /**
     * Builds a real-mesh scene: an OBJ file's mesh standing on the floor, centred, its largest extent
     * {@value #OBJ_EXTENT}, under a light of edge {@value #OBJ_LIGHT_EDGE}: built in place, or for
     * {@value #INSTANCE_PREFIX}, the mesh as read placed by an instance that scales and moves it.
     *
     * @param name {@value #OBJ_PREFIX} or {@value #INSTANCE_PREFIX} and the file's path
     * @return the scene
     */
    private static Scene realMesh(String name) {
        Path file = objPath(name);
        TriangleMesh raw = ObjMesh.readMesh(file);
        double[] low = { Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY };
        double[] high = { Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY };
        for (int v = 0; v < raw.getVerticesCount(); ++v) {
            Point3D p = raw.getVertex(v);
            double[] xyz = { p.getX(), p.getY(), p.getZ() };
            for (int k = 0; k < 3; ++k) {
                low[k] = Math.min(low[k], xyz[k]);
                high[k] = Math.max(high[k], xyz[k]);
            }
        }
        double extent = Math.max(high[0] - low[0], Math.max(high[1] - low[1], high[2] - low[2]));
        double scale = OBJ_EXTENT / extent;
        Point3D position = new Point3D(-scale * (low[0] + high[0]) / 2, FLOOR_Y - scale * low[1],
                -scale * (low[2] + high[2]) / 2);
        Scene scene = floorAndLight(name, OBJ_LIGHT_EDGE, OBJ_LIGHT);
        TriangleMesh mesh = name.startsWith(INSTANCE_PREFIX) ? raw : ObjMesh.readMesh(file, scale, position);
        mesh.setMaterial(DIFFUSE);
        scene.geometries.add(name.startsWith(OBJ_PREFIX) ? mesh : new Instance(mesh,
                Transform.scale(scale).then(Transform.translate(new Vector(position.getX(), position.getY(),
                        position.getZ())))));
        System.out.printf("%s: %d triangles, scaled by %.4g%n", name, mesh.getTrianglesCount(), scale);
        return scene;
    }

    /** {@return scene SG: scene S with a glossy floor} */
    private static Scene glossyFloor() {
        Scene scene = buildScene(false);
        ((Geometry) scene.geometries.getGeometries().get(0)).setMaterial(GLOSSY_FLOOR);
        return scene;
    }

    /**
     * Builds scene S, or with meshes instead of spheres, scene M.
     *
     * @param meshes true for scene M
     * @return the scene
     */
    static Scene buildScene(boolean meshes) {
        Scene scene = floorAndLight(meshes ? "M" : "S", LIGHT_EDGE);
        int triangles = 0;
        if (meshes)
            for (TriangleMesh mesh : sphereMeshes()) {
                scene.geometries.add(mesh.setMaterial(DIFFUSE));
                triangles += mesh.getTrianglesCount();
            }
        else
            for (int s = 0; s < CENTERS.length; ++s)
                scene.geometries.add(new Sphere(CENTERS[s], RADII[s]).setMaterial(DIFFUSE));
        if (meshes)
            System.out.printf("M: %d spheres of %d rings x %d segments = %d triangles each, %d in all%n",
                    CENTERS.length, MESH_RINGS, MESH_SEGMENTS,
                    SphereMesh.trianglesCount(MESH_RINGS, MESH_SEGMENTS), triangles);
        return scene;
    }

    /** {@return M's three sphere meshes} */
    private static List<TriangleMesh> sphereMeshes() {
        List<TriangleMesh> meshes = new ArrayList<>();
        for (int s = 0; s < CENTERS.length; ++s)
            meshes.add(SphereMesh.mesh(CENTERS[s], RADII[s], MESH_RINGS, MESH_SEGMENTS));
        return meshes;
    }

    /** {@return the CPU time of this process so far, in ns, all its threads together} */
    private static long processCpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    /**
     * The median of some values.
     *
     * @param values the values, one or more
     * @return their median (the mean of the middle two when their number is even)
     */
    static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int mid = sorted.length / 2;
        return sorted.length % 2 == 1 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
    }

    /**
     * Formats seconds for the printed line.
     *
     * @param seconds the seconds of each frame
     * @return them with three decimals, separated by spaces
     */
    private static String format(double[] seconds) {
        StringBuilder text = new StringBuilder();
        for (double s : seconds)
            text.append(text.length() == 0 ? "" : " ").append(String.format("%.3f", s));
        return text.toString();
    }

    /**
     * Parses a whole number option.
     *
     * @param value the option's value
     * @param min   the smallest value allowed
     * @return the number
     */
    private static int wholeNumber(String value, int min) {
        try {
            int n = Integer.parseInt(value);
            if (n >= min)
                return n;
        } catch (NumberFormatException e) {
            // reported below
        }
        return usage("expected a whole number " + min + " or more, got " + value);
    }

    /**
     * Prints the usage and exits.
     *
     * @param problem what was wrong with the command line
     * @param <T>     any type, so that callers can return the call
     * @return never returns
     */
    private static <T> T usage(String problem) {
        System.err.println("benchmark: " + problem);
        System.err.println("usage: Benchmark [--scene S|M|M1|MS|G10k|G100k|G1M|F2|SDOF|SAA|SAAA|SG|obj:PATH|inst:PATH|all,"
                + " or several"
                + " separated by commas]"
                + " [--frames N] [--warmup N] [--threads N]");
        System.exit(2);
        throw new IllegalStateException(problem);
    }
}
