package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.transmittance;
import static testutil.TestBundles.MAX_GATHERED;
import static testutil.TestBundles.THICK;
import static testutil.TestBundles.assertPacket;
import static testutil.TestBundles.boxesMeeting;
import static testutil.TestBundles.gatherLeaving;
import static testutil.TestBundles.gathered;
import static testutil.TestBundles.gatheredRay;
import static testutil.TestBundles.meeting;
import static testutil.TestBundles.pointOnTriangle;
import static testutil.TestBundles.randomHalfSide;
import static testutil.TestBundles.rayState;
import static testutil.TestBundles.rayTransmittance;
import static testutil.TestBundles.setPyramid;
import static testutil.TestBundles.shadowRays;
import static testutil.TestBundles.squarePoint;
import static testutil.TestBundles.stray;
import static testutil.TestRandom.randomPoint;
import static testutil.TestRandom.randomUnit;
import static testutil.TestScenes.perpendicular;
import static testutil.TestScenes.pointIn;
import static testutil.TestScenes.pointOn;
import static testutil.TestScenes.triangle;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;

import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.TestBundles;
import testutil.TestScenes.TestScene;

/**
 * Fixtures of the tests that need the package's own access ({@link ShadowFrustum#originOf},
 * {@link ShadowFrustum#originsBehind}, the builder): builds of the tree's parts, random bundles through
 * scenes, bundles leaving a mesh's surface, and the surfaces of triangles the gather leaves out between a
 * bundle's two ray origins.
 */
final class BvhFixtures {
    /** Not instantiable. */
    private BvhFixtures() {
    }

    /**
     * A build over some geometries on one thread, done, as the hierarchy makes it.
     *
     * @param owners the geometries of the tree
     * @return the builder, its nodes and leaf order made
     */
    static BvhBuilder built(Geometry... owners) {
        BvhBuilder builder = new BvhBuilder(owners, 1);
        builder.build();
        return builder;
    }

    /**
     * How often gather gave each kind of answer, and how many rays were blocked or dimmed. The two
     * kinds of true cannot be told apart through the API: they are told by how many of the tree's
     * bodies may meet the frustum.
     */
    static final class GatherCounts {
        /** gather gave false. */
        int none;
        /** gather gave true, at most 32 of the tree's bodies may meet the frustum: the bodies are kept. */
        int few;
        /** gather gave true, more than 32 of the tree's bodies may meet the frustum: a subtree is kept. */
        int subtree;
        /**
         * gather gave true, at most 32 of the tree's bodies may meet the frustum, but its walk first
         * branched where the last gather's kept a subtree: that subtree is kept again.
         */
        int kept;
        /** bundles whose pyramid meets some boxes but no polygon's plane among them. */
        int planeCulled;
        /** bundles with a thickness (apex on a body's surface). */
        int thick;
        int rays;
        int darkened;
    }

