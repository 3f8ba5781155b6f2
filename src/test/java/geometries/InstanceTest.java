package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestInstances.DELTA;
import static testutil.TestInstances.PLACEMENTS;
import static testutil.TestInstances.SIMILARITY;
import static testutil.TestInstances.assertSameHit;
import static testutil.TestInstances.inPlace;

import java.nio.file.Path;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import benchmark.SphereMesh;
import accel.RayState;
import accel.ShadowFrustum;
import geometries.Intersectable.GeoPoint;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.Render;
import renderer.RayTracerBasic;
import scene.Scene;
import testutil.TestBundles;
import testutil.TestInstances;
import testutil.TestMeshes;

/**
 * Unit tests for {@link geometries.Instance}: a body placed by a transform answers as the body built
 * in place would.
 */
class InstanceTest {
    private static final Vector DOWN = new Vector(0, 0, -1);
    private static final Path FOLDER = Path.of("target", "test-images", "instances");

    /** The unit sphere at the origin. */
    private final Sphere unit = new Sphere(Point3D.ZERO, 1);

    /** {@return the nearest hit of a body's own intersections, or null} */
    private static GeoPoint nearest(Intersectable body, Ray ray) {
        return ray.findClosestGeoPoint(body.findGeoIntersections(ray));
    }

    /** {@return a frustum set to the pyramid from an apex to the square c ± a ± b, 0 thick} */
    private static ShadowFrustum pyramid(Point3D apex, Point3D c, Vector a, Vector b) {
        ShadowFrustum frustum = new ShadowFrustum();
        assertTrue(frustum.set(new double[] { apex.getX(), apex.getY(), apex.getZ() }, new double[] { c.getX(),
                c.getY(), c.getZ(), a.getX(), a.getY(), a.getZ(), b.getX(), b.getY(), b.getZ() }, 0),
                "the pyramid must not be flat");
        return frustum;
    }

    /**
     * The bundle of a point on top of a placed body, where a ray down from (0.05, 0.03, 10) meets it:
     * from 0.001 off the surface along its normal to a square of half-side 50 across the normal, 10 above,
     * told the surface it leaves (its back face across the normal).
     */
    private static ShadowFrustum bundleAbove(Instance body) {
        GeoPoint top = nearest(body, new Ray(new Point3D(0.05, 0.03, 10), DOWN));
        Vector n = top.getNormal();
        Vector a = n.crossProduct(new Vector(1, 0, 0)).normalize().scale(50);
        Vector b = n.crossProduct(a).normalize().scale(50);
        ShadowFrustum frustum = pyramid(top.point.add(n.scale(0.001)), top.point.add(n.scale(10)), a, b);
        frustum.setLeaving(1, top.point.getX(), top.point.getY(), top.point.getZ(), 0.001 * n.getX(),
                0.001 * n.getY(), 0.001 * n.getZ());
        return frustum;
    }

    /** Test method for {@link Instance#mayMeet(ShadowFrustum)}: the bundle carried into the body's space. */
    @Test
    void testMayMeet() {
        TriangleMesh cube = TestMeshes.cube(-0.5, -0.5, -0.5, 1);
        Instance turned = new Instance(cube, Transform.rotateZ(45));
        Vector a = new Vector(0.01, 0, 0);
        Vector b = new Vector(0, 0.01, 0);

        // ===== Equivalence Partitions Tests =====
        // TC01: a thin bundle up through the turned cube: true
        assertTrue(turned.mayMeet(pyramid(new Point3D(0, 0, -5), new Point3D(0, 0, 5), a, b)),
                "TC01: a bundle through the body must meet it");
        // TC02: the same bundle through a corner of the cube's box (|x| + |y| ≤ 0.71 inside the cube): false
        assertFalse(turned.mayMeet(pyramid(new Point3D(0.65, 0.65, -5), new Point3D(0.65, 0.65, 5), a, b)),
                "TC02: a bundle past the body, through its box, must not meet it");
        // TC03: a bundle that leaves the top of a sphere mesh stretched to an ellipsoid and raised, toward a
        // wide square above, told the surface it leaves: no triangle of the body meets it, false
        TriangleMesh ball = SphereMesh.mesh(Point3D.ZERO, 1, 12, 24);
        Instance raised = new Instance(ball, Transform.scale(2, 1, 1).then(Transform.translate(new Vector(0, 0, 1))));
        ShadowFrustum leaving = bundleAbove(raised);
        assertTrue(leaving.hasBackFace(), "TC03: the bundle's back face must be placed");
        assertFalse(raised.mayMeet(leaving), "TC03: the surface the bundle leaves must be set aside");

        // ===== Boundary Values Tests =====
        // TC11: the same under a mirror (x → −x): the back face carried still sets the surface aside
        Instance mirrored = new Instance(ball, Transform.scale(-2, 1, 1).then(Transform.translate(new Vector(0, 0, 1))));
        ShadowFrustum mirroredLeaving = bundleAbove(mirrored);
        assertTrue(mirroredLeaving.hasBackFace(), "TC11: the bundle's back face must be placed");
        assertFalse(mirrored.mayMeet(mirroredLeaving), "TC11: a mirror must keep the surface aside");
        // TC12: the thin bundle of TC01 ending at z = −2, before the cube: false
        assertFalse(turned.mayMeet(pyramid(new Point3D(0, 0, -5), new Point3D(0, 0, -2), a, b)),
                "TC12: a bundle that ends before the body must not meet it");
    }

