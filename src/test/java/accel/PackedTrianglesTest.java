package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.assertPoint;
import static testutil.BruteForce.transmittance;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable.GeoPoint;
import geometries.Sphere;
import geometries.Triangle;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/** Unit tests for {@link PackedTriangles}: course-style triangles packed into one mesh for the walks. */
class PackedTrianglesTest {
    private static final double DELTA = 1e-12;

    /** A triangle in the plane z = height, across the z axis. */
    private static Triangle across(double height) {
        return new Triangle(new Point3D(-1, -1, height), new Point3D(2, -1, height), new Point3D(-1, 2, height));
    }

    /** A course-style triangle of another class, which the hierarchy must not pack. */
    private static final class OwnTriangle extends Triangle {
        OwnTriangle(Point3D p1, Point3D p2, Point3D p3) {
            super(p1, p2, p3);
        }
    }

    /** Test method for {@link PackedTriangles#take(List)}. */
    @Test
    void testTake() {
        Sphere sphere = new Sphere(new Point3D(0, 0, 10), 1);
        Triangle own = new OwnTriangle(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0));

        // ===== Equivalence Partitions Tests =====
        // TC01: a sphere, then 5 triangles and a triangle of its own class: the 5 leave, their mesh
        // (15 vertices, their corners in order) takes the first one's place
        List<Geometry> bounded = new ArrayList<>(List.of(sphere, across(1), across(2), own, across(3), across(4),
                across(5)));
        PackedTriangles packed = PackedTriangles.take(bounded);
        assertNotNull(packed, "TC01: 5 triangles are packed");
        assertEquals(List.of(sphere, packed.mesh, own), bounded, "TC01: the sphere, the mesh, the own triangle");
        assertEquals(5, packed.mesh.getTrianglesCount(), "TC01: 5 triangles in the mesh");
        for (int t = 0; t < 5; ++t)
            for (int k = 0; k < 3; ++k)
                assertEquals(packed.triangles[t].getVertices().get(k), packed.mesh.getVertex(
                        packed.mesh.getVertexIndex(t, k)), "TC01: triangle " + t + "'s corner " + k + " in order");
        assertTrue(packed.isMesh(packed.mesh), "TC01: the mesh is the packed one");

