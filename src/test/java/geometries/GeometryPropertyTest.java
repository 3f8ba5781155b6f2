package geometries;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestRandom.randomPoint;
import static testutil.TestRandom.randomUnit;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.Function;
import java.util.function.ToDoubleFunction;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Property tests across all geometry types: thousands of seeded random rays aimed around randomly
 * placed and sized bodies. Every point returned must lie on the surface (within 1e-9 of the scene's
 * scale), strictly ahead of the ray's start, within the maximum distance when one is given, sorted by
 * distance, and the body's normal there must be a unit vector. The tests also check that enough
 * rays hit, so that they are not vacuous.
 */
class GeometryPropertyTest {
    /** Bodies per geometry type. */
    private static final int BODIES = 25;
    /** Random rays per body. */
    private static final int RAYS_PER_BODY = 200;
    /** Relative tolerance for points on the surface and for unit normals. */
    private static final double TOLERANCE = 1e-9;
    /** Relative margin within which the reference solver calls a ray too near a boundary to judge. */
    private static final double MARGIN = 1e-6;

    /**
     * A body under test.
     *
     * @param geometry        the geometry
     * @param centre          a point at the middle of the region rays are aimed at
     * @param size            the body's size: rays are aimed within about this distance of the centre
     * @param maxPoints       the most points a ray can meet (2 for convex bodies and tubes, 1 for flat ones)
     * @param surfaceDistance the distance from a point to the body's surface
     * @param reference       an independent solver: the sorted distances along a ray where it meets the
     *                        body, or null when the ray passes too near an edge, tangent or its start
     *                        for a clear answer
     * @param aim             draws a random point to aim a ray at, around the body
     */
    private record Body(Geometry geometry, Point3D centre, double size, int maxPoints,
                        ToDoubleFunction<Point3D> surfaceDistance, Function<Ray, double[]> reference,
                        Function<Random, Point3D> aim) {
        /** A body aimed at through the cube of half-edge 1.2 × size around its centre. */
        Body(Geometry geometry, Point3D centre, double size, int maxPoints, ToDoubleFunction<Point3D> surfaceDistance,
             Function<Ray, double[]> reference) {
            this(geometry, centre, size, maxPoints, surfaceDistance, reference,
                    rnd -> randomPoint(rnd, centre, 1.2 * size));
        }
    }

    /**
     * What a run of random rays found.
     *
     * @param rays     rays cast (without a distance limit)
     * @param hits     rays that met the body
     * @param points   points found in all
     * @param compared rays whose intersections were compared with the reference solver
     */
    private record Stats(int rays, int hits, int points, int compared) {
    }

    // ---------------------------------------------------------------- random helpers

    /** A random body size between 0.1 and 100 (log-uniform), so the tests cover several scales. */
    private static double randomSize(Random rnd) {
        return Math.pow(10, -1 + 3 * rnd.nextDouble());
    }

    /** A random centre in the cube [−50, 50]³. */
    private static Point3D randomCentre(Random rnd) {
        return randomPoint(rnd, Point3D.ZERO, 50);
    }

    // ---------------------------------------------------------------- vector helpers (on doubles, no zero-vector traps)

    private static double[] diff(Point3D a, Point3D b) {
        return new double[] { a.getX() - b.getX(), a.getY() - b.getY(), a.getZ() - b.getZ() };
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double dot(double[] a, Vector b) {
        return a[0] * b.getX() + a[1] * b.getY() + a[2] * b.getZ();
    }

    private static double norm(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
    }

    private static double[] array(Vector v) {
        return new double[] { v.getX(), v.getY(), v.getZ() };
    }

    /** Distance from a point to a plane through q0 with unit normal n. */
    private static double planeDistance(Point3D p, Point3D q0, Vector n) {
        return Math.abs(dot(diff(p, q0), n));
    }

    /** Distance from a point to the (closed) convex polygon: off its plane and beyond its edges. */
    private static double polygonDistance(Point3D p, Polygon polygon) {
        double off = Math.abs(dot(diff(p, polygon.getVertices().get(0)), polygon.getPlane().getNormal()));
        return Math.max(off, Math.max(0, polygonOutside(p, polygon)));
    }

    /**
     * How far a point of the polygon's plane lies outside the polygon: the largest distance beyond
     * the lines of its edges, negative inside (minus the distance to the nearest edge line).
     */
    private static double polygonOutside(Point3D p, Polygon polygon) {
        List<Point3D> vs = polygon.getVertices();
        double[] n = array(polygon.getPlane().getNormal());
        // orientation of the vertices around n: +1 counter-clockwise, −1 clockwise
        double orientation = Math.signum(dot(cross(diff(vs.get(1), vs.get(0)), diff(vs.get(2), vs.get(1))), n));
        double outside = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < vs.size(); ++i) {
            Point3D a = vs.get(i);
            double[] edge = diff(vs.get((i + 1) % vs.size()), a);
            double[] inward = cross(n, edge);
            double signed = orientation * dot(diff(p, a), inward) / norm(inward);
            outside = Math.max(outside, -signed);
        }
        return outside;
    }

