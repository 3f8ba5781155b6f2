package accel;

import geometries.Tube;
import geometries.TriangleMesh;
import geometries.Triangle;
import geometries.Sphere;
import geometries.Polygon;
import geometries.Plane;
import geometries.Intersectable;
import geometries.Geometry;
import geometries.Geometries;
import geometries.Cylinder;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static primitives.Util.alignZero;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestRandom.edgeOrInner;
import static testutil.TestRandom.randomPoint;
import static testutil.TestRandom.randomUnit;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.BoundingVolumeHierarchy}: closest hits and transmittance equal
 * the brute-force answers of every body's own query on seeded random scenes (by the renderer's rule:
 * polygons closed, see {@link #renderedIntersections}), the shape of the tree, and rays on the
 * boundaries of the slab test and of the bodies.
 */
class BoundingVolumeHierarchyTest {
    /** Tolerance on the coordinates of a hit point. */
    private static final double POINT_DELTA = 1e-7;
    /** Two hits whose distances differ by less than this are a tie: either body is right. */
    private static final double TIE = 1e-9;
    /** Rays whose hit lies this close to the transmittance distance are not judged. */
    private static final double MARGIN = 1e-6;
    /** The renderer's transmittance cut-off. */
    private static final double MIN_K = 1e-3;

    /**
     * A random test scene.
     *
     * @param geometries the composite handed to the hierarchy (may nest composites)
     * @param bodies     every body in it, to aim rays at
     * @param size       the half-width of the cube the bodies lie in
     */
    private record TestScene(Geometries geometries, List<Intersectable> bodies, double size) {
    }

    /**
     * A body that is not a {@link Geometry}: it hands the intersections of the body it wraps, so the
     * hierarchy must test it on every ray.
     */
    private static final class Wrapper extends Intersectable {
        private final Intersectable inner;

        /**
         * Wraps a body.
         *
         * @param inner the body
         */
        Wrapper(Intersectable inner) {
            this.inner = inner;
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            return inner.findGeoIntersections(ray, maxDistance);
        }
    }

    // ---------------------------------------------------------------- random scenes and rays

    /**
     * A random sphere.
     *
     * @param rnd       the generator
     * @param size      the half-width of the cube its centre lies in
     * @param minRadius the smallest radius
     * @param maxRadius the largest radius
     * @return the sphere
     */
    private static Sphere randomSphere(Random rnd, double size, double minRadius, double maxRadius) {
        return new Sphere(randomPoint(rnd, Point3D.ZERO, size), minRadius + (maxRadius - minRadius) * rnd.nextDouble());
    }

    /**
     * A random triangle: its vertices lie in a small cube around a random point.
     *
     * @param rnd     the generator
     * @param size    the half-width of the cube its centre lies in
     * @param maxEdge the half-width of the cube around its centre its vertices lie in
     * @return the triangle
     */
    private static Triangle randomTriangle(Random rnd, double size, double maxEdge) {
        Point3D center = randomPoint(rnd, Point3D.ZERO, size);
        while (true) {
            try {
                return new Triangle(randomPoint(rnd, center, maxEdge), randomPoint(rnd, center, maxEdge),
                        randomPoint(rnd, center, maxEdge));
            } catch (IllegalArgumentException e) {
                // collinear by chance: draw again
            }
        }
    }

    /**
     * A random quadrilateral: a square with a random orientation.
     *
     * @param rnd  the generator
     * @param size the half-width of the cube its centre lies in
     * @return the polygon
     */
    private static Polygon randomSquare(Random rnd, double size) {
        Point3D center = randomPoint(rnd, Point3D.ZERO, size);
        Vector normal = randomUnit(rnd);
        Vector u = normal.crossProduct(Math.abs(normal.getX()) < 0.9 ? new Vector(1, 0, 0) : new Vector(0, 1, 0))
                .normalize().scale(0.1 + rnd.nextDouble());
        Vector v = normal.crossProduct(u);
        return new Polygon(center.add(u), center.add(v), center.add(u.scale(-1)), center.add(v.scale(-1)));
    }

    /**
     * A random cylinder.
     *
     * @param rnd  the generator
     * @param size the half-width of the cube its base lies in
     * @return the cylinder
     */
    private static Cylinder randomCylinder(Random rnd, double size) {
        return new Cylinder(new Ray(randomPoint(rnd, Point3D.ZERO, size), randomUnit(rnd)), 0.2 + rnd.nextDouble(),
                0.5 + 2 * rnd.nextDouble());
    }

    /**
     * A random scene of the kind a scene index names (20 kinds, 1 to 2000 bodies).
     *
     * @param rnd   the generator
     * @param index which scene, 0..19
     * @return the scene
     */
    private static TestScene randomScene(Random rnd, int index) {
        List<Intersectable> bodies = new ArrayList<>();
        double size = 10;
        switch (index) {
        case 0 -> bodies.add(randomSphere(rnd, size, 1, 3));
        case 1 -> bodies.add(randomTriangle(rnd, size, 5));
        case 2 -> {
            for (int i = 0; i < 3; ++i)
                bodies.add(randomSphere(rnd, size, 0.5, 3));
            bodies.add(new Plane(new Point3D(0, -12, 0), new Vector(0.1, 1, 0.2)));
        }
        case 3 -> {
            for (int i = 0; i < 4; ++i)
                bodies.add(randomTriangle(rnd, size, 4));
        }
        case 4 -> {
            for (int i = 0; i < 5; ++i)
                bodies.add(i % 2 == 0 ? randomSphere(rnd, size, 0.5, 2) : randomTriangle(rnd, size, 3));
        }
        case 5 -> {
            for (int i = 0; i < 16; ++i)
                bodies.add(i % 2 == 0 ? randomSphere(rnd, size, 0.5, 2) : randomTriangle(rnd, size, 3));
            bodies.add(randomCylinder(rnd, size));
            bodies.add(new Plane(new Point3D(0, 0, -13), new Vector(0, 0, 1)));
        }
        case 6 -> {
            for (int i = 0; i < 50; ++i)
                bodies.add(randomSphere(rnd, size, 0.2, 2));
        }
        case 7 -> {
            for (int i = 0; i < 50; ++i)
                bodies.add(randomTriangle(rnd, size, 3));
        }
        case 8 -> {
            for (int i = 0; i < 200; ++i)
                bodies.add(i % 3 == 0 ? randomSphere(rnd, size, 0.1, 1) : randomTriangle(rnd, size, 1.5));
        }
        case 9 -> {
            for (int i = 0; i < 500; ++i)
                bodies.add(i % 2 == 0 ? randomSphere(rnd, size, 0.05, 0.8) : randomTriangle(rnd, size, 1));
            bodies.add(randomCylinder(rnd, size));
            bodies.add(randomSquare(rnd, size));
            bodies.add(new Tube(new Ray(new Point3D(0, 0, 0), new Vector(1, 1, 0)), 0.5));
            bodies.add(new Plane(new Point3D(0, 11, 0), new Vector(0, -1, 0)));
        }
        case 10 -> {
            for (int i = 0; i < 1000; ++i)
                bodies.add(i % 2 == 0 ? randomSphere(rnd, size, 0.05, 0.5) : randomTriangle(rnd, size, 0.8));
        }
        case 11 -> {
            for (int i = 0; i < 2000; ++i)
                bodies.add(i % 4 == 0 ? randomSphere(rnd, size, 0.05, 0.4) : randomTriangle(rnd, size, 0.6));
        }
        case 12 -> { // many tiny triangles
            for (int i = 0; i < 2000; ++i)
                bodies.add(randomTriangle(rnd, size, 1e-2));
        }
        case 13, 14 -> { // every body's box has the same centre
            Point3D c = new Point3D(1, -2, 0.5);
            int n = index == 13 ? 300 : 1000;
            for (int i = 0; i < n; ++i) {
                if (i % 2 == 0) {
                    bodies.add(new Sphere(c, 0.1 + 8 * rnd.nextDouble()));
                    continue;
                }
                Vector a = randomUnit(rnd).scale(0.5 + 8 * rnd.nextDouble());
                Vector b = new Vector(a.getX() * (2 * rnd.nextDouble() - 1), a.getY() * (2 * rnd.nextDouble() - 1),
                        a.getZ() * (2 * rnd.nextDouble() - 1));
                try {
                    bodies.add(new Triangle(c.add(a), c.add(a.scale(-1)), c.add(b)));
                } catch (IllegalArgumentException e) {
                    // collinear by chance: skip it
                }
            }
        }
        case 17 -> { // two far clusters
            for (int i = 0; i < 400; ++i) {
                Point3D c = new Point3D(i % 2 == 0 ? -9 : 9, 0, 0);
                bodies.add(i % 3 == 0 ? new Sphere(randomPoint(rnd, c, 1), 0.05 + 0.2 * rnd.nextDouble())
                        : new Triangle(randomPoint(rnd, c, 1), randomPoint(rnd, c, 1), randomPoint(rnd, c, 1)));
            }
        }
        case 18 -> { // big and small overlapping spheres
            for (int i = 0; i < 300; ++i)
                bodies.add(randomSphere(rnd, size, 0.01, i % 10 == 0 ? 5 : 0.5));
        }
        default -> { // 15, 16, 19: filled below
        }
        }
        if (index == 15 || index == 16)
            return nestedScene(rnd, index == 15 ? 300 : 60, size);
        if (index == 19) {
            for (int i = 0; i < 100; ++i)
                bodies.add(i % 3 == 0 ? randomSquare(rnd, size) : randomTriangle(rnd, size, 2));
            bodies.add(new Wrapper(randomSphere(rnd, size, 1, 3)));
            bodies.add(new Wrapper(new Geometries(randomTriangle(rnd, size, 3), randomSphere(rnd, size, 0.5, 1))));
        }
        return new TestScene(new Geometries(bodies.toArray(new Intersectable[0])), bodies, size);
    }

    /**
     * A scene whose bodies are spread over composites nested three deep, some of them empty, with a
     * plane and a cylinder.
     *
     * @param rnd   the generator
     * @param n     the number of spheres and triangles
     * @param size  the half-width of the cube the bodies lie in
     * @return the scene
     */
    private static TestScene nestedScene(Random rnd, int n, double size) {
        Geometries root = new Geometries();
        List<Geometries> composites = new ArrayList<>(List.of(root));
        for (int i = 0; i < 3; ++i) {
            Geometries child = new Geometries();
            root.add(child);
            composites.add(child);
            for (int j = 0; j < 2; ++j) {
                Geometries grandchild = new Geometries(new Geometries());
                child.add(grandchild);
                composites.add(grandchild);
            }
        }
        List<Intersectable> bodies = new ArrayList<>();
        for (int i = 0; i < n; ++i) {
            Intersectable body = i % 2 == 0 ? randomSphere(rnd, size, 0.1, 1.5) : randomTriangle(rnd, size, 2);
            composites.get(rnd.nextInt(composites.size())).add(body);
            bodies.add(body);
        }
        Plane plane = new Plane(new Point3D(0, 0, -11), new Vector(0.2, 0.1, 1));
        Cylinder cylinder = randomCylinder(rnd, size);
        composites.get(3).add(plane);
        composites.get(5).add(new Geometries(cylinder));
        bodies.add(plane);
        bodies.add(cylinder);
        return new TestScene(root, bodies, size);
    }

    /**
     * A random point on or in a body, to aim a ray at.
     *
     * @param rnd  the generator
     * @param body the body
     * @return the point
     */
    private static Point3D pointIn(Random rnd, Intersectable body) {
        if (body instanceof Sphere sphere)
            return sphere.getCenter().add(randomUnit(rnd).scale(sphere.getRadius() * (0.01 + 0.98 * rnd.nextDouble())));
        if (body instanceof Polygon polygon) {
            List<Point3D> vertices = polygon.getVertices();
            double[] weights = new double[vertices.size()];
            double sum = 0;
            for (int i = 0; i < weights.length; ++i)
                sum += weights[i] = -Math.log(1 - rnd.nextDouble());
            double x = 0;
            double y = 0;
            double z = 0;
            for (int i = 0; i < weights.length; ++i) {
                x += weights[i] / sum * vertices.get(i).getX();
                y += weights[i] / sum * vertices.get(i).getY();
                z += weights[i] / sum * vertices.get(i).getZ();
            }
            return new Point3D(x, y, z);
        }
        if (body instanceof Cylinder cylinder)
            return cylinder.getAxisRay().getPoint(cylinder.getHeight() * rnd.nextDouble());
        if (body instanceof Wrapper wrapper)
            return pointIn(rnd, wrapper.inner);
        if (body instanceof Geometries composite)
            return pointIn(rnd, composite.getGeometries().get(0));
        return randomPoint(rnd, Point3D.ZERO, 5);
    }

    /**
     * A random ray through a scene: from anywhere around or inside it, half of them aimed at a point
     * of a random body, some along a coordinate axis.
     *
     * @param rnd   the generator
     * @param scene the scene
     * @return the ray
     */
    private static Ray randomRay(Random rnd, TestScene scene) {
        List<Intersectable> bodies = scene.bodies();
        double choice = rnd.nextDouble();
        Point3D origin = choice < 0.15 ? pointIn(rnd, bodies.get(rnd.nextInt(bodies.size())))
                : randomPoint(rnd, Point3D.ZERO, 1.5 * scene.size());
        double aim = rnd.nextDouble();
        if (aim < 0.1) {
            double sign = rnd.nextBoolean() ? 1 : -1;
            double zero = rnd.nextBoolean() ? 0.0 : -0.0;
            int axis = rnd.nextInt(3);
            return new Ray(origin, new Vector(axis == 0 ? sign : zero, axis == 1 ? sign : zero, axis == 2 ? sign : zero));
        }
        if (aim < 0.6) {
            Point3D target = pointIn(rnd, bodies.get(rnd.nextInt(bodies.size())));
            if (target.distance(origin) > 1e-6)
                return new Ray(origin, target.subtract(origin));
        }
        return new Ray(origin, randomUnit(rnd));
    }

    // ---------------------------------------------------------------- references and assertions

    /**
     * The brute-force closest hit: every intersection of the composite, the nearest kept.
     *
     * @param geometries the composite
     * @param ray        the ray
     * @return the nearest intersection, or null
     */
    private static GeoPoint reference(Intersectable geometries, Ray ray) {
        return ray.findClosestGeoPoint(renderedIntersections(geometries, ray, Double.POSITIVE_INFINITY));
    }

    /**
     * The brute-force intersections by the renderer's rule: every body's own query, except that
     * polygons are closed (the course's {@link Intersectable#findGeoIntersections} takes them as open).
     *
     * @param item the body or composite
     * @param ray  the ray
     * @param maxT the largest distance that counts
     * @return the intersections, or null when there is none
     */
    private static List<GeoPoint> renderedIntersections(Intersectable item, Ray ray, double maxT) {
        if (item instanceof Polygon polygon)
            return polygon.singleHit(ray, maxT);
        if (!(item instanceof Geometries composite))
            return item.findGeoIntersections(ray, maxT);
        List<GeoPoint> all = new ArrayList<>();
        for (Intersectable child : composite.getGeometries()) {
            List<GeoPoint> hits = renderedIntersections(child, ray, maxT);
            if (hits != null)
                all.addAll(hits);
        }
        return all.isEmpty() ? null : all;
    }

    /**
     * The brute-force transmittance: the product of the kT at every intersection up to a distance.
     *
     * @param geometries the composite
     * @param ray        the ray
     * @param maxT       the distance
     * @return the product (1 when nothing is crossed)
     */
    private static double referenceTransmittance(Intersectable geometries, Ray ray, double maxT) {
        List<GeoPoint> hits = renderedIntersections(geometries, ray, maxT);
        double product = 1;
        if (hits != null)
            for (GeoPoint hit : hits)
                product *= hit.geometry.getMaterial().getKt();
        return product;
    }

    /**
     * The hierarchy's transmittance along a ray.
     *
     * @param bvh   the hierarchy (or scan)
     * @param ray   the ray
     * @param maxT  the distance
     * @param minK  the cut-off
     * @param query the scratch space
     * @return the transmittance
     */
    private static double transmittance(BoundingVolumeHierarchy bvh, Ray ray, double maxT, double minK, Query query) {
        Point3D p = ray.getP0();
        Vector d = ray.getDir();
        return bvh.transmittance(query.setRay(p.getX(), p.getY(), p.getZ(), d.getX(), d.getY(), d.getZ(), maxT), minK);
    }

    /**
     * Asserts that a hit is the expected one: both null, or the same body (either of two bodies hit
     * at the same distance) at the same point.
     *
     * @param expected the brute-force hit
     * @param actual   the hit found
     * @param ray      the ray
     * @param message  the failure message
     */
    private static void assertSameHit(GeoPoint expected, GeoPoint actual, Ray ray, String message) {
        if (expected == null) {
            assertNull(actual, message + ": no hit expected for " + ray);
            return;
        }
        assertNotNull(actual, message + ": expected " + expected + " for " + ray);
        Point3D p0 = ray.getP0();
        if (actual.geometry != expected.geometry)
            assertEquals(p0.distance(expected.point), p0.distance(actual.point), TIE,
                    message + ": another body hit (not a tie) for " + ray + ": expected " + expected + ", got " + actual);
        assertPoint(expected.point, actual.point, message + " for " + ray);
    }

    /**
     * Asserts a point's coordinates within {@link #POINT_DELTA}.
     *
     * @param expected the expected point
     * @param actual   the actual point
     * @param message  the failure message
     */
    private static void assertPoint(Point3D expected, Point3D actual, String message) {
        assertEquals(expected.getX(), actual.getX(), POINT_DELTA, message + " (x)");
        assertEquals(expected.getY(), actual.getY(), POINT_DELTA, message + " (y)");
        assertEquals(expected.getZ(), actual.getZ(), POINT_DELTA, message + " (z)");
    }

    /**
     * Asserts that the hierarchy, the linear scan and the brute force all find the expected hit.
     *
     * @param geometries the composite
     * @param ray        the ray
     * @param expected   the expected point, or null for no hit
     * @param tc         the test-case label
     */
    private static void assertHitEverywhere(Intersectable geometries, Ray ray, Point3D expected, String tc) {
        for (BoundingVolumeHierarchy bvh : List.of(BoundingVolumeHierarchy.build(geometries),
                BoundingVolumeHierarchy.scan(geometries))) {
            GeoPoint hit = bvh.closestHit(ray, bvh.newQuery());
            if (expected == null)
                assertNull(hit, tc + ": no hit expected for " + ray);
            else {
                assertNotNull(hit, tc + ": a hit expected for " + ray);
                assertPoint(expected, hit.point, tc + ": wrong hit point");
            }
            assertSameHit(reference(geometries, ray), hit, ray, tc + ": differs from the brute force");
        }
    }

    // ---------------------------------------------------------------- tests

    /**
     * Test method for {@link BoundingVolumeHierarchy#closestHit(Ray, Query)}
     * against the brute force, on 20 random scenes × 500 random rays.
     */
    @Test
    void testClosestHitRandomScenes() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 20 seeded scenes of 1..2000 spheres and triangles (with planes, a tube, cylinders,
        // squares, bodies that are not Geometry, nested composites, many tiny triangles, all boxes
        // about one centre): the hierarchy and the scan give the brute-force closest hit of each ray
        Random rnd = new Random(20240611);
        int hits = 0;
        for (int s = 0; s < 20; ++s) {
            TestScene scene = randomScene(rnd, s);
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries());
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene.geometries());
            Query query = bvh.newQuery();
            Query scanQuery = scan.newQuery();
            for (int r = 0; r < 500; ++r) {
                Ray ray = randomRay(rnd, scene);
                GeoPoint expected = reference(scene.geometries(), ray);
                if (expected != null)
                    ++hits;
                assertSameHit(expected, bvh.closestHit(ray, query), ray, "TC01: scene " + s + " ray " + r + " (tree)");
                assertSameHit(expected, scan.closestHit(ray, scanQuery), ray, "TC01: scene " + s + " ray " + r + " (scan)");
            }
        }
        // the rays are aimed so that most of them hit something: the comparison is not vacuous
        assertTrue(hits > 20 * 500 / 2, "TC01: too few rays hit anything (" + hits + ")");
        // TC02: two rows of 8 spheres of radius 1 along z, at z = 0..70 and z = 1000..1070 (the root
        // splits them, and both children are met): a ray along +z from z = −50 hits the near row's
        // first sphere at 49, one along −z from z = 2000 the far row's last at 929; once that hit is
        // found, the other row, set aside on the stack, lies beyond it
        Geometries rows = new Geometries();
        for (int i = 0; i < 8; ++i)
            rows.add(new Sphere(new Point3D(0, 0, 10 * i), 1), new Sphere(new Point3D(0, 0, 1000 + 10 * i), 1));
        BoundingVolumeHierarchy rowsTree = BoundingVolumeHierarchy.build(rows);
        Query rowsQuery = rowsTree.newQuery();
        Ray forward = new Ray(new Point3D(0, 0, -50), new Vector(0, 0, 1));
        Ray backward = new Ray(new Point3D(0, 0, 2000), new Vector(0, 0, -1));
        assertPoint(new Point3D(0, 0, -1), rowsTree.closestHit(forward, rowsQuery).point, "TC02: forward");
        assertPoint(new Point3D(0, 0, 1071), rowsTree.closestHit(backward, rowsQuery).point, "TC02: backward");
        assertSameHit(reference(rows, forward), rowsTree.closestHit(forward, rowsQuery), forward, "TC02: forward");
        assertSameHit(reference(rows, backward), rowsTree.closestHit(backward, rowsQuery), backward, "TC02: backward");

        // ===== Boundary Values Tests =====
        // TC11: 8 spheres of radius 0.5 at x = 2^24 + 1 + 3i (no float holds these numbers: the tree's
        // boxes, in floats, are rounded outward), rays along −z through points 1e-7 inside each sphere's
        // outline at its lowest and highest x: every one hits, as the brute-force search finds
        Geometries far = new Geometries();
        double x0 = (1 << 24) + 1;
        for (int i = 0; i < 8; ++i)
            far.add(new Sphere(new Point3D(x0 + 3 * i, 0.3, 0), 0.5));
        BoundingVolumeHierarchy farTree = BoundingVolumeHierarchy.build(far);
        assertTrue(farTree.getNodesCount() > 1, "TC11: the spheres must be split into several nodes");
        Query farQuery = farTree.newQuery();
        for (int i = 0; i < 8; ++i)
            for (double side : new double[] { -1, 1 }) {
                Ray ray = new Ray(new Point3D(x0 + 3 * i + side * (0.5 - 1e-7), 0.3, 10), new Vector(0, 0, -1));
                GeoPoint expected = reference(far, ray);
                assertTrue(expected != null, "TC11: sphere " + i + " must be hit near its outline");
                assertSameHit(expected, farTree.closestHit(ray, farQuery), ray, "TC11: sphere " + i + " side " + side);
            }
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#transmittance} on opaque scenes: an any-hit
     * query, 0 exactly when the closest hit is within the distance.
     */
    @Test
    void testTransmittanceOpaque() {
        // ===== Equivalence Partitions Tests =====
        // TC01: opaque random scenes, random distances: 0 when the closest hit is at most that far, else 1
        Random rnd = new Random(77);
        int blocked = 0;
        int open = 0;
        for (int s : new int[] { 0, 2, 5, 6, 8, 9, 12, 13, 15, 17, 19 }) {
            TestScene scene = randomScene(rnd, s);
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries());
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene.geometries());
            Query query = bvh.newQuery();
            for (int r = 0; r < 300; ++r) {
                Ray ray = randomRay(rnd, scene);
                GeoPoint closest = reference(scene.geometries(), ray);
                double t = closest == null ? Double.POSITIVE_INFINITY : ray.getP0().distance(closest.point);
                // random distances, and distances just before and just past the hit
                double[] distances = { 60 * rnd.nextDouble(), t + 1e-5, Math.max(1e-7, t - 1e-5),
                        Double.POSITIVE_INFINITY };
                for (double d : distances) {
                    if (closest != null && Math.abs(t - d) < MARGIN)
                        continue;
                    double expected = closest != null && t <= d ? 0 : 1;
                    if (expected == 0)
                        ++blocked;
                    else
                        ++open;
                    String tc = "TC01: scene " + s + " ray " + r + " " + ray + " distance " + d;
                    assertEquals(expected, transmittance(bvh, ray, d, MIN_K, query), 0, tc + " (tree)");
                    assertEquals(expected, transmittance(bvh, ray, d, 0, query), 0, tc + " (tree, no cut-off)");
                    assertEquals(expected, transmittance(scan, ray, d, MIN_K, scan.newQuery()), 0, tc + " (scan)");
                }
            }
        }
        assertTrue(blocked > 1000 && open > 1000, "TC01: too few blocked (" + blocked + ") or open (" + open + ") rays");

        // ===== Boundary Values Tests =====
        // TC11: a sphere at distance 4..6 along the ray: distance 4 − 1e-9 gives 1, 4 gives 0 (the hit counts)
        Geometries one = new Geometries(new Sphere(new Point3D(0, 0, -5), 1));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(one);
        Ray down = new Ray(new Point3D(0, 0, 0), new Vector(0, 0, -1));
        assertEquals(1, transmittance(bvh, down, 4 - 1e-9, MIN_K, bvh.newQuery()), 0, "TC11: hit beyond the distance");
        assertEquals(0, transmittance(bvh, down, 4, MIN_K, bvh.newQuery()), 0, "TC11: hit at the distance");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#transmittance} on transparent scenes: the
     * product of kT over the intersections up to the distance.
     */
    @Test
    void testTransmittanceTransparent() {
        // ===== Equivalence Partitions Tests =====
        // TC01: random kT (0.5, 0.9, 0.25, 1, some opaque): the product of kT over the intersections
        // up to d (polygons closed), and 0 below the cut-off; the scan gives the same
        Random rnd = new Random(4242);
        double[] kts = { 0.5, 0.9, 0.25, 1, 0.75, 0.999, 0.5, 0.9, 0 };
        int partial = 0;
        for (int s : new int[] { 0, 4, 5, 6, 8, 9, 13, 15, 18, 19 }) {
            TestScene scene = randomScene(rnd, s);
            for (Intersectable body : scene.bodies())
                setKt(body, kts, rnd);
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries());
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene.geometries());
            Query query = bvh.newQuery();
            Query scanQuery = scan.newQuery();
            for (int r = 0; r < 300; ++r) {
                Ray ray = randomRay(rnd, scene);
                double d = rnd.nextInt(8) == 0 ? Double.POSITIVE_INFINITY : 60 * rnd.nextDouble();
                if (nearAHit(scene.geometries(), ray, d))
                    continue;
                double expected = referenceTransmittance(scene.geometries(), ray, d);
                if (expected > 0 && expected < 1)
                    ++partial;
                String tc = "TC01: scene " + s + " ray " + r + " " + ray + " distance " + d;
                assertEquals(expected, transmittance(bvh, ray, d, 0, query), 1e-12, tc + " (tree)");
                assertEquals(expected, transmittance(scan, ray, d, 0, scanQuery), 1e-12, tc + " (scan)");
                double cut = expected < MIN_K ? 0 : expected;
                assertEquals(cut, transmittance(bvh, ray, d, MIN_K, query), 1e-12, tc + " (tree, cut-off)");
                assertEquals(cut, transmittance(scan, ray, d, MIN_K, scanQuery), 1e-12, tc + " (scan, cut-off)");
            }
        }
        assertTrue(partial > 500, "TC01: too few rays through transparent bodies (" + partial + ")");

        // ===== Boundary Values Tests =====
        // TC11: a sphere of kT 0.5 crossed twice and a triangle of kT 0.5 behind it: 0.25 up to the
        // triangle, 0.125 past it; with the cut-off 0.2 the second is 0
        Geometries glass = new Geometries(
                new Sphere(new Point3D(0, 0, -5), 1).setMaterial(new Material().setKt(0.5)),
                new Triangle(new Point3D(-1, -1, -8), new Point3D(1, -1, -8), new Point3D(0, 1, -8))
                        .setMaterial(new Material().setKt(0.5)));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(glass);
        Ray down = new Ray(new Point3D(0, 0, 0), new Vector(0, 0, -1));
        assertEquals(0.25, transmittance(bvh, down, 7, 0, bvh.newQuery()), 1e-12, "TC11: two sphere crossings");
        assertEquals(0.125, transmittance(bvh, down, 8, 0, bvh.newQuery()), 1e-12, "TC11: and the triangle");
        assertEquals(0, transmittance(bvh, down, 8, 0.2, bvh.newQuery()), 0, "TC11: below the cut-off");
        // TC12: a ray starting inside the sphere crosses it once: 0.5
        Ray inside = new Ray(new Point3D(0, 0, -5), new Vector(0, 0, 1));
        assertEquals(0.5, transmittance(bvh, inside, 10, 0, bvh.newQuery()), 1e-12, "TC12: one crossing from inside");
    }

    /**
     * Sets a random kT on a body (on the body inside a wrapper or a composite).
     *
     * @param body the body
     * @param kts  the kT values to draw from
     * @param rnd  the generator
     */
    private static void setKt(Intersectable body, double[] kts, Random rnd) {
        if (body instanceof Geometry geometry)
            geometry.setMaterial(new Material().setKt(kts[rnd.nextInt(kts.length)]));
        else if (body instanceof Wrapper wrapper)
            setKt(wrapper.inner, kts, rnd);
        else if (body instanceof Geometries composite)
            for (Intersectable child : composite.getGeometries())
                setKt(child, kts, rnd);
    }

    /**
     * Whether any intersection of a ray lies within {@link #MARGIN} of a distance.
     *
     * @param geometries the composite
     * @param ray        the ray
     * @param d          the distance
     * @return true when the answer would hang on rounding
     */
    private static boolean nearAHit(Intersectable geometries, Ray ray, double d) {
        List<GeoPoint> hits = renderedIntersections(geometries, ray, Double.POSITIVE_INFINITY);
        if (hits != null)
            for (GeoPoint hit : hits)
                if (Math.abs(ray.getP0().distance(hit.point) - d) < MARGIN)
                    return true;
        return false;
    }

    /**
     * Test method for the shape of the tree: {@link BoundingVolumeHierarchy#getNodesCount()},
     * {@link BoundingVolumeHierarchy#getDepth()} and {@link BoundingVolumeHierarchy#getBoundedCount()}.
     */
    @Test
    void testStructure() {
        Random rnd = new Random(5);
        Ray anyRay = new Ray(new Point3D(0, 0, 100), new Vector(0, 0, -1));

        // ===== Equivalence Partitions Tests =====
        // TC01: 1000 spread spheres: one node per body at most (2n − 1), an odd count (every inner
        // node has two children), depth well below the limit of 64
        Geometries spread = new Geometries();
        for (int i = 0; i < 1000; ++i)
            spread.add(randomSphere(rnd, 100, 0.1, 1));
        BoundingVolumeHierarchy big = BoundingVolumeHierarchy.build(spread);
        assertEquals(1000, big.getBoundedCount(), "TC01: wrong bounded count");
        assertTrue(big.getNodesCount() > 1 && big.getNodesCount() <= 2 * 1000 - 1,
                "TC01: wrong nodes count " + big.getNodesCount());
        assertEquals(1, big.getNodesCount() % 2, "TC01: a full binary tree has an odd nodes count");
        assertTrue(big.getDepth() >= 2 && big.getDepth() <= 32, "TC01: depth " + big.getDepth() + " is not well below 64");

        // TC02: planes and tubes stay outside the tree and are not counted; a cylinder is bounded
        Geometries mixed = new Geometries(new Sphere(new Point3D(0, 0, 0), 1),
                new Triangle(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)),
                new Plane(new Point3D(0, 0, -1), new Vector(0, 0, 1)),
                new Tube(new Ray(Point3D.ZERO, new Vector(1, 0, 0)), 1),
                new Cylinder(new Ray(Point3D.ZERO, new Vector(0, 1, 0)), 1, 2),
                new Geometries(new Plane(new Point3D(0, 0, -3), new Vector(0, 1, 1))));
        BoundingVolumeHierarchy mixedBvh = BoundingVolumeHierarchy.build(mixed);
        assertEquals(3, mixedBvh.getBoundedCount(), "TC02: planes and tubes must not be counted");
        assertEquals(1, mixedBvh.getNodesCount(), "TC02: 3 bodies make one leaf");

        // TC03: 5 spheres far apart along x: splitting pays, so more than one node
        Geometries five = new Geometries();
        for (int i = 0; i < 5; ++i)
            five.add(new Sphere(new Point3D(100 * i, 0, 0), 1));
        BoundingVolumeHierarchy fiveBvh = BoundingVolumeHierarchy.build(five);
        assertTrue(fiveBvh.getNodesCount() >= 3, "TC03: 5 spread spheres must be split");
        assertTrue(fiveBvh.getDepth() >= 2, "TC03: 5 spread spheres must be split");

        // TC04: the scan has no tree: 0 nodes, depth 0, nothing in a tree
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(spread);
        assertEquals(0, scan.getNodesCount(), "TC04: the scan has no nodes");
        assertEquals(0, scan.getDepth(), "TC04: the scan has no depth");
        assertEquals(0, scan.getBoundedCount(), "TC04: the scan has nothing in a tree");

        // ===== Boundary Values Tests =====
        // TC11: an empty composite (also one of empty composites): 0 nodes, depth 0, no hit, transmittance 1
        for (Geometries empty : emptyComposites()) {
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(empty);
            assertEquals(0, bvh.getNodesCount(), "TC11: an empty composite has no nodes");
            assertEquals(0, bvh.getDepth(), "TC11: an empty composite has depth 0");
            assertEquals(0, bvh.getBoundedCount(), "TC11: an empty composite has no bodies");
            assertNull(bvh.closestHit(anyRay, bvh.newQuery()), "TC11: an empty composite is never hit");
            assertEquals(1, transmittance(bvh, anyRay, 1000, MIN_K, bvh.newQuery()), 0, "TC11: nothing blocks the light");
        }

        // TC12: one body (also given bare, not in a composite): 1 node, depth 1, found
        Sphere lone = new Sphere(new Point3D(0, 0, 0), 1);
        for (Intersectable single : List.of(new Geometries(lone), lone)) {
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(single);
            assertEquals(1, bvh.getNodesCount(), "TC12: one body makes one node");
            assertEquals(1, bvh.getDepth(), "TC12: one body makes depth 1");
            assertEquals(1, bvh.getBoundedCount(), "TC12: one body in the tree");
            GeoPoint hit = bvh.closestHit(anyRay, bvh.newQuery());
            assertSame(lone, hit.geometry, "TC12: the body must be hit");
            assertPoint(new Point3D(0, 0, 1), hit.point, "TC12: wrong hit point");
        }

        // TC13: 2, 3 and 4 bodies, even far apart: one leaf
        for (int n = 2; n <= 4; ++n) {
            Geometries few = new Geometries();
            for (int i = 0; i < n; ++i)
                few.add(new Sphere(new Point3D(100 * i, 0, 0), 1));
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(few);
            assertEquals(1, bvh.getNodesCount(), "TC13: " + n + " bodies make one leaf");
            assertEquals(1, bvh.getDepth(), "TC13: " + n + " bodies make depth 1");
        }

        // TC14: only unbounded bodies: no tree, yet the plane is hit
        BoundingVolumeHierarchy planes = BoundingVolumeHierarchy.build(
                new Geometries(new Plane(new Point3D(0, 0, -1), new Vector(0, 0, 1))));
        assertEquals(0, planes.getNodesCount(), "TC14: a plane makes no node");
        assertEquals(0, planes.getBoundedCount(), "TC14: a plane is not bounded");
        assertPoint(new Point3D(0, 0, -1), planes.closestHit(anyRay, planes.newQuery()).point, "TC14: the plane must be hit");

        // TC15: 2000 bodies whose boxes share one centre cannot be split apart usefully: the tree
        // stays within the limits and every body is kept
        TestScene sameCentre = randomScene(rnd, 14);
        BoundingVolumeHierarchy centred = BoundingVolumeHierarchy.build(sameCentre.geometries());
        assertEquals(sameCentre.bodies().size(), centred.getBoundedCount(), "TC15: every body must be in the tree");
        assertTrue(centred.getDepth() <= 64, "TC15: depth over the limit");
        assertTrue(centred.getNodesCount() <= 2 * centred.getBoundedCount() - 1, "TC15: too many nodes");

        // TC16: the hierarchy is built once: a body added to the composite afterwards is not seen
        // (build a new hierarchy after changing the scene)
        Geometries growing = new Geometries(new Sphere(new Point3D(10, 0, 0), 1));
        BoundingVolumeHierarchy before = BoundingVolumeHierarchy.build(growing);
        growing.add(new Sphere(new Point3D(0, 0, 0), 1));
        assertNotNull(growing.findGeoIntersections(anyRay), "TC16: the composite itself sees the new body");
        assertNull(before.closestHit(anyRay, before.newQuery()), "TC16: the hierarchy must not see a body added after it");
        assertEquals(1, transmittance(before, anyRay, 1000, MIN_K, before.newQuery()), 0,
                "TC16: the new body must not block the old hierarchy's light");
        assertEquals(1, before.getBoundedCount(), "TC16: the count must stay as built");
        BoundingVolumeHierarchy after = BoundingVolumeHierarchy.build(growing);
        assertPoint(new Point3D(0, 0, 1), after.closestHit(anyRay, after.newQuery()).point,
                "TC16: a new hierarchy must see the new body");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#build(Intersectable, int)}: a build shared out
     * among threads answers every query as the one built on one thread and as the brute force.
     */
    @Test
    void testParallelBuildRandomScenes() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 20 seeded scenes (1..2000 bodies, some transparent), built on 2, 3 and 8 threads: the
        // same shape (nodes, depth, bodies) as on one thread, the same closest hit (the same body at
        // the same point) and the same transmittance of each ray, and the brute force's answers
        Random rnd = new Random(16);
        double[] kts = { 0, 0, 0.5, 0.9 };
        int hits = 0;
        for (int s = 0; s < 20; ++s) {
            TestScene scene = randomScene(rnd, s);
            for (Intersectable body : scene.bodies())
                setKt(body, kts, rnd);
            BoundingVolumeHierarchy single = BoundingVolumeHierarchy.build(scene.geometries());
            for (int threads : new int[] { 2, 3, 8 }) {
                BoundingVolumeHierarchy parallel = BoundingVolumeHierarchy.build(scene.geometries(), threads);
                String tc = "TC01: scene " + s + ", " + threads + " threads";
                assertEquals(single.getNodesCount(), parallel.getNodesCount(), tc + ": wrong nodes count");
                assertEquals(single.getDepth(), parallel.getDepth(), tc + ": wrong depth");
                assertEquals(single.getBoundedCount(), parallel.getBoundedCount(), tc + ": wrong bounded count");
                for (int r = 0; r < 100; ++r) {
                    Ray ray = randomRay(rnd, scene);
                    GeoPoint expected = single.closestHit(ray, single.newQuery());
                    GeoPoint actual = parallel.closestHit(ray, parallel.newQuery());
                    assertSameHit(reference(scene.geometries(), ray), actual, ray, tc + " ray " + r + " (brute force)");
                    if (expected != null) {
                        ++hits;
                        assertSame(expected.geometry, actual.geometry, tc + " ray " + r + ": another body hit");
                        assertPoint(expected.point, actual.point, tc + " ray " + r);
                    }
                    double d = 60 * rnd.nextDouble();
                    assertEquals(transmittance(single, ray, d, 0, single.newQuery()),
                            transmittance(parallel, ray, d, 0, parallel.newQuery()), 1e-12,
                            tc + " ray " + r + ": wrong transmittance");
                }
            }
        }
        assertTrue(hits > 3 * 20 * 100 / 2, "TC01: too few rays hit anything (" + hits + ")");

        // ===== Boundary Values Tests =====
        // TC11: more threads than bodies (1, 2 and 5 bodies on 8 threads): the same tree as on one thread
        Ray down = new Ray(new Point3D(0, 0, 100), new Vector(0, 0, -1));
        for (int n : new int[] { 1, 2, 5 }) {
            Geometries few = new Geometries();
            for (int i = 0; i < n; ++i)
                few.add(new Sphere(new Point3D(100 * i, 0, 0), 1));
            BoundingVolumeHierarchy parallel = BoundingVolumeHierarchy.build(few, 8);
            assertEquals(BoundingVolumeHierarchy.build(few).getNodesCount(), parallel.getNodesCount(),
                    "TC11: " + n + " bodies: wrong nodes count");
            assertPoint(new Point3D(0, 0, 1), parallel.closestHit(down, parallel.newQuery()).point,
                    "TC11: " + n + " bodies: the first sphere must be hit");
        }
        // TC12: an empty composite on 2 threads: no nodes, no hit
        BoundingVolumeHierarchy empty = BoundingVolumeHierarchy.build(new Geometries(), 2);
        assertEquals(0, empty.getNodesCount(), "TC12: an empty composite has no nodes");
        assertNull(empty.closestHit(down, empty.newQuery()), "TC12: an empty composite is never hit");
    }

    /** Test method for {@link BoundingVolumeHierarchy#isBuiltFrom(Intersectable)}. */
    @Test
    void testIsBuiltFrom() {
        Geometries inner = new Geometries(new Sphere(new Point3D(5, 0, 0), 1));
        Geometries scene = new Geometries(new Sphere(new Point3D(0, 0, 0), 1), inner);
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene, 2);

        // ===== Equivalence Partitions Tests =====
        // TC01: the same composite, unchanged: up to date (true)
        assertTrue(bvh.isBuiltFrom(scene), "TC01: an unchanged composite must be up to date");
        // TC02: another composite with the same bodies: out of date (false)
        assertFalse(bvh.isBuiltFrom(new Geometries(scene.getGeometries().toArray(new Intersectable[0]))),
                "TC02: another composite must be out of date");
        // TC03: a body added to a nested composite: out of date (false), and a new build is up to date
        inner.add(new Sphere(new Point3D(10, 0, 0), 1));
        assertFalse(bvh.isBuiltFrom(scene), "TC03: a body added to a nested composite must be seen");
        bvh = BoundingVolumeHierarchy.build(scene);
        assertTrue(bvh.isBuiltFrom(scene), "TC03: a new build must be up to date");
        // TC04: a body added to the composite itself: out of date (false)
        scene.add(new Triangle(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)));
        assertFalse(bvh.isBuiltFrom(scene), "TC04: a body added to the composite must be seen");
        // TC05: the brute-force scan knows the same (true, then false after an addition)
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene);
        assertTrue(scan.isBuiltFrom(scene), "TC05: an unchanged composite must be up to date for the scan");
        inner.add(new Plane(new Point3D(0, 0, -1), new Vector(0, 0, 1)));
        assertFalse(scan.isBuiltFrom(scene), "TC05: a body added must be seen by the scan");

        // ===== Boundary Values Tests =====
        // TC11: a composite nested after the build, then a body added to it: out of date both times (false)
        Geometries late = new Geometries();
        bvh = BoundingVolumeHierarchy.build(scene);
        scene.add(late);
        assertFalse(bvh.isBuiltFrom(scene), "TC11: a composite nested after the build must be seen");
        bvh = BoundingVolumeHierarchy.build(scene);
        late.add(new Sphere(new Point3D(0, 5, 0), 1));
        assertFalse(bvh.isBuiltFrom(scene), "TC11: a body added to a late nested composite must be seen");
        // TC12: a single body, not a composite: up to date for itself (true), not for another body (false)
        Sphere lone = new Sphere(new Point3D(0, 0, 0), 1);
        BoundingVolumeHierarchy single = BoundingVolumeHierarchy.build(lone);
        assertTrue(single.isBuiltFrom(lone), "TC12: a single body must be up to date");
        assertFalse(single.isBuiltFrom(new Sphere(new Point3D(0, 0, 0), 1)), "TC12: another body must be out of date");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#build(Intersectable)},
     * {@link BoundingVolumeHierarchy#build(Intersectable, int)} and
     * {@link BoundingVolumeHierarchy#scan(Intersectable)} with bad input.
     */
    @Test
    void testBadInput() {
        // ===== Boundary Values Tests =====
        // TC11: a null composite
        assertMessage(assertThrows(IllegalArgumentException.class, () -> BoundingVolumeHierarchy.build(null),
                "TC11: build(null) must throw"), "geometries", "TC11");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> BoundingVolumeHierarchy.scan(null),
                "TC11: scan(null) must throw"), "geometries", "TC11");
        // TC12: no thread to build on (0 threads)
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> BoundingVolumeHierarchy.build(new Geometries(), 0), "TC12: 0 threads must throw"),
                "threads", "TC12");
    }

    /**
     * Test method for rays along a coordinate axis: zero direction components make the slab test
     * divide by zero (±∞, and 0·∞ = NaN on a slab's face).
     */
    @Test
    void testAxisRays() {
        // a 7×7×7 grid of spheres of radius 0.4 at integer points, and triangles in the planes x = ±3.5
        Geometries grid = new Geometries();
        for (int i = -3; i <= 3; ++i)
            for (int j = -3; j <= 3; ++j)
                for (int k = -3; k <= 3; ++k)
                    grid.add(new Sphere(new Point3D(i, j, k), 0.4));
        grid.add(new Triangle(new Point3D(3.5, -4, -4), new Point3D(3.5, 4, -4), new Point3D(3.5, 0, 4)),
                new Triangle(new Point3D(-3.5, -4, -4), new Point3D(-3.5, 4, -4), new Point3D(-3.5, 0, 4)));

        // ===== Equivalence Partitions Tests =====
        // TC01: down the z axis through a column of spheres: the top sphere at (i, j, 3.4)
        assertHitEverywhere(grid, new Ray(new Point3D(1, -2, 10), new Vector(0, 0, -1)), new Point3D(1, -2, 3.4), "TC01");
        // TC02: along −x, direction components −0.0: the triangle at x = 3.5 first, at (3.5, 0, 0)
        assertHitEverywhere(grid, new Ray(new Point3D(10, 0, 0), new Vector(-1, -0.0, -0.0)), new Point3D(3.5, 0, 0), "TC02");
        // TC03: along +y between the spheres' columns: no hit
        assertHitEverywhere(grid, new Ray(new Point3D(0.5, -10, 0.5), new Vector(0, 1, 0)), null, "TC03");
        // TC04: random rays along the axes, ±0.0 components, from grid points and half-grid points
        Random rnd = new Random(9);
        for (int r = 0; r < 600; ++r) {
            double[] o = new double[3];
            for (int k = 0; k < 3; ++k)
                o[k] = rnd.nextInt(3) == 0 ? rnd.nextInt(21) / 2.0 - 5 : 10 * rnd.nextDouble() - 5;
            int axis = rnd.nextInt(3);
            double sign = rnd.nextBoolean() ? 1 : -1;
            double zero = rnd.nextBoolean() ? 0.0 : -0.0;
            Ray ray = new Ray(new Point3D(o[0], o[1], o[2]),
                    new Vector(axis == 0 ? sign : zero, axis == 1 ? sign : zero, axis == 2 ? sign : zero));
            assertHitEverywhere(grid, ray, pointOrNull(reference(grid, ray)), "TC04: ray " + r);
        }

        // ===== Boundary Values Tests =====
        // TC11: a ray along z touching the spheres of the column x = 0, y = 0 (x = 0.4): tangent, no hit
        assertHitEverywhere(grid, new Ray(new Point3D(0.4, 0, 10), new Vector(0, 0, -1)), null, "TC11");
        // TC12: a ray down z starting exactly on the top of the grid's box (z = 3.4), on the top of a
        // sphere: the start does not count, so the sphere's bottom at (0, 0, 2.6)
        assertHitEverywhere(grid, new Ray(new Point3D(0, 0, 3.4), new Vector(0, 0, -1)), new Point3D(0, 0, 2.6), "TC12");
        // TC13: the same ray up: it leaves the grid, no hit
        assertHitEverywhere(grid, new Ray(new Point3D(0, 0, 3.4), new Vector(0, 0, 1)), null, "TC13");
    }

    /**
     * The point of a hit, or null.
     *
     * @param hit the hit (may be null)
     * @return its point
     */
    private static Point3D pointOrNull(GeoPoint hit) {
        return hit == null ? null : hit.point;
    }

    /**
     * Test method for rays starting exactly on a box face: a closed unit cube of 12 triangles (its box
     * is the cube) with a sphere inside.
     */
    @Test
    void testRaysOnBoxFaces() {
        Geometries cube = new Geometries(cube(0, 1));
        Geometries withBall = new Geometries(cube(0, 1));
        withBall.add(new Sphere(new Point3D(0.5, 0.5, 0.5), 0.25));

        // ===== Equivalence Partitions Tests =====
        // TC01: from the middle of face x = 0 into the cube: the opposite face at (1, 0.5, 0.5)
        assertHitEverywhere(cube, new Ray(new Point3D(0, 0.5, 0.5), new Vector(1, 0, 0)), new Point3D(1, 0.5, 0.5), "TC01");
        // TC02: the same with the ball inside: the ball at (0.25, 0.5, 0.5)
        assertHitEverywhere(withBall, new Ray(new Point3D(0, 0.5, 0.5), new Vector(1, 0, 0)), new Point3D(0.25, 0.5, 0.5), "TC02");
        // TC03: from the face out of the cube: no hit
        assertHitEverywhere(withBall, new Ray(new Point3D(0, 0.5, 0.5), new Vector(-1, 0, 0)), null, "TC03");

        // ===== Boundary Values Tests =====
        // TC11: from face x = 0 along it (x component 0): the edge of face y = 1 at (0, 1, 0.5)
        assertHitEverywhere(cube, new Ray(new Point3D(0, 0.5, 0.5), new Vector(0, 1, 0)), new Point3D(0, 1, 0.5), "TC11");
        // TC12: from the plane of face x = 0, outside the cube, along it (−0.0): face y = 1's edge at (0, 1, 0.5)
        assertHitEverywhere(cube, new Ray(new Point3D(0, 2, 0.5), new Vector(-0.0, -1, 0)), new Point3D(0, 1, 0.5), "TC12");
        // TC13: from face x = 1 (the box's top in x) along z: the edge of face z = 0 at (1, 0.5, 0)
        assertHitEverywhere(cube, new Ray(new Point3D(1, 0.5, 0.5), new Vector(0, 0, -1)), new Point3D(1, 0.5, 0), "TC13");
        // TC14: from a corner of the box along an edge: the other end of the edge, (1, 0, 0)
        assertHitEverywhere(cube, new Ray(new Point3D(0, 0, 0), new Vector(1, 0, 0)), new Point3D(1, 0, 0), "TC14");
        // TC15: random rays from random points of the six faces, random directions and along the faces
        Random rnd = new Random(31);
        for (int r = 0; r < 300; ++r) {
            double[] o = { rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble() };
            int face = rnd.nextInt(3);
            o[face] = rnd.nextInt(2);
            Vector dir = randomUnit(rnd);
            if (rnd.nextBoolean()) {
                double[] d = { dir.getX(), dir.getY(), dir.getZ() };
                d[face] = 0;
                dir = new Vector(d[0], d[1], d[2]);
            }
            Ray ray = new Ray(new Point3D(o[0], o[1], o[2]), dir);
            assertHitEverywhere(withBall, ray, pointOrNull(reference(withBall, ray)), "TC15: ray " + r);
        }
    }

    /**
     * The 12 triangles of a closed axis-aligned cube.
     *
     * @param lo the low corner's coordinates
     * @param hi the high corner's coordinates
     * @return the triangles
     */
    private static Intersectable[] cube(double lo, double hi) {
        Point3D[] c = new Point3D[8];
        for (int i = 0; i < 8; ++i)
            c[i] = new Point3D((i & 1) == 0 ? lo : hi, (i & 2) == 0 ? lo : hi, (i & 4) == 0 ? lo : hi);
        int[][] faces = { { 0, 2, 6, 4 }, { 1, 5, 7, 3 }, { 0, 4, 5, 1 }, { 2, 3, 7, 6 }, { 0, 1, 3, 2 }, { 4, 6, 7, 5 } };
        List<Intersectable> triangles = new ArrayList<>();
        for (int[] f : faces) {
            triangles.add(new Triangle(c[f[0]], c[f[1]], c[f[2]]));
            triangles.add(new Triangle(c[f[0]], c[f[2]], c[f[3]]));
        }
        return triangles.toArray(new Intersectable[0]);
    }

    /**
     * Test method for rays through edges and vertices shared by triangles: on the renderer's path
     * polygons are closed, so a mesh has no seams, with or without the tree (the course's query on the
     * composite takes them as open).
     */
    @Test
    void testSharedEdges() {
        // ===== Equivalence Partitions Tests =====
        // TC01: two triangles making the square [-1, 1]² at z = 0, split along the diagonal: a ray
        // straight down through (0.3, 0.3) on the diagonal hits one of them there
        Triangle lower = new Triangle(new Point3D(-1, -1, 0), new Point3D(1, -1, 0), new Point3D(1, 1, 0));
        Triangle upper = new Triangle(new Point3D(-1, -1, 0), new Point3D(1, 1, 0), new Point3D(-1, 1, 0));
        Geometries square = new Geometries(lower, upper);
        Ray diagonal = new Ray(new Point3D(0.3, 0.3, 5), new Vector(0, 0, -1));
        assertHitEverywhere(square, diagonal, new Point3D(0.3, 0.3, 0), "TC01");
        GeoPoint hit = BoundingVolumeHierarchy.build(square).closestHit(diagonal, BoundingVolumeHierarchy.build(square).newQuery());
        assertTrue(hit.geometry == lower || hit.geometry == upper, "TC01: one of the two triangles must be hit");
        // TC02: the course's query on the composite, for the same ray through the shared edge (null)
        assertNull(square.findGeoIntersections(diagonal), "TC02: the course's open triangles are missed on their edge");

        // ===== Boundary Values Tests =====
        // TC11: a 20 × 20 grid of squares over [-5, 5]² at z = 0 (800 triangles, diagonals alternating):
        // rays from above and below, slanted, aimed at random points of the grid lines, of the
        // diagonals and at the vertices, all hit the mesh there
        int n = 20;
        double h = 10.0 / n;
        Geometries mesh = new Geometries();
        Point3D[][] v = new Point3D[n + 1][n + 1];
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                v[i][j] = new Point3D(-5 + i * h, -5 + j * h, 0);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                if ((i + j) % 2 == 0)
                    mesh.add(new Triangle(v[i][j], v[i + 1][j], v[i + 1][j + 1]),
                            new Triangle(v[i][j], v[i + 1][j + 1], v[i][j + 1]));
                else
                    mesh.add(new Triangle(v[i][j], v[i + 1][j], v[i][j + 1]),
                            new Triangle(v[i + 1][j], v[i + 1][j + 1], v[i][j + 1]));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(mesh);
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(mesh);
        Query query = bvh.newQuery();
        Random rnd = new Random(12);
        for (int r = 0; r < 1500; ++r) {
            int i = rnd.nextInt(n);
            int j = rnd.nextInt(n);
            double s = rnd.nextDouble();
            Point3D target = switch (r % 4) {
            case 0 -> new Point3D(v[i][j].getX(), -5 + (j + s) * h, 0); // a line x = const
            case 1 -> new Point3D(-5 + (i + s) * h, v[i][j].getY(), 0); // a line y = const
            case 2 -> (i + j) % 2 == 0 // the cell's diagonal
                    ? new Point3D(-5 + (i + s) * h, -5 + (j + s) * h, 0)
                    : new Point3D(-5 + (i + 1 - s) * h, -5 + (j + s) * h, 0);
            default -> v[i][j]; // a vertex
            };
            Point3D origin = randomPoint(rnd, new Point3D(0, 0, rnd.nextBoolean() ? 8 : -8), 5);
            Ray ray = r % 5 == 0 ? new Ray(new Point3D(target.getX(), target.getY(), origin.getZ()),
                    new Vector(0, 0, -Math.signum(origin.getZ()))) : new Ray(origin, target.subtract(origin));
            String tc = "TC11: ray " + r + " at " + target;
            GeoPoint treeHit = bvh.closestHit(ray, query);
            GeoPoint scanHit = scan.closestHit(ray, scan.newQuery());
            assertNotNull(treeHit, tc + ": the mesh has a seam (tree)");
            assertNotNull(scanHit, tc + ": the mesh has a seam (scan)");
            assertPoint(target, treeHit.point, tc + ": wrong hit point (tree)");
            assertPoint(target, scanHit.point, tc + ": wrong hit point (scan)");
            assertEquals(0, transmittance(bvh, ray, 100, MIN_K, query), 0, tc + ": the light leaks through a seam");
        }
    }

    /**
     * Test method for rays starting inside a sphere (the box test clamps to the ray's start).
     */
    @Test
    void testRayInsideSphere() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a lone sphere of radius 2, the ray from (0.5, 0, 0) along x: (2, 0, 0)
        Sphere big = new Sphere(Point3D.ZERO, 2);
        assertHitEverywhere(new Geometries(big), new Ray(new Point3D(0.5, 0, 0), new Vector(1, 0, 0)), new Point3D(2, 0, 0), "TC01");
        // TC02: with a small sphere inside it and 200 small spheres around: the small one at (0.75, 0, 0)
        Random rnd = new Random(3);
        Geometries crowd = new Geometries(big, new Sphere(new Point3D(1, 0, 0), 0.25));
        for (int i = 0; i < 200; ++i)
            crowd.add(new Sphere(randomPoint(rnd, new Point3D(0, 0, 0), 20).add(new Vector(25, 0, 0)), 0.5));
        assertHitEverywhere(crowd, new Ray(Point3D.ZERO, new Vector(1, 0, 0)), new Point3D(0.75, 0, 0), "TC02");
        // TC03: from the centre of the big sphere in random directions: the big sphere at distance 2,
        // or the small one
        for (int r = 0; r < 200; ++r) {
            Ray ray = new Ray(new Point3D(-0.5, 0, 0), randomUnit(rnd));
            assertHitEverywhere(crowd, ray, pointOrNull(reference(crowd, ray)), "TC03: ray " + r);
            assertNotNull(reference(crowd, ray), "TC03: a ray from inside a sphere must hit");
        }

        // ===== Boundary Values Tests =====
        // TC11: from a point on the lone sphere outward: no hit
        Geometries lone = new Geometries(big);
        assertHitEverywhere(lone, new Ray(new Point3D(2, 0, 0), new Vector(1, 0, 0)), null, "TC11");
        // TC12: from a point on the lone sphere inward: the opposite point (−2, 0, 0)
        assertHitEverywhere(lone, new Ray(new Point3D(2, 0, 0), new Vector(-1, 0, 0)), new Point3D(-2, 0, 0), "TC12");
        // TC13: from the centre, the transmittance of an opaque sphere up to 1.9 is 1, up to 2.1 is 0
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(lone);
        Ray fromCentre = new Ray(Point3D.ZERO, new Vector(0, 1, 0));
        assertEquals(1, transmittance(bvh, fromCentre, 1.9, MIN_K, bvh.newQuery()), 0, "TC13: not yet at the sphere");
        assertEquals(0, transmittance(bvh, fromCentre, 2.1, MIN_K, bvh.newQuery()), 0, "TC13: past the sphere");
    }

    /**
     * Test method for hits inside a body's tolerance just outside its exact shape: the closed
     * polygons' edge tolerance and the cylinder's cap tolerance reach past the exact bounding box,
     * and the tree must find what the brute force finds.
     */
    @Test
    void testToleranceMargins() {
        // ===== Boundary Values Tests =====
        // TC11: a sharp triangle (tip at x = −1) hit 3.5e-9 beyond its tip (barycentric tolerance 1e-9)
        Geometries sharp = new Geometries(new Triangle(new Point3D(-1, 0, 0), new Point3D(1, -0.01, 0), new Point3D(1, 0.01, 0)));
        Ray pastTip = new Ray(new Point3D(-1 - 3.5e-9, 0, 5), new Vector(0, 0, -1));
        assertNotNull(reference(sharp, pastTip), "TC11: the triangle's tolerance must take this ray");
        assertHitEverywhere(sharp, pastTip, new Point3D(-1 - 3.5e-9, 0, 0), "TC11");

        // TC12: the same sliver as a Polygon (edge tolerance 1e-9 of its size): hit 1e-7 beyond its tip
        Geometries sliver = new Geometries(new Polygon(new Point3D(-1, 0, 0), new Point3D(1, -0.01, 0), new Point3D(1, 0.01, 0)));
        Ray pastSliver = new Ray(new Point3D(-1 - 1e-7, 0, 5), new Vector(0, 0, -1));
        assertNotNull(reference(sliver, pastSliver), "TC12: the polygon's tolerance must take this ray");
        assertHitEverywhere(sliver, pastSliver, new Point3D(-1 - 1e-7, 0, 0), "TC12");

        // TC13: a thin cylinder (radius 1e-3): a ray along its axis 3e-8 outside the rim hits the top cap
        Geometries thin = new Geometries(new Cylinder(new Ray(Point3D.ZERO, new Vector(0, 0, 1)), 1e-3, 1));
        Ray pastRim = new Ray(new Point3D(1e-3 + 3e-8, 0, 5), new Vector(0, 0, -1));
        assertNotNull(reference(thin, pastRim), "TC13: the cap's tolerance must take this ray");
        assertHitEverywhere(thin, pastRim, new Point3D(1e-3 + 3e-8, 0, 1), "TC13");
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
        public double nearestHit(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
            return NO_HIT;
        }
    }

    /**
     * Test method for the triangles the tree tests from its own copy of their data: only plain
     * {@link Triangle}s are copied, a subclass keeps its own intersection test.
     */
    @Test
    void testTriangleSubclass() {
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

    // ---------------------------------------------------------------- shadow bundles

    /** The thickness of the renderer's bundles whose rays leave the surface on both sides (Ray.DELTA). */
    private static final double THICK = 0.1;
    /** The most bodies of the tree gather keeps one by one (Query.MAX_GATHERED). */
    private static final int MAX_GATHERED = 32;

    /**
     * Sets the query's frustum to a bundle's pyramid, without thickness, and gathers for it.
     *
     * @param bvh   the hierarchy (or scan)
     * @param query the scratch space
     * @param apex  the rays' common origin
     * @param c     the centre of the light's square
     * @param a     half of one side of the square
     * @param b     half of the other side
     * @return what {@link BoundingVolumeHierarchy#gather} returns
     */
    private static boolean gather(BoundingVolumeHierarchy bvh, Query query, Point3D apex, Point3D c, Vector a,
                                  Vector b) {
        return gather(bvh, query, apex, c, a, b, 0);
    }

    /**
     * Sets the query's frustum to a bundle's (thick) pyramid and gathers for it.
     *
     * @param bvh       the hierarchy (or scan)
     * @param query     the scratch space
     * @param apex      the apex
     * @param c         the centre of the light's square
     * @param a         half of one side of the square
     * @param b         half of the other side
     * @param thickness how far the rays may stray from the pyramid
     * @return what {@link BoundingVolumeHierarchy#gather} returns
     */
    private static boolean gather(BoundingVolumeHierarchy bvh, Query query, Point3D apex, Point3D c, Vector a,
                                  Vector b, double thickness) {
        assertTrue(query.getFrustum().set(apex.getX(), apex.getY(), apex.getZ(), c.getX(), c.getY(), c.getZ(),
                a.getX(), a.getY(), a.getZ(), b.getX(), b.getY(), b.getZ(), thickness),
                "the bundle's pyramid must not be flat");
        return bvh.gather(query);
    }

    /**
     * A point of a light's square c + s·a + r·b, s and r in [−1, 1], a quarter of them on its edges
     * and corners.
     *
     * @param rnd the generator
     * @param c   the centre
     * @param a   half of one side
     * @param b   half of the other side
     * @return the point
     */
    private static Point3D squarePoint(Random rnd, Point3D c, Vector a, Vector b) {
        double s = edgeOrInner(rnd);
        double r = edgeOrInner(rnd);
        return new Point3D(c.getX() + s * a.getX() + r * b.getX(), c.getY() + s * a.getY() + r * b.getY(),
                c.getZ() + s * a.getZ() + r * b.getZ());
    }

    /**
     * A random vector of a random direction and a length from 0.01 to 3 (log-uniform).
     *
     * @param rnd the generator
     * @return the vector
     */
    private static Vector randomHalfSide(Random rnd) {
        return randomUnit(rnd).scale(Math.pow(10, -2 + 2.5 * rnd.nextDouble()));
    }

    /**
     * A point moved by a random vector no longer than a length (a third of the time exactly that long).
     *
     * @param rnd    the generator
     * @param point  the point
     * @param length the largest move (0: the point itself)
     * @return the moved point
     */
    private static Point3D stray(Random rnd, Point3D point, double length) {
        if (length == 0)
            return point;
        Vector move = randomUnit(rnd);
        double scale = rnd.nextInt(3) == 0 ? length : length * rnd.nextDouble();
        return new Point3D(point.getX() + scale * move.getX(), point.getY() + scale * move.getY(),
                point.getZ() + scale * move.getZ());
    }

    /**
     * A random point on the surface of a body (up to rounding), to put a bundle's apex on.
     *
     * @param rnd  the generator
     * @param body the body
     * @return the point
     */
    private static Point3D pointOn(Random rnd, Intersectable body) {
        if (body instanceof Sphere sphere)
            return sphere.getCenter().add(randomUnit(rnd).scale(sphere.getRadius()));
        if (body instanceof Tube tube) { // and Cylinder: a point of the side
            Ray axis = tube.getAxisRay();
            double t = tube instanceof Cylinder cylinder ? cylinder.getHeight() * rnd.nextDouble()
                    : 10 * (2 * rnd.nextDouble() - 1);
            return axis.getPoint(t).add(perpendicular(rnd, axis.getDir()).scale(tube.getRadius()));
        }
        if (body instanceof Plane plane)
            return plane.getQ0().add(perpendicular(rnd, plane.getNormal()).scale(0.1 + 10 * rnd.nextDouble()));
        if (body instanceof Wrapper wrapper)
            return pointOn(rnd, wrapper.inner);
        if (body instanceof Geometries composite)
            return pointOn(rnd, composite.getGeometries().get(0));
        return pointIn(rnd, body); // a polygon's inner points lie on it
    }

    /**
     * A random unit vector orthogonal to a direction.
     *
     * @param rnd the generator
     * @param dir the direction
     * @return the vector
     */
    private static Vector perpendicular(Random rnd, Vector dir) {
        while (true) {
            Vector cross = dir.crossProduct(randomUnit(rnd));
            if (cross.length() > 1e-3)
                return cross.normalize();
        }
    }

    /**
     * How many of a composite's bounded bodies (the tree's bodies) may meet the frustum: their boxes
     * meet it and their own test ({@link Geometry#mayMeet}, for a polygon its plane) says they may.
     * When more than {@value #MAX_GATHERED}, gather keeps a subtree instead of the bodies.
     *
     * @param item    the composite or body
     * @param frustum the frustum, set
     * @return the count
     */
    private static int boxesMeeting(Intersectable item, ShadowFrustum frustum) {
        return meeting(item, frustum, true);
    }

    /**
     * How many of a composite's bounded bodies have boxes the frustum meets, or also pass their own test
     * ({@link TriangleMesh#mayMeet(int, ShadowFrustum)} for each triangle of a mesh, a body each).
     *
     * @param item    the composite or body
     * @param frustum the frustum, set
     * @param ownTest whether the bodies' own test counts too
     * @return the count
     */
    private static int meeting(Intersectable item, ShadowFrustum frustum, boolean ownTest) {
        if (item instanceof Geometries composite) {
            int count = 0;
            for (Intersectable child : composite.getGeometries())
                count += meeting(child, frustum, ownTest);
            return count;
        }
        if (item instanceof TriangleMesh mesh) {
            int count = 0;
            double[] box = new double[6];
            for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
                mesh.bounds(t, box, 0);
                count += frustum.meetsBox(box, 0) && (!ownTest || mesh.mayMeet(t, frustum)) ? 1 : 0;
            }
            return count;
        }
        if (item instanceof Geometry geometry) {
            double[] box = geometry.bounds();
            return box != null && frustum.meetsBox(box, 0) && (!ownTest || geometry.mayMeet(frustum)) ? 1 : 0;
        }
        return 0;
    }

    /**
     * The transmittance of one ray of a bundle after its gather, through gatheredTransmittance.
     *
     * @param bvh    the hierarchy
     * @param ray    the ray (the same one, with the same direction, as the tree's answer is asked for)
     * @param maxT   the distance to the square
     * @param minK   the cut-off
     * @param query  the scratch space, as the gather left it
     * @return the transmittance
     */
    private static double gathered(BoundingVolumeHierarchy bvh, Ray ray, double maxT, double minK, Query query) {
        Point3D p = ray.getP0();
        Vector d = ray.getDir();
        return bvh.bundleRayTransmittance(query.setRay(p.getX(), p.getY(), p.getZ(), d.getX(), d.getY(), d.getZ(), maxT), minK);
    }

    /**
     * How often gather gave each kind of answer, and how many rays were blocked or dimmed. The two
     * kinds of true cannot be told apart through the API: they are told by how many of the tree's
     * bodies may meet the frustum.
     */
    private static final class GatherCounts {
        /** gather gave false. */
        private int none;
        /** gather gave true, at most 32 of the tree's bodies may meet the frustum: the bodies are kept. */
        private int few;
        /** gather gave true, more than 32 of the tree's bodies may meet the frustum: a subtree is kept. */
        private int subtree;
        /** bundles whose pyramid meets some boxes but no polygon's plane among them. */
        private int planeCulled;
        /** bundles with a thickness (apex on a body's surface). */
        private int thick;
        private int rays;
        private int darkened;
    }

    /**
     * Traces random bundles through a scene: for every bundle, every ray from (near) the apex to
     * (near) a random point of the square has the same gathered transmittance as its transmittance
     * through the tree. A third of the bundles start exactly on a body's surface and are
     * {@value #THICK} thick (their rays' ends moved by up to that much, as the renderer moves shadow
     * rays off the surface); a quarter of the squares are wide (half-sides 3 to 15), the others
     * 0.01 to 3.
     *
     * @param rnd     the generator
     * @param scene   the scene
     * @param opaque  whether every body is opaque (the answers are then exactly 0 or 1)
     * @param threads the number of threads the hierarchy is built on
     * @param counts  the counters to add to
     * @param tc      the test-case label
     */
    private static void checkBundles(Random rnd, TestScene scene, boolean opaque, int threads, GatherCounts counts,
                                     String tc) {
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries(), threads);
        Query query = bvh.newQuery();
        Query treeQuery = bvh.newQuery();
        ShadowFrustum frustum = query.getFrustum();
        List<Intersectable> bodies = scene.bodies();
        for (int bundle = 0; bundle < 60; ++bundle) {
            double choice = rnd.nextDouble();
            double thickness = 0;
            Point3D apex;
            if (choice < 0.2)
                apex = randomPoint(rnd, Point3D.ZERO, 1.5 * scene.size());
            else if (choice < 0.55) {
                apex = pointOn(rnd, bodies.get(rnd.nextInt(bodies.size())));
                thickness = THICK;
            } else {
                apex = pointIn(rnd, bodies.get(rnd.nextInt(bodies.size())));
                if (choice > 0.8)
                    apex = apex.add(randomUnit(rnd).scale(rnd.nextDouble()));
            }
            Point3D c = apex.add(randomUnit(rnd).scale(0.5 + 30 * rnd.nextDouble()));
            boolean wide = rnd.nextInt(4) == 0;
            Vector a = wide ? randomUnit(rnd).scale(3 + 12 * rnd.nextDouble()) : randomHalfSide(rnd);
            Vector b = wide ? randomUnit(rnd).scale(3 + 12 * rnd.nextDouble()) : randomHalfSide(rnd);
            if (a.crossProduct(b).length() < 1e-3 * a.length() * b.length()
                    || !frustum.set(apex.getX(), apex.getY(), apex.getZ(), c.getX(), c.getY(), c.getZ(),
                    a.getX(), a.getY(), a.getZ(), b.getX(), b.getY(), b.getZ(), thickness))
                continue; // a flat pyramid: the renderer walks the tree instead
            int meeting = boxesMeeting(scene.geometries(), frustum);
            if (meeting == 0 && meeting(scene.geometries(), frustum, false) > 0)
                ++counts.planeCulled;
            boolean found = bvh.gather(query);
            int bundleNumber = bundle;
            Point3D origin = apex;
            double thick = thickness;
            Supplier<String> bundleLabel = () -> tc + " bundle " + bundleNumber + " (apex " + origin + ", c " + c
                    + ", a " + a + ", b " + b + ", thickness " + thick + ", gathered " + found + ", " + meeting
                    + " boxes meet)";
            if (!found) {
                // a body that may meet the frustum (its box and its own test) is in nodes whose boxes meet it: gathered
                assertEquals(0, meeting, () -> bundleLabel.get() + ": nothing gathered though bodies may meet");
                ++counts.none;
            } else if (meeting > MAX_GATHERED)
                ++counts.subtree;
            else
                ++counts.few;
            if (thickness > 0)
                ++counts.thick;
            List<Ray> rays = new ArrayList<>();
            List<Double> distances = new ArrayList<>();
            for (int r = 0; r < 40; ++r) {
                Point3D target = squarePoint(rnd, c, a, b);
                Point3D start = stray(rnd, apex, thickness);
                Point3D end = r % 3 == 0 // moved as the renderer moves it: by the start's move
                        ? new Point3D(target.getX() + start.getX() - apex.getX(),
                        target.getY() + start.getY() - apex.getY(), target.getZ() + start.getZ() - apex.getZ())
                        : stray(rnd, target, thickness);
                double distance = start.distance(end);
                if (distance < 1e-6)
                    continue;
                Ray ray = new Ray(start, end.subtract(start));
                int rayNumber = r;
                Supplier<String> label = () -> bundleLabel.get() + " ray " + rayNumber + " " + ray + " distance "
                        + distance;
                for (double minK : new double[] { MIN_K, 0 }) {
                    double expected = transmittance(bvh, ray, distance, minK, treeQuery);
                    double actual = gathered(bvh, ray, distance, minK, query);
                    if (opaque) {
                        assertTrue(expected == 0 || expected == 1, () -> label.get() + ": an opaque scene gives 0 or 1");
                        assertEquals(expected, actual, 0, label);
                    } else
                        assertEquals(expected, actual, 1e-12, label);
                    if (!found)
                        assertEquals(1, actual, 0, () -> label.get() + ": nothing gathered, nothing may block");
                }
                ++counts.rays;
                if (transmittance(bvh, ray, distance, 0, treeQuery) < 1)
                    ++counts.darkened;
                rays.add(ray);
                distances.add(distance);
            }
            assertPacket(bvh, query, bvh, treeQuery, rays, distances, opaque ? 0 : 1e-12, bundleLabel);
        }
    }

    /**
     * Asserts that the rays of a bundle traced as one packet, after its gather, each get the
     * transmittance a reference (the tree itself, or the scan) gives them alone, with the cut-off and
     * without.
     *
     * @param bvh            the hierarchy
     * @param query          the scratch space, as the gather left it
     * @param reference      the hierarchy (or scan) that traces the rays alone
     * @param referenceQuery another scratch space, for the rays alone
     * @param rays           the rays
     * @param distances      their distances to the square
     * @param delta          the tolerance (0: equal to the bit)
     * @param label          the bundle's label
     */
    private static void assertPacket(BoundingVolumeHierarchy bvh, Query query, BoundingVolumeHierarchy reference,
                                     Query referenceQuery, List<Ray> rays, List<Double> distances, double delta,
                                     Supplier<String> label) {
        for (double minK : new double[] { MIN_K, 0 }) {
            fillPacket(query, rays, distances);
            bvh.packetTransmittances(query, minK);
            for (int r = 0; r < rays.size(); ++r) {
                double expected = transmittance(reference, rays.get(r), distances.get(r), minK, referenceQuery);
                int number = r;
                assertEquals(expected, query.getTransmittance(r), delta,
                        () -> label.get() + " packet ray " + number + " " + rays.get(number) + " (minK " + minK + ")");
            }
        }
    }

    /**
     * Empties a query's packet and puts rays in it.
     *
     * @param query     the scratch space
     * @param rays      the rays
     * @param distances their distances
     */
    private static void fillPacket(Query query, List<Ray> rays, List<Double> distances) {
        query.clearPacket();
        for (int r = 0; r < rays.size(); ++r) {
            Point3D p = rays.get(r).getP0();
            Vector d = rays.get(r).getDir();
            query.addToPacket(p.getX(), p.getY(), p.getZ(), d.getX(), d.getY(), d.getZ(), distances.get(r));
        }
    }

    /**
     * A dense triangle mesh: a sphere of radius 6 cut into 960 triangles, with 6 small spheres around
     * it and a floor plane below.
     *
     * @param rnd the generator
     * @return the scene
     */
    private static TestScene meshScene(Random rnd) {
        return meshScene(rnd, false);
    }

    /**
     * The dense mesh scene of {@link #meshScene(Random)}, its sphere's triangles as {@link Triangle}s or
     * as one {@link TriangleMesh} (the scene's bodies to start bundles on are the triangles all the same).
     *
     * @param rnd    the generator
     * @param asMesh whether the sphere is a {@link TriangleMesh}
     * @return the scene
     */
    private static TestScene meshScene(Random rnd, boolean asMesh) {
        List<Intersectable> bodies = new ArrayList<>(benchmark.SphereMesh.triangles(Point3D.ZERO, 6, 16, 32));
        Geometries geometries = asMesh ? new Geometries(benchmark.SphereMesh.mesh(Point3D.ZERO, 6, 16, 32))
                : new Geometries(bodies.toArray(new Intersectable[0]));
        for (int i = 0; i < 7; ++i) {
            Geometry body = i < 6 ? new Sphere(Point3D.ZERO.add(randomUnit(rnd).scale(8 + rnd.nextDouble())),
                    0.3 + rnd.nextDouble()) : new Plane(new Point3D(0, -7, 0), new Vector(0, 1, 0));
            bodies.add(body);
            geometries.add(body);
        }
        return new TestScene(geometries, bodies, 8);
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} and
     * {@link BoundingVolumeHierarchy#gatheredTransmittance}: on seeded random scenes, every ray of a
     * bundle has the transmittance the tree gives it, whether gather found nothing, a few bodies or
     * (more than 32 of them) a subtree.
     */
    @Test
    void testGatheredTransmittanceRandomScenes() {
        // ===== Equivalence Partitions Tests =====
        // TC01: opaque random scenes (with planes, a tube, cylinders, squares, bodies that are not
        // Geometry, nested composites, a dense mesh): 60 bundles each from random apexes on (thick), in,
        // near and away from the bodies to random narrow and wide squares, 40 rays each:
        // gatheredTransmittance = transmittance, 0 or 1, and so is the answer of each ray of the
        // bundle traced as one packet (gatheredTransmittances)
        Random rnd = new Random(7031);
        GatherCounts opaque = new GatherCounts();
        for (int s : new int[] { 0, 2, 3, 5, 6, 7, 8, 9, 13, 15, 17, 19 })
            checkBundles(rnd, randomScene(rnd, s), true, 1, opaque, "TC01: scene " + s);
        for (int m = 0; m < 2; ++m)
            checkBundles(rnd, meshScene(rnd), true, 1, opaque, "TC01: mesh scene " + m);
        assertCounts(opaque, "TC01");
        // TC02: the same with random kT (0.5, 0.9, 0.25, 1, some opaque), the hierarchy built on 3
        // threads: equal within 1e-12, one by one and as a packet
        double[] kts = { 0.5, 0.9, 0.25, 1, 0.75, 0.999, 0.5, 0.9, 0 };
        GatherCounts transparent = new GatherCounts();
        for (int s : new int[] { 0, 2, 4, 5, 6, 8, 9, 13, 15, 18, 19, -1, -1 }) {
            TestScene scene = s < 0 ? meshScene(rnd) : randomScene(rnd, s);
            for (Intersectable body : scene.bodies())
                setKt(body, kts, rnd);
            checkBundles(rnd, scene, false, 3, transparent, "TC02: " + (s < 0 ? "mesh scene" : "scene " + s));
        }
        assertCounts(transparent, "TC02");

        // TC03: the dense mesh as one TriangleMesh, whose gathered triangles are tested from their own
        // copies of the mesh's numbers: the same answers, opaque and with random kT
        GatherCounts mesh = new GatherCounts();
        for (int m = 0; m < 6; ++m) {
            TestScene scene = meshScene(rnd, true);
            if (m % 2 == 1)
                setKt(scene.geometries(), kts, rnd);
            checkBundles(rnd, scene, m % 2 == 0, 1 + m % 3, mesh, "TC03: TriangleMesh scene " + m);
        }
        assertTrue(mesh.few >= 50 && mesh.subtree >= 20 && mesh.none >= 20, "TC03: too few bundles of each kind ("
                + mesh.none + " none, " + mesh.few + " few, " + mesh.subtree + " subtrees)");
    }

    /**
     * Asserts that gather gave every kind of answer often and that some rays were darkened, so the
     * comparison is not vacuous.
     *
     * @param counts the counters
     * @param tc     the test-case label
     */
    private static void assertCounts(GatherCounts counts, String tc) {
        assertTrue(counts.none >= 30, tc + ": too few bundles with nothing gathered (" + counts.none + ")");
        assertTrue(counts.few >= 100, tc + ": too few bundles with a few bodies gathered (" + counts.few + ")");
        assertTrue(counts.subtree >= 50, tc + ": too few bundles meeting more than 32 boxes (" + counts.subtree + ")");
        assertTrue(counts.thick >= 100, tc + ": too few thick bundles (" + counts.thick + ")");
        assertTrue(counts.planeCulled >= 10, tc + ": too few bundles whose polygons were culled by their planes ("
                + counts.planeCulled + ")");
        assertTrue(counts.darkened >= 500 && counts.rays - counts.darkened >= 500,
                tc + ": too few darkened (" + counts.darkened + ") or open (" + (counts.rays - counts.darkened)
                        + ") rays of " + counts.rays);
    }

    /**
     * Two plates of 10 × 10 unit cells, each cell cut into two triangles along its diagonal, over
     * x, y in [−5, 5]: a transparent one (kT 0.5) at z = 0 and an opaque one at z = 2.
     *
     * @return the composite of the 400 triangles
     */
    private static Geometries twoPlates() {
        Geometries plates = new Geometries();
        Material glass = new Material().setKt(0.5);
        Material opaque = new Material();
        for (double z : new double[] { 0, 2 })
            for (int i = -5; i < 5; ++i)
                for (int j = -5; j < 5; ++j) {
                    Material material = z == 0 ? glass : opaque;
                    plates.add(new Triangle(new Point3D(i, j, z), new Point3D(i + 1, j, z), new Point3D(i + 1, j + 1, z))
                                    .setMaterial(material),
                            new Triangle(new Point3D(i, j, z), new Point3D(i + 1, j + 1, z), new Point3D(i, j + 1, z))
                                    .setMaterial(material));
                }
        return plates;
    }

    /**
     * Traces a packet from an apex to the points of a square at height z on a 3 × 3 grid (−0.8, 0
     * and 0.8 of each half-side, so that no ray crosses the plates of {@link #twoPlates} on an edge),
     * after gathering its bundle.
     *
     * @param bvh   the hierarchy
     * @param query the scratch space
     * @param apex  the rays' origin
     * @param z     the height of the square (centre (0.1, 0.2, z), half-sides 4)
     * @return the rays' answers
     */
    private static double[] plateBundle(BoundingVolumeHierarchy bvh, Query query, Point3D apex, double z) {
        assertTrue(query.getFrustum().set(apex.getX(), apex.getY(), apex.getZ(), 0.1, 0.2, z, 4, 0, 0, 0, 4, 0, 0),
                "the bundle's pyramid must be set");
        bvh.gather(query);
        List<Ray> rays = new ArrayList<>();
        List<Double> distances = new ArrayList<>();
        for (double s : new double[] { -3.2, 0, 3.2 })
            for (double t : new double[] { -3.2, 0, 3.2 }) {
                Point3D target = new Point3D(0.1 + s, 0.2 + t, z);
                rays.add(new Ray(apex, target.subtract(apex)));
                distances.add(apex.distance(target));
            }
        fillPacket(query, rays, distances);
        bvh.packetTransmittances(query, MIN_K);
        double[] answers = new double[rays.size()];
        for (int r = 0; r < answers.length; ++r)
            answers[r] = query.getTransmittance(r);
        return answers;
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gatheredTransmittances} and the packet of a
     * {@link Query}: a closed bundle of many bodies, transparent blockers and blockers beyond the
     * light, a bundle that keeps no subtree; the packet's bounds.
     */
    @Test
    void testPackets() {
        Geometries plates = twoPlates();
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(plates);
        Query query = bvh.newQuery();
        Point3D apex = new Point3D(0.05, 0.1, -5);
        // ===== Equivalence Partitions Tests =====
        // TC01: the light between the plates, more than 32 triangles in the pyramid (a subtree is
        // walked as a packet): each ray passes the transparent plate once, 0.5, and the opaque plate
        // beyond the light does not count
        for (double answer : plateBundle(bvh, query, apex, 1))
            assertEquals(0.5, answer, 1e-12, "TC01: through the transparent plate only");
        assertTrue(boxesMeeting(plates, query.getFrustum()) > 32, "TC01: more than 32 triangles must meet the pyramid");
        // TC02: the light above both plates: every ray is blocked, 0
        for (double answer : plateBundle(bvh, query, apex, 3))
            assertEquals(0, answer, 0, "TC02: blocked by the opaque plate");
        // TC03: the light below both plates: nothing in the way, 1
        for (double answer : plateBundle(bvh, query, apex, -1))
            assertEquals(1, answer, 0, "TC03: nothing before the light");
        // TC04: 100 random rays of the TC01 bundle (more than the packet's first room for 16), some
        // through the triangles' shared edges: each gets the tree's answer for it alone
        plateBundle(bvh, query, apex, 1);
        assertTrue(query.isSubtreeGathered(), "TC04: more than 32 triangles: a subtree is kept");
        Random rnd = new Random(16);
        List<Ray> rays = new ArrayList<>();
        List<Double> distances = new ArrayList<>();
        for (int r = 0; r < 100; ++r) {
            Point3D target = new Point3D(0.1 + 8 * rnd.nextDouble() - 4, 0.2 + 8 * rnd.nextDouble() - 4, 1);
            rays.add(new Ray(apex, target.subtract(apex)));
            distances.add(apex.distance(target));
        }
        fillPacket(query, rays, distances);
        assertEquals(100, query.getPacketSize(), "TC04: the packet holds every ray added");
        bvh.packetTransmittances(query, MIN_K);
        for (int r = 0; r < rays.size(); ++r)
            assertEquals(transmittance(bvh, rays.get(r), distances.get(r), MIN_K, bvh.newQuery()),
                    query.getTransmittance(r), 1e-12, "TC04: ray " + r);
        // TC05: a narrow bundle (square of half-side 0.01 at z = −4.9, nothing in between) keeps no
        // subtree, and its packet's rays each let all the light through
        assertTrue(query.getFrustum().set(0.05, 0.1, -5, 0.05, 0.1, -4.9, 0.01, 0, 0, 0, 0.01, 0, 0),
                "TC05: the pyramid must be set");
        bvh.gather(query);
        assertFalse(query.isSubtreeGathered(), "TC05: no subtree for a bundle that meets nothing");
        fillPacket(query, rays.subList(0, 1), List.of(0.1));
        bvh.packetTransmittances(query, MIN_K);
        assertEquals(1, query.getTransmittance(0), 0, "TC05: nothing before the light");

        // ===== Boundary Values Tests =====
        // TC11: a cleared packet holds no ray, and tracing it answers nothing
        query.clearPacket();
        assertEquals(0, query.getPacketSize(), "TC11: a cleared packet is empty");
        bvh.packetTransmittances(query, MIN_K);
        assertMessage(assertThrows(IllegalArgumentException.class, () -> query.getTransmittance(0),
                "TC11: an empty packet has no answer"), "packet", "TC11");
        // TC12: a packet of one ray: the ray's own answer (the light just before the transparent plate: 1)
        plateBundle(bvh, query, apex, 1);
        query.clearPacket();
        query.addToPacket(0.05, 0.1, -5, 0, 0, 1, 5 - 1e-6);
        bvh.packetTransmittances(query, MIN_K);
        assertEquals(1, query.getTransmittance(0), 0, "TC12: the light just before the plate");
        // TC13: answers only for rays 0 to size − 1
        assertMessage(assertThrows(IllegalArgumentException.class, () -> query.getTransmittance(-1),
                "TC13: ray −1"), "packet", "TC13");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> query.getTransmittance(1),
                "TC13: ray past the packet"), "packet", "TC13");
    }

    /**
     * 8 × 8 unit cells over x, y in [−4, 4], each with four bodies close together, so that each cell
     * makes one leaf of the tree: a triangle of a transparent mesh (kT 0.5) at z = 0 and a
     * {@link Triangle} (kT 0.5) of the same shape at z = 0.02, both (0.05, 0.05), (0.95, 0.05),
     * (0.5, 0.95) off the cell's corner; a triangle of an opaque mesh at z = 0.04 over the cell's left
     * part, (0.05, 0.05), (0.45, 0.05), (0.45, 0.95) off it; a sphere (kT 0.5) of radius 0.08 at
     * (0.7, 0.3, 0.06) off it. Above them all, a transparent plane (kT 0.5) at z = 0.5.
     *
     * @return the composite
     */
    private static Geometries layeredCells() {
        double[] vertices = new double[3 * 3 * 64];
        double[] opaqueVertices = new double[3 * 3 * 64];
        int[] indices = new int[3 * 64];
        Geometries cells = new Geometries();
        Material glass = new Material().setKt(0.5);
        for (int c = 0; c < 64; ++c) {
            double x = c % 8 - 4;
            double y = c / 8 - 4;
            setCorners(vertices, c, x, y, 0, 0.05, 0.05, 0.95, 0.05, 0.5, 0.95);
            setCorners(opaqueVertices, c, x, y, 0.04, 0.05, 0.05, 0.45, 0.05, 0.45, 0.95);
            for (int k = 0; k < 3; ++k)
                indices[3 * c + k] = 3 * c + k;
            cells.add(new Triangle(new Point3D(x + 0.05, y + 0.05, 0.02), new Point3D(x + 0.95, y + 0.05, 0.02),
                            new Point3D(x + 0.5, y + 0.95, 0.02)).setMaterial(glass),
                    new Sphere(new Point3D(x + 0.7, y + 0.3, 0.06), 0.08).setMaterial(glass));
        }
        cells.add(new TriangleMesh(vertices, indices).setMaterial(glass), new TriangleMesh(opaqueVertices, indices),
                new Plane(new Point3D(0, 0, 0.5), new Vector(0, 0, 1)).setMaterial(glass));
        return cells;
    }

    /**
     * Sets the three corners of triangle c of a mesh's vertices: points (x + u, y + v, z) for the
     * three pairs (u, v) given.
     */
    private static void setCorners(double[] vertices, int c, double x, double y, double z, double... uv) {
        for (int k = 0; k < 3; ++k) {
            vertices[9 * c + 3 * k] = x + uv[2 * k];
            vertices[9 * c + 3 * k + 1] = y + uv[2 * k + 1];
            vertices[9 * c + 3 * k + 2] = z;
        }
    }

    /**
     * Traces a packet of rays of the bundle from (0, 0, −50) to the square of half-sides 4.5 at z = 1
     * over {@link #layeredCells}, each ray through a point at z = 0 off the corner of a cell, to z = 1.
     *
     * @param bvh     the hierarchy over the cells
     * @param query   the scratch space
     * @param targets per ray, its cell (0 to 63) and its point's offset from the cell's corner, three
     *                numbers each
     * @param minK    the cut-off
     * @param tc      the test-case label
     * @return the rays' answers, each checked against the tree's answer for the ray alone
     */
    private static double[] cellsPacket(BoundingVolumeHierarchy bvh, Query query, double[] targets, double minK,
                                        String tc) {
        assertTrue(query.getFrustum().set(0, 0, -50, 0, 0, 1, 4.5, 0, 0, 0, 4.5, 0, 0), tc + ": the pyramid must be set");
        bvh.gather(query);
        assertTrue(query.isSubtreeGathered(), tc + ": the bundle meets more than 32 bodies: a packet is walked");
        Point3D apex = new Point3D(0, 0, -50);
        List<Ray> rays = new ArrayList<>();
        List<Double> distances = new ArrayList<>();
        for (int r = 0; r < targets.length; r += 3) {
            int c = (int) targets[r];
            Vector direction = new Point3D(c % 8 - 4 + targets[r + 1], c / 8 - 4 + targets[r + 2], 0).subtract(apex);
            rays.add(new Ray(apex, direction));
            distances.add(direction.length() * 51 / 50);
        }
        fillPacket(query, rays, distances);
        bvh.packetTransmittances(query, minK);
        double[] answers = new double[rays.size()];
        for (int r = 0; r < answers.length; ++r) {
            answers[r] = query.getTransmittance(r);
            assertEquals(transmittance(bvh, rays.get(r), distances.get(r), minK, bvh.newQuery()), answers[r], 0,
                    tc + ": ray " + r + " as alone");
        }
        return answers;
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gatheredTransmittances} on leaves that mix a
     * transparent and an opaque mesh's triangles with other bodies, where some of a leaf's rays are
     * blocked by a body in the middle of the leaf and others go on: each ray's answer is its own.
     */
    @Test
    void testPacketLeaves() {
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(layeredCells());
        Query query = bvh.newQuery();
        // the points off a cell's corner: through the opaque triangle (0), both transparent triangles
        // only (0.5³ with the plane), also the sphere, twice (0.5⁵), and nothing but the plane (0.5)
        double[][] kinds = { { 0.3, 0.3 }, { 0.55, 0.5 }, { 0.7, 0.3 }, { 0.9, 0.8 } };
        double[] expected = { 0, 0.125, 0.03125, 0.5 };
        Random rnd = new Random(1608);
        List<Integer> order = new ArrayList<>();
        for (int r = 0; r < 4 * 64; ++r)
            order.add(r);
        java.util.Collections.shuffle(order, rnd);
        double[] targets = new double[3 * order.size()];
        for (int r = 0; r < order.size(); ++r) {
            int kind = order.get(r) % 4;
            targets[3 * r] = order.get(r) / 4;
            targets[3 * r + 1] = kinds[kind][0];
            targets[3 * r + 2] = kinds[kind][1];
        }
        // ===== Equivalence Partitions Tests =====
        // TC01: four rays through each cell, in random order: blocked in the leaf (0), through its two
        // transparent triangles (0.125), and the sphere (0.03125), or through none of its bodies (0.5)
        double[] answers = cellsPacket(bvh, query, targets, MIN_K, "TC01");
        for (int r = 0; r < answers.length; ++r)
            assertEquals(expected[order.get(r) % 4], answers[r], 0, "TC01: ray " + r + " of kind " + order.get(r) % 4);
        // TC02: with the cut-off 0.05, the sphere's rays fall below it in the leaf: 0; the others as in TC01
        answers = cellsPacket(bvh, query, targets, 0.05, "TC02");
        for (int r = 0; r < answers.length; ++r)
            assertEquals(order.get(r) % 4 == 2 ? 0 : expected[order.get(r) % 4], answers[r], 0, "TC02: ray " + r);

        // ===== Boundary Values Tests =====
        // TC11: every ray blocked, one per cell through its opaque triangle: 0 each
        double[] blocked = new double[3 * 64];
        for (int c = 0; c < 64; ++c) {
            blocked[3 * c] = c;
            blocked[3 * c + 1] = 0.3;
            blocked[3 * c + 2] = 0.3;
        }
        for (double answer : cellsPacket(bvh, query, blocked, MIN_K, "TC11"))
            assertEquals(0, answer, 0, "TC11: blocked by the opaque triangle");
        // TC12: the same ray through the sphere of cell 27 forty times, then one through its opaque
        // triangle: 0.03125 each, and 0
        double[] twins = new double[3 * 41];
        for (int r = 0; r < 41; ++r) {
            twins[3 * r] = 27;
            twins[3 * r + 1] = r < 40 ? 0.7 : 0.3;
            twins[3 * r + 2] = 0.3;
        }
        answers = cellsPacket(bvh, query, twins, MIN_K, "TC12");
        for (int r = 0; r < 40; ++r)
            assertEquals(0.03125, answers[r], 0, "TC12: twin ray " + r);
        assertEquals(0, answers[40], 0, "TC12: the last ray, blocked");
    }

    /**
     * A row of 40 small triangles at z = 0, triangle i around (i, 0, 0) (x from i − 0.1 to i + 0.1,
     * y from −0.1 to 0.1).
     *
     * @return the composite
     */
    private static Geometries triangleRow() {
        Geometries row = new Geometries();
        for (int i = 0; i < 40; ++i)
            row.add(new Triangle(new Point3D(i - 0.1, -0.1, 0), new Point3D(i + 0.1, -0.1, 0), new Point3D(i, 0.1, 0)));
        return row;
    }

    /**
     * Asserts that 200 random rays of the last gathered bundle have the tree's transmittance: from the
     * apex to a random point of the square, both ends moved by up to the thickness.
     *
     * @param bvh       the hierarchy
     * @param query     the scratch space, as the gather left it
     * @param apex      the apex
     * @param c         the centre of the square
     * @param a         half of one side
     * @param b         half of the other side
     * @param thickness how far the rays' ends may be moved
     * @param rnd       the generator
     * @param tc        the test-case label
     * @return how many of the rays were blocked
     */
    private static int assertBundle(BoundingVolumeHierarchy bvh, Query query, Point3D apex, Point3D c, Vector a,
                                    Vector b, double thickness, Random rnd, String tc) {
        Query treeQuery = bvh.newQuery();
        int blocked = 0;
        for (int r = 0; r < 200; ++r) {
            Point3D start = stray(rnd, apex, thickness);
            Point3D target = stray(rnd, squarePoint(rnd, c, a, b), thickness);
            Ray ray = new Ray(start, target.subtract(start));
            double distance = target.distance(start);
            double expected = transmittance(bvh, ray, distance, MIN_K, treeQuery);
            int number = r;
            assertEquals(expected, gathered(bvh, ray, distance, MIN_K, query), 0,
                    () -> tc + ": ray " + number + " from " + start + " to " + target);
            if (expected == 0)
                ++blocked;
        }
        return blocked;
    }

    /**
     * Asserts that the ray from one point to another has a given transmittance, both through the tree
     * and through the bodies the last gather kept.
     *
     * @param expected the transmittance
     * @param bvh      the hierarchy
     * @param query    the scratch space, as the gather left it
     * @param from     the ray's start
     * @param to       the ray's end
     * @param message  the failure message
     */
    private static void assertRay(double expected, BoundingVolumeHierarchy bvh, Query query, Point3D from, Point3D to,
                                  String message) {
        Ray ray = new Ray(from, to.subtract(from));
        double distance = from.distance(to);
        assertEquals(expected, transmittance(bvh, ray, distance, MIN_K, bvh.newQuery()), 0, message + " (tree)");
        assertEquals(expected, gathered(bvh, ray, distance, MIN_K, query), 0, message + " (gathered)");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} on its boundaries: the scan, empty
     * composites, the limit of 32 bodies (a subtree kept beyond it), a dense mesh under a big light,
     * thick bundles starting on a surface, a refused frustum, planes and bodies that are not geometries.
     */
    @Test
    void testGatherBoundaries() {
        Random rnd = new Random(32);
        Point3D up = new Point3D(0, 0, 5);
        Vector a = new Vector(1, 0, 0);
        Vector b = new Vector(0, 1, 0);
        Point3D below = new Point3D(0, 0, -1);
        Point3D above = new Point3D(0, 0, 1);

        // ===== Equivalence Partitions Tests =====
        // TC01: one sphere in the pyramid from (0, 0, 5) down to (±1, ±1, −1): true, and the rays
        // through it are blocked as through the tree
        Geometries ball = new Geometries(new Sphere(new Point3D(0, 0, 2), 0.5));
        BoundingVolumeHierarchy ballBvh = BoundingVolumeHierarchy.build(ball);
        Query ballQuery = ballBvh.newQuery();
        assertTrue(gather(ballBvh, ballQuery, up, below, a, b), "TC01: the sphere in the pyramid must be gathered");
        assertTrue(assertBundle(ballBvh, ballQuery, up, below, a, b, 0, rnd, "TC01") > 0,
                "TC01: some rays must be blocked");
        // TC02: the same sphere beside the pyramid (at x = 3): false, every ray open
        Geometries aside = new Geometries(new Sphere(new Point3D(3, 0, 2), 0.5));
        BoundingVolumeHierarchy asideBvh = BoundingVolumeHierarchy.build(aside);
        Query asideQuery = asideBvh.newQuery();
        assertFalse(gather(asideBvh, asideQuery, up, below, a, b), "TC02: a sphere beside the pyramid must not be gathered");
        assertEquals(0, assertBundle(asideBvh, asideQuery, up, below, a, b, 0, rnd, "TC02"), "TC02: no ray may be blocked");
        // TC03: the 40 triangles of a row under a pyramid covering all of them: true (a subtree is kept),
        // and the rays agree with the tree, through each triangle blocked, between them open
        BoundingVolumeHierarchy rowBvh = BoundingVolumeHierarchy.build(triangleRow());
        Query rowQuery = rowBvh.newQuery();
        Point3D apexRow = new Point3D(20, 0, 10);
        Point3D cRow = new Point3D(20, 0, -10);
        Vector aRow = new Vector(50, 0, 0);
        assertTrue(gather(rowBvh, rowQuery, apexRow, cRow, aRow, b), "TC03: a pyramid over 40 triangles must give true");
        assertBundle(rowBvh, rowQuery, apexRow, cRow, aRow, b, 0, rnd, "TC03");
        for (int i = 0; i < 40; ++i) {
            assertRay(0, rowBvh, rowQuery, apexRow, new Point3D(2 * i - 20, 0, -10), "TC03: through triangle " + i);
            assertRay(1, rowBvh, rowQuery, apexRow, new Point3D(2 * i - 19, 0, -10), "TC03: past triangle " + i);
        }
        // TC04: a body that is not a Geometry is always gathered, even far from the pyramid: true
        Geometries wrapped = new Geometries(new Wrapper(new Sphere(new Point3D(50, 50, 50), 1)));
        BoundingVolumeHierarchy wrappedBvh = BoundingVolumeHierarchy.build(wrapped);
        assertTrue(gather(wrappedBvh, wrappedBvh.newQuery(), up, below, a, b),
                "TC04: a body that is not a Geometry must be gathered");
        // TC05: a dense mesh (a sphere of radius 5 in 2208 triangles) and a big light square (edge 40) at
        // y = 12 above it, seen from the centre of a triangle at the equator with thickness 0.1, as the
        // renderer sees a point near the terminator: hundreds of boxes meet the pyramid, true, and the
        // rays (into the mesh blocked, away from it open) agree with the tree
        List<Triangle> mesh = benchmark.SphereMesh.triangles(Point3D.ZERO, 5, 24, 48);
        BoundingVolumeHierarchy meshBvh = BoundingVolumeHierarchy.build(new Geometries(mesh.toArray(new Intersectable[0])));
        Query meshQuery = meshBvh.newQuery();
        Point3D equator = new Point3D(5, 0, 0);
        Triangle nearest = mesh.get(0);
        for (Triangle triangle : mesh)
            if (centroid(triangle).distance(equator) < centroid(nearest).distance(equator))
                nearest = triangle;
        Point3D onMesh = centroid(nearest);
        Point3D light = new Point3D(0, 12, 0);
        Vector aLight = new Vector(20, 0, 0);
        Vector bLight = new Vector(0, 0, 20);
        assertTrue(gather(meshBvh, meshQuery, onMesh, light, aLight, bLight, THICK), "TC05: the mesh must be gathered");
        int meeting = boxesMeeting(new Geometries(mesh.toArray(new Intersectable[0])), meshQuery.getFrustum());
        assertTrue(meeting > 10 * MAX_GATHERED, "TC05: the pyramid must meet hundreds of boxes, met " + meeting);
        int blockedOnMesh = assertBundle(meshBvh, meshQuery, onMesh, light, aLight, bLight, THICK, rnd, "TC05");
        assertTrue(blockedOnMesh > 20 && blockedOnMesh < 180,
                "TC05: rays into the mesh must be blocked, the others open: " + blockedOnMesh + " of 200 blocked");
        // TC06: a thick bundle (0.1) from the centre (5, 0, 0) of triangle 5 of the row, to a square
        // across the row's plane (z from −0.5 to 2.5): true (the triangle holds the apex), and rays that
        // start below it or end below the plane through it are blocked
        Point3D onRow = new Point3D(5, 0, 0);
        Point3D cAcross = new Point3D(5, 0, 1);
        Vector bAcross = new Vector(0, 0.3, 1.5);
        assertTrue(gather(rowBvh, rowQuery, onRow, cAcross, a, bAcross, THICK), "TC06: the triangle under the apex");
        int blockedOnRow = assertBundle(rowBvh, rowQuery, onRow, cAcross, a, bAcross, THICK, rnd, "TC06");
        assertTrue(blockedOnRow > 0 && blockedOnRow < 200, "TC06: some rays blocked, some open: " + blockedOnRow);
        // the ray from the apex to the square's centre (5, 0, 1), moved 0.1 down: blocked; moved 0.1 up: open
        assertRay(0, rowBvh, rowQuery, new Point3D(5, 0, -0.1), new Point3D(5, 0, 0.9), "TC06: from below the triangle");
        assertRay(1, rowBvh, rowQuery, new Point3D(5, 0, 0.1), new Point3D(5, 0, 1.1), "TC06: from above the triangle");

        // ===== Boundary Values Tests =====
        // TC11: the scan with bodies (a plane among them) gives true, even for a pyramid meeting nothing,
        // and its rays agree with its transmittance; an empty scan (also of empty composites) gives false
        for (Geometries scene : List.of(ball, aside, triangleRow(), new Geometries(new Plane(Point3D.ZERO,
                new Vector(0, 0, 1))))) {
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene);
            Query scanQuery = scan.newQuery();
            assertTrue(gather(scan, scanQuery, up, below, a, b), "TC11: the scan of bodies must give true");
            assertBundle(scan, scanQuery, up, below, a, b, 0, rnd, "TC11");
            assertTrue(gather(scan, scanQuery, new Point3D(100, 100, 100), new Point3D(100, 100, 110), a, b),
                    "TC11: the scan of bodies must give true even where nothing is");
        }
        for (Geometries empty : emptyComposites()) {
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(empty);
            Query scanQuery = scan.newQuery();
            assertFalse(gather(scan, scanQuery, up, below, a, b), "TC11: an empty scan must give false");
            assertEquals(1, gathered(scan, new Ray(up, new Vector(0, 0, -1)), 6, MIN_K, scanQuery), 0,
                    "TC11: nothing may block in an empty scan");
        }
        // TC12: an empty composite (also one of empty composites): false, and every ray is open
        for (Geometries empty : emptyComposites()) {
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(empty);
            Query query = bvh.newQuery();
            assertFalse(gather(bvh, query, up, below, a, b), "TC12: an empty composite gathers nothing");
            assertEquals(1, gathered(bvh, new Ray(up, new Vector(0, 0, -1)), 6, MIN_K, query), 0, "TC12: nothing may block");
        }
        // TC13: a pyramid whose section at z = 0 is x ∈ [−0.5, 31.5]: exactly 32 triangles, true, and
        // the rays through each of them blocked (random rays of the row's bundles seldom meet a triangle:
        // they are compared with the tree, the rays through the triangles are aimed)
        Point3D apex32 = new Point3D(15.5, 0, 10);
        Point3D c32 = new Point3D(15.5, 0, -10);
        Vector a32 = new Vector(32, 0, 0);
        assertTrue(gather(rowBvh, rowQuery, apex32, c32, a32, b), "TC13: 32 triangles must be gathered");
        assertEquals(32, boxesMeeting(triangleRow(), rowQuery.getFrustum()), "TC13: 32 boxes must meet the pyramid");
        assertBundle(rowBvh, rowQuery, apex32, c32, a32, b, 0, rnd, "TC13");
        for (int i = 0; i < 32; ++i)
            assertRay(0, rowBvh, rowQuery, apex32, new Point3D(2 * i - 15.5, 0, -10), "TC13: through triangle " + i);
        // TC14: its section widened to x ∈ [−0.5, 32.5]: 33 triangles, more than 32: true, and the ray
        // through each of the 33 is blocked, the rays between them open
        Point3D apex33 = new Point3D(16, 0, 10);
        Point3D c33 = new Point3D(16, 0, -10);
        Vector a33 = new Vector(33, 0, 0);
        assertTrue(gather(rowBvh, rowQuery, apex33, c33, a33, b), "TC14: 33 triangles must give true");
        assertEquals(33, boxesMeeting(triangleRow(), rowQuery.getFrustum()), "TC14: 33 boxes must meet the pyramid");
        for (int i = 0; i < 33; ++i) {
            assertRay(0, rowBvh, rowQuery, apex33, new Point3D(2 * i - 16, 0, -10), "TC14: through triangle " + i);
            assertRay(1, rowBvh, rowQuery, apex33, new Point3D(2 * i - 15, 0, -10), "TC14: past triangle " + i);
        }
        assertBundle(rowBvh, rowQuery, apex33, c33, a33, b, 0, rnd, "TC14");
        // TC15: the same query gathers again after a subtree: a pyramid over the triangles 0..3 only
        // (x ∈ [−0.5, 3.5]): true, the rays agree and those through the 4 are blocked; then one beside the
        // row: false
        Point3D apex4 = new Point3D(1.5, 0, 10);
        Point3D c4 = new Point3D(1.5, 0, -10);
        Vector a4 = new Vector(4, 0, 0);
        assertTrue(gather(rowBvh, rowQuery, apex4, c4, a4, b), "TC15: 4 triangles must be gathered");
        assertBundle(rowBvh, rowQuery, apex4, c4, a4, b, 0, rnd, "TC15");
        for (int i = 0; i < 4; ++i)
            assertRay(0, rowBvh, rowQuery, apex4, new Point3D(2 * i - 1.5, 0, -10), "TC15: through triangle " + i);
        assertTrue(gather(rowBvh, rowQuery, apex33, c33, a33, b), "TC15: 33 triangles again");
        assertFalse(gather(rowBvh, rowQuery, new Point3D(20, 5, 10), new Point3D(20, 5, -10), a, b),
                "TC15: a pyramid beside the row after a subtree must give false");
        assertEquals(0, assertBundle(rowBvh, rowQuery, new Point3D(20, 5, 10), new Point3D(20, 5, -10), a, b, 0, rnd,
                "TC15"), "TC15: no ray beside the row may be blocked");

        // TC16: a plane z = 0 alone: the pyramid from (0, 0, 5) to z = 1 does not meet it (false, every
        // ray open); to z = −1 it crosses it (true, every ray blocked)
        Geometries floor = new Geometries(new Plane(Point3D.ZERO, new Vector(0, 0, 1)));
        BoundingVolumeHierarchy floorBvh = BoundingVolumeHierarchy.build(floor);
        Query floorQuery = floorBvh.newQuery();
        assertFalse(gather(floorBvh, floorQuery, up, above, a, b), "TC16: a plane the pyramid does not reach");
        assertEquals(0, assertBundle(floorBvh, floorQuery, up, above, a, b, 0, rnd, "TC16"), "TC16: no ray may be blocked");
        assertTrue(gather(floorBvh, floorQuery, up, below, a, b), "TC16: a plane the pyramid crosses");
        assertEquals(200, assertBundle(floorBvh, floorQuery, up, below, a, b, 0, rnd, "TC16"),
                "TC16: every ray must be blocked");
        // TC17: the pyramid's base on the plane (z = 0): true, every ray ends on it and is blocked
        assertTrue(gather(floorBvh, floorQuery, up, Point3D.ZERO, a, b), "TC17: a plane touching the base");
        assertEquals(200, assertBundle(floorBvh, floorQuery, up, Point3D.ZERO, a, b, 0, rnd, "TC17"),
                "TC17: a hit at the ray's end blocks it");
        // TC18: the plane behind the apex (the pyramid from (0, 0, 5) up to z = 10): false
        assertFalse(gather(floorBvh, floorQuery, up, new Point3D(0, 0, 10), a, b), "TC18: a plane behind the apex");
        // TC19: two planes, the pyramid crossing only z = 0: true, and the rays blocked by it
        Geometries two = new Geometries(new Plane(Point3D.ZERO, new Vector(0, 0, 1)),
                new Plane(new Point3D(0, 0, 20), new Vector(0, 0, 1)));
        BoundingVolumeHierarchy twoBvh = BoundingVolumeHierarchy.build(two);
        Query twoQuery = twoBvh.newQuery();
        assertTrue(gather(twoBvh, twoQuery, up, below, a, b), "TC19: only the crossed plane must be gathered");
        assertEquals(200, assertBundle(twoBvh, twoQuery, up, below, a, b, 0, rnd, "TC19"), "TC19: every ray must be blocked");
        // TC20: the plane z = −0.05 just below an apex (0, 0, 0) whose pyramid goes up to z = 5: set aside
        // by a thin pyramid (false), kept by one 0.1 thick (true), whose rays starting below it are blocked
        Geometries low = new Geometries(new Plane(new Point3D(0, 0, -0.05), new Vector(0, 0, 1)));
        BoundingVolumeHierarchy lowBvh = BoundingVolumeHierarchy.build(low);
        Query lowQuery = lowBvh.newQuery();
        Point3D top = new Point3D(0, 0, 5);
        assertFalse(gather(lowBvh, lowQuery, Point3D.ZERO, top, a, b), "TC20: the plane 0.05 behind a thin pyramid");
        assertTrue(gather(lowBvh, lowQuery, Point3D.ZERO, top, a, b, THICK), "TC20: the plane 0.05 behind a thick pyramid");
        int blockedLow = assertBundle(lowBvh, lowQuery, Point3D.ZERO, top, a, b, THICK, rnd, "TC20");
        assertTrue(blockedLow > 0 && blockedLow < 200, "TC20: rays from below blocked, from above open: " + blockedLow);
        // TC21: a refused (flat) frustum sets nothing aside: gather gives true over the row (a subtree), and
        // rays through each triangle are blocked, between them open
        assertFalse(rowQuery.getFrustum().set(5, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0), "TC21: a flat pyramid is refused");
        assertTrue(rowBvh.gather(rowQuery), "TC21: after a refused set everything must be gathered");
        for (int i = 0; i < 40; ++i) {
            assertRay(0, rowBvh, rowQuery, new Point3D(i, 0, 5), new Point3D(i, 0, -5), "TC21: through triangle " + i);
            assertRay(1, rowBvh, rowQuery, new Point3D(i + 0.5, 0, 5), new Point3D(i + 0.5, 0, -5),
                    "TC21: past triangle " + i);
        }
        // TC22: a refused frustum over the ball (one body, kept one by one): true, the ray through it blocked
        assertFalse(ballQuery.getFrustum().set(0, 0, 7, 0, 0, 7, 1, 0, 0, 0, 1, 0, 0), "TC22: a flat pyramid is refused");
        assertTrue(ballBvh.gather(ballQuery), "TC22: after a refused set the ball must be gathered");
        assertRay(0, ballBvh, ballQuery, up, below, "TC22: the ray through the ball");
        assertRay(1, ballBvh, ballQuery, new Point3D(3, 0, 5), new Point3D(3, 0, -1), "TC22: a ray past the ball");
    }

    // ---------------------------------------------------------------- bundles leaving a surface

    /** How far the light's square must lie off the tangent plane for one side (LightSquare.SIDE_MARGIN). */
    private static final double SIDE_MARGIN = 1e-6;

    /**
     * A bumpy height field as one mesh: z = 0.5·sin(1.3x)·cos(0.9y) over [−6, 6]², 24 × 24 cells of
     * two triangles each (1152 triangles), their normals up.
     *
     * @return the mesh
     */
    private static TriangleMesh bumpyMesh() {
        int cells = 24;
        double[] vertices = new double[3 * (cells + 1) * (cells + 1)];
        for (int i = 0; i <= cells; ++i)
            for (int j = 0; j <= cells; ++j) {
                double x = -6 + 12.0 * i / cells;
                double y = -6 + 12.0 * j / cells;
                int v = 3 * (i * (cells + 1) + j);
                vertices[v] = x;
                vertices[v + 1] = y;
                vertices[v + 2] = 0.5 * Math.sin(1.3 * x) * Math.cos(0.9 * y);
            }
        int[] indices = new int[6 * cells * cells];
        int k = 0;
        for (int i = 0; i < cells; ++i)
            for (int j = 0; j < cells; ++j) {
                int v00 = i * (cells + 1) + j;
                int v10 = v00 + cells + 1;
                int[] corners = { v00, v10, v10 + 1, v00, v10 + 1, v00 + 1 };
                System.arraycopy(corners, 0, indices, k, 6);
                k += 6;
            }
        return new TriangleMesh(vertices, indices);
    }

    /**
     * What the bundles leaving a mesh's surface did: how many of each kind, and how often a gathered
     * triangle was skipped for a ray by its start.
     */
    private static final class StartCounts {
        /** bundles whose square straddles the tangent plane: the starts set. */
        private int straddling;
        /** bundles whose square lies on one side: the back face set. */
        private int oneSide;
        /** straddling bundles that kept at most 32 bodies, some mesh triangle behind a start among them. */
        private int straddlingSkipping;
        /** (ray, gathered triangle) pairs skipped by the start. */
        private int skipped;
        private int rays;
        private int darkened;

        /** Asserts that both kinds of bundles were seen, at least a number of each. */
        void assertBothKinds(int least, String tc) {
            assertTrue(straddling >= least && oneSide >= least, tc + ": too few straddling (" + straddling
                    + ") or one-sided (" + oneSide + ") bundles");
        }
    }

    /**
     * Sets a bundle leaving a surface point as the renderer's light square does (LightSquare.gather):
     * when the square lies on one side of the tangent plane the pyramid starts DELTA off it on that
     * side and gets the back face across the normal; otherwise it starts at the point, DELTA thick,
     * and the starts p ± n are set; then gathers.
     *
     * @param bvh   the hierarchy
     * @param query the scratch space
     * @param p     the point on the surface
     * @param n     the surface's normal scaled to DELTA
     * @param c     the centre of the square
     * @param a     half of one side (as long as b)
     * @param b     half of the other side
     * @return {the side the rays all leave to (1 or −1, 0 when the square straddles the plane), 1 when
     *         gather found something else 0}; null for a flat pyramid
     */
    private static int[] gatherLeaving(BoundingVolumeHierarchy bvh, Query query, Point3D p, Vector n, Point3D c,
                                       Vector a, Vector b) {
        return gatherLeaving(bvh, query, p, n, c, a, b, true);
    }

    /**
     * Sets a bundle leaving a surface point as the renderer's light square does (LightSquare.gather),
     * for a point on a triangle ({@link #gatherLeaving(BoundingVolumeHierarchy, Query, Point3D, Vector,
     * Point3D, Vector, Vector)}) or on another body (a plane's, a sphere's: no back face, no starts).
     *
     * @param bvh   the hierarchy
     * @param query the scratch space
     * @param p     the point on the surface
     * @param n     the surface's normal scaled to DELTA
     * @param c     the centre of the square
     * @param a     half of one side (as long as b)
     * @param b     half of the other side
     * @param facet whether the point lies on a triangle: the frustum is told the surface it leaves
     * @return {the side the rays all leave to (1 or −1, 0 when the square straddles the plane), 1 when
     *         gather found something else 0}; null for a flat pyramid
     */
    private static int[] gatherLeaving(BoundingVolumeHierarchy bvh, Query query, Point3D p, Vector n, Point3D c,
                                       Vector a, Vector b, boolean facet) {
        Vector w = c.subtract(p);
        double centre = n.dotProduct(w);
        double spread = Math.abs(n.dotProduct(a)) + Math.abs(n.dotProduct(b));
        double margin = SIDE_MARGIN * Ray.DELTA * (w.length() + 2 * a.length());
        int side = centre - spread > margin ? 1 : centre + spread < -margin ? -1 : 0;
        Point3D apex = side == 0 ? p : p.add(n.scale(side));
        Point3D base = side == 0 ? c : c.add(n.scale(side));
        ShadowFrustum frustum = query.getFrustum();
        if (!frustum.set(apex.getX(), apex.getY(), apex.getZ(), base.getX(), base.getY(), base.getZ(), a.getX(),
                a.getY(), a.getZ(), b.getX(), b.getY(), b.getZ(), side == 0 ? Ray.DELTA : 0))
            return null;
        if (facet && side != 0) {
            frustum.setBackFace(side * n.getX(), side * n.getY(), side * n.getZ());
            assertTrue(frustum.hasBackFace(), "the base of a bundle leaving on one side must lie ahead of its back face");
        } else if (facet)
            frustum.setOrigins(p.getX(), p.getY(), p.getZ(), n.getX(), n.getY(), n.getZ());
        return new int[] { side, bvh.gather(query) ? 1 : 0 };
    }

    /**
     * The shadow rays of a bundle as the renderer traces them (LightSquare.traceSamples): from the
     * point to random points of the square, each starting DELTA off the surface on the side it leaves to.
     *
     * @param rnd   the generator
     * @param p     the point on the surface
     * @param n     the surface's normal scaled to DELTA
     * @param c     the centre of the square
     * @param a     half of one side
     * @param b     half of the other side
     * @param count the number of rays
     * @return the rays, {ox, oy, oz, dx, dy, dz, distance} each
     */
    private static double[][] shadowRays(Random rnd, Point3D p, Vector n, Point3D c, Vector a, Vector b, int count) {
        double[][] rays = new double[count][];
        for (int r = 0; r < count; ++r) {
            Point3D target = squarePoint(rnd, c, a, b);
            double dx = target.getX() - p.getX();
            double dy = target.getY() - p.getY();
            double dz = target.getZ() - p.getZ();
            double distance = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double inverse = 1 / distance;
            dx *= inverse;
            dy *= inverse;
            dz *= inverse;
            double side = alignZero(n.getX() * dx + n.getY() * dy + n.getZ() * dz);
            double offset = side > 0 ? 1 : side < 0 ? -1 : 0;
            rays[r] = new double[] { p.getX() + offset * n.getX(), p.getY() + offset * n.getY(),
                    p.getZ() + offset * n.getZ(), dx, dy, dz, distance };
        }
        return rays;
    }

    /**
     * A point of a mesh's triangle: p1 + u·(p2 − p1) + v·(p3 − p1).
     *
     * @param mesh the mesh
     * @param t    the triangle's index
     * @param u    the weight of the first edge
     * @param v    the weight of the second edge (u + v at most 1 for a point on the triangle)
     * @return the point
     */
    private static Point3D pointOnTriangle(TriangleMesh mesh, int t, double u, double v) {
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        mesh.triangleData(t, data, 0);
        return new Point3D(data[0] + u * data[3] + v * data[6], data[1] + u * data[4] + v * data[7],
                data[2] + u * data[5] + v * data[8]);
    }

    /**
     * A random bundle leaving a random point of a mesh's triangle (or one of its vertices): its square straddling the tangent
     * plane (even bundles: beside the point, tilted across the plane) or lying on one side of it (odd
     * bundles: over it, a quarter of them under it). Every ray's gathered transmittance, after the
     * gather as the renderer sets it, equals the scan's transmittance, exactly, with the cut-off and
     * without, and so does the packet's; and no gathered triangle skipped for a ray by its start is
     * hit by it.
     *
     * @param rnd    the generator
     * @param mesh   the mesh to start on
     * @param bvh    the hierarchy of the scene
     * @param scan   the scan of the scene
     * @param bundle   the bundle's number
     * @param atVertex whether the point is a vertex of the triangle, shared with its neighbours
     * @param counts   the counters to add to
     * @param tc       the test-case label
     */
    private static void checkLeaving(Random rnd, TriangleMesh mesh, BoundingVolumeHierarchy bvh,
                                     BoundingVolumeHierarchy scan, int bundle, boolean atVertex, StartCounts counts,
                                     String tc) {
        Query query = bvh.newQuery();
        Query scanQuery = scan.newQuery();
        int t = rnd.nextInt(mesh.getTrianglesCount());
        double u = atVertex ? 1 : rnd.nextDouble();
        Point3D p = pointOnTriangle(mesh, t, u, (1 - u) * rnd.nextDouble());
        Vector normal = mesh.getNormal(t);
        Vector n = normal.scale(Ray.DELTA / normal.length());
        Vector along = perpendicular(rnd, normal);
        double distance = 2 + 20 * rnd.nextDouble();
        Point3D c;
        Vector a;
        if (bundle % 2 == 0) { // beside the point, a side of the square across the tangent plane
            c = p.add(along.scale(distance)).add(normal.scale(0.05 * distance * (2 * rnd.nextDouble() - 1)));
            double tilt = 0.3 + rnd.nextDouble();
            a = normal.scale(Math.cos(tilt)).add(normal.crossProduct(along).scale(Math.sin(tilt)));
        } else { // over (or under) the point
            double side = bundle % 4 == 1 || rnd.nextInt(2) == 0 ? 1 : -1;
            c = p.add(normal.scale(side * distance)).add(along.scale(2 * distance * rnd.nextDouble()));
            a = perpendicular(rnd, c.subtract(p));
        }
        Vector b = a.crossProduct(c.subtract(p)).normalize();
        double half = distance * (bundle % 2 == 0 ? 0.05 + 0.2 * rnd.nextDouble() : 0.01 + 0.1 * rnd.nextDouble());
        a = a.normalize().scale(half);
        b = b.scale(half);
        int[] gathered = gatherLeaving(bvh, query, p, n, c, a, b);
        if (gathered == null)
            return;
        if (gathered[0] == 0)
            ++counts.straddling;
        else
            ++counts.oneSide;
        ShadowFrustum frustum = query.getFrustum();
        double[][] rays = shadowRays(rnd, p, n, c, a, b, 30);
        String bundleLabel = tc + " bundle " + bundle + " (p " + p + ", n " + n + ", c " + c + ", a " + a + ", b " + b
                + ", side " + gathered[0] + ", gathered " + gathered[1] + ")";
        List<Ray> packet = new ArrayList<>();
        List<Double> distances = new ArrayList<>();
        for (double[] ray : rays) {
            Supplier<String> label = () -> bundleLabel + " ray " + Arrays.toString(ray);
            for (double minK : new double[] { MIN_K, 0 }) {
                double expected = scan.transmittance(scanQuery.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), minK);
                assertEquals(expected, bvh.bundleRayTransmittance(query.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), minK), 0, label);
            }
            ++counts.rays;
            if (scan.transmittance(scanQuery.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), 0) < 1)
                ++counts.darkened;
            packet.add(new Ray(new Point3D(ray[0], ray[1], ray[2]), new Vector(ray[3], ray[4], ray[5])));
            distances.add(ray[6]);
        }
        assertPacket(bvh, query, scan, scanQuery, packet, distances, 0, () -> bundleLabel);
        if (gathered[1] == 0 || query.isSubtreeGathered())
            return;
        // the mesh's triangles the gather kept (box and own test), and the rays that skip them
        boolean skipping = false;
        double[] box = new double[6];
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        for (int k = 0; k < mesh.getTrianglesCount(); ++k) {
            mesh.bounds(k, box, 0);
            if (!frustum.meetsBox(box, 0) || !mesh.mayMeet(k, frustum))
                continue;
            mesh.triangleData(k, data, 0);
            int behind = frustum.originsBehind(data, 0);
            for (double[] ray : rays)
                if ((frustum.originOf(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5]) & behind) != 0) {
                    ++counts.skipped;
                    skipping = true;
                    int triangle = k;
                    assertEquals(Geometry.NO_HIT, Triangle.intersect(data, 0, ray[0], ray[1], ray[2], ray[3], ray[4],
                            ray[5], ray[6]), 0, () -> bundleLabel + ": triangle " + triangle + " skipped by the ray "
                            + Arrays.toString(ray) + " is hit by it");
                }
        }
        if (skipping && gathered[0] == 0)
            ++counts.straddlingSkipping;
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} and
     * {@link BoundingVolumeHierarchy#gatheredTransmittance} on bundles that leave a mesh's surface, set
     * as the renderer sets them ({@link ShadowFrustum#setBackFace}, {@link ShadowFrustum#setOrigins}):
     * every ray's answer equals the brute-force scan's, though gathered triangles behind a ray's start
     * are skipped, and a bundle leaving a convex mesh gathers nothing.
     */
    @Test
    void testGatheredTransmittanceLeavingSurface() {
        Random rnd = new Random(20261202);
        double[] halves = { 0.5 };

        // ===== Equivalence Partitions Tests =====
        // TC01: a tessellated sphere (radius 6, 960 triangles, one TriangleMesh) with 4 small spheres
        // around, and a bumpy height field (1152 triangles) with a sphere over it; opaque, and with kT
        // 0.5 everywhere (its products are exact in any order): 200 bundles each from random points of
        // the meshes, half of them straddling the tangent plane, 30 rays each: gatheredTransmittance
        // (and the packet's answer) = the scan's transmittance, exactly
        StartCounts counts = new StartCounts();
        for (int scene = 0; scene < 4; ++scene) {
            TriangleMesh mesh = scene % 2 == 0 ? benchmark.SphereMesh.mesh(Point3D.ZERO, 6, 16, 32) : bumpyMesh();
            Geometries geometries = new Geometries(mesh);
            if (scene % 2 == 0)
                for (int i = 0; i < 4; ++i)
                    geometries.add(new Sphere(Point3D.ZERO.add(randomUnit(rnd).scale(8 + rnd.nextDouble())),
                            0.5 + rnd.nextDouble()));
            else
                geometries.add(new Sphere(new Point3D(1, -1, 3), 1.5));
            if (scene >= 2)
                setKt(geometries, halves, rnd);
            checkLeaving(rnd, mesh, geometries, 200, false, counts, "TC01: scene " + scene);
        }
        // both kinds of bundles are common, some rays are darkened and some open, and gathered triangles
        // of straddling bundles are skipped often: the comparison is not vacuous
        counts.assertBothKinds(300, "TC01");
        assertTrue(counts.darkened >= 3000 && counts.rays - counts.darkened >= 3000, "TC01: too few darkened ("
                + counts.darkened + ") or open (" + (counts.rays - counts.darkened) + ") rays of " + counts.rays);
        assertTrue(counts.straddlingSkipping >= 200 && counts.skipped >= 20000, "TC01: too few straddling bundles "
                + "skipping triangles (" + counts.straddlingSkipping + "), or skips (" + counts.skipped + ")");

        // TC02: the tessellated sphere alone, low lights over random points of it (the square on the normal's
        // side): the back face sets the whole convex mesh aside (gather false, every ray open as the scan
        // says), where without it the same pyramid keeps, in about a fifth of the bundles, triangles behind
        // its apex whose planes it meets and that lie outside none of its five faces
        TriangleMesh sphere = benchmark.SphereMesh.mesh(Point3D.ZERO, 6, 16, 32);
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(new Geometries(sphere));
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(new Geometries(sphere));
        Query query = bvh.newQuery();
        Query scanQuery = scan.newQuery();
        int withoutBackFace = 0;
        for (int bundle = 0; bundle < 100; ++bundle) {
            int t = rnd.nextInt(sphere.getTrianglesCount());
            Point3D p = pointOnTriangle(sphere, t, 0.1 + 0.4 * rnd.nextDouble(), 0.1 + 0.4 * rnd.nextDouble());
            Vector normal = sphere.getNormal(t);
            Vector n = normal.scale(Ray.DELTA / normal.length());
            // a low light: 2 to 22 away, 0.05 to 0.3 of that over the tangent plane
            double distance = 2 + 20 * rnd.nextDouble();
            double height = 0.05 + 0.25 * rnd.nextDouble();
            Point3D c = p.add(perpendicular(rnd, normal).scale(distance)).add(normal.scale(height * distance));
            Vector a = perpendicular(rnd, c.subtract(p)).scale(distance * height * (0.05 + 0.4 * rnd.nextDouble()));
            Vector b = a.crossProduct(c.subtract(p)).normalize().scale(a.length());
            int[] gathered = gatherLeaving(bvh, query, p, n, c, a, b);
            assertNotNull(gathered, "TC02: the pyramid must not be flat");
            int number = bundle;
            assertEquals(1, gathered[0], () -> "TC02: bundle " + number + " must leave on the normal's side");
            assertEquals(0, gathered[1], () -> "TC02: bundle " + number + " from " + p + " must gather nothing");
            for (double[] ray : shadowRays(rnd, p, n, c, a, b, 20)) {
                assertEquals(1, scan.transmittance(scanQuery.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), MIN_K), 0, "TC02: a ray leaving a convex mesh is open");
                assertEquals(1, bvh.bundleRayTransmittance(query.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), MIN_K), 0, "TC02: a ray leaving a convex mesh is open (gathered)");
            }
            // the same pyramid without the back face
            Point3D apex = p.add(n);
            Point3D base = c.add(n);
            assertTrue(query.getFrustum().set(apex.getX(), apex.getY(), apex.getZ(), base.getX(), base.getY(),
                    base.getZ(), a.getX(), a.getY(), a.getZ(), b.getX(), b.getY(), b.getZ(), 0), "TC02: set again");
            if (bvh.gather(query))
                ++withoutBackFace;
        }
        assertTrue(withoutBackFace >= 10, "TC02: without the back face too few bundles gathered the surface ("
                + withoutBackFace + " of 100)");

        // ===== Boundary Values Tests =====
        // TC11: bundles leaving the meshes' vertices, each shared by several triangles whose planes pass
        // through the point: every ray's answer is the scan's, exactly
        StartCounts atVertices = new StartCounts();
        for (TriangleMesh mesh : List.of(sphere, bumpyMesh()))
            checkLeaving(rnd, mesh, new Geometries(mesh, new Sphere(new Point3D(1, 9, 3), 1.5)), 100, true,
                    atVertices, "TC11: " + mesh);
        atVertices.assertBothKinds(50, "TC11");
    }

    /**
     * {@link #checkLeaving} for bundles 0, 1, … of a scene, in its hierarchy and its scan.
     *
     * @param geometries the scene, the mesh in it
     * @param bundles    how many bundles
     */
    private static void checkLeaving(Random rnd, TriangleMesh mesh, Geometries geometries, int bundles,
                                     boolean atVertex, StartCounts counts, String tc) {
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(geometries);
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(geometries);
        for (int bundle = 0; bundle < bundles; ++bundle)
            checkLeaving(rnd, mesh, bvh, scan, bundle, atVertex, counts, tc);
    }

    // ---------------------------------------------------------------- triangles left out behind both starts

    /**
     * The triangles of a scene, as one mesh or as course-style {@link Triangle} objects, each the same
     * numbers.
     *
     * @param body      the mesh or the composite of the triangles
     * @param mesh      the mesh, or null
     * @param triangles the triangles' objects, or null
     */
    private record Surface(Intersectable body, TriangleMesh mesh, List<Triangle> triangles) {
        /**
         * Builds the triangles, all of one kT.
         *
         * @param vertices the triangles, nine coordinates each
         * @param asMesh   true for one mesh, false for Triangle objects in a Geometries
         * @param kT       the transparency of every triangle
         * @return the surface
         */
        static Surface of(List<double[]> vertices, boolean asMesh, double kT) {
            Material material = new Material().setKt(kT);
            if (asMesh) {
                double[] coordinates = new double[9 * vertices.size()];
                int[] indices = new int[3 * vertices.size()];
                for (int t = 0; t < vertices.size(); ++t) {
                    System.arraycopy(vertices.get(t), 0, coordinates, 9 * t, 9);
                    for (int i = 0; i < 3; ++i)
                        indices[3 * t + i] = 3 * t + i;
                }
                TriangleMesh mesh = new TriangleMesh(coordinates, indices);
                mesh.setMaterial(material);
                return new Surface(mesh, mesh, null);
            }
            List<Triangle> triangles = new ArrayList<>();
            for (double[] v : vertices) {
                Triangle triangle = new Triangle(new Point3D(v[0], v[1], v[2]), new Point3D(v[3], v[4], v[5]),
                        new Point3D(v[6], v[7], v[8]));
                triangle.setMaterial(material);
                triangles.add(triangle);
            }
            return new Surface(new Geometries(triangles.toArray(new Intersectable[0])), null, triangles);
        }

        /**
         * Whether the gather keeps triangle t (if its box meets the frustum).
         *
         * @param t       the triangle's index
         * @param frustum the frustum
         * @return its mayMeet
         */
        boolean mayMeet(int t, ShadowFrustum frustum) {
            return mesh != null ? mesh.mayMeet(t, frustum) : triangles.get(t).mayMeet(frustum);
        }
    }

    /**
     * The two triangles of the rectangle [x0, x1] × [y0, y1] whose height runs linearly in x from h0 to h1.
     *
     * @param list where to add them
     */
    private static void addCell(List<double[]> list, double x0, double x1, double y0, double y1, double h0,
                                double h1) {
        list.add(new double[] { x0, y0, h0, x1, y0, h1, x1, y1, h1 });
        list.add(new double[] { x0, y0, h0, x1, y1, h1, x0, y1, h0 });
    }

    /**
     * A ray as {@link #shadowRays} gives it: {ox, oy, oz, dx, dy, dz, distance}, from a point to another.
     *
     * @param from the start
     * @param to   the end
     * @return the ray
     */
    private static double[] rayFromTo(Point3D from, Point3D to) {
        Vector d = to.subtract(from);
        double distance = d.length();
        d = d.normalize();
        return new double[] { from.getX(), from.getY(), from.getZ(), d.getX(), d.getY(), d.getZ(), distance };
    }

    /**
     * A bundle leaving a point p of a surface z = 0 (starts p ± {@link #UP}) to the square centred
     * (10, p.y, 0), half-sides (0, 0, h) and (0, h, 0), straddling the surface, gathered over the surface
     * and a sphere (8, p.y, 0), radius 0.5, kT 0.5; the hierarchy of the two and their scan.
     *
     * @param surface   the surface
     * @param p         the point the rays leave
     * @param c         the centre of the square
     * @param a         half of one side
     * @param b         half of the other side
     * @param bvh       the hierarchy
     * @param query     its scratch space, as the gather left it
     * @param scan      the scan of the same scene
     * @param scanQuery the scan's scratch space
     */
    private record Straddling(Surface surface, Point3D p, Point3D c, Vector a, Vector b, BoundingVolumeHierarchy bvh,
                              Query query, BoundingVolumeHierarchy scan, Query scanQuery) {
        /**
         * Builds the scene and gathers the bundle as {@link #gatherLeaving} sets it, asserting that its
         * square straddles the surface, that something is gathered, one by one.
         *
         * @param surface the surface
         * @param p       the point the rays leave
         * @param half    the square's half-side h
         * @param kind    the failure messages' prefix
         * @return the gathered bundle
         */
        static Straddling of(Surface surface, Point3D p, double half, String kind) {
            Point3D c = new Point3D(10, p.getY(), 0);
            Vector a = new Vector(0, 0, half);
            Vector b = new Vector(0, half, 0);
            Sphere sphere = new Sphere(new Point3D(8, p.getY(), 0), 0.5);
            sphere.setMaterial(new Material().setKt(0.5));
            Geometries scene = new Geometries(surface.body(), sphere);
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene);
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene);
            Query query = bvh.newQuery();
            int[] gathered = gatherLeaving(bvh, query, p, UP, c, a, b);
            assertNotNull(gathered, kind + ": the pyramid must not be flat");
            assertEquals(0, gathered[0], kind + ": the square must straddle the surface");
            assertEquals(1, gathered[1], kind + ": something must be gathered");
            assertFalse(query.isSubtreeGathered(), kind + ": few bodies are kept one by one");
            return new Straddling(surface, p, c, a, b, bvh, query, scan, scan.newQuery());
        }

        /**
         * The bundle's shadow rays as the renderer traces them ({@link BoundingVolumeHierarchyTest#shadowRays}).
         *
         * @param rnd   the generator
         * @param count the number of rays
         * @return the rays
         */
        double[][] shadowRays(Random rnd, int count) {
            return BoundingVolumeHierarchyTest.shadowRays(rnd, p, UP, c, a, b, count);
        }

        /**
         * Asserts that a ray's gathered transmittance is exactly the scan's, with and without the cut-off.
         *
         * @param ray   {ox, oy, oz, dx, dy, dz, distance}
         * @param label the failure message
         * @return the scan's answer without the cut-off
         */
        double assertAsScan(double[] ray, String label) {
            double expected = 0;
            for (double minK : new double[] { MIN_K, 0 }) {
                expected = scan.transmittance(scanQuery.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), minK);
                assertEquals(expected, bvh.bundleRayTransmittance(query.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), minK), 0, () -> label + " " + Arrays.toString(ray) + " minK " + minK);
            }
            return expected;
        }
    }

    /** The normal of the surfaces z = 0 scaled to DELTA: the starts p ± UP. */
    private static final Vector UP = new Vector(0, 0, Ray.DELTA);

    /** {@return the failure messages' name of a surface of one mesh or of Triangle objects} */
    private static String kind(boolean asMesh) {
        return asMesh ? "mesh" : "Triangle objects";
    }

    /**
     * A surface along z = 0 with a low ridge, all of it between the starts (0.1 off it): flat over x
     * from −2 to 1, down to −0.05 at x = 2, up to 0.05 at x = 3, back to 0 at x = 4, y from −1 to 2. A
     * ray from (0.5, 0.3, 0) along x crosses the slope up at x = 2.5, inside a triangle.
     *
     * @return the triangles
     */
    private static List<double[]> ridge() {
        List<double[]> list = new ArrayList<>();
        double[] x = { -2, 1, 2, 3, 4 };
        double[] h = { 0, 0, -0.05, 0.05, 0 };
        for (int i = 0; i + 1 < x.length; ++i)
            addCell(list, x[i], x[i + 1], -1, 2, h[i], h[i + 1]);
        return list;
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gatheredTransmittance} on a ray from neither start
     * ({@link ShadowFrustum#setOrigins}): the gather left out the triangles between the starts, and such a
     * ray is traced through the whole hierarchy, with exactly the scan's answer, also when a left-out
     * triangle blocks it.
     * <p>
     * An opaque ridge surface ({@link #ridge}), as a mesh and as Triangle objects, and a sphere (8, 0.3, 0),
     * radius 0.5, kT 0.5; the bundle leaves p = (0.5, 0.3, 0), n = (0, 0, 0.1), to the square centred
     * (10, 0.3, 0), half-sides (0, 0, 1) and (0, 1, 0), which straddles the surface.
     */
    @Test
    void testGatheredTransmittanceFromNeitherStart() {
        Random rnd = new Random(20261204);
        Point3D p = new Point3D(0.5, 0.3, 0);
        List<double[]> ridge = ridge();
        for (boolean asMesh : new boolean[] { true, false }) {
            String kind = kind(asMesh);
            Straddling bundle = Straddling.of(Surface.of(ridge, asMesh, 0), p, 1, kind);
            Point3D c = bundle.c();
            Surface surface = bundle.surface();
            ShadowFrustum frustum = bundle.query().getFrustum();
            // every triangle of the ridge lies behind both starts and is left out
            for (int t = 0; t < ridge.size(); ++t) {
                assertTrue(frustum.behindOrigins(ridge.get(t), 0, 3, 6), kind + ": triangle " + t + " behind both");
                assertFalse(surface.mayMeet(t, frustum), kind + ": triangle " + t + " must be left out");
            }
            double[] along = rayFromTo(p, c);
            // the left-out triangle that the ray from p along the surface hits: the slope up, at x = 2.5
            double[] slope = ridge.get(4);
            assertTrue(Triangle.intersect(slope[0], slope[1], slope[2], slope[3] - slope[0], slope[4] - slope[1],
                    slope[5] - slope[2], slope[6] - slope[0], slope[7] - slope[1], slope[8] - slope[2],
                    Triangle.parallelLimit(slope[3] - slope[0], slope[4] - slope[1], slope[5] - slope[2],
                            slope[6] - slope[0], slope[7] - slope[1], slope[8] - slope[2]), along[0], along[1],
                    along[2], along[3], along[4], along[5], along[6]) < Geometry.NO_HIT,
                    kind + ": the ray along the surface must hit the left-out slope");

            // ===== Equivalence Partitions Tests =====
            // TC01: from p along the surface into the rising slope: start 0 (expects 0, the scan's answer)
            assertEquals(0, frustum.originOf(along[0], along[1], along[2], along[3], along[4], along[5]),
                    "TC01: " + kind + ": a ray from p starts at neither");
            assertEquals(0, bundle.assertAsScan(along, "TC01: " + kind + ": from p along"), 0,
                    "TC01: " + kind + ": the left-out slope blocks the ray from p");
            // TC02: from p up to (10, 0.3, 0.5), over the ridge, into and out of the sphere (expects 0.25, the
            // scan's)
            assertEquals(0.25, bundle.assertAsScan(rayFromTo(p, new Point3D(10, 0.3, 0.5)),
                    "TC02: " + kind + ": from p up"), 0, "TC02: " + kind + ": only the sphere dims it");
            // TC03: from p + 0.3n (off both starts) along x, into the slope at x = 2.8 (expects 0, the scan's)
            Point3D off = p.add(UP.scale(0.3));
            assertEquals(0, bundle.assertAsScan(rayFromTo(off, c.add(UP.scale(0.3))),
                    "TC03: " + kind + ": from off both starts"), 0, "TC03: " + kind + ": the slope blocks it");
            // TC04: 100 rays from random points off both starts (within 0.1 of p) to the square: the scan's answers
            int blocked = 0;
            for (int r = 0; r < 100; ++r) {
                double[] ray = rayFromTo(stray(rnd, p, Ray.DELTA), squarePoint(rnd, c, bundle.a(), bundle.b()));
                assertEquals(0, frustum.originOf(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5]), "TC04: start 0");
                if (bundle.assertAsScan(ray, "TC04: " + kind + ": from off the starts") == 0)
                    ++blocked;
            }
            assertTrue(blocked >= 5 && blocked <= 95, "TC04: " + kind + ": blocked " + blocked + " of 100");
            // TC05: rays from the starts, as the renderer traces them: the scan's answers
            for (double[] ray : bundle.shadowRays(rnd, 100))
                bundle.assertAsScan(ray, "TC05: " + kind + ": from a start");

            // ===== Boundary Values Tests =====
            // TC11: from p + n exactly along the surface (d·n = 0): start 0, over the ridge, through the
            // sphere (expects 0.25, the scan's)
            double[] above = rayFromTo(p.add(UP), c.add(UP));
            assertEquals(0, frustum.originOf(above[0], above[1], above[2], above[3], above[4], above[5]),
                    "TC11: along the surface from p + n starts at neither");
            assertEquals(0.25, bundle.assertAsScan(above, "TC11: " + kind), 0,
                    "TC11: " + kind + ": only the sphere dims it");
        }
    }

    /**
     * Shelves over and under the surface z = 0 around p = (0, 0, 0), and the surface itself: at
     * heights ±0.3 (x 2..6) and ±0.6 (x 3..7), y −3..3, and the floor [−2, 2]², two triangles each.
     *
     * @return the triangles, the floor's two first
     */
    private static List<double[]> shelves() {
        List<double[]> list = new ArrayList<>();
        addCell(list, -2, 2, -2, 2, 0, 0);
        for (double h : new double[] { 0.3, -0.3 })
            addCell(list, 2, 6, -3, 3, h, h);
        for (double h : new double[] { 0.6, -0.6 })
            addCell(list, 3, 7, -3, 3, h, h);
        return list;
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} and
     * {@link BoundingVolumeHierarchy#gatheredTransmittance} with the starts set: a gathered triangle
     * behind one start only is kept for the rays from the other, and every ray gets exactly the scan's
     * answer, transparent bodies multiplying; the surface between the starts is left out. The same for
     * one mesh and for course-style Triangle objects.
     * <p>
     * The {@link #shelves} all kT 0.5, and a sphere (8, 0, 0), radius 0.5, kT 0.5, across the surface; the
     * bundle leaves p = (0, 0, 0), n = (0, 0, 0.1), to the square centred (10, 0, 0), half-sides
     * (0, 0, 2) and (0, 2, 0).
     */
    @Test
    void testGatheredTransmittancePerStart() {
        Random rnd = new Random(20261205);
        Point3D p = Point3D.ZERO;
        List<double[]> shelves = shelves();
        for (boolean asMesh : new boolean[] { true, false }) {
            String kind = kind(asMesh);
            Straddling bundle = Straddling.of(Surface.of(shelves, asMesh, 0.5), p, 2, kind);
            ShadowFrustum frustum = bundle.query().getFrustum();
            Surface surface = bundle.surface();

            // ===== Equivalence Partitions Tests =====
            // TC01: the floor's triangles lie behind both starts (expects left out)
            for (int t = 0; t < 2; ++t) {
                assertTrue(frustum.behindOrigins(shelves.get(t), 0, 3, 6), "TC01: " + kind + ": floor behind both");
                assertFalse(surface.mayMeet(t, frustum), "TC01: " + kind + ": the floor must be left out");
            }
            // TC02: the shelves over the surface lie behind p − n only, those under it behind p + n only
            // (expects kept)
            for (int t = 2; t < shelves.size(); ++t) {
                double[] v = shelves.get(t);
                double[] data = { v[0], v[1], v[2], v[3] - v[0], v[4] - v[1], v[5] - v[2], v[6] - v[0], v[7] - v[1],
                        v[8] - v[2] };
                assertEquals(v[2] > 0 ? ShadowFrustum.BELOW : ShadowFrustum.ABOVE, frustum.originsBehind(data, 0),
                        "TC02: " + kind + ": shelf triangle " + t + " behind one start");
                assertFalse(frustum.behindOrigins(v, 0, 3, 6), "TC02: " + kind + ": shelf " + t + " not behind both");
                assertTrue(surface.mayMeet(t, frustum), "TC02: " + kind + ": shelf " + t + " must be kept");
            }
            // TC03: 400 rays from the starts to random points of the square, as the renderer traces them: the
            // scan's answers, exactly; per start some are dimmed twice or more (two shelves, or into and out of
            // the sphere: ≤ 0.25) and some open
            int[] dimmedTwice = new int[3];
            int[] open = new int[3];
            for (double[] ray : bundle.shadowRays(rnd, 400)) {
                int start = frustum.originOf(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5]);
                double answer = bundle.assertAsScan(ray, "TC03: " + kind + ": start " + start);
                if (answer <= 0.25)
                    ++dimmedTwice[start];
                else if (answer == 1)
                    ++open[start];
            }
            for (int start = ShadowFrustum.ABOVE; start <= ShadowFrustum.BELOW; ++start)
                assertTrue(dimmedTwice[start] >= 20 && open[start] >= 20, "TC03: " + kind + ": from start " + start
                        + " too few rays dimmed twice (" + dimmedTwice[start] + ") or open (" + open[start] + ")");
            // TC04: from p + n through the shelf at 0.3 (x 5) and the one at 0.6 (x 6.67) to (10, 0, 1): start
            // ABOVE (expects 0.25); its mirror from p − n (expects 0.25)
            double[] up = rayFromTo(p.add(UP), new Point3D(10, 0, 1));
            assertEquals(ShadowFrustum.ABOVE, frustum.originOf(up[0], up[1], up[2], up[3], up[4], up[5]), "TC04");
            assertEquals(0.25, bundle.assertAsScan(up, "TC04: " + kind + ": up"), 0,
                    "TC04: " + kind + ": two shelves over the surface");
            double[] down = rayFromTo(p.add(UP.scale(-1)), new Point3D(10, 0, -1));
            assertEquals(ShadowFrustum.BELOW, frustum.originOf(down[0], down[1], down[2], down[3], down[4], down[5]),
                    "TC04");
            assertEquals(0.25, bundle.assertAsScan(down, "TC04: " + kind + ": down"), 0,
                    "TC04: " + kind + ": two shelves under the surface");

            // ===== Boundary Values Tests =====
            // TC11: from p + n to the square's lowest edge (10, 0, −2): it leaves to the other side, start 0,
            // traced alone through the lower shelves (expects the scan's answer)
            bundle.assertAsScan(rayFromTo(p.add(UP), new Point3D(10, 0, -2)),
                    "TC11: " + kind + ": from p + n downwards");
            // TC12: the floor alone: every triangle left out behind the starts, yet the bundle is not open, as
            // a ray from neither start may meet them (expects true, and a ray from a start lets all through)
            Surface floor = Surface.of(shelves.subList(0, 2), asMesh, 0.5);
            BoundingVolumeHierarchy floorBvh = BoundingVolumeHierarchy.build(new Geometries(floor.body()));
            Query floorQuery = floorBvh.newQuery();
            int[] floorGathered = gatherLeaving(floorBvh, floorQuery, p, UP, bundle.c(), bundle.a(), bundle.b());
            assertNotNull(floorGathered, "TC12: the pyramid must not be flat");
            assertTrue(floorQuery.getFrustum().leftBehindOrigins(),
                    "TC12: " + kind + ": the floor between the starts must be left out");
            assertEquals(1, floorGathered[1], "TC12: " + kind + ": a bundle that left triangles out must not be open");
            assertEquals(1, floorBvh.bundleRayTransmittance(floorQuery.setRay(up[0], up[1], up[2], up[3], up[4], up[5], up[6]), 0), 0, "TC12: " + kind + ": a ray from a start over the floor");
        }
    }

    /**
     * Composites without a body: an empty one, and one of empty composites.
     *
     * @return new composites
     */
    private static List<Geometries> emptyComposites() {
        return List.of(new Geometries(), new Geometries(new Geometries(), new Geometries(new Geometries())));
    }

    /**
     * The centroid of a triangle, a point on it.
     *
     * @param triangle the triangle
     * @return the centroid
     */
    private static Point3D centroid(Triangle triangle) {
        List<Point3D> v = triangle.getVertices();
        return new Point3D((v.get(0).getX() + v.get(1).getX() + v.get(2).getX()) / 3,
                (v.get(0).getY() + v.get(1).getY() + v.get(2).getY()) / 3,
                (v.get(0).getZ() + v.get(1).getZ() + v.get(2).getZ()) / 3);
    }

    // ---------------------------------------------------------------- bundles blocked by closed meshes

    /** The centre of the light's square over the scenes of closed meshes. */
    private static final Point3D SOLID_LIGHT = new Point3D(0, 0, 30);
    /** The floor z = 0 of the scenes of closed meshes, and its normal. */
    private static final Vector FLOOR_NORMAL = new Vector(0, 0, 1);

    /**
     * A scene of closed sphere meshes over a floor, under a light's square around {@link #SOLID_LIGHT}.
     *
     * @param geometries the composite: the floor, the closed meshes, the open ones, the spheres
     * @param closed     the closed meshes
     * @param open       the open meshes
     * @param spheres    the {@link Sphere} bodies
     */
    private record SolidScene(Geometries geometries, List<TriangleMesh> closed, List<TriangleMesh> open,
                              List<Sphere> spheres) {
        /**
         * Builds a random scene: the opaque floor z = 0; closed sphere meshes (radius 1 to 3, 6 to 11
         * rings, centres over x, y in [−8, 8] at heights 0.5 to 6, some cutting the floor) of a kT, and
         * one more of kT 0.5 when that kT is 0; an open bowl (a sphere's mesh without its top cap) and
         * two spheres, opaque.
         *
         * @param rnd   the generator
         * @param count the number of closed meshes of the kT
         * @param kT    their kT
         * @return the scene
         */
        static SolidScene random(Random rnd, int count, double kT) {
            Geometries geometries = new Geometries(new Plane(Point3D.ZERO, FLOOR_NORMAL));
            List<TriangleMesh> closed = new ArrayList<>();
            for (int m = 0; m < count + (kT == 0 ? 1 : 0); ++m) {
                int rings = 6 + rnd.nextInt(6);
                TriangleMesh mesh = benchmark.SphereMesh.mesh(randomAbove(rnd, 0.5, 6), 1 + 2 * rnd.nextDouble(), rings,
                        2 * rings);
                mesh.setMaterial(new Material().setKt(m < count ? kT : 0.5));
                closed.add(mesh);
                geometries.add(mesh);
            }
            TriangleMesh bowl = bowl(randomAbove(rnd, 2, 6), 1.5 + rnd.nextDouble(), 8, 16);
            geometries.add(bowl);
            List<Sphere> spheres = new ArrayList<>();
            for (int i = 0; i < 2; ++i) {
                Sphere sphere = new Sphere(randomAbove(rnd, 1.5, 8), 0.5 + rnd.nextDouble());
                spheres.add(sphere);
                geometries.add(sphere);
            }
            return new SolidScene(geometries, closed, List.of(bowl), spheres);
        }

        /**
         * A random point over x, y in [−8, 8] at a height.
         *
         * @param rnd  the generator
         * @param low  the lowest height
         * @param high the highest height
         * @return the point
         */
        private static Point3D randomAbove(Random rnd, double low, double high) {
            return new Point3D(16 * rnd.nextDouble() - 8, 16 * rnd.nextDouble() - 8,
                    low + (high - low) * rnd.nextDouble());
        }
    }

    /**
     * An open mesh: a sphere's mesh without the triangles of its top cap.
     *
     * @param centre   the sphere's centre
     * @param radius   its radius
     * @param rings    its bands
     * @param segments its slices
     * @return the mesh
     */
    private static TriangleMesh bowl(Point3D centre, double radius, int rings, int segments) {
        TriangleMesh sphere = benchmark.SphereMesh.mesh(centre, radius, rings, segments);
        double[] vertices = new double[3 * sphere.getVerticesCount()];
        for (int v = 0; v < sphere.getVerticesCount(); ++v) {
            Point3D vertex = sphere.getVertex(v);
            vertices[3 * v] = vertex.getX();
            vertices[3 * v + 1] = vertex.getY();
            vertices[3 * v + 2] = vertex.getZ();
        }
        int perSlice = 2 * (rings - 1); // the top's triangle first, then the bands' and the bottom's
        int[] indices = new int[3 * (sphere.getTrianglesCount() - segments)];
        int i = 0;
        for (int t = 0; t < sphere.getTrianglesCount(); ++t)
            if (t % perSlice != 0)
                for (int k = 0; k < 3; ++k)
                    indices[i++] = sphere.getVertexIndex(t, k);
        return new TriangleMesh(vertices, indices);
    }

    /** What the bundles over closed meshes did. */
    private static final class SolidCounts {
        /** bundles blocksBundle said were blocked. */
        private int blocked;
        /** of them, bundles leaving a mesh's surface (the rays entering the mesh). */
        private int blockedOnMesh;
        /** bundles that gathered something and were not blocked. */
        private int unblocked;
        /** rays of unblocked bundles traced as a packet that pass through an opaque closed mesh's ball. */
        private int ballRays;
        /** rays traced, and of them those the scan found darkened. */
        private int rays;
        private int darkened;
    }

    /**
     * Traces random bundles through a scene of closed meshes as the renderer sets them: from random
     * points of the floor (a third of them right under a closed mesh), of the meshes' triangles and of
     * the spheres, to squares of half-side 0.5 to 6 around {@link #SOLID_LIGHT}, 24 rays each. When
     * {@link BoundingVolumeHierarchy#blocksBundle} says a bundle is blocked, every ray's brute-force
     * answer is 0, and the scan blocks no bundle itself; otherwise every ray's gathered transmittance,
     * and its answer in the packet, is exactly the scan's.
     *
     * @param rnd     the generator
     * @param scene   the scene
     * @param bundles the number of bundles
     * @param counts  the counters to add to
     * @param tc      the test-case label
     */
    private static void checkSolidBundles(Random rnd, SolidScene scene, int bundles, SolidCounts counts, String tc) {
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries());
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene.geometries());
        Query query = bvh.newQuery();
        Query scanQuery = scan.newQuery();
        Query scanGather = scan.newQuery();
        List<TriangleMesh> meshes = new ArrayList<>(scene.closed());
        meshes.addAll(scene.open());
        for (int bundle = 0; bundle < bundles; ++bundle) {
            double choice = rnd.nextDouble();
            Point3D p;
            Vector normal = FLOOR_NORMAL;
            boolean facet = false;
            if (choice < 0.35)
                p = new Point3D(24 * rnd.nextDouble() - 12, 24 * rnd.nextDouble() - 12, 0);
            else if (choice < 0.55) {
                double[] box = new double[6];
                scene.closed().get(rnd.nextInt(scene.closed().size())).bounds(box, 0);
                p = new Point3D((box[0] + box[3]) / 2 + rnd.nextGaussian(), (box[1] + box[4]) / 2 + rnd.nextGaussian(),
                        0);
            } else if (choice < 0.85) {
                TriangleMesh mesh = meshes.get(rnd.nextInt(meshes.size()));
                int t = rnd.nextInt(mesh.getTrianglesCount());
                double u = rnd.nextDouble();
                p = pointOnTriangle(mesh, t, u, (1 - u) * rnd.nextDouble());
                normal = mesh.getNormal(t);
                facet = true;
            } else {
                Sphere sphere = scene.spheres().get(rnd.nextInt(scene.spheres().size()));
                normal = randomUnit(rnd);
                p = sphere.getCenter().add(normal.scale(sphere.getRadius()));
            }
            Vector n = normal.scale(Ray.DELTA / normal.length());
            Point3D c = SOLID_LIGHT.add(new Vector(10 * rnd.nextDouble() - 5, 10 * rnd.nextDouble() - 5, 1));
            double half = 0.5 + 5.5 * rnd.nextDouble();
            double angle = Math.PI * rnd.nextDouble();
            Vector a = new Vector(Math.cos(angle), Math.sin(angle), 0).scale(half);
            Vector b = new Vector(-Math.sin(angle), Math.cos(angle), 0).scale(half);
            int[] gathered = gatherLeaving(bvh, query, p, n, c, a, b, facet);
            if (gathered == null)
                continue;
            boolean blocked = gathered[1] == 1 && bvh.blocksBundle(query);
            double[][] rays = shadowRays(rnd, p, n, c, a, b, 24);
            String bundleLabel = tc + " bundle " + bundle + " (p " + p + ", n " + n + ", c " + c + ", a " + a + ", b "
                    + b + ", facet " + facet + ", side " + gathered[0] + ", gathered " + gathered[1] + ", blocked "
                    + blocked + ")";
            if (blocked) {
                ++counts.blocked;
                if (facet)
                    ++counts.blockedOnMesh;
                int[] scanGathered = gatherLeaving(scan, scanGather, p, n, c, a, b, facet);
                assertFalse(scanGathered[1] == 1 && scan.blocksBundle(scanGather),
                        bundleLabel + ": the scan must block no bundle");
            } else if (gathered[1] == 1)
                ++counts.unblocked;
            List<Ray> packet = new ArrayList<>();
            List<Double> distances = new ArrayList<>();
            for (double[] ray : rays) {
                Supplier<String> label = () -> bundleLabel + " ray " + Arrays.toString(ray);
                double expected = 1;
                for (double minK : new double[] { MIN_K, 0 }) {
                    expected = scan.transmittance(scanQuery.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), minK);
                    if (blocked)
                        assertEquals(0, expected, 0, () -> label.get() + ": a ray of a blocked bundle must be blocked");
                    else
                        assertEquals(expected, bvh.bundleRayTransmittance(query.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), minK), 0, label);
                }
                ++counts.rays;
                if (expected < 1) // without the cut-off
                    ++counts.darkened;
                packet.add(new Ray(new Point3D(ray[0], ray[1], ray[2]), new Vector(ray[3], ray[4], ray[5])));
                distances.add(ray[6]);
                if (!blocked && query.isSubtreeGathered() && throughBall(scene.closed(), ray))
                    ++counts.ballRays;
            }
            if (!blocked)
                assertPacket(bvh, query, scan, scanQuery, packet, distances, 0, () -> bundleLabel);
        }
    }

    /**
     * Whether a ray passes through the inner ball of one of some meshes that are opaque.
     *
     * @param meshes the meshes
     * @param ray    {ox, oy, oz, dx, dy, dz, distance}
     * @return true when it does
     */
    private static boolean throughBall(List<TriangleMesh> meshes, double[] ray) {
        for (TriangleMesh mesh : meshes) {
            InnerBall ball = InnerBall.of(mesh);
            if (ball != null && mesh.getMaterial().getKt() == 0
                    && ball.crossedBy(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]))
                return true;
        }
        return false;
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#blocksBundle} and
     * {@link BoundingVolumeHierarchy#gatheredTransmittances}: a bundle is said blocked only when the
     * brute-force scan blocks every one of its rays, and in a packet a ray through a closed opaque
     * mesh's ball gets exactly the scan's answer.
     */
    @Test
    void testBlocksBundle() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 4 random scenes of 3 opaque closed sphere meshes (and one of kT 0.5), an open bowl, two
        // spheres and a floor, 120 bundles each, as the renderer sets them (thin from the floor and the
        // spheres, thin or thick from the meshes' triangles): blocked bundles are blocked ray by ray by
        // the scan (not by its own blocksBundle), the others' rays get the scan's answers, one by one
        // and in packets
        Random rnd = new Random(20261204);
        SolidCounts opaque = new SolidCounts();
        for (int s = 0; s < 4; ++s)
            checkSolidBundles(rnd, SolidScene.random(rnd, 3, 0), 120, opaque, "TC01: scene " + s);
        // both answers are common, many blocked bundles leave a mesh, many packet rays pass through a ball
        assertTrue(opaque.blocked >= 60 && opaque.unblocked >= 150, "TC01: too few blocked (" + opaque.blocked
                + ") or unblocked (" + opaque.unblocked + ") bundles");
        assertTrue(opaque.blockedOnMesh >= 20, "TC01: too few blocked bundles leaving a mesh: " + opaque.blockedOnMesh);
        assertTrue(opaque.ballRays >= 200, "TC01: too few packet rays through a ball: " + opaque.ballRays);
        assertTrue(opaque.darkened >= 3000 && opaque.rays - opaque.darkened >= 3000, "TC01: too few darkened ("
                + opaque.darkened + ") or open (" + (opaque.rays - opaque.darkened) + ") rays of " + opaque.rays);
        // TC02: the same with every closed mesh of kT 0.5: no bundle is blocked, the rays through the
        // balls get the scan's answers (products of 0.5, exact in any order)
        SolidCounts transparent = new SolidCounts();
        for (int s = 0; s < 2; ++s)
            checkSolidBundles(rnd, SolidScene.random(rnd, 3, 0.5), 120, transparent, "TC02: scene " + s);
        assertEquals(0, transparent.blocked, "TC02: transparent meshes must block no bundle");
        assertTrue(transparent.unblocked >= 100, "TC02: too few bundles gathered something: " + transparent.unblocked);
        // TC03: a scene of TC02 inside an opaque closed sphere mesh (radius 60 around (0, 0, 10)) whose box
        // holds the light: its ball lies across every bundle, but no bundle is blocked and every ray gets
        // the scan's answer
        SolidScene inside = SolidScene.random(rnd, 3, 0.5);
        TriangleMesh enclosing = benchmark.SphereMesh.mesh(new Point3D(0, 0, 10), 60, 8, 16);
        inside.geometries().add(enclosing);
        List<TriangleMesh> closed = new ArrayList<>(inside.closed());
        closed.add(enclosing);
        SolidCounts enclosed = new SolidCounts();
        checkSolidBundles(rnd, new SolidScene(inside.geometries(), closed, inside.open(), inside.spheres()), 120,
                enclosed, "TC03");
        assertNotNull(InnerBall.of(enclosing), "TC03: the enclosing mesh has an inner ball");
        assertEquals(0, enclosed.blocked, "TC03: a mesh around the light must block no bundle");
        assertTrue(enclosed.unblocked >= 50, "TC03: too few bundles gathered something: " + enclosed.unblocked);

        // ===== Boundary Values Tests =====
        // TC11: 17 opaque closed sphere meshes of radii 1, 1.1, …, 2.6 in a row along x (6 apart, at
        // height 4), a narrow bundle (half-side 0.5) from the floor right under each to a square right
        // over it: only the 16 largest balls are tried, so every bundle but the smallest mesh's is
        // blocked; every ray is blocked by the scan, one by one, and the scan blocks no bundle
        Geometries row = new Geometries(new Plane(Point3D.ZERO, FLOOR_NORMAL));
        for (int m = 0; m < 17; ++m)
            row.add(benchmark.SphereMesh.mesh(new Point3D(6 * m - 48, 0, 4), 1 + 0.1 * m, 8, 16));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(row);
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(row);
        Query query = bvh.newQuery();
        Query scanQuery = scan.newQuery();
        Vector n = FLOOR_NORMAL.scale(Ray.DELTA);
        Vector a = new Vector(0.5, 0, 0);
        Vector b = new Vector(0, 0.5, 0);
        for (int m = 0; m < 17; ++m) {
            Point3D p = new Point3D(6 * m - 48, 0, 0);
            Point3D c = new Point3D(6 * m - 48, 0, 30);
            int[] gathered = gatherLeaving(bvh, query, p, n, c, a, b, false);
            assertEquals(1, gathered[1], "TC11: the bundle under mesh " + m + " must gather it");
            assertEquals(m > 0, bvh.blocksBundle(query), "TC11: the bundle under mesh " + m
                    + (m > 0 ? " must be blocked" : " must not be blocked: its ball is the 17th largest"));
            gatherLeaving(scan, scanQuery, p, n, c, a, b, false);
            assertFalse(scan.blocksBundle(scanQuery), "TC11: the scan must block no bundle (mesh " + m + ")");
            for (double[] ray : shadowRays(rnd, p, n, c, a, b, 10))
                assertEquals(0, scan.transmittance(scanQuery.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), 0), 0, "TC11: a ray under mesh " + m + " must be blocked");
        }
    }
}