    /**
     * Test method for {@link Instance#packetTransmittances(Query, int)}: a packet of shadow rays taken
     * into the bodies' trees together answers as each ray alone.
     */
    @Test
    void testPacketTransmittances() {
        TriangleMesh cube = TestMeshes.cube(-0.5, -0.5, -0.5, 1);
        TriangleMesh glass = (TriangleMesh) TestMeshes.cube(-0.5, -0.5, -0.5, 1)
                .setMaterial(new Material().setKt(0.5));
        TriangleMesh ball = SphereMesh.mesh(Point3D.ZERO, 1, 24, 48);
        Geometries world = new Geometries(new Instance(cube, Transform.rotateZ(45)),
                new Instance(glass, Transform.translate(new Vector(3, 0, 0))),
                new Instance(ball, Transform.scale(4).then(Transform.translate(new Vector(-20, 0, 0)))));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(world);
        Query query = bvh.newQuery();
        Point3D apex = new Point3D(1.5, 0, -10);
        Point3D c = new Point3D(1.5, 0, 10);
        Vector a = new Vector(3.5, 0, 0);
        Vector b = new Vector(0, 0.5, 0);
        // rays from the apex to x = −1.5, 2 and 4.5 on the light cross z = 0 at x = 0, 1.75 and 3
        List<Ray> rays = List.of(rayTo(apex, -1.5), rayTo(apex, 2), rayTo(apex, 4.5));
        List<Double> distances = rays.stream().map(ray -> distanceTo(apex, ray)).toList();

        // ===== Equivalence Partitions Tests =====
        // TC01: a bundle over the turned cube and the glass cube gathers both: its rays are a packet
        assertTrue(TestBundles.gather(bvh, query, apex, c, a, b), "TC01: the bundle must meet the cubes");
        assertTrue(query.isPacketTraced(), "TC01: a bundle that gathers instances is traced as a packet");
        assertFalse(query.isSubtreeGathered(), "TC01: two instances are kept one by one");
        // TC02: through the turned cube 0, between the cubes 1, through the glass cube its kT 0.5 twice (in and out)
        TestBundles.fillPacket(query, rays, distances);
        bvh.packetTransmittances(query, 0);
        double[] expected = { 0, 1, 0.25 };
        for (int r = 0; r < rays.size(); ++r)
            assertEquals(expected[r], query.getTransmittance(r), DELTA, "TC02: wrong transmittance of ray " + r);
        // TC03: the same as each ray alone, with and without a limit below which a ray counts as blocked
        TestBundles.assertPacket(bvh, query, bvh, bvh.newQuery(), rays, distances, 0, () -> "TC03");

        // ===== Boundary Values Tests =====
        // TC11: a limit above the glass cube's 0.25: the ray through it is blocked, 0
        TestBundles.fillPacket(query, rays, distances);
        bvh.packetTransmittances(query, 0.3);
        assertEquals(0, query.getTransmittance(2), DELTA, "TC11: below the limit a ray is blocked");
        // TC12: a thin bundle up through the middle of the big instanced ball, a closed mesh: every ray
        // is blocked
        Point3D under = new Point3D(-20, 0, -10);
        Point3D over = new Point3D(-20, 0, 10);
        Vector small = new Vector(0.2, 0, 0);
        Vector side = new Vector(0, 0.2, 0);
        assertTrue(TestBundles.gather(bvh, query, under, over, small, side), "TC12: the bundle must meet the ball");
        List<Ray> up = List.of(new Ray(under, new Vector(0, 0, 1)), new Ray(under, new Vector(0.01, 0.01, 1)));
        List<Double> upDistances = List.of(20.0, 20.0);
        TestBundles.fillPacket(query, up, upDistances);
        bvh.packetTransmittances(query, 0);
        for (int r = 0; r < up.size(); ++r)
            assertEquals(0, query.getTransmittance(r), 0, "TC12: a ray through the ball must be blocked");
        // TC13: the bundle of TC01 leaving a surface across x on both sides (ray origins set): a ray from
        // p − n, one from p + n and one from p itself (traced alone) each get their answer alone
        double n = 0.001;
        ShadowFrustum frustum = query.getFrustum();
        assertTrue(frustum.set(new double[] { 1.5, 0, -10 }, new double[] { 1.5, 0, 10, 3.5, 0, 0, 0, 0.5, 0 }, n),
                "TC13: the pyramid must not be flat");
        frustum.setOrigins(1.5, 0, -10, n, 0, 0);
        assertTrue(bvh.gather(query), "TC13: the bundle must meet the cubes");
        assertTrue(query.isPacketTraced(), "TC13: a bundle that gathers instances is traced as a packet");
        List<Ray> leaving = List.of(rayTo(new Point3D(1.5 - n, 0, -10), -1.5), rayTo(new Point3D(1.5 + n, 0, -10), 4.5),
                rayTo(apex, 2));
        List<Double> leavingDistances = leaving.stream().map(ray -> distanceTo(ray.getP0(), ray)).toList();
        TestBundles.assertPacket(bvh, query, bvh, bvh.newQuery(), leaving, leavingDistances, 0, () -> "TC13");
    }