    // ---------------------------------------------------------------- the independent reference solver

    /**
     * The positive roots of a·t² + 2·halfB·t + c = 0 (a &gt; 0), where halfB² − a·c = a·(r² − d²) for
     * a line at distance d from a centre or axis.
     *
     * @return the positive roots in ascending order, or null when the line is within the margin of
     *         tangent or a root is within the margin of 0 (the ray starts on the surface)
     */
    private static double[] quadraticRoots(double a, double halfB, double c, double r, double scale) {
        double disc = halfB * halfB - a * c;
        if (Math.abs(disc) < MARGIN * a * r * r)
            return null;
        if (disc < 0)
            return new double[0];
        double root = Math.sqrt(disc);
        double t1 = (-halfB - root) / a;
        double t2 = (-halfB + root) / a;
        if (Math.abs(t1) < MARGIN * scale || Math.abs(t2) < MARGIN * scale)
            return null;
        return t1 > 0 ? new double[] { t1, t2 } : t2 > 0 ? new double[] { t2 } : new double[0];
    }

    /** Reference intersections with a sphere. */
    private static double[] sphereReference(Ray ray, Point3D c, double r) {
        double[] oc = diff(ray.getP0(), c);
        double[] d = array(ray.getDir());
        return quadraticRoots(1, dot(oc, d), dot(oc, oc) - r * r, r, r + norm(oc));
    }

    /** Reference intersections with a tube or the side of a cylinder (nearly parallel rays are unclear). */
    private static double[] tubeReference(Ray ray, Ray axis, double r) {
        double[] va = array(axis.getDir());
        double[] oc = diff(ray.getP0(), axis.getP0());
        double[] d = array(ray.getDir());
        double dv = dot(d, va);
        double ov = dot(oc, va);
        double[] dPerp = { d[0] - dv * va[0], d[1] - dv * va[1], d[2] - dv * va[2] };
        double[] oPerp = { oc[0] - ov * va[0], oc[1] - ov * va[1], oc[2] - ov * va[2] };
        double a = dot(dPerp, dPerp);
        if (a < MARGIN)
            return null;
        return quadraticRoots(a, dot(dPerp, oPerp), dot(oPerp, oPerp) - r * r, r, r + norm(oPerp));
    }

    /** Reference intersection with a plane: one distance, none, or null when unclear. */
    private static double[] planeReference(Ray ray, Point3D q0, Vector n) {
        double nv = dot(array(ray.getDir()), n);
        if (Math.abs(nv) < MARGIN)
            return null;
        double t = dot(diff(q0, ray.getP0()), n) / nv;
        if (Math.abs(t) < MARGIN * ray.getP0().distance(q0))
            return null;
        return t > 0 ? new double[] { t } : new double[0];
    }

    /** Reference intersection with a polygon: its plane's, when clearly inside or outside. */
    private static double[] polygonReference(Ray ray, Polygon polygon, double size) {
        double[] ts = planeReference(ray, polygon.getVertices().get(0), polygon.getPlane().getNormal());
        if (ts == null || ts.length == 0)
            return ts;
        double outside = polygonOutside(ray.getPoint(ts[0]), polygon);
        if (Math.abs(outside) < MARGIN * size)
            return null;
        return outside < 0 ? ts : new double[0];
    }