    /** The identity's 12 numbers, for {@link BoundingVolumeHierarchy#mayMeet(ShadowFrustum, double[], double[])}. */
    static final double[] IDENTITY_MAP = primitives.Transform.IDENTITY.toArray();

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
    static void checkBundles(Random rnd, TestScene scene, boolean opaque, int threads, GatherCounts counts,
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
                    || !setPyramid(frustum, apex, c, a, b, thickness))
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
            // the walk that stops at the first body, with the pyramid carried onto itself, finds one when the gather does
            assertEquals(found, bvh.mayMeet(frustum, IDENTITY_MAP, IDENTITY_MAP), () -> bundleLabel.get() + ": mayMeet disagrees");
            if (!found) {
                // a body that may meet the frustum (its box and its own test) is in nodes whose boxes meet it: gathered
                assertEquals(0, meeting, () -> bundleLabel.get() + ": nothing gathered though bodies may meet");
                ++counts.none;
            } else if (meeting > MAX_GATHERED)
                ++counts.subtree;
            else if (query.isSubtreeGathered())
                ++counts.kept;
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
                        assertTrue(expected == 0 || expected == 1, () -> label.get()
                                + ": an opaque scene gives 0 or 1");
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
     * Asserts that gather gave every kind of answer often and that some rays were darkened, so the
     * comparison is not vacuous.
     *
     * @param counts the counters
     * @param tc     the test-case label
     */
    static void assertCounts(GatherCounts counts, String tc) {
        assertTrue(counts.none >= 30, tc + ": too few bundles with nothing gathered (" + counts.none + ")");
        assertTrue(counts.few >= 100, tc + ": too few bundles with a few bodies gathered (" + counts.few + ")");
        assertTrue(counts.subtree >= 50, tc + ": too few bundles meeting more than 32 boxes (" + counts.subtree + ")");
        assertTrue(counts.kept >= 5, tc + ": too few bundles keeping the last gather's subtree (" + counts.kept + ")");
        assertTrue(counts.thick >= 100, tc + ": too few thick bundles (" + counts.thick + ")");
        assertTrue(counts.planeCulled >= 10, tc + ": too few bundles whose polygons were culled by their planes ("
                + counts.planeCulled + ")");
        assertTrue(counts.darkened >= 500 && counts.rays - counts.darkened >= 500,
                tc + ": too few darkened (" + counts.darkened + ") or open (" + (counts.rays - counts.darkened)
                        + ") rays of " + counts.rays);
    }

    /**
     * A bumpy height field as one mesh: z = 0.5·sin(1.3x)·cos(0.9y) over [−6, 6]², 24 × 24 cells of
     * two triangles each (1152 triangles), their normals up.
     *
     * @return the mesh
     */
    static TriangleMesh bumpyMesh() {
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
     * triangle was skipped for a ray by its origin.
     */
    static final class OriginCounts {
        /** bundles whose square straddles the tangent plane: the ray origins set. */
        int straddling;
        /** bundles whose square lies on one side: the back face set. */
        int oneSide;
        /** straddling bundles that kept at most 32 bodies, some mesh triangle behind an origin among them. */
        int straddlingSkipping;
        /** (ray, gathered triangle) pairs skipped by the origin. */
        int skipped;
        int rays;
        int darkened;

        /** Asserts that both kinds of bundles were seen, at least a number of each. */
        void assertBothKinds(int least, String tc) {
            assertTrue(straddling >= least && oneSide >= least, tc + ": too few straddling (" + straddling
                    + ") or one-sided (" + oneSide + ") bundles");
        }
    }

    /**
     * A random bundle leaving a random point of a mesh's triangle (or one of its vertices): its square straddling
     * the tangent plane (even bundles: beside the point, tilted across the plane) or lying on one side of it (odd
     * bundles: over it, a quarter of them under it). Every ray's gathered transmittance, after the
     * gather as the renderer sets it, equals the scan's transmittance, exactly, with the cut-off and
     * without, and so does the packet's; and no gathered triangle skipped for a ray by its origin is
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
    static void checkLeaving(Random rnd, TriangleMesh mesh, BoundingVolumeHierarchy bvh,
                                     BoundingVolumeHierarchy scan, int bundle, boolean atVertex, OriginCounts counts,
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
                double expected = rayTransmittance(scan, scanQuery, ray, minK);
                assertEquals(expected, gatheredRay(bvh, query, ray, minK), 0, label);
            }
            ++counts.rays;
            if (rayTransmittance(scan, scanQuery, ray, 0) < 1)
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
                    assertEquals(Geometry.NO_HIT, mesh.triangleHit(k, rayState(ray)), 0, () -> bundleLabel
                            + ": triangle " + triangle + " skipped by the ray " + Arrays.toString(ray) + " is hit by it");
                }
        }
        if (skipping && gathered[0] == 0)
            ++counts.straddlingSkipping;
    }

    /**
     * {@link #checkLeaving} for bundles 0, 1, … of a scene, in its hierarchy and its scan.
     *
     * @param geometries the scene, the mesh in it
     * @param bundles    how many bundles
     */
    static void checkLeaving(Random rnd, TriangleMesh mesh, Geometries geometries, int bundles,
                                     boolean atVertex, OriginCounts counts, String tc) {
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(geometries);
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(geometries);
        for (int bundle = 0; bundle < bundles; ++bundle)
            checkLeaving(rnd, mesh, bvh, scan, bundle, atVertex, counts, tc);
    }


    /**
     * The triangles of a scene, as one mesh or as course-style {@link Triangle} objects, each the same
     * numbers.
     *
     * @param body      the mesh or the composite of the triangles
     * @param mesh      the mesh, or null
     * @param triangles the triangles' objects, or null
     */
    record Surface(Intersectable body, TriangleMesh mesh, List<Triangle> triangles) {
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
                Triangle triangle = triangle(v);
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
    static void addCell(List<double[]> list, double x0, double x1, double y0, double y1, double h0,
                                double h1) {
        list.add(new double[] { x0, y0, h0, x1, y0, h1, x1, y1, h1 });
        list.add(new double[] { x0, y0, h0, x1, y1, h1, x0, y1, h0 });
    }

    /**
     * A bundle leaving a point p of a surface z = 0 (ray origins p ± {@link #UP}) to the square centred
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
    record Straddling(Surface surface, Point3D p, Point3D c, Vector a, Vector b, BoundingVolumeHierarchy bvh,
                      Query query, BoundingVolumeHierarchy scan, Query scanQuery) {
        /**
         * Builds the scene and gathers the bundle as {@link testutil.TestBundles#gatherLeaving} sets it, asserting
         * that its square straddles the surface, that something is gathered, one by one.
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
         * The bundle's shadow rays as the renderer traces them ({@link TestBundles#shadowRays}).
         *
         * @param rnd   the generator
         * @param count the number of rays
         * @return the rays
         */
        double[][] shadowRays(Random rnd, int count) {
            return TestBundles.shadowRays(rnd, p, UP, c, a, b, count);
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
                expected = rayTransmittance(scan, scanQuery, ray, minK);
                assertEquals(expected, gatheredRay(bvh, query, ray, minK), 0, () -> label + " " + Arrays.toString(ray)
                        + " minK " + minK);
            }
            return expected;
        }
    }