        // ===== Boundary Values Tests =====
        // TC11: 3 triangles: none packed, the list unchanged
        List<Geometry> three = new ArrayList<>(List.of(across(1), sphere, across(2), across(3)));
        List<Geometry> before = List.copyOf(three);
        assertNull(PackedTriangles.take(three), "TC11: 3 triangles are too few");
        assertEquals(before, three, "TC11: the list is unchanged");
        // TC12: exactly 4 triangles, the first body: packed, the mesh first
        List<Geometry> four = new ArrayList<>(List.of(across(1), across(2), across(3), across(4), sphere));
        PackedTriangles packedFour = PackedTriangles.take(four);
        assertNotNull(packedFour, "TC12: 4 triangles are packed");
        assertEquals(List.of(packedFour.mesh, sphere), four, "TC12: the mesh, then the sphere");
    }

    /**
     * Test method for the walks over packed triangles ({@link BoundingVolumeHierarchy#closestHit},
     * {@link BoundingVolumeHierarchy#transmittance}): each triangle answers with its own material.
     */
    @Test
    void testWalks() {
        double[] kTs = { 0.5, 0.8, 0.9, 0.25, 1.0 };
        Geometries scene = new Geometries();
        List<Triangle> triangles = new ArrayList<>();
        for (int t = 0; t < kTs.length; ++t) {
            Triangle triangle = across(t + 1);
            triangle.setMaterial(new Material().setKt(kTs[t]));
            triangles.add(triangle);
            scene.add(triangle);
        }
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene);
        Query query = bvh.newQuery();

        // ===== Equivalence Partitions Tests =====
        // TC01: a ray down from z = 10: its closest hit is the top triangle itself (z = 5)
        GeoPoint hit = bvh.closestHit(new Ray(new Point3D(0, 0, 10), new Vector(0, 0, -1)), query);
        assertSame(triangles.get(4), hit.geometry, "TC01: the hit reports the Triangle object");
        assertEquals(new Point3D(0, 0, 5), hit.point, "TC01: at z = 5");
        // TC02: a shadow ray up from z = 0 to z = 10: the product of the five kT, 0.09
        double product = 0.5 * 0.8 * 0.9 * 0.25;
        assertEquals(product, bvh.transmittance(query.setRay(0, 0, 0, 0, 0, 1, 10), 0.001), DELTA,
                "TC02: every triangle's own kT");
        // TC03: a triangle's material changed after the build: read at the next ray (kT 0: blocked)
        triangles.get(2).getMaterial().setKt(0);
        assertEquals(0, bvh.transmittance(query.setRay(0, 0, 0, 0, 0, 1, 10), 0.001), DELTA,
                "TC03: the changed kT is read");

        // ===== Boundary Values Tests =====
        // TC11: a shadow ray that ends between the second and the third triangle (at z = 2.5): 0.4
        triangles.get(2).getMaterial().setKt(0.9);
        assertEquals(0.5 * 0.8, bvh.transmittance(query.setRay(0, 0, 0, 0, 0, 1, 2.5), 0.001), DELTA,
                "TC11: only the triangles before the end");
        // TC12: rays beside every triangle (x = 5): no hit (null), all the light through (1)
        assertNull(bvh.closestHit(new Ray(new Point3D(5, 0, 10), new Vector(0, 0, -1)), query),
                "TC12: a ray beside the triangles hits nothing");
        assertEquals(1, bvh.transmittance(query.setRay(5, 0, 0, 0, 0, 1, 10), 0.001), DELTA,
                "TC12: a shadow ray beside the triangles lets all through");
    }

    /** A triangle with its own intersection test: it is never hit. */
    private static final class HiddenTriangle extends Triangle {
        /**
         * Creates the triangle.
         *
         * @param p1 first vertex
         * @param p2 second vertex
         * @param p3 third vertex
         */
        HiddenTriangle(Point3D p1, Point3D p2, Point3D p3) {
            super(p1, p2, p3);
        }

        @Override
        public double nearestHit(RayState ray) {
            return NO_HIT;
        }
    }

    /**
     * Test method for the triangles the tree tests from its own copy of their data: only plain
     * {@link Triangle}s are copied, a subclass keeps its own intersection test.
     */
    @Test
    void testTakeKeepsSubclasses() {
        Material opaque = new Material();
        Triangle plain = new Triangle(new Point3D(-1, -1, -5), new Point3D(1, -1, -5), new Point3D(0, 1, -5));
        plain.setMaterial(opaque);
        Triangle hidden = new HiddenTriangle(new Point3D(-1, -1, -3), new Point3D(1, -1, -3), new Point3D(0, 1, -3));
        hidden.setMaterial(opaque);
        Ray down = new Ray(new Point3D(0, 0, 0), new Vector(0, 0, -1));

        // ===== Equivalence Partitions Tests =====
        // TC01: the hidden triangle in front of a plain one: the closest hit is the plain one at (0, 0, −5)
        BoundingVolumeHierarchy both = BoundingVolumeHierarchy.build(new Geometries(hidden, plain));
        GeoPoint hit = both.closestHit(down, both.newQuery());
        assertNotNull(hit, "TC01: the plain triangle must be hit");
        assertSame(plain, hit.geometry, "TC01: wrong body hit");
        assertPoint(new Point3D(0, 0, -5), hit.point, "TC01: wrong hit point");
        // TC02: the opaque plain triangle blocks the light past it (transmittance 0), not before it (1)
        assertEquals(0, transmittance(both, down, 10, MIN_K, both.newQuery()), 0, "TC02: blocked past the triangle");
        assertEquals(1, transmittance(both, down, 4, MIN_K, both.newQuery()), 0,
                "TC02: the hidden triangle must not block");

        // ===== Boundary Values Tests =====
        // TC11: the hidden triangle alone: no hit, transmittance 1
        BoundingVolumeHierarchy alone = BoundingVolumeHierarchy.build(new Geometries(hidden));
        assertNull(alone.closestHit(down, alone.newQuery()), "TC11: the hidden triangle must not be hit");
        assertEquals(1, transmittance(alone, down, 10, MIN_K, alone.newQuery()), 0, "TC11: nothing blocks");
    }
}