    /** Reference intersections with a closed cylinder: side between the caps, and the cap discs. */
    private static double[] cylinderReference(Ray ray, Ray axis, double r, double h) {
        double[] side = tubeReference(ray, axis, r);
        double dv = dot(array(ray.getDir()), axis.getDir());
        if (side == null || Math.abs(dv) < MARGIN)
            return null;
        double s0 = dot(diff(ray.getP0(), axis.getP0()), axis.getDir());
        List<Double> ts = new ArrayList<>();
        for (double t : side) {
            double s = s0 + t * dv;
            if (Math.abs(s) < MARGIN * h || Math.abs(s - h) < MARGIN * h)
                return null;
            if (s > 0 && s < h)
                ts.add(t);
        }
        for (double capHeight : new double[] { 0, h }) {
            double t = (capHeight - s0) / dv;
            if (Math.abs(t) < MARGIN * (r + h))
                return null;
            if (t < 0)
                continue;
            double radial = radialAndHeight(ray.getPoint(t), axis)[0];
            if (Math.abs(radial - r) < MARGIN * r)
                return null;
            if (radial < r)
                ts.add(t);
        }
        return ts.stream().sorted().mapToDouble(Double::doubleValue).toArray();
    }

    /** Distance from a point to the axis line of a tube, and its height along the axis. */
    private static double[] radialAndHeight(Point3D p, Ray axis) {
        double[] d = diff(p, axis.getP0());
        Vector va = axis.getDir();
        double s = dot(d, va);
        double[] perp = { d[0] - s * va.getX(), d[1] - s * va.getY(), d[2] - s * va.getZ() };
        return new double[] { norm(perp), s };
    }

    // ---------------------------------------------------------------- body factories

    private static Body randomSphere(Random rnd) {
        Point3D c = randomCentre(rnd);
        double r = randomSize(rnd);
        Sphere sphere = new Sphere(c, r);
        return new Body(sphere, c, r, 2, p -> Math.abs(p.distance(c) - r), ray -> sphereReference(ray, c, r));
    }

    private static Body randomPlane(Random rnd) {
        Point3D q0 = randomCentre(rnd);
        Plane plane = new Plane(q0, randomUnit(rnd));
        return new Body(plane, q0, randomSize(rnd), 1, p -> planeDistance(p, q0, plane.getNormal()),
                ray -> planeReference(ray, q0, plane.getNormal()));
    }

    /** A convex polygon of 3 to 8 vertices on a circle, in a random plane. */
    private static Body randomPolygon(Random rnd) {
        Point3D c = randomCentre(rnd);
        double r = randomSize(rnd);
        double[] n = array(randomUnit(rnd));
        double[] helper = Math.abs(n[0]) < 0.9 ? new double[] { 1, 0, 0 } : new double[] { 0, 1, 0 };
        double[] u = cross(n, helper);
        double lu = norm(u);
        u = new double[] { u[0] / lu, u[1] / lu, u[2] / lu };
        double[] v = cross(n, u);
        int count = 3 + rnd.nextInt(6);
        double[] gaps = new double[count];
        double total = 0;
        for (int k = 0; k < count; ++k)
            total += gaps[k] = 0.3 + rnd.nextDouble();
        Point3D[] vertices = new Point3D[count];
        double angle = rnd.nextDouble() * 2 * Math.PI;
        for (int k = 0; k < count; ++k) {
            angle += 2 * Math.PI * gaps[k] / total;
            double cos = r * Math.cos(angle);
            double sin = r * Math.sin(angle);
            vertices[k] = new Point3D(c.getX() + cos * u[0] + sin * v[0], c.getY() + cos * u[1] + sin * v[1],
                    c.getZ() + cos * u[2] + sin * v[2]);
        }
        Polygon polygon = new Polygon(vertices);
        // aim at the disc of radius 1.2·r around the centre in the polygon's plane
        double[] uu = u;
        Function<Random, Point3D> aim = rand -> {
            double x = (2 * rand.nextDouble() - 1) * 1.2 * r;
            double y = (2 * rand.nextDouble() - 1) * 1.2 * r;
            return new Point3D(c.getX() + x * uu[0] + y * v[0], c.getY() + x * uu[1] + y * v[1],
                    c.getZ() + x * uu[2] + y * v[2]);
        };
        return new Body(polygon, c, r, 1, p -> polygonDistance(p, polygon), ray -> polygonReference(ray, polygon, r),
                aim);
    }

