package accel;

import static accel.BvhFixtures.built;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.assertPoint;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Intersectable.GeoPoint;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.TestBundles;
import testutil.TestMeshes;
import testutil.TestScenes.Wrapper;

/**
 * Unit tests for {@link LeafBodies}, the bodies the hierarchy tests: the scene's bodies sorted, their
 * places and boxes in leaf order, and the answers of packed triangles and of the intersectables that
 * are not geometries.
 */
class LeafBodiesTest {
    private static final double DELTA = 1e-9;
    private static final Geometry[] NO_GEOMETRY = new Geometry[0];
    private static final Intersectable[] NO_OTHER = new Intersectable[0];

    /** The bodies of a build over some geometries, none unbounded, none packed. */
    private static LeafBodies bodiesOf(Geometry... owners) {
        return new LeafBodies(NO_GEOMETRY, NO_OTHER, null, built(owners), 1);
    }

    /** A course-style triangle of a transparency at x = 3i in the plane z = 0: (3i, 0), (3i + 1, 0), (3i, 1). */
    private static Triangle triangle(int i, double kT) {
        return (Triangle) new Triangle(new Point3D(3 * i, 0, 0), new Point3D(3 * i + 1, 0, 0),
                new Point3D(3 * i, 1, 0)).setMaterial(new Material().setKt(kT));
    }

    /** Test method for {@link LeafBodies#flatten}. */
    @Test
    void testFlatten() {
        Sphere ball = new Sphere(Point3D.ZERO, 1);
        Plane floor = new Plane(new Point3D(0, 0, -1), new Vector(0, 0, 1));
        TriangleMesh cube = TestMeshes.cube(3, 0, 0, 1);
        Wrapper wrapper = new Wrapper(new Sphere(new Point3D(0, 0, 5), 1));
        // ===== Equivalence Partitions Tests =====
        // TC01: nested composites: the sphere and the mesh bounded, the plane unbounded, the wrapper apart
        List<Geometry> bounded = new ArrayList<>();
        List<Geometry> infinite = new ArrayList<>();
        List<Intersectable> generic = new ArrayList<>();
        LeafBodies.flatten(new Geometries(ball, new Geometries(floor, new Geometries(cube)), wrapper), bounded,
                infinite, generic, new double[6]);
        assertEquals(List.of(ball, cube), bounded, "TC01: bounded");
        assertEquals(List.of(floor), infinite, "TC01: unbounded");
        assertEquals(List.of(wrapper), generic, "TC01: not geometries");

        // ===== Boundary Values Tests =====
        // TC11: empty composites: nothing
        bounded.clear();
        infinite.clear();
        generic.clear();
        LeafBodies.flatten(new Geometries(new Geometries()), bounded, infinite, generic, new double[6]);
        assertTrue(bounded.isEmpty() && infinite.isEmpty() && generic.isEmpty(), "TC11: nothing");
        // TC12: a single body, no composite: itself
        LeafBodies.flatten(ball, bounded, infinite, generic, new double[6]);
        assertEquals(List.of(ball), bounded, "TC12: the body itself");
    }

    /**
     * Test method for {@link LeafBodies#LeafBodies}: each body of the tree at its place in leaf order,
     * a mesh's triangle by its number and its box in floats rounded outward, a whole body by its box.
     */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a sphere and a cube mesh: 13 bodies, the 12 triangles once each, boxes as the build's
        Sphere ball = new Sphere(new Point3D(5, 0, 0), 1);
        TriangleMesh cube = TestMeshes.cube(0, 0, 0, 1);
        BvhBuilder builder = built(ball, cube);
        double[] boxes = builder.boxes.clone();
        LeafBodies bodies = new LeafBodies(NO_GEOMETRY, NO_OTHER, null, builder, 1);
        assertEquals(13, bodies.count(), "TC01: wrong body count");
        boolean[] seen = new boolean[12];
        for (int b = 0; b < bodies.count(); ++b) {
            int part = bodies.bodyPart[b];
            if (bodies.owner(b) == cube) {
                assertTrue(part >= 0 && part < 12 && !seen[part], "TC01: body " + b + " is triangle " + part);
                seen[part] = true;
                for (int k = 0; k < 3; ++k) {
                    assertTrue(bodies.triangleBounds[6 * b + k] <= boxes[6 * b + k], "TC01: body " + b + ", low " + k);
                    assertTrue(bodies.triangleBounds[6 * b + 3 + k] >= boxes[6 * b + 3 + k],
                            "TC01: body " + b + ", high " + k);
                }
            } else {
                assertSame(ball, bodies.owner(b), "TC01: body " + b + " must be the sphere");
                assertEquals(-1, part, "TC01: the sphere is whole body 0");
                for (int k = 0; k < 6; ++k)
                    assertEquals(boxes[6 * b + k], bodies.wholeBounds[k], 0, "TC01: the sphere's box, " + k);
            }
        }
        assertEquals(6, bodies.wholeBounds.length, "TC01: one whole body");

