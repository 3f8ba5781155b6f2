package testutil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static primitives.Util.alignZero;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.transmittance;
import static testutil.TestRandom.edgeOrInner;
import static testutil.TestRandom.randomUnit;

import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;
import java.util.Random;
import java.util.function.Supplier;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import accel.RayState;
import accel.ShadowFrustum;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.TriangleMesh;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Shadow bundles shared by the tests of the frustum and of the hierarchy's walks: random pyramids and the
 * segments their rays may cover, points of a light's square, gathers set as the renderer sets them
 * (LightSquare), shadow rays leaving a surface, and packets of rays.
 */
public final class TestBundles {
    /** Not instantiable. */
    private TestBundles() {
    }


    /** The thickness of the renderer's bundles whose rays leave the surface on both sides (Ray.DELTA). */
    public static final double THICK = 0.1;

    /** The most bodies of the tree gather keeps one by one (Query.MAX_GATHERED). */
    public static final int MAX_GATHERED = 32;

    /**
     * A bundle's pyramid without thickness, from an apex to the square c ± a ± b.
     *
     * @param apex the rays' common origin
     * @param c    the centre of the light's square
     * @param a    half of one side of the square
     * @param b    half of the other side
     */
    public record Pyramid(Point3D apex, Point3D c, Vector a, Vector b) {
        /**
         * Sets the query's frustum to the pyramid and gathers for it.
         *
         * @param bvh   the hierarchy
         * @param query the scratch space
         * @return what {@link BoundingVolumeHierarchy#gather} returns
         */
        public boolean gather(BoundingVolumeHierarchy bvh, Query query) {
            return TestBundles.gather(bvh, query, apex, c, a, b);
        }

        /**
         * Sets a frustum to the pyramid.
         *
         * @param frustum the frustum
         * @return what {@link ShadowFrustum#set} returns
         */
        public boolean set(ShadowFrustum frustum) {
            return setPyramid(frustum, apex, c, a, b, 0);
        }
    }

    /** The pyramid over all 40 triangles of {@link TestScenes#triangleRow} (x ∈ [−5, 45] at z = 0): a subtree. */
    public static final Pyramid ROW_ALL = new Pyramid(new Point3D(20, 0, 10), new Point3D(20, 0, -10),
            new Vector(50, 0, 0), new Vector(0, 1, 0));
    /** The pyramid over triangles 19 and 20 of the row (x ∈ [18.5, 20.5]), on both sides of its root's split. */
    public static final Pyramid ROW_MIDDLE = new Pyramid(new Point3D(19.5, 0, 10), new Point3D(19.5, 0, -10),
            new Vector(2, 0, 0), new Vector(0, 1, 0));
    /** The pyramid over triangles 2 and 3 of the row (x ∈ [1.5, 3.5]), on one side of its root's split. */
    public static final Pyramid ROW_START = new Pyramid(new Point3D(2.5, 0, 10), new Point3D(2.5, 0, -10),
            new Vector(2, 0, 0), new Vector(0, 1, 0));

    /**
     * Asserts that a query forgets the subtree its last gather kept: after {@link #ROW_ALL} kept one and
     * forget ran, {@link #ROW_MIDDLE} is gathered one by one.
     *
     * @param rowBvh the hierarchy of {@link TestScenes#triangleRow}
     * @param query  the query
     * @param forget what makes it forget
     * @param tc     the test-case label
     */
    public static void assertForgetsSubtree(BoundingVolumeHierarchy rowBvh, Query query, Runnable forget, String tc) {
        assertGathersRowSubtree(rowBvh, query, tc);
        forget.run();
        assertTrue(ROW_MIDDLE.gather(rowBvh, query), tc + ": triangles 19 and 20 must be gathered");
        assertFalse(query.isSubtreeGathered(), tc + ": a forgotten subtree is not kept again");
    }

    /**
     * Asserts that {@link #ROW_ALL} gathers the 40 triangles of {@link TestScenes#triangleRow} as a subtree.
     *
     * @param rowBvh the hierarchy of {@link TestScenes#triangleRow}
     * @param query  the query
     * @param tc     the test-case label
     */
    public static void assertGathersRowSubtree(BoundingVolumeHierarchy rowBvh, Query query, String tc) {
        assertTrue(ROW_ALL.gather(rowBvh, query), tc + ": 40 triangles must be gathered");
        assertTrue(query.isSubtreeGathered(), tc + ": 40 triangles make a subtree");
    }