    /** A triangle of three random points in a cube, not too thin. */
    private static Body randomTriangle(Random rnd) {
        Point3D c = randomCentre(rnd);
        double size = randomSize(rnd);
        while (true) {
            Point3D a = randomPoint(rnd, c, size);
            Point3D b = randomPoint(rnd, c, size);
            Point3D d = randomPoint(rnd, c, size);
            double[] e1 = diff(b, a);
            double[] e2 = diff(d, a);
            if (norm(cross(e1, e2)) > 0.05 * norm(e1) * norm(e2)) {
                Triangle triangle = new Triangle(a, b, d);
                // aim at the parallelogram a + α·e1 + β·e2, α, β ∈ [−0.1, 1.1], that holds the triangle
                Function<Random, Point3D> aim = rand -> {
                    double alpha = -0.1 + 1.2 * rand.nextDouble();
                    double beta = -0.1 + 1.2 * rand.nextDouble();
                    return new Point3D(a.getX() + alpha * e1[0] + beta * e2[0], a.getY() + alpha * e1[1] + beta * e2[1],
                            a.getZ() + alpha * e1[2] + beta * e2[2]);
                };
                return new Body(triangle, c, size, 1, p -> polygonDistance(p, triangle),
                        ray -> polygonReference(ray, triangle, size), aim);
            }
        }
    }

    private static Body randomTube(Random rnd) {
        Point3D c = randomCentre(rnd);
        double r = randomSize(rnd);
        Ray axis = new Ray(c, randomUnit(rnd));
        Tube tube = new Tube(axis, r);
        return new Body(tube, c, r, 2, p -> Math.abs(radialAndHeight(p, axis)[0] - r), ray -> tubeReference(ray, axis, r));
    }

    private static Body randomCylinder(Random rnd) {
        Point3D base = randomCentre(rnd);
        double size = randomSize(rnd);
        double r = size * (0.3 + 0.7 * rnd.nextDouble());
        double h = size * (0.5 + 2.5 * rnd.nextDouble());
        Ray axis = new Ray(base, randomUnit(rnd));
        Cylinder cylinder = new Cylinder(axis, r, h);
        Point3D middle = axis.getPoint(h / 2);
        return new Body(cylinder, middle, Math.max(r, h / 2), 2, p -> {
            double[] rs = radialAndHeight(p, axis);
            double radial = rs[0];
            double s = rs[1];
            double beyondHeight = Math.max(0, Math.max(-s, s - h));
            double side = Math.hypot(radial - r, beyondHeight);
            double beyondRim = Math.max(0, radial - r);
            double bottom = Math.hypot(s, beyondRim);
            double top = Math.hypot(s - h, beyondRim);
            return Math.min(side, Math.min(bottom, top));
        }, ray -> cylinderReference(ray, axis, r, h));
    }

    // ---------------------------------------------------------------- the checks

    /**
     * Checks every property of the intersections of one ray with a body.
     *
     * @param body        the body
     * @param ray         the ray
     * @param maxDistance a distance limit for a second query
     * @param tc          the test case label for messages
     * @return the intersections found without a limit (null when none)
     */
    private static List<GeoPoint> checkRay(Body body, Ray ray, double maxDistance, String tc) {
        Geometry g = body.geometry();
        Point3D p0 = ray.getP0();
        double[] dir = array(ray.getDir());
        double sceneScale = body.size() + p0.distance(body.centre());
        List<GeoPoint> all = g.findGeoIntersections(ray);
        List<Double> ts = new ArrayList<>();
        if (all != null) {
            assertFalse(all.isEmpty(), tc + ": an empty list instead of null for " + g + ", " + ray);
            assertTrue(all.size() <= body.maxPoints(), tc + ": too many points " + all + " for " + g + ", " + ray);
            double previous = 0;
            for (GeoPoint gp : all) {
                assertSame(g, gp.geometry, tc + ": wrong geometry in a GeoPoint");
                Point3D p = gp.point;
                double[] d = diff(p, p0);
                double t = dot(d, dir);
                double tol = TOLERANCE * Math.max(sceneScale, t);
                assertTrue(t > 0, tc + ": point " + p + " not ahead of the ray " + ray + " on " + g);
                assertTrue(t > previous, tc + ": points not sorted by distance " + all + " for " + ray + " on " + g);
                previous = t;
                double[] offLine = { d[0] - t * dir[0], d[1] - t * dir[1], d[2] - t * dir[2] };
                assertEquals(0, norm(offLine), tol, tc + ": point " + p + " is off the ray " + ray);
                assertEquals(0, body.surfaceDistance().applyAsDouble(p), tol,
                        tc + ": point " + p + " is off the surface of " + g + " (ray " + ray + ")");
                assertEquals(1, g.getNormal(p).length(), TOLERANCE,
                        tc + ": the normal at " + p + " on " + g + " is not a unit vector");
                ts.add(t);
            }
        }
        // the plain point query agrees with the GeoPoint query
        List<Point3D> points = g.findIntersections(ray);
        assertEquals(all == null ? null : all.stream().map(gp -> gp.point).toList(), points,
                tc + ": findIntersections disagrees with findGeoIntersections for " + g + ", " + ray);

        // with a distance limit: exactly the points no farther than the limit
        List<GeoPoint> limited = g.findGeoIntersections(ray, maxDistance);
        boolean nearLimit = ts.stream().anyMatch(t -> Math.abs(t - maxDistance) <= TOLERANCE * sceneScale);
        if (!nearLimit) {
            List<GeoPoint> expected = all == null ? List.of()
                    : all.stream().filter(gp -> dot(diff(gp.point, p0), dir) <= maxDistance).toList();
            assertEquals(expected.isEmpty() ? null : expected, limited,
                    tc + ": wrong points within distance " + maxDistance + " for " + g + ", " + ray);
        }
        if (limited != null)
            for (GeoPoint gp : limited)
                assertTrue(gp.point.distance(p0) <= maxDistance * (1 + 1e-12) + 1e-12,
                        tc + ": point " + gp.point + " beyond the maximum distance " + maxDistance);
        return all;
    }

