package benchmark;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import geometries.Geometries;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.Render;
import scene.Scene;

/**
 * The project's speed benchmark (SPEC §7). It renders the reference scenes S (three spheres on a
 * floor, one square light, soft shadows with 9 × 9 + 1 shadow rays) and M (the same with every sphere
 * tessellated into a triangle mesh) and prints, per scene, the primary and shadow rays of a frame
 * (and the share of the shadow rays whose bundle was open: nothing could block them, so no body was
 * tested), the median seconds of the timed frames, and million shadow rays per second.
 * <p>
 * Options: {@code --scene S|M|all} (default all), {@code --frames N} timed frames (default 5),
 * {@code --warmup N} untimed frames first (default 2), {@code --threads N} (default 0, all cores).
 * The last frame of each scene is written to {@code target/benchmark/<scene>.png}.
 */
public final class Benchmark {
    /** The width and height of the pictures, in pixels. */
    private static final int SIZE = 800;
    /** The bands from pole to pole of a sphere's mesh in scene M. */
    private static final int MESH_RINGS = 129;
    /** The slices around the axis of a sphere's mesh in scene M. */
    private static final int MESH_SEGMENTS = 128;
    /** Where the pictures go. */
    private static final Path OUTPUT = Path.of("target", "benchmark");

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
        int warmup = 2;
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
        List<String> scenes = switch (sceneOption) {
            case "S", "M" -> List.of(sceneOption);
            case "all" -> List.of("S", "M");
            default -> usage("--scene must be S, M or all, got " + sceneOption);
        };
        int threadsUsed = threads == 0 ? Runtime.getRuntime().availableProcessors() : threads;
        System.out.printf("JVM %s (%s), %d available processors, %d threads, %d warm-up + %d timed frames%n",
                Runtime.version(), System.getProperty("java.vm.name"), Runtime.getRuntime().availableProcessors(),
                threadsUsed, warmup, frames);
        for (String name : scenes)
            run(name, frames, warmup, threads);
    }

    /**
     * Renders one scene: the warm-up frames, then the timed ones, and prints its line.
     *
     * @param name    "S" or "M"
     * @param frames  the number of timed frames
     * @param warmup  the number of untimed frames first
     * @param threads the number of threads, 0 for all cores
     */
    private static void run(String name, int frames, int warmup, int threads) {
        RayTracerBasic rayTracer = new RayTracerBasic(buildScene(name.equals("M")));
        Camera camera = new Camera(new Point3D(0, 0, 1000), new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(150, 150).setVpDistance(1000);
        Render render = new Render().setImageWriter(new ImageWriter(name, SIZE, SIZE, OUTPUT)).setCamera(camera)
                .setRayTracer(rayTracer).setSoftShadows(true).setSqrtBeamNum(9).setMultithreading(threads);
        for (int f = 0; f < warmup; ++f)
            render.renderImage();
        double[] seconds = new double[frames];
        long primary = 0;
        long shadow = 0;
        long open = 0;
        for (int f = 0; f < frames; ++f) {
            long primaryBefore = rayTracer.getPrimaryRaysCount();
            long shadowBefore = rayTracer.getShadowRaysCount();
            long openBefore = rayTracer.getOpenShadowRaysCount();
            long start = System.nanoTime();
            render.renderImage();
            seconds[f] = (System.nanoTime() - start) / 1e9;
            primary = rayTracer.getPrimaryRaysCount() - primaryBefore;
            shadow = rayTracer.getShadowRaysCount() - shadowBefore;
            open = rayTracer.getOpenShadowRaysCount() - openBefore;
        }
        render.writeToImage();
        double median = median(seconds);
        System.out.printf("%s: %d pixels, %d primary rays/frame, %d shadow rays/frame (%.1f %% in open bundles),"
                        + " median %.3f s/frame (frames %s s), %.2f M shadow rays/s%n",
                name, SIZE * SIZE, primary, shadow, 100.0 * open / shadow, median, format(seconds),
                shadow / median / 1e6);
    }

    /**
     * Builds scene S, or with meshes instead of spheres, scene M.
     *
     * @param meshes true for scene M
     * @return the scene
     */
    static Scene buildScene(boolean meshes) {
        Scene scene = new Scene(meshes ? "M" : "S");
        Material diffuse = new Material().setKd(0.8);
        scene.geometries.add(new Plane(new Point3D(0, -50, 0), new Vector(0, 1, 0)).setMaterial(diffuse));
        Point3D[] centers = { new Point3D(-40, -20, 0), new Point3D(30, -30, 20), new Point3D(5, -35, -50) };
        double[] radii = { 30, 20, 15 };
        int triangles = 0;
        for (int s = 0; s < centers.length; ++s) {
            if (meshes) {
                Geometries mesh = new Geometries();
                for (Triangle triangle : SphereMesh.triangles(centers[s], radii[s], MESH_RINGS, MESH_SEGMENTS)) {
                    mesh.add(triangle.setMaterial(diffuse));
                    ++triangles;
                }
                scene.geometries.add(mesh);
            } else
                scene.geometries.add(new Sphere(centers[s], radii[s]).setMaterial(diffuse));
        }
        if (meshes)
            System.out.printf("M: %d spheres of %d rings x %d segments = %d triangles each, %d in all%n",
                    centers.length, MESH_RINGS, MESH_SEGMENTS,
                    SphereMesh.trianglesCount(MESH_RINGS, MESH_SEGMENTS), triangles);
        scene.lights.add(new PointLight(new Color(255, 255, 255), new Point3D(0, 100, 0))
                .setEdgesSize(20).setUV(new Vector(1, 0, 0), new Vector(0, 0, 1)));
        return scene;
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
        System.err.println("usage: Benchmark [--scene S|M|all] [--frames N] [--warmup N] [--threads N]");
        System.exit(2);
        throw new IllegalStateException(problem);
    }
}
