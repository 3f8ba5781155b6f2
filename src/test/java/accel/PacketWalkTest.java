package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.transmittance;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestBundles.boxesMeeting;
import static testutil.TestBundles.fillPacket;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link PacketWalk}, through {@link BoundingVolumeHierarchy#packetTransmittances} and the
 * packet of a {@link Query}: each ray of a packet gets its own answer.
 */
class PacketWalkTest {
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
                    plates.add(new Triangle(new Point3D(i, j, z), new Point3D(i + 1, j, z),
                            new Point3D(i + 1, j + 1, z))
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
        assertTrue(query.getFrustum().set(new double[] { apex.getX(), apex.getY(), apex.getZ() },
                new double[] { 0.1, 0.2, z, 4, 0, 0, 0, 4, 0 }, 0),
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
     * Test method for {@link BoundingVolumeHierarchy#packetTransmittances} and the packet of a
     * {@link Query}: a closed bundle of many bodies, transparent blockers and blockers beyond the
     * light, a bundle that keeps no subtree, an empty packet and a packet of one ray.
     */
    @Test
    void testTransmittances() {
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
        assertTrue(query.getFrustum().set(new double[] { 0.05, 0.1, -5 },
                new double[] { 0.05, 0.1, -4.9, 0.01, 0, 0, 0, 0.01, 0 }, 0),
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
        assertTrue(query.getFrustum().set(new double[] { 0, 0, -50 }, new double[] { 0, 0, 1, 4.5, 0, 0, 0, 4.5, 0 },
                0), tc
                + ": the pyramid must be set");
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
     * Test method for {@link BoundingVolumeHierarchy#packetTransmittances} on leaves that mix a
     * transparent and an opaque mesh's triangles with other bodies, where some of a leaf's rays are
     * blocked by a body in the middle of the leaf and others go on: each ray's answer is its own.
     */
    @Test
    void testTransmittancesInLeaves() {
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
        Collections.shuffle(order, rnd);
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
}