    /**
     * A random ray from the cube of half-edge 3 × size around a body towards a point the body is aimed at.
     *
     * @param rnd  the random source
     * @param body the body
     * @return the ray, or null when its start and the aimed point nearly coincide
     */
    private static Ray randomAimedRay(Random rnd, Body body) {
        Point3D origin = randomPoint(rnd, body.centre(), 3 * body.size());
        Point3D target = body.aim().apply(rnd);
        return origin.distance(target) < 1e-3 * body.size() ? null : new Ray(origin, target.subtract(origin));
    }

    /**
     * Casts random rays at random bodies of one type and checks them all, and compares them with the
     * reference solver when the ray is clear of edges and tangents: no point may be missing.
     *
     * @param factory makes a random body
     * @param seed    the random seed
     * @return the counts of rays, hits, points and compared rays
     */
    private static Stats castRandomRays(Function<Random, Body> factory, long seed) {
        Random rnd = new Random(seed);
        int rays = 0;
        int hits = 0;
        int points = 0;
        int compared = 0;
        for (int b = 0; b < BODIES; ++b) {
            Body body = factory.apply(rnd);
            double size = body.size();
            for (int k = 0; k < RAYS_PER_BODY; ++k) {
                Ray ray = randomAimedRay(rnd, body);
                if (ray == null)
                    continue;
                Point3D origin = ray.getP0();
                double maxDistance = (0.01 + 8 * rnd.nextDouble()) * size;
                List<GeoPoint> found = checkRay(body, ray, maxDistance, "TC01");
                ++rays;
                if (found != null) {
                    ++hits;
                    points += found.size();
                }
                double[] expected = body.reference().apply(ray);
                if (expected != null) {
                    ++compared;
                    int count = found == null ? 0 : found.size();
                    assertEquals(expected.length, count, "TC01: wrong number of points " + found + " on "
                            + body.geometry() + " for " + ray + ", expected at t = " + Arrays.toString(expected));
                    double sceneScale = size + origin.distance(body.centre());
                    for (int q = 0; q < count; ++q)
                        assertEquals(expected[q], found.get(q).point.distance(origin),
                                TOLERANCE * Math.max(sceneScale, expected[q]),
                                "TC01: wrong point " + found.get(q).point + " on " + body.geometry() + " for " + ray);
                }
            }
        }
        return new Stats(rays, hits, points, compared);
    }