    /** The normal of the surfaces z = 0 scaled to DELTA: the ray origins p ± UP. */
    static final Vector UP = new Vector(0, 0, Ray.DELTA);

    /** {@return the failure messages' name of a surface of one mesh or of Triangle objects} */
    static String kind(boolean asMesh) {
        return asMesh ? "mesh" : "Triangle objects";
    }

    /**
     * A surface along z = 0 with a low ridge, all of it between the origins (0.1 off it): flat over x
     * from −2 to 1, down to −0.05 at x = 2, up to 0.05 at x = 3, back to 0 at x = 4, y from −1 to 2. A
     * ray from (0.5, 0.3, 0) along x crosses the slope up at x = 2.5, inside a triangle.
     *
     * @return the triangles
     */
    static List<double[]> ridge() {
        List<double[]> list = new ArrayList<>();
        double[] x = { -2, 1, 2, 3, 4 };
        double[] h = { 0, 0, -0.05, 0.05, 0 };
        for (int i = 0; i + 1 < x.length; ++i)
            addCell(list, x[i], x[i + 1], -1, 2, h[i], h[i + 1]);
        return list;
    }

    /**
     * Shelves over and under the surface z = 0 around p = (0, 0, 0), and the surface itself: at
     * heights ±0.3 (x 2..6) and ±0.6 (x 3..7), y −3..3, and the floor [−2, 2]², two triangles each.
     *
     * @return the triangles, the floor's two first
     */
    static List<double[]> shelves() {
        List<double[]> list = new ArrayList<>();
        addCell(list, -2, 2, -2, 2, 0, 0);
        for (double h : new double[] { 0.3, -0.3 })
            addCell(list, 2, 6, -3, 3, h, h);
        for (double h : new double[] { 0.6, -0.6 })
            addCell(list, 3, 7, -3, 3, h, h);
        return list;
    }
}