    /**
     * Asserts that a query keeps the subtree its last gather kept: after {@link #ROW_ALL}, {@link #ROW_MIDDLE}
     * keeps it again.
     *
     * @param rowBvh the hierarchy of {@link TestScenes#triangleRow}
     * @param query  the query
     * @param tc     the test-case label
     */
    public static void assertKeepsSubtree(BoundingVolumeHierarchy rowBvh, Query query, String tc) {
        assertGathersRowSubtree(rowBvh, query, tc);
        assertTrue(ROW_MIDDLE.gather(rowBvh, query), tc + ": triangles 19 and 20 must be gathered");
        assertTrue(query.isSubtreeGathered(), tc + ": the last subtree is kept again");
    }

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
    public static boolean gather(BoundingVolumeHierarchy bvh, Query query, Point3D apex, Point3D c, Vector a,
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
    public static boolean gather(BoundingVolumeHierarchy bvh, Query query, Point3D apex, Point3D c, Vector a,
                                  Vector b, double thickness) {
        assertTrue(setPyramid(query.getFrustum(), apex, c, a, b, thickness), "the bundle's pyramid must not be flat");
        return bvh.gather(query);
    }

    /**
     * Sets a frustum to the pyramid from an apex to the square c ± a ± b.
     *
     * @param frustum   the frustum
     * @param apex      the apex
     * @param c         the centre of the light's square
     * @param a         half of one side of the square
     * @param b         half of the other side
     * @param thickness how far the rays may stray from the pyramid
     * @return what {@link ShadowFrustum#set} returns: false for a flat pyramid
     */
    public static boolean setPyramid(ShadowFrustum frustum, Point3D apex, Point3D c, Vector a, Vector b,
                                     double thickness) {
        return frustum.set(new double[] { apex.getX(), apex.getY(), apex.getZ() }, new double[] { c.getX(), c.getY(),
                c.getZ(), a.getX(), a.getY(), a.getZ(), b.getX(), b.getY(), b.getZ() }, thickness);
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
    public static Point3D squarePoint(Random rnd, Point3D c, Vector a, Vector b) {
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
    public static Vector randomHalfSide(Random rnd) {
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
    public static Point3D stray(Random rnd, Point3D point, double length) {
        if (length == 0)
            return point;
        Vector move = randomUnit(rnd);
        double scale = rnd.nextInt(3) == 0 ? length : length * rnd.nextDouble();
        return new Point3D(point.getX() + scale * move.getX(), point.getY() + scale * move.getY(),
                point.getZ() + scale * move.getZ());
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
    public static int boxesMeeting(Intersectable item, ShadowFrustum frustum) {
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
    public static int meeting(Intersectable item, ShadowFrustum frustum, boolean ownTest) {
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
     * The transmittance of one ray of a bundle after its gather, through
     * {@link BoundingVolumeHierarchy#bundleRayTransmittance}.
     *
     * @param bvh    the hierarchy
     * @param ray    the ray (the same one, with the same direction, as the tree's answer is asked for)
     * @param maxT   the distance to the square
     * @param minK   the cut-off
     * @param query  the scratch space, as the gather left it
     * @return the transmittance
     */
    public static double gathered(BoundingVolumeHierarchy bvh, Ray ray, double maxT, double minK, Query query) {
        Point3D p = ray.getP0();
        Vector d = ray.getDir();
        return bvh.bundleRayTransmittance(query.setRay(p.getX(), p.getY(), p.getZ(), d.getX(), d.getY(), d.getZ(),
                maxT), minK);
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
    public static void assertPacket(BoundingVolumeHierarchy bvh, Query query, BoundingVolumeHierarchy reference,
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
    public static void fillPacket(Query query, List<Ray> rays, List<Double> distances) {
        query.clearPacket();
        for (int r = 0; r < rays.size(); ++r) {
            Point3D p = rays.get(r).getP0();
            Vector d = rays.get(r).getDir();
            query.addToPacket(p.getX(), p.getY(), p.getZ(), d.getX(), d.getY(), d.getZ(), distances.get(r));
        }
    }


    /** How far the light's square must lie off the tangent plane for one side (LightSquare.SIDE_MARGIN). */
    public static final double SIDE_MARGIN = 1e-6;

    /**
     * Sets a bundle leaving a surface point as the renderer's light square does (LightSquare.gather):
     * when the square lies on one side of the tangent plane the pyramid starts DELTA off it on that
     * side and gets the back face across the normal; otherwise it starts at the point, DELTA thick,
     * and the ray origins p ± n are set; then gathers.
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
    public static int[] gatherLeaving(BoundingVolumeHierarchy bvh, Query query, Point3D p, Vector n, Point3D c,
                                       Vector a, Vector b) {
        return gatherLeaving(bvh, query, p, n, c, a, b, true);
    }

    /**
     * Sets a bundle leaving a surface point as the renderer's light square does (LightSquare.gather),
     * for a point on a triangle ({@link #gatherLeaving(BoundingVolumeHierarchy, Query, Point3D, Vector,
     * Point3D, Vector, Vector)}) or on another body (a plane's, a sphere's: no back face, no ray origins).
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
    public static int[] gatherLeaving(BoundingVolumeHierarchy bvh, Query query, Point3D p, Vector n, Point3D c,
                                       Vector a, Vector b, boolean facet) {
        Vector w = c.subtract(p);
        double centre = n.dotProduct(w);
        double spread = Math.abs(n.dotProduct(a)) + Math.abs(n.dotProduct(b));
        double margin = SIDE_MARGIN * Ray.DELTA * (w.length() + 2 * a.length());
        int side = centre - spread > margin ? 1 : centre + spread < -margin ? -1 : 0;
        Point3D apex = side == 0 ? p : p.add(n.scale(side));
        Point3D base = side == 0 ? c : c.add(n.scale(side));
        ShadowFrustum frustum = query.getFrustum();
        if (!setPyramid(frustum, apex, base, a, b, side == 0 ? Ray.DELTA : 0))
            return null;
        if (facet && side != 0) {
            frustum.setBackFace(side * n.getX(), side * n.getY(), side * n.getZ());
            assertTrue(frustum.hasBackFace(),
                    "the base of a bundle leaving on one side must lie ahead of its back face");
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
    public static double[][] shadowRays(Random rnd, Point3D p, Vector n, Point3D c, Vector a, Vector b, int count) {
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
    public static Point3D pointOnTriangle(TriangleMesh mesh, int t, double u, double v) {
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        mesh.triangleData(t, data, 0);
        return new Point3D(data[0] + u * data[3] + v * data[6], data[1] + u * data[4] + v * data[7],
                data[2] + u * data[5] + v * data[8]);
    }

    /**
     * A triangle's data as {@link TriangleMesh#triangleData} writes it, from its vertices: p1, p2 − p1
     * and p3 − p1 (no parallel limit), after {@code at} zeros.
     *
     * @param at where p1 goes
     * @param v  the vertices p1, p2, p3, three coordinates each
     * @return the data
     */
    public static double[] triangleData(int at, double... v) {
        double[] data = new double[at + 9];
        for (int k = 0; k < 3; ++k) {
            data[at + k] = v[k];
            data[at + 3 + k] = v[3 + k] - v[k];
            data[at + 6 + k] = v[6 + k] - v[k];
        }
        return data;
    }

    /**
     * A ray's numbers for the bodies' tests.
     *
     * @param ray {ox, oy, oz, dx, dy, dz, distance}, as {@link #rayFromTo} gives it
     * @return the ray as a {@link RayState}
     */
    public static RayState rayState(double[] ray) {
        return new RayState().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]);
    }

    /**
     * A ray as {@link #shadowRays} gives it: {ox, oy, oz, dx, dy, dz, distance}, from a point to another.
     *
     * @param from the start
     * @param to   the end
     * @return the ray
     */
    public static double[] rayFromTo(Point3D from, Point3D to) {
        Vector d = to.subtract(from);
        double distance = d.length();
        d = d.normalize();
        return new double[] { from.getX(), from.getY(), from.getZ(), d.getX(), d.getY(), d.getZ(), distance };
    }

    /**
     * A random base point of a pyramid: c + s·a + r·b, some of them on the base's edges and corners.
     *
     * @param rnd the generator
     * @param p   the pyramid {apex, c, a, b}, 12 doubles
     * @return the point
     */
    public static double[] basePoint(Random rnd, double[] p) {
        double s = edgeOrInner(rnd);
        double r = edgeOrInner(rnd);
        double[] point = new double[3];
        for (int k = 0; k < 3; ++k)
            point[k] = p[3 + k] + s * p[6 + k] + r * p[9 + k];
        return point;
    }

    /**
     * A random vector no longer than a length, a third of them exactly that long.
     *
     * @param rnd    the generator
     * @param length the largest length (0 gives the zero vector)
     * @return the three coordinates
     */
    public static double[] strayVector(Random rnd, double length) {
        double x = rnd.nextGaussian();
        double y = rnd.nextGaussian();
        double z = rnd.nextGaussian();
        double scale = (rnd.nextInt(3) == 0 ? length : length * rnd.nextDouble()) / Math.sqrt(x * x + y * y + z * z);
        return new double[] { x * scale, y * scale, z * scale };
    }

    /**
     * A random segment a ray of a thick bundle may cover: from the apex to a base point, both ends moved
     * by random vectors no longer than the thickness (a third of the time by one and the same vector, as
     * the renderer moves a shadow ray off the surface).
     *
     * @param rnd       the generator
     * @param p         the pyramid {apex, c, a, b}
     * @param thickness the pyramid's thickness
     * @return {start, end}, 6 doubles
     */
    public static double[] raySegment(Random rnd, double[] p, double thickness) {
        double[] base = basePoint(rnd, p);
        double[] start = strayVector(rnd, thickness);
        double[] end = rnd.nextInt(3) == 0 ? start : strayVector(rnd, thickness);
        return new double[] { p[0] + start[0], p[1] + start[1], p[2] + start[2], base[0] + end[0], base[1] + end[1],
                base[2] + end[2] };
    }

    /**
     * A random point of a segment, a fifth of them at its end and a tenth at its start.
     *
     * @param rnd     the generator
     * @param segment {start, end}
     * @return the point
     */
    public static double[] segmentPoint(Random rnd, double[] segment) {
        int choice = rnd.nextInt(10);
        double t = choice < 2 ? 1 : choice == 2 ? 0 : rnd.nextDouble();
        return new double[] { segment[0] + t * (segment[3] - segment[0]), segment[1] + t * (segment[4] - segment[1]),
                segment[2] + t * (segment[5] - segment[2]) };
    }

    /** The margin of the standard pyramid ({@link #standard}): 1e-7 of its size 28. */
    public static final double STANDARD_MARGIN = 2.8e-6;

    /**
     * The standard pyramid: apex (0, 0, 0), base (±2, ±2, 10), no thickness. Its sides are the planes
     * x = ±z/5 and y = ±z/5, its base the plane z = 10, and its margin {@value #STANDARD_MARGIN}.
     *
     * @return the frustum
     */
    public static ShadowFrustum standard() {
        return standard(0);
    }

    /**
     * The standard pyramid: apex (0, 0, 0), base (±2, ±2, 10), with a thickness.
     *
     * @param thickness how far the rays may stray from the pyramid
     * @return the frustum
     */
    public static ShadowFrustum standard(double thickness) {
        ShadowFrustum frustum = new ShadowFrustum();
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, thickness),
                "the standard pyramid must be set");
        return frustum;
    }

    /**
     * Whether a box holds a point.
     *
     * @param box   {minX, minY, minZ, maxX, maxY, maxZ}
     * @param point the point
     * @return true when the point is in the (closed) box
     */
    public static boolean holds(double[] box, double[] point) {
        return point[0] >= box[0] && point[0] <= box[3] && point[1] >= box[1] && point[1] <= box[4]
                && point[2] >= box[2] && point[2] <= box[5];
    }

    /**
     * Sets a frustum to a pyramid of {@link #randomPyramid}'s numbers.
     *
     * @param frustum   the frustum
     * @param p         the pyramid: apex, c, a, b
     * @param thickness the frustum's thickness
     * @return what {@link ShadowFrustum#set} answers: false for a flat pyramid
     */
    public static boolean setPyramid(ShadowFrustum frustum, double[] p, double thickness) {
        return frustum.set(Arrays.copyOfRange(p, 0, 3), Arrays.copyOfRange(p, 3, 12), thickness);
    }

    /**
     * A random pyramid: apex and base centre in [−20, 20]³, half-sides a and b of random directions
     * and lengths 0.01..5.
     *
     * @param rnd the generator
     * @return {apex, c, a, b}
     */
    public static double[] randomPyramid(Random rnd) {
        double[] p = new double[12];
        for (int k = 0; k < 6; ++k)
            p[k] = 40 * rnd.nextDouble() - 20;
        for (int v = 0; v < 2; ++v) {
            double length = 0.01 + 5 * rnd.nextDouble();
            double x = rnd.nextGaussian();
            double y = rnd.nextGaussian();
            double z = rnd.nextGaussian();
            double norm = Math.sqrt(x * x + y * y + z * z);
            p[6 + 3 * v] = x / norm * length;
            p[7 + 3 * v] = y / norm * length;
            p[8 + 3 * v] = z / norm * length;
        }
        return p;
    }

    /**
     * A random bundle: a random pyramid ({@link #randomPyramid}), thin or thick, set in a frustum, and
     * segments its rays may cover ({@link #raySegment}).
     *
     * @param pyramid   the pyramid {apex, c, a, b}
     * @param thickness its thickness
     * @param segments  200 segments, {start, end} each
     */
    public record RandomBundle(double[] pyramid, double thickness, double[][] segments) {
        /**
         * Draws a bundle, a quarter of them (every fourth) thin, the others 1e-4 to 1 thick
         * (log-uniform), and sets its pyramid in a frustum.
         *
         * @param rnd     the generator
         * @param frustum the frustum to set
         * @param f       the bundle's number
         * @return the bundle, or null when the pyramid is flat (refused, no segment drawn)
         */
        private static RandomBundle set(Random rnd, ShadowFrustum frustum, int f) {
            double[] p = randomPyramid(rnd);
            double thickness = f % 4 == 0 ? 0 : Math.pow(10, -4 + 4 * rnd.nextDouble());
            if (!setPyramid(frustum, p, thickness))
                return null;
            double[][] segments = new double[200][];
            for (int i = 0; i < segments.length; ++i)
                segments[i] = raySegment(rnd, p, thickness);
            return new RandomBundle(p, thickness, segments);
        }

        /**
         * Draws some bundles ({@link #set}) one after the other as they are walked, each set in a
         * frustum when it is reached; the flat ones are left out.
         *
         * @param rnd     the generator
         * @param frustum the frustum to set
         * @param count   how many to draw
         * @return the bundles, to walk once
         */
        public static Iterable<RandomBundle> walk(Random rnd, ShadowFrustum frustum, int count) {
            return () -> new Iterator<>() {
                private int f;
                private RandomBundle next;
                private boolean drawn;

                @Override
                public boolean hasNext() {
                    // drawn only when asked for: the frustum holds the bundle last returned until then
                    while (!drawn) {
                        next = f < count ? set(rnd, frustum, f++) : null;
                        drawn = next != null || f >= count;
                    }
                    return next != null;
                }

                @Override
                public RandomBundle next() {
                    if (!hasNext())
                        throw new NoSuchElementException("no more random bundles");
                    drawn = false;
                    return next;
                }
            };
        }
    }

    /**
     * The transmittance of a ray given as numbers, through the tree (or the scan) alone.
     *
     * @param bvh   the hierarchy (or scan)
     * @param query the scratch space
     * @param ray   {ox, oy, oz, dx, dy, dz, distance}
     * @param minK  the cut-off
     * @return the transmittance
     */
    public static double rayTransmittance(BoundingVolumeHierarchy bvh, Query query, double[] ray, double minK) {
        return bvh.transmittance(query.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), minK);
    }

    /**
     * The transmittance of a ray given as numbers, through the bodies the last gather kept.
     *
     * @param bvh   the hierarchy (or scan)
     * @param query the scratch space, as the gather left it
     * @param ray   {ox, oy, oz, dx, dy, dz, distance}
     * @param minK  the cut-off
     * @return the transmittance
     */
    public static double gatheredRay(BoundingVolumeHierarchy bvh, Query query, double[] ray, double minK) {
        return bvh.bundleRayTransmittance(query.setRay(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]), minK);
    }
}