    /**
     * Casts rays that start on the surface of random bodies (at points found by earlier rays) in
     * random directions not grazing the surface, and checks them all: valid points, never the start
     * point itself, and no more than the points the body can still have beyond it (none for a flat body).
     *
     * @param factory makes a random body
     * @param seed    the random seed
     * @return the counts of rays, hits and points
     */
    private static Stats castRaysFromSurface(Function<Random, Body> factory, long seed) {
        Random rnd = new Random(seed);
        int rays = 0;
        int hits = 0;
        int points = 0;
        for (int b = 0; b < BODIES; ++b) {
            Body body = factory.apply(rnd);
            double size = body.size();
            for (int k = 0; k < RAYS_PER_BODY; ++k) {
                Ray aimed = randomAimedRay(rnd, body);
                if (aimed == null)
                    continue;
                List<Point3D> first = body.geometry().findIntersections(aimed);
                if (first == null)
                    continue;
                Point3D start = first.get(0);
                // leave out directions within about half a degree of the tangent plane: there a start point
                // rounded off the surface by 1e-14 could meet the surface again at t above the library's 1e-10
                Vector normal = body.geometry().getNormal(start);
                Vector d = randomUnit(rnd);
                while (Math.abs(d.dotProduct(normal)) < 0.01)
                    d = randomUnit(rnd);
                Ray ray = new Ray(start, d);
                List<GeoPoint> found = checkRay(body, ray, (0.01 + 8 * rnd.nextDouble()) * size, "TC10");
                ++rays;
                if (found != null) {
                    assertTrue(found.size() <= body.maxPoints() - 1,
                            "TC10: the ray from the surface point " + start + " meets " + body.geometry()
                                    + " too often: " + found);
                    for (GeoPoint gp : found)
                        assertTrue(gp.point.distance(start) > TOLERANCE * size,
                                "TC10: the ray from " + start + " hits its own start point on " + body.geometry());
                    ++hits;
                    points += found.size();
                }
            }
        }
        return new Stats(rays, hits, points, 0);
    }

    /**
     * Runs both random checks for a geometry type and asserts the hit counts are not vacuous.
     *
     * @param factory           makes a random body
     * @param seed              the random seed
     * @param minHitRate        the least fraction of the aimed rays that must hit
     * @param minSurfaceHitRate the least fraction of the rays from the surface that must hit again
     */
    private static void check(Function<Random, Body> factory, long seed, double minHitRate, double minSurfaceHitRate) {
        // ===== Equivalence Partitions Tests =====
        // TC01: random rays aimed around random bodies: every point valid, and enough rays hit
        Stats aimed = castRandomRays(factory, seed);
        assertTrue(aimed.rays() >= BODIES * RAYS_PER_BODY * 0.99, "TC01: too few rays cast: " + aimed);
        assertTrue(aimed.hits() >= minHitRate * aimed.rays(), "TC01: too few rays hit, the test is vacuous: " + aimed);
        assertTrue(aimed.compared() >= 0.95 * aimed.rays(), "TC01: too few rays compared with the reference: " + aimed);

        // ===== Boundary Values Tests =====
        // TC10: random rays starting on the surface: never the start point, at most maxPoints − 1 points
        // (so none for a flat body)
        Stats fromSurface = castRaysFromSurface(factory, seed + 1);
        assertTrue(fromSurface.rays() >= 0.1 * BODIES * RAYS_PER_BODY, "TC10: too few rays cast: " + fromSurface);
        assertTrue(fromSurface.hits() >= minSurfaceHitRate * fromSurface.rays(),
                "TC10: too few rays from the surface hit again, the test is vacuous: " + fromSurface);
    }

    /**
     * Random rays against spheres.
     */
    @Test
    void testSphere() {
        check(GeometryPropertyTest::randomSphere, 11, 0.4, 0.3);
    }

    /**
     * Random rays against planes.
     */
    @Test
    void testPlane() {
        check(GeometryPropertyTest::randomPlane, 12, 0.7, 0);
    }

    /**
     * Random rays against convex polygons.
     */
    @Test
    void testPolygon() {
        check(GeometryPropertyTest::randomPolygon, 13, 0.25, 0);
    }

    /**
     * Random rays against triangles.
     */
    @Test
    void testTriangle() {
        check(GeometryPropertyTest::randomTriangle, 14, 0.25, 0);
    }

    /**
     * Random rays against tubes.
     */
    @Test
    void testTube() {
        check(GeometryPropertyTest::randomTube, 15, 0.6, 0.3);
    }

    /**
     * Random rays against cylinders.
     */
    @Test
    void testCylinder() {
        check(GeometryPropertyTest::randomCylinder, 16, 0.35, 0.3);
    }
}