        // ===== Boundary Values Tests =====
        // TC11: no body: nothing kept
        LeafBodies none = bodiesOf();
        assertEquals(0, none.count(), "TC11: no body");
        assertEquals(0, none.wholeBounds.length + none.triangleBounds.length, "TC11: no box");
        // TC12: a mesh alone: no whole body
        assertEquals(0, bodiesOf(cube).wholeBounds.length, "TC12: no whole body");
    }

    /** Test method for {@link LeafBodies#kT(TriangleMesh, int)}. */
    @Test
    void testKT() {
        TriangleMesh glass = (TriangleMesh) TestMeshes.cube(0, 0, -3, 1).setMaterial(new Material().setKt(0.3));
        List<Geometry> scene = new ArrayList<>(
                List.of(glass, triangle(0, 0.1), triangle(1, 0.2), triangle(2, 0.4), triangle(3, 0.8)));
        PackedTriangles packed = PackedTriangles.take(scene);
        LeafBodies bodies = new LeafBodies(NO_GEOMETRY, NO_OTHER, packed, built(scene.toArray(NO_GEOMETRY)), 1);
        // ===== Equivalence Partitions Tests =====
        // TC01: a mesh's triangle: the mesh's kT, 0.3
        assertEquals(0.3, bodies.kT(glass, 5), DELTA, "TC01");
        // TC02: a packed triangle: its own kT, 0.1, 0.2, 0.4, 0.8
        double[] kTs = { 0.1, 0.2, 0.4, 0.8 };
        for (int t = 0; t < 4; ++t)
            assertEquals(kTs[t], bodies.kT(packed.mesh, t), DELTA, "TC02: triangle " + t);

        // ===== Boundary Values Tests =====
        // TC11: nothing packed: the mesh's own kT
        assertEquals(0.3, bodiesOf(glass).kT(glass, 0), DELTA, "TC11");
    }

    /** Test method for {@link LeafBodies#hitPoint(Ray, RayState)}. */
    @Test
    void testHitPoint() {
        TriangleMesh cube = TestMeshes.cube(0, 0, 0, 1);
        List<Geometry> scene = new ArrayList<>(List.of(cube));
        Triangle[] plain = new Triangle[4];
        for (int i = 0; i < plain.length; ++i)
            scene.add(plain[i] = triangle(i, 0));
        PackedTriangles packed = PackedTriangles.take(scene);
        LeafBodies bodies = new LeafBodies(NO_GEOMETRY, NO_OTHER, packed, built(scene.toArray(NO_GEOMETRY)), 1);
        // ===== Equivalence Partitions Tests =====
        // TC01: a packed triangle's hit reports its Triangle, at (3i + 0.25, 0.25, 0)
        for (int i = 0; i < plain.length; ++i) {
            Ray down = new Ray(new Point3D(3 * i + 0.25, 0.25, 5), new Vector(0, 0, -1));
            GeoPoint hit = bodies.hitPoint(down, hitState(packed.mesh, i, 5));
            assertSame(plain[i], hit.geometry, "TC01: triangle " + i + " must be reported");
            assertPoint(new Point3D(3 * i + 0.25, 0.25, 0), hit.point, "TC01: triangle " + i);
        }
        // TC02: a mesh's hit reports the mesh, on its top face at (0.5, 0.5, 1)
        Ray down = new Ray(new Point3D(0.5, 0.5, 5), new Vector(0, 0, -1));
        GeoPoint hit = bodies.hitPoint(down, hitState(cube, topTriangle(cube, down), 4));
        assertSame(cube, hit.geometry, "TC02: the mesh must be reported");
        assertPoint(new Point3D(0.5, 0.5, 1), hit.point, "TC02");
    }

    /** A closest-hit walk's state that found a body's part at a distance. */
    private static RayState hitState(Geometry body, int part, double t) {
        RayState state = new RayState().set(0, 0, 0, 0, 0, 1, Geometry.NO_HIT);
        state.keepNearer(t, body, part);
        return state;
    }

    /** {@return the triangle of a mesh that a ray meets nearest, by the triangle test of the walks} */
    private static int topTriangle(TriangleMesh mesh, Ray ray) {
        RayState state = TestBundles.rayState(TestBundles.rayFromTo(ray.getP0(), ray.getPoint(100)));
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        int nearest = -1;
        double nearestT = Geometry.NO_HIT;
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            mesh.triangleData(t, data, 0);
            double hit = Triangle.intersect(state, data, 0, data[TriangleMesh.PARALLEL_LIMIT]);
            if (hit < nearestT) {
                nearestT = hit;
                nearest = t;
            }
        }
        return nearest;
    }

    /** Test method for {@link LeafBodies#meets(ShadowFrustum, int)}, on the standard pyramid (sides x, y = ±z/5). */
    @Test
    void testMeets() {
        ShadowFrustum frustum = TestBundles.standard();
        Sphere inside = new Sphere(new Point3D(0, 0, 5), 0.5);
        Sphere outside = new Sphere(new Point3D(5, 0, 5), 0.5);
        // at z = 5: one triangle around the axis, one at x = 5
        TriangleMesh mesh = new TriangleMesh(new double[] { -0.2, -0.2, 5, 0.2, -0.2, 5, 0, 0.2, 5, 5, -0.2, 5, 5.4,
                -0.2, 5, 5.2, 0.2, 5 }, new int[] { 0, 1, 2, 3, 4, 5 });
        // box x ∈ [1.1, 2.1], z ∈ [4.5, 5.5]: its corner (1.1, 0, 5.5) on the side x = z/5
        Sphere touching = new Sphere(new Point3D(1.6, 0, 5), 0.5);
        // the same 0.1 further out
        Sphere past = new Sphere(new Point3D(1.7, 0, 5), 0.5);
        LeafBodies bodies = bodiesOf(inside, outside, mesh, touching, past);
        int checked = 0;
        for (int b = 0; b < bodies.count(); ++b) {
            Geometry owner = bodies.owner(b);
            boolean meets = bodies.meets(frustum, b);
            // ===== Equivalence Partitions Tests =====
            // TC01: the sphere and the triangle in the pyramid meet it
            if (owner == inside || owner == mesh && bodies.bodyPart[b] == 0)
                assertTrue(meets, "TC01: body " + b + " is in the pyramid");
            // TC02: the sphere and the triangle beside it do not
            else if (owner == outside || owner == mesh)
                assertFalse(meets, "TC02: body " + b + " is beside the pyramid");
            // ===== Boundary Values Tests =====
            // TC11: a box touching a side meets it
            else if (owner == touching)
                assertTrue(meets, "TC11: a box on the side");
            // TC12: 0.1 past the side: not
            else
                assertFalse(meets, "TC12: a box 0.1 past the side");
            ++checked;
        }
        assertEquals(6, checked, "six bodies");
    }

    /**
     * Test method for {@link LeafBodies#nearestOfOthers(RayState)}, {@link LeafBodies#nearestOfOthers(Ray,
     * GeoPoint)} and {@link LeafBodies#throughOthers(RayState, double)}: a wrapped sphere (kT 0.5) of
     * radius 1 at (0, 0, −5), the rays down the z axis from the origin.
     */
    @Test
    void testOthers() {
        Sphere glass = (Sphere) new Sphere(new Point3D(0, 0, -5), 1).setMaterial(new Material().setKt(0.5));
        LeafBodies bodies = new LeafBodies(NO_GEOMETRY, new Intersectable[] { new Wrapper(glass) }, null, built(), 1);
        LeafBodies alone = bodiesOf();
        Ray down = new Ray(Point3D.ZERO, new Vector(0, 0, -1));
        // ===== Equivalence Partitions Tests =====
        // TC01: the nearest hit of the wrapped sphere: 4 away, at (0, 0, −4)
        assertEquals(4, bodies.nearestOfOthers(downTo(100)), DELTA, "TC01");
        assertPoint(new Point3D(0, 0, -4), bodies.nearestOfOthers(down, null).point, "TC01");
        // TC02: a nearer hit so far is kept
        GeoPoint nearer = new GeoPoint(glass, new Point3D(0, 0, -1));
        assertSame(nearer, bodies.nearestOfOthers(down, nearer), "TC02: the nearer hit");
        // TC03: through the sphere, in and out: 0.5 · 0.5
        assertEquals(0.25, bodies.throughOthers(transmittanceRay(100, 0), 1), DELTA, "TC03");
        // TC04: the light inside the sphere: once, 0.5
        assertEquals(0.5, bodies.throughOthers(transmittanceRay(5, 0), 1), DELTA, "TC04");
        // TC05: 0.25 below the smallest product that counts, 0.3: 0
        assertEquals(0, bodies.throughOthers(transmittanceRay(100, 0.3), 1), 0, "TC05");

        // ===== Boundary Values Tests =====
        // TC11: the hit beyond the distance that counts: none
        assertEquals(Geometry.NO_HIT, bodies.nearestOfOthers(downTo(3.5)), "TC11");
        // TC12: no intersectable apart: no hit, the transmittance as it was
        assertEquals(Geometry.NO_HIT, alone.nearestOfOthers(downTo(100)), "TC12");
        assertNull(alone.nearestOfOthers(down, null), "TC12");
        assertEquals(0.7, alone.throughOthers(transmittanceRay(100, 0), 0.7), 0, "TC12");
    }

    /** {@return the ray down the z axis from the origin, up to a distance} */
    private static RayState downTo(double maxT) {
        return new RayState().set(0, 0, 0, 0, 0, -1, maxT);
    }

    /** {@return the ray down the z axis from the origin, up to a distance, its transmittance started} */
    private static RayState transmittanceRay(double maxT, double minK) {
        RayState ray = downTo(maxT);
        ray.startTransmittance(minK);
        return ray;
    }
}