    /** {@return the ray from a point to the point (x, 0, 10) of a light} */
    private static Ray rayTo(Point3D from, double x) {
        return new Ray(from, new Point3D(x, 0, 10).subtract(from));
    }

    /** {@return the distance from a point along a ray to the light's plane z = 10} */
    private static double distanceTo(Point3D from, Ray ray) {
        return (10 - from.getZ()) / ray.getDir().getZ();
    }

    /** Test method for {@link Instance#Instance(Intersectable, Transform)}, {@link Instance#getBody()} and {@link Instance#getTransform()}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the body and the transform given are kept
        Transform move = Transform.translate(new Vector(1, 2, 3));
        Instance instance = new Instance(unit, move);
        assertSame(unit, instance.getBody(), "TC01: wrong body");
        assertSame(move, instance.getTransform(), "TC01: wrong transform");

        // ===== Boundary Values Tests =====
        // TC11: a null body is refused, naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new Instance(null, move),
                "TC11: a null body must throw"), "body", "TC11");
        // TC12: a null transform is refused, naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new Instance(unit, null),
                "TC12: a null transform must throw"), "transform", "TC12");
        // TC13: an instance has no material, emission or texture of its own (its body's show)
        assertThrows(UnsupportedOperationException.class, () -> instance.setMaterial(new Material()),
                "TC13: setMaterial must be refused");
        assertThrows(UnsupportedOperationException.class, () -> instance.setEmission(Color.BLACK),
                "TC13: setEmission must be refused");
        assertThrows(UnsupportedOperationException.class,
                () -> instance.setTexture(new primitives.CheckerTexture(Color.BLACK, Color.BLACK, 1)),
                "TC13: setTexture must be refused");
    }

    /** Test method for {@link Instance#findGeoIntersections(Ray)} with closed-form answers. */
    @Test
    void testFindGeoIntersections() {
        Instance moved = new Instance(unit, Transform.translate(new Vector(5, 0, 0)));
        Ray down = new Ray(new Point3D(5, 0, 10), DOWN);

        // ===== Equivalence Partitions Tests =====
        // TC01: a translated sphere is crossed at (5, 0, 1) and (5, 0, -1), nearest first, on the sphere
        List<GeoPoint> hits = moved.findGeoIntersections(down);
        assertEquals(List.of(new Point3D(5, 0, 1), new Point3D(5, 0, -1)), hits.stream().map(h -> h.point).toList(),
                "TC01: wrong points");
        assertSame(unit, hits.get(0).geometry, "TC01: the hit must name the body");
        assertEquals(new Vector(0, 0, 1), hits.get(0).getNormal(), "TC01: wrong normal");
        // TC02: a sphere stretched to an ellipsoid of half-axes (2, 1, 3) at (0, 0, 4): the closed form
        // hits of many random rays, and the normals ((x / a², y / b², z / c²), normalised)
        Point3D centre = new Point3D(0, 0, 4);
        double[] axes = { 2, 1, 3 };
        Instance ellipsoid = new Instance(unit, Transform.scale(2, 1, 3).then(Transform.translate(new Vector(0, 0, 4))));
        Random rnd = new Random(1);
        for (int i = 0; i < 500; ++i) {
            Ray ray = testutil.TestRandom.rayThrough(rnd, testutil.TestRandom.randomPoint(rnd, centre, 3), 20);
            assertEllipsoidHit(ray, centre, axes, nearest(ellipsoid, ray), "TC02: ray " + i);
        }
        // TC03: a mesh under every placement: the hits of the mesh built in place, in the same order
        TriangleMesh grid = TestInstances.cubeGrid(3, new Material());
        for (Transform placement : PLACEMENTS) {
            Instance instance = new Instance(grid, placement);
            TriangleMesh copy = inPlace(grid, placement);
            for (int i = 0; i < 300; ++i) {
                Ray ray = testutil.TestRandom.rayThrough(rnd, testutil.TestRandom.randomPoint(rnd, placement.apply(Point3D.ZERO), 2), 20);
                List<GeoPoint> expected = copy.findGeoIntersections(ray);
                List<GeoPoint> actual = instance.findGeoIntersections(ray);
                assertEquals(expected == null ? 0 : expected.size(), actual == null ? 0 : actual.size(),
                        "TC03: wrong hit count for " + ray + " under " + placement);
                if (expected != null) {
                    expected = expected.stream().sorted(java.util.Comparator.comparingDouble(
                            h -> h.point.distance(ray.getP0()))).toList();
                    for (int k = 0; k < expected.size(); ++k)
                        assertSameHit(expected.get(k), actual.get(k), "TC03: hit " + k + " of " + ray);
                }
            }
        }

        // ===== Boundary Values Tests =====
        // TC11: a ray that misses the placed body (null)
        assertNull(moved.findGeoIntersections(new Ray(new Point3D(0, 0, 10), DOWN)), "TC11: a miss must give null");
        // TC12: a distance that ends between the two hits (only (5, 0, 1))
        assertEquals(List.of(new Point3D(5, 0, 1)),
                moved.findGeoIntersections(down, 10).stream().map(h -> h.point).toList(), "TC12: wrong points within 10");
        // TC13: a ray from inside the body (one hit, the far side)
        assertEquals(List.of(new Point3D(5, 0, -1)), moved.findIntersections(new Ray(new Point3D(5, 0, 0), DOWN)),
                "TC13: wrong point from inside");
    }

