package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

import benchmark.SphereMesh;
import geometries.Intersectable.GeoPoint;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.Render;
import scene.Scene;

/**
 * Unit tests for {@link MeshShading}, through {@link TriangleMesh}'s smooth normals: their checks, their
 * computation from the faces, their interpolation at vertices, edges and centroids, the shadow point of
 * the shadow-terminator fix, and pictures of smooth meshes.
 */
class MeshShadingTest {
    private static final double DELTA = 1e-12;
    private static final double SQRT2 = Math.sqrt(2);

    /** One triangle in the plane z = 0, its vertex normals tilted outward like a patch of a sphere. */
    private static TriangleMesh patch() {
        return new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 })
                .setNormals(new double[] { 0, 0, 1, 1 / SQRT2, 0, 1 / SQRT2, 0, 1 / SQRT2, 1 / SQRT2 });
    }

    /** Asserts two vectors are equal component by component within {@link #DELTA}. */
    private static void assertVector(double x, double y, double z, Vector actual, String message) {
        assertEquals(x, actual.getX(), DELTA, message + " (x)");
        assertEquals(y, actual.getY(), DELTA, message + " (y)");
        assertEquals(z, actual.getZ(), DELTA, message + " (z)");
    }

    /** Asserts a vector is (x, y, z) normalised. */
    private static void assertDirection(double x, double y, double z, Vector actual, String message) {
        double length = Math.sqrt(x * x + y * y + z * z);
        assertVector(x / length, y / length, z / length, actual, message);
    }

    /** The hit of a ray straight down onto the point (x, y) of the plane z = 0. */
    private static MeshPoint hitFromAbove(TriangleMesh mesh, double x, double y) {
        List<GeoPoint> hits = mesh.findGeoIntersections(new Ray(new Point3D(x, y, 5), new Vector(0, 0, -1)));
        return assertInstanceOf(MeshPoint.class, hits.get(0), "a hit on a mesh is a MeshPoint");
    }

    /** Test method for {@link TriangleMesh#setNormals(double[])}. */
    @Test
    void testSetNormals() {
        double[] up = { 0, 0, 1, 0, 0, 1, 0, 0, 1 };
        TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 });
        // ===== Equivalence Partitions Tests =====
        // TC01: a new mesh is flat; with normals it is smooth and keeps a copy of them
        assertFalse(mesh.isSmooth(), "TC01: a new mesh must be flat");
        assertNull(mesh.getNormals(), "TC01: a flat mesh has no normals");
        assertSame(mesh, mesh.setNormals(up), "TC01: setNormals must return the mesh");
        up[2] = 7;
        assertEquals(1, mesh.getNormals()[2], 0, "TC01: the mesh must keep its own copy of the normals");
        assertTrue(mesh.isSmooth(), "TC01: a mesh with normals is smooth");
        // TC02: a null array, or one of the wrong length (normals for 2 of the 3 vertices)
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> mesh.setNormals(null),
                "TC02: null normals");
        assertMessage(e, "normals", "TC02");
        e = assertThrows(IllegalArgumentException.class, () -> mesh.setNormals(new double[6]), "TC02: too few");
        assertMessage(e, "9 numbers", "TC02");
        // TC03: a normal that is not a unit vector, or NaN, names its vertex
        e = assertThrows(IllegalArgumentException.class,
                () -> mesh.setNormals(new double[] { 0, 0, 1, 0, 0, 2, 0, 0, 1 }), "TC03: length 2");
        assertMessage(e, "vertex 1", "TC03");
        assertMessage(e, "unit", "TC03");
        e = assertThrows(IllegalArgumentException.class,
                () -> mesh.setNormals(new double[] { 0, 0, 1, 0, 0, 1, Double.NaN, 0, 1 }), "TC03: NaN");
        assertMessage(e, "vertex 2", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: a length within 1e-6 of 1 is a unit vector; a zero normal is not
        mesh.setNormals(new double[] { 0, 0, 1 + 0.9e-6, 0, 0, 1, 0, 0, 1 });
        assertThrows(IllegalArgumentException.class, () -> mesh.setNormals(new double[9]), "TC11: zero normals");
        // TC12: a refused array leaves the normals as they were
        assertEquals(1 + 0.9e-6, mesh.getNormals()[2], 0, "TC12: a refused array must change nothing");
    }

    /** Test method for {@link TriangleMesh#smoothNormals()}. */
    @Test
    void testSmoothNormals() {
        // ===== Equivalence Partitions Tests =====
        // TC01: an octahedron's vertices get exactly their directions from the centre
        double[] corners = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
        int[] faces = { 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5 };
        TriangleMesh octahedron = new TriangleMesh(corners, faces);
        assertSame(octahedron, octahedron.smoothNormals(), "TC01: smoothNormals must return the mesh");
        double[] normals = octahedron.getNormals();
        for (int v = 0; v < 6; ++v)
            for (int i = 0; i < 3; ++i)
                assertEquals(corners[3 * v + i], normals[3 * v + i], DELTA, "TC01: vertex " + v + ", component " + i);
        // TC02: each face counts by its angle at the vertex: 90° of a face facing +z and 45° of one
        // facing +x give (π/2·(0, 0, 1) + π/4·(1, 0, 0)) normalised, (1, 0, 2)/√5 (the faces' areas are equal)
        TriangleMesh corner = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1 },
                new int[] { 0, 1, 2, 0, 2, 3 }).smoothNormals();
        double[] atCorner = corner.getNormals();
        assertDirection(1, 0, 2, new Vector(atCorner[0], atCorner[1], atCorner[2]), "TC02: angle-weighted normal");

        // ===== Boundary Values Tests =====
        // TC11: the two sides of a sheet cancel: the vertex takes its first face's normal, (0, 0, 1)
        TriangleMesh sheet = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 },
                new int[] { 0, 1, 2, 0, 2, 1 }).smoothNormals();
        assertVector(0, 0, 1, new Vector(sheet.getNormals()[0], sheet.getNormals()[1], sheet.getNormals()[2]),
                "TC11: cancelled normals fall back to the first face's");
        // TC12: a vertex no triangle uses gets (0, 0, 1)
        TriangleMesh unused = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 0, 1, 5, 5, 5 },
                new int[] { 0, 1, 2 }).smoothNormals();
        assertVector(0, 0, 1, new Vector(unused.getNormals()[9], unused.getNormals()[10], unused.getNormals()[11]),
                "TC12: an unused vertex");
    }

    /**
     * Test method for {@link MeshPoint#getNormal()} and {@link TriangleMesh#getNormal(Point3D)} on a smooth
     * mesh: the vertex normals n1 = (0, 0, 1), n2 = (1, 0, 1)/√2, n3 = (0, 1, 1)/√2 interpolated.
     */
    @Test
    void testInterpolatedNormal() {
        TriangleMesh mesh = patch();
        // ===== Equivalence Partitions Tests =====
        // TC01: at the centroid, (n1 + n2 + n3) normalised
        double s = 1 / SQRT2;
        assertDirection(s, s, 1 + 2 * s, hitFromAbove(mesh, 1.0 / 3, 1.0 / 3).getNormal(), "TC01: at the centroid");
        assertDirection(s, s, 1 + 2 * s, mesh.getNormal(new Point3D(1.0 / 3, 1.0 / 3, 0)), "TC01: getNormal(point)");
        // TC02: inside, at weights (0.5, 0.25, 0.25): (0.5·n1 + 0.25·n2 + 0.25·n3) normalised
        assertDirection(0.25 * s, 0.25 * s, 0.5 + 0.5 * s, hitFromAbove(mesh, 0.25, 0.25).getNormal(),
                "TC02: inside");
        // TC03: the flat normal is still the triangle's
        assertVector(0, 0, 1, mesh.getNormal(0), "TC03: the triangle's own normal");

        // ===== Boundary Values Tests =====
        // TC11: at a vertex, its own normal
        assertVector(s, 0, s, mesh.getNormal(new Point3D(1, 0, 0)), "TC11: at vertex 2");
        assertVector(0, 0, 1, mesh.getNormal(Point3D.ZERO), "TC11: at vertex 1");
        // TC12: at the middle of an edge, the sum of its two vertices' normals normalised
        assertDirection(s, 0, 1 + s, mesh.getNormal(new Point3D(0.5, 0, 0)), "TC12: middle of edge 1-2");
        assertDirection(s, s, 2 * s, mesh.getNormal(new Point3D(0.5, 0.5, 0)), "TC12: middle of edge 2-3");
        // TC13: where the normals cancel (n2 = −n3, halfway between them) the triangle's normal stands in
        TriangleMesh opposed = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 })
                .setNormals(new double[] { 0, 0, 1, 1, 0, 0, -1, 0, 0 });
        assertVector(0, 0, 1, opposed.getNormal(new Point3D(0.5, 0.5, 0)), "TC13: cancelled normals");
    }

    /**
     * Test method for {@link MeshPoint#getShadowPoint(Vector)}: at the centroid of {@link #patch()} the
     * point lies 2/(3√2) below the tangent planes of vertices 2 and 3 and on vertex 1's, so it rises by
     * 1/3 · 2/(3√2) along n2 and n3 each, to (4/9, 4/9, 2/9).
     */
    @Test
    void testShadowPoint() {
        MeshPoint centroid = hitFromAbove(patch(), 1.0 / 3, 1.0 / 3);
        Vector fromAbove = new Vector(0, 0, -1);
        // ===== Equivalence Partitions Tests =====
        // TC01: a light above: the point is lifted onto the curved surface, to (4/9, 4/9, 2/9)
        Point3D lifted = centroid.getShadowPoint(fromAbove);
        assertVector(4.0 / 9, 4.0 / 9, 2.0 / 9, new Vector(lifted), "TC01: the lifted point");
        // TC02: a light below: seen from there the surface is concave, the point stays
        assertSame(centroid.point, centroid.getShadowPoint(new Vector(0, 0, 1)), "TC02: a light below");
        // TC03: normals tilted inward (a concave patch): the point stays
        TriangleMesh bowl = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 })
                .setNormals(new double[] { 0, 0, 1, -1 / SQRT2, 0, 1 / SQRT2, 0, -1 / SQRT2, 1 / SQRT2 });
        MeshPoint inBowl = hitFromAbove(bowl, 1.0 / 3, 1.0 / 3);
        assertSame(inBowl.point, inBowl.getShadowPoint(fromAbove), "TC03: a concave patch");
        // TC04: a flat mesh's hit, and a hit on another body, is its own shadow point
        TriangleMesh flat = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 });
        MeshPoint onFlat = hitFromAbove(flat, 0.2, 0.2);
        assertSame(onFlat.point, onFlat.getShadowPoint(fromAbove), "TC04: a flat mesh");
        GeoPoint onSphere = new GeoPoint(new Sphere(Point3D.ZERO, 1), new Point3D(0, 0, 1));
        assertSame(onSphere.point, onSphere.getShadowPoint(fromAbove), "TC04: a sphere");

        // ===== Boundary Values Tests =====
        // TC11: at vertex 1, on its own tangent plane and its weight alone: the point stays
        MeshPoint atVertex = new MeshPoint(patch(), 0, Point3D.ZERO);
        assertEquals(Point3D.ZERO, atVertex.getShadowPoint(fromAbove), "TC11: at a vertex");
        // TC12: a light along the surface (l ⊥ the smooth normal) leaves the point as it is
        MeshPoint atTwo = new MeshPoint(patch(), 0, new Point3D(1, 0, 0));
        assertSame(atTwo.point, atTwo.getShadowPoint(new Vector(1, 0, -1)), "TC12: a light along the surface");
    }

    /** Test method for {@link TriangleMesh#setUVs(double[])}, {@link MeshPoint#getUV()} and {@link TriangleMesh#getUV(Point3D)}. */
    @Test
    void testUVs() {
        TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 });
        // ===== Equivalence Partitions Tests =====
        // TC01: none by default; set, a copy is kept
        assertNull(mesh.getUVs(), "TC01: no UVs by default");
        double[] uvs = { 0.2, 0.1, 0.8, 0.1, 0.2, 0.9 };
        assertSame(mesh, mesh.setUVs(uvs), "TC01: setUVs must return the mesh");
        uvs[0] = 5;
        assertEquals(0.2, mesh.getUVs()[0], 0, "TC01: the mesh must keep its own copy");
        // TC02: at the centroid, the mean of the three UVs: (0.4, 11/30)
        assertArrayEquals(new double[] { 0.4, 1.1 / 3 }, hitFromAbove(mesh, 1.0 / 3, 1.0 / 3).getUV(), DELTA,
                "TC02: at the centroid");
        assertArrayEquals(new double[] { 0.4, 1.1 / 3 }, mesh.getUV(new Point3D(1.0 / 3, 1.0 / 3, 0)), DELTA,
                "TC02: getUV(point)");
        // TC03: the wrong length, a NaN (naming its vertex), null
        assertMessage(assertThrows(IllegalArgumentException.class, () -> mesh.setUVs(new double[4]),
                "TC03: too few"), "6 numbers", "TC03");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> mesh.setUVs(new double[] { 0, 0, 0, 0, Double.NaN, 0 }), "TC03: NaN"), "vertex 2", "TC03");
        assertThrows(IllegalArgumentException.class, () -> mesh.setUVs(null), "TC03: null");
        // ===== Boundary Values Tests =====
        // TC11: at a vertex its own UV; at the middle of an edge the mean of its two
        assertArrayEquals(new double[] { 0.8, 0.1 }, mesh.getUV(new Point3D(1, 0, 0)), DELTA, "TC11: at vertex 2");
        assertArrayEquals(new double[] { 0.5, 0.5 }, mesh.getUV(new Point3D(0.5, 0.5, 0)), DELTA, "TC11: an edge");
        // TC12: a mesh without UVs has no surface coordinates
        TriangleMesh bare = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 });
        assertThrows(UnsupportedOperationException.class, () -> bare.getUV(new Point3D(0.2, 0.2, 0)), "TC12");
    }

    // ===== pictures =====

    private static final Path FOLDER = Path.of("target", "test-images", "smooth");
    private static final int SIZE = 120;
    private static final Color EMISSION = new Color(10, 10, 30);
    private static final Vector LIGHT = new Vector(-1, -0.15, -0.25);

    /** A UV sphere of radius 50 at the origin, cut into few triangles, flat or smooth, diffuse. */
    private static TriangleMesh coarseSphere(int rings, int segments, boolean smooth) {
        TriangleMesh mesh = SphereMesh.mesh(Point3D.ZERO, 50, rings, segments);
        if (smooth)
            mesh.smoothNormals();
        mesh.setEmission(EMISSION).setMaterial(new Material().setKd(0.8));
        return mesh;
    }

    private static Camera camera() {
        return new Camera(new Point3D(0, 0, 1000), new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpSize(120, 120)
                .setVpDistance(1000);
    }

    /** Renders a mesh alone under a directional light from the right (and a little from the front). */
    private static ImageWriter render(String name, TriangleMesh mesh) {
        Scene scene = new Scene(name).setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.05));
        scene.geometries.add(mesh);
        scene.lights.add(new DirectionalLight(new Color(300, 280, 250), LIGHT));
        ImageWriter image = new ImageWriter(name, SIZE, SIZE, FOLDER);
        Render render = new Render().setImageWriter(image).setCamera(camera()).setRayTracer(new RayTracerBasic(scene));
        render.renderImage();
        render.writeToImage();
        return image;
    }

    /** The largest difference of the red levels of a pixel and its right and lower neighbours, over the inside of the sphere. */
    private static int largestStep(ImageWriter image) {
        int largest = 0;
        for (int y = 10; y < SIZE - 10; ++y)
            for (int x = 10; x < SIZE - 10; ++x)
                if (onSphere(x, y) && onSphere(x + 1, y) && onSphere(x, y + 1)) {
                    int red = image.getPixel(x, y).getRed();
                    largest = Math.max(largest, Math.abs(red - image.getPixel(x + 1, y).getRed()));
                    largest = Math.max(largest, Math.abs(red - image.getPixel(x, y + 1).getRed()));
                }
        return largest;
    }

    /** Whether pixel (x, y) sees well inside the sphere's outline (radius 50 in a view of 120 × 120 units). */
    private static boolean onSphere(int x, int y) {
        double px = (x + 0.5) - SIZE / 2.0;
        double py = (y + 0.5) - SIZE / 2.0;
        return px * px + py * py < 44 * 44;
    }

    /**
     * Test method for smooth shading in a render: the smooth sphere mesh has no facets, neighbouring pixels
     * differ little, where the flat one's facets jump.
     */
    @Test
    void testNoFaceting() {
        int smooth = largestStep(render("smooth", coarseSphere(12, 24, true)));
        int flat = largestStep(render("flat", coarseSphere(12, 24, false)));
        // ===== Equivalence Partitions Tests =====
        // TC01: smooth: no two neighbouring pixels differ by more than 6 levels
        assertTrue(smooth <= 6, "TC01: the smooth mesh shows facets, a step of " + smooth + " levels");
        // TC02: flat, the same mesh's facets make steps of more than 12 levels
        assertTrue(flat > 12, "TC02: the flat mesh should show its facets, largest step " + flat);
    }

    /**
     * Test method for the shadow-terminator fix in a render: on a very coarse smooth sphere (5 rings, 8
     * segments) lit near grazing, every point whose smooth normal faces the light is lit — no dark speckle
     * of facets shadowing their neighbours near the terminator, and no dark rim where the smooth normal
     * turns away from the viewer at the outline.
     */
    @Test
    void testNoTerminatorArtefacts() {
        TriangleMesh mesh = coarseSphere(5, 8, true);
        ImageWriter image = render("terminator", mesh);
        Camera camera = camera();
        Vector toLight = LIGHT.scale(-1).normalize();
        int nearTerminator = 0;
        int darkNearTerminator = 0;
        int darkOnRim = 0;
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x) {
                Ray ray = camera.constructRayThroughPixel(SIZE, SIZE, x, y);
                List<GeoPoint> hits = mesh.findGeoIntersections(ray);
                if (hits == null)
                    continue;
                MeshPoint hit = (MeshPoint) hits.get(0);
                double facing = hit.getNormal().dotProduct(toLight);
                // lit by more than 0.8 · 0.05 · 280 = 11 levels of green
                boolean dark = image.getPixel(x, y).getGreen() <= EMISSION.getG() + 255 * 0.05 + 1;
                if (facing > 0.05 && facing < 0.5) {
                    ++nearTerminator;
                    if (dark)
                        ++darkNearTerminator;
                }
                if (facing > 0.05 && hit.getNormal().dotProduct(ray.getDir()) >= 0 && dark)
                    ++darkOnRim;
            }
        // ===== Equivalence Partitions Tests =====
        // TC01: near the terminator (the smooth normal 3° to 60° from grazing the light) no pixel is dark
        assertTrue(nearTerminator > 500, "TC01: the band near the terminator must be in view, " + nearTerminator);
        assertEquals(0, darkNearTerminator, "TC01: dark pixels of " + nearTerminator + " near the terminator");
        // ===== Boundary Values Tests =====
        // TC11: on the lit outline, where the smooth normal turns away from the camera, no pixel is dark
        assertEquals(0, darkOnRim, "TC11: dark pixels on the lit outline");
    }
}