    /** Asserts that a hit is the nearest one of a ray on an axis-aligned ellipsoid, with its normal. */
    private static void assertEllipsoidHit(Ray ray, Point3D centre, double[] axes, GeoPoint hit, String message) {
        double[] p = { ray.getP0().getX() - centre.getX(), ray.getP0().getY() - centre.getY(),
                ray.getP0().getZ() - centre.getZ() };
        double[] d = { ray.getDir().getX(), ray.getDir().getY(), ray.getDir().getZ() };
        double a = 0;
        double b = 0;
        double c = -1;
        for (int k = 0; k < 3; ++k) {
            double s = axes[k] * axes[k];
            a += d[k] * d[k] / s;
            b += 2 * p[k] * d[k] / s;
            c += p[k] * p[k] / s;
        }
        double discriminant = b * b - 4 * a * c;
        double t1 = (-b - Math.sqrt(discriminant)) / (2 * a);
        double t2 = (-b + Math.sqrt(discriminant)) / (2 * a);
        double t = t1 > 0 ? t1 : t2;
        if (discriminant <= 1e-9 || t <= 0) {
            if (discriminant < -1e-9 || t2 < 0)
                assertNull(hit, message + ": no hit expected");
            return;
        }
        assertNotNull(hit, message + ": a hit expected");
        Point3D expected = ray.getPoint(t);
        assertEquals(0, expected.distance(hit.point), DELTA, message + ": wrong point");
        Vector normal = new Vector((expected.getX() - centre.getX()) / (axes[0] * axes[0]),
                (expected.getY() - centre.getY()) / (axes[1] * axes[1]),
                (expected.getZ() - centre.getZ()) / (axes[2] * axes[2])).normalize();
        assertEquals(1, normal.dotProduct(hit.getNormal()), DELTA, message + ": wrong normal");
    }

    /**
     * Test method for {@link Instance#nearestHit(RayState)}, {@link Instance#transmittance(RayState)} and
     * {@link Instance#bounds(double[], int)}.
     */
    @Test
    void testFastPath() {
        Sphere glass = (Sphere) new Sphere(Point3D.ZERO, 1).setMaterial(new Material().setKt(0.5));
        TriangleMesh pane = (TriangleMesh) TestMeshes.cuboid(-1, -1, -3, 1, 1, -2.5).setMaterial(new Material().setKt(0.4));
        Instance group = new Instance(new Geometries(glass, pane), Transform.scale(2, 1, 1));

        // ===== Equivalence Partitions Tests =====
        // TC01: a ray down from (0.3, 0.1, 10) first meets the stretched sphere at z = √(1 − 0.15² − 0.1²)
        RayState down = new RayState().set(0.3, 0.1, 10, 0, 0, -1, Geometry.NO_HIT);
        assertEquals(10 - Math.sqrt(1 - 0.0225 - 0.01), group.nearestHit(down), 1e-12, "TC01: wrong distance");
        // TC02: the ray crosses each inner body twice: 0.5² · 0.4² of the light passes, each body's own kT
        assertEquals(0.25 * 0.16, group.transmittance(down), 1e-12, "TC02: wrong transmittance");
        // TC03: the box of a unit cube turned 45° about z: x and y within ±√2, z within ±1 (padded a little)
        double[] box = new double[6];
        assertTrue(new Instance(TestMeshes.cuboid(-1, -1, -1, 1, 1, 1), Transform.rotateZ(45)).bounds(box, 0),
                "TC03: a turned cube is bounded");
        double[] expected = { -Math.sqrt(2), -Math.sqrt(2), -1, Math.sqrt(2), Math.sqrt(2), 1 };
        for (int k = 0; k < 6; ++k)
            assertEquals(expected[k], box[k], 1e-5, "TC03: wrong box bound " + k);

        // ===== Boundary Values Tests =====
        // TC11: the ray's distance ends inside the sphere (at z = 0.5): one crossing of it only (0.5)
        assertEquals(0.5, group.transmittance(down.set(0.3, 0.1, 10, 0, 0, -1, 9.5)), 1e-12, "TC11: wrong transmittance");
        // TC12: an instance of a plane is unbounded (no box), and still hit where the turned plane is:
        // the plane z = 0 turned 90° about x is y = 0, met at distance 5 from (0, 5, 0) going -y
        // (the normal +z turned to −y)
        Material matte = new Material().setKd(0.5);
        Instance wall = new Instance(new Plane(Point3D.ZERO, new Vector(0, 0, 1)).setMaterial(matte), Transform.rotateX(90));
        assertNull(wall.bounds(), "TC12: an instance of a plane has no box");
        assertEquals(5, wall.nearestHit(new RayState().set(0, 5, 0, 0, -1, 0, Geometry.NO_HIT)), 1e-12,
                "TC12: wrong distance to the turned plane");
        Ray slanted = new Ray(new Point3D(1, 5, 2), new Vector(0, -1, 0.2));
        BoundingVolumeHierarchy walls = new Geometries(wall).hierarchy(1);
        assertSameHit(nearest(new Plane(Point3D.ZERO, new Vector(0, -1, 0)).setMaterial(matte), slanted),
                walls.closestHit(slanted, walls.newQuery()), "TC12: the turned plane through a hierarchy");
        // TC13: an instance of an empty group: no box and no hit
        assertNull(new Instance(new Geometries(), Transform.IDENTITY).bounds(), "TC13: nothing has no box");
        assertEquals(Geometry.NO_HIT, new Instance(new Geometries(), Transform.IDENTITY).nearestHit(down),
                "TC13: nothing is never hit");
    }

    /** Test method for instances of instances: the body placed by both transforms in turn. */
    @Test
    void testInstanceOfInstance() {
        TriangleMesh grid = TestInstances.cubeGrid(2, new Material());
        Transform inner = PLACEMENTS.get(3);
        Transform outer = SIMILARITY;
        Instance twice = new Instance(new Instance(grid, inner), outer);
        Instance once = new Instance(grid, inner.then(outer));
        TriangleMesh copy = inPlace(grid, inner.then(outer));
        BoundingVolumeHierarchy bvh = new Geometries(twice).hierarchy(1);
        Random rnd = new Random(3);

        // ===== Equivalence Partitions Tests =====
        // TC01: many random rays: the hits of one instance by the composed transform and of the copy,
        // on the course path and through a hierarchy, naming the mesh
        for (int i = 0; i < 500; ++i) {
            Ray ray = testutil.TestRandom.rayThrough(rnd, testutil.TestRandom.randomPoint(rnd, outer.apply(inner.apply(Point3D.ZERO)), 3), 30);
            GeoPoint expected = nearest(copy, ray);
            assertSameHit(expected, nearest(twice, ray), "TC01: course path, ray " + i);
            assertSameHit(nearest(once, ray), nearest(twice, ray), "TC01: composed transform, ray " + i);
            GeoPoint fast = bvh.closestHit(ray, bvh.newQuery());
            assertSameHit(expected, fast, "TC01: hierarchy, ray " + i);
            if (fast != null)
                assertSame(grid, fast.geometry, "TC01: the hit must name the innermost body");
        }

        // ===== Boundary Values Tests =====
        // TC11: an instance of itself cannot be made, and a group cannot be added to an instance of itself
        Geometries group = new Geometries(grid);
        Instance ofGroup = new Instance(new Instance(group, inner), outer);
        assertMessage(assertThrows(IllegalArgumentException.class, () -> group.add(ofGroup),
                "TC11: a group must not hold an instance of itself"), "contain itself", "TC11");
    }

    /**
     * Test method for {@link Instance#version()} and the hierarchy's sharing: many instances of one body
     * walk the one hierarchy the body keeps, and a body added inside an instance is seen.
     */
    @Test
    void testSharedHierarchy() {
        TriangleMesh grid = TestInstances.cubeGrid(4, new Material());
        Geometries scene = new Geometries();
        for (int i = 0; i < 1000; ++i)
            scene.add(new Instance(grid, Transform.rotateZ(i).then(Transform.translate(new Vector(1 + i % 40 * 5, i / 40 * 5, 0)))));
        BoundingVolumeHierarchy outer = scene.hierarchy(2);

        // ===== Equivalence Partitions Tests =====
        // TC01: the outer tree holds 1000 bodies, not 768 000 triangles
        assertEquals(1000, outer.getBoundedCount(), "TC01: each instance must be one body of the outer tree");
        // TC02: every instance walks the one hierarchy the mesh keeps
        BoundingVolumeHierarchy shared = grid.hierarchy(1);
        for (Intersectable item : scene.getGeometries())
            assertSame(shared, ((Instance) item).tree(), "TC02: the body's hierarchy must be shared");
        // TC03: a body added to a group inside an instance raises the instance's and the scene's versions:
        // the outer hierarchy is out of date, and the new one sees the new body at its place
        Geometries inner = new Geometries(new Sphere(Point3D.ZERO, 1));
        Geometries world = new Geometries(new Instance(inner, Transform.translate(new Vector(0, 0, -10))));
        BoundingVolumeHierarchy before = world.hierarchy(1);
        long version = world.version();
        inner.add(new Sphere(new Point3D(20, 0, 0), 1));
        assertTrue(world.version() > version, "TC03: the scene's version must grow");
        assertFalse(before.isBuiltFrom(world), "TC03: the outer hierarchy must be out of date");
        BoundingVolumeHierarchy after = world.hierarchy(1);
        assertEquals(new Point3D(20, 0, -9), after.closestHit(new Ray(new Point3D(20, 0, 0), DOWN), after.newQuery()).point,
                "TC03: the new body must be hit through the instance");

        // ===== Boundary Values Tests =====
        // TC11: an instance of a single body keeps the body's version (0)
        assertEquals(0, new Instance(grid, Transform.IDENTITY).version(), "TC11: a mesh never changes");
    }

    /** Test method for {@link Instance#getNormal(Point3D)}. */
    @Test
    void testGetNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a sphere stretched along x: at (2, 0, 0) the normal is +x, at (0, 0, 1) it is +z
        Instance stretched = new Instance(unit, Transform.scale(2, 1, 1));
        assertEquals(new Vector(1, 0, 0), stretched.getNormal(new Point3D(2, 0, 0)), "TC01: wrong normal at x");
        assertEquals(new Vector(0, 0, 1), stretched.getNormal(new Point3D(0, 0, 1)), "TC01: wrong normal at z");

        // ===== Boundary Values Tests =====
        // TC11: an instance of a group has no one normal at a point
        assertThrows(IllegalArgumentException.class,
                () -> new Instance(new Geometries(unit), Transform.IDENTITY).getNormal(new Point3D(1, 0, 0)),
                "TC11: an instance of a group must refuse");
    }

    /**
     * Renders the render test's scene (a turned, stretched box, a sphere scaled and moved, and a glass
     * slab above a floor, lit from a side): placed by instances, or built in place.
     */
    private static ImageWriter render(String name, boolean instanced, boolean soft) {
        Scene scene = new Scene("instances " + name);
        TriangleMesh box = (TriangleMesh) TestMeshes.cuboid(-1, -1, -1, 1, 1, 1).setEmission(new Color(40, 20, 10))
                .setMaterial(new Material().setKd(0.6).setKs(0.3).setShininess(20));
        Sphere ball = (Sphere) new Sphere(Point3D.ZERO, 1).setEmission(new Color(10, 40, 10))
                .setMaterial(new Material().setKd(0.5).setKs(0.4).setShininess(40));
        TriangleMesh slab = (TriangleMesh) TestMeshes.cuboid(-1, -1, -1, 1, 1, 1).setEmission(new Color(5, 5, 30))
                .setMaterial(new Material().setKd(0.2).setKt(0.5));
        Transform boxPlace = Transform.scale(8, 4, 3).then(Transform.rotateZ(30)).then(Transform.translate(new Vector(-20, 10, 20)));
        Transform ballPlace = Transform.scale(10).then(Transform.translate(new Vector(20, -15, 25)));
        Transform slabPlace = Transform.scale(6, 6, 2).then(Transform.rotateX(20)).then(Transform.translate(new Vector(15, 20, 15)));
        scene.geometries.add(new Plane(Point3D.ZERO, new Vector(0, 0, 1)).setMaterial(new Material().setKd(0.8)));
        if (instanced)
            scene.geometries.add(new Instance(box, boxPlace), new Instance(ball, ballPlace), new Instance(slab, slabPlace));
        else
            scene.geometries.add(inPlace(box, boxPlace), inPlace(ball, ballPlace), inPlace(slab, slabPlace));
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point3D(-60, 60, 100)).setEdgesSize(10)
                .setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        ImageWriter image = new ImageWriter(name + (instanced ? "-instanced" : "-in-place"), 80, 80, FOLDER);
        Render render = new Render().setImageWriter(image)
                .setCamera(new Camera(new Point3D(0, 0, 1000), DOWN, new Vector(0, 1, 0)).setVpSize(120, 120)
                        .setVpDistance(1000))
                .setRayTracer(new RayTracerBasic(scene)).setSoftShadows(soft).setSqrtBeamNum(4);
        render.renderImage();
        render.writeToImage();
        return image;
    }

    /** Test method for an instance in a picture: its shadow, and the picture of the copy built in place. */
    @Test
    void testRender() {
        for (boolean soft : new boolean[] { false, true }) {
            String name = soft ? "soft" : "hard";
            ImageWriter instanced = render(name, true, soft);
            ImageWriter inPlace = render(name, false, soft);

            // ===== Equivalence Partitions Tests =====
            // TC01: the scaled sphere's shadow on the floor (about (47, -40): pixel (71, 67)) is darker than
            // the lit floor (about (-45, -40): pixel (10, 67))
            assertTrue(instanced.getPixel(71, 67).getRed() < instanced.getPixel(10, 67).getRed() / 2,
                    "TC01: " + name + " shadow of the instance must be darker than the lit floor");
            // TC02: every pixel within one level per channel of the picture built in place
            for (int y = 0; y < 80; ++y)
                for (int x = 0; x < 80; ++x) {
                    java.awt.Color a = instanced.getPixel(x, y);
                    java.awt.Color b = inPlace.getPixel(x, y);
                    int difference = Math.max(Math.abs(a.getRed() - b.getRed()),
                            Math.max(Math.abs(a.getGreen() - b.getGreen()), Math.abs(a.getBlue() - b.getBlue())));
                    assertTrue(difference <= 1, "TC02: " + name + " pixel (" + x + ", " + y + ") differs by "
                            + difference + ": " + a + " against " + b);
                }
        }
    }
}
