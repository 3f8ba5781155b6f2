package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MIN_K;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestBundles.assertForgetsSubtree;
import static testutil.TestBundles.assertGathersRowSubtree;
import static testutil.TestBundles.assertKeepsSubtree;
import static testutil.TestScenes.triangleRow;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Instance;
import geometries.Sphere;
import primitives.Point3D;
import primitives.Transform;
import primitives.Vector;
import testutil.TestBundles;

/** Unit tests for {@link Query}, a thread's scratch space: its ray, its frustum and its packet. */
class QueryTest {
    /** Test method for {@link Query#setRay}. */
    @Test
    void testSetRay() {
        Query query = BoundingVolumeHierarchy.build(new Geometries()).newQuery();
        // ===== Equivalence Partitions Tests =====
        // TC01: the numbers kept as the next query's ray, the query answered
        assertSame(query, query.setRay(1, 2, 3, 0, 0.6, 0.8, 7), "TC01: the query itself");
        RayState ray = query.ray;
        assertEquals(1, ray.ox(), 0, "TC01: ox");
        assertEquals(2, ray.oy(), 0, "TC01: oy");
        assertEquals(3, ray.oz(), 0, "TC01: oz");
        assertEquals(0, ray.dx(), 0, "TC01: dx");
        assertEquals(0.6, ray.dy(), 0, "TC01: dy");
        assertEquals(0.8, ray.dz(), 0, "TC01: dz");
        assertEquals(7, ray.maxT(), 0, "TC01: maxT");
        // ===== Boundary Values Tests =====
        // TC11: an unlimited distance
        assertEquals(Double.POSITIVE_INFINITY, query.setRay(0, 0, 0, 1, 0, 0, Double.POSITIVE_INFINITY).ray.maxT(),
                "TC11");
    }

    /**
     * Test method for {@link Query#clearPacket()}, {@link Query#addToPacket}, {@link Query#getPacketSize()}
     * and {@link Query#getTransmittance(int)}: 20 rays up the z axis, with nothing in the way.
     */
    @Test
    void testPacket() {
        Geometries aside = new Geometries(new Sphere(new Point3D(9, 9, 9), 1));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(aside);
        Query query = bvh.newQuery();
        TestBundles.gather(bvh, query, Point3D.ZERO, new Point3D(0, 0, 10), new Vector(1, 0, 0), new Vector(0, 1, 0));
        // ===== Equivalence Partitions Tests =====
        // TC01: 20 rays added, more than the first room for 16: all kept, in order, each answering 1
        query.clearPacket();
        for (int r = 0; r < 20; ++r)
            query.addToPacket(0, 0, 0, 0, 0, 1, r + 1);
        assertEquals(20, query.getPacketSize(), "TC01: 20 rays");
        for (int r = 0; r < 20; ++r)
            assertEquals(r + 1, query.packet.rays[r].maxT(), 0, "TC01: ray " + r + " in its place");
        bvh.packetTransmittances(query, MIN_K);
        for (int r = 0; r < 20; ++r)
            assertEquals(1, query.getTransmittance(r), 0, "TC01: ray " + r + " meets nothing");

        // ===== Boundary Values Tests =====
        // TC11: no answer before the first ray or after the last
        assertMessage(assertThrows(IllegalArgumentException.class, () -> query.getTransmittance(-1), "TC11: ray −1"),
                "packet", "TC11");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> query.getTransmittance(20), "TC11: ray 20"),
                "packet", "TC11");
        // TC12: a cleared packet: no ray, no answer
        query.clearPacket();
        assertEquals(0, query.getPacketSize(), "TC12: no ray");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> query.getTransmittance(0), "TC12: ray 0"),
                "packet", "TC12");
    }

    /**
     * Test method for {@link Query#getFrustum()}, {@link Query#isSubtreeGathered()} and
     * {@link Query#isPacketTraced()}: what the last gather found, for rows of unit spheres at x = 0, 2,
     * 4 … on the x axis, all under a bundle from (n − 1, 0, 10) to a square at z = −10 (half-sides 2n + 2
     * and 1).
     */
    @Test
    void testGathered() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 3 spheres: kept one by one, no packet
        Query few = gatherRow(rowOf(3));
        assertFalse(few.isSubtreeGathered(), "TC01: kept one by one");
        assertFalse(few.isPacketTraced(), "TC01: no packet");
        // TC02: 50 spheres: a subtree, traced as a packet
        Query many = gatherRow(rowOf(50));
        assertTrue(many.isSubtreeGathered(), "TC02: a subtree");
        assertTrue(many.isPacketTraced(), "TC02: a packet");
        // TC03: 3 spheres, one of them an instance: kept one by one, traced as a packet
        Geometries row = rowOf(2);
        row.add(new Instance(new Sphere(Point3D.ZERO, 1), Transform.translate(new Vector(4, 0, 0))));
        Query instanced = gatherRow(row);
        assertFalse(instanced.isSubtreeGathered(), "TC03: kept one by one");
        assertTrue(instanced.isPacketTraced(), "TC03: an instance takes the rays as a packet");

        // ===== Boundary Values Tests =====
        // TC11: 32 spheres, as many as are kept one by one: no subtree
        assertFalse(gatherRow(rowOf(32)).isSubtreeGathered(), "TC11: 32 kept one by one");
        // TC12: 33 spheres: a subtree
        assertTrue(gatherRow(rowOf(33)).isSubtreeGathered(), "TC12: 33 make a subtree");
        // TC13: the frustum is the query's own, the same object every time
        Query query = BoundingVolumeHierarchy.build(rowOf(1)).newQuery();
        assertSame(query.getFrustum(), query.getFrustum(), "TC13: one frustum a query");
    }

    /** {@return n unit spheres at x = 0, 2, 4 … on the x axis} */
    private static Geometries rowOf(int n) {
        Geometries row = new Geometries();
        for (int i = 0; i < n; ++i)
            row.add(new Sphere(new Point3D(2 * i, 0, 0), 1));
        return row;
    }

    /** {@return a new query of the row's tree, after a gather of the bundle over all its spheres} */
    private static Query gatherRow(Geometries row) {
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(row);
        Query query = bvh.newQuery();
        int n = row.getGeometries().size();
        assertTrue(TestBundles.gather(bvh, query, new Point3D(n - 1, 0, 10), new Point3D(n - 1, 0, -10),
                new Vector(2 * n + 2, 0, 0), new Vector(0, 1, 0)), "the bundle must meet the spheres");
        return query;
    }

    /**
     * Test method for {@link Query#forgetLastGather()}: the next gather keeps no subtree of an earlier one.
     * On the row of 40 triangles ({@code triangleRow}), under the pyramid over all of them and the one over
     * triangles 19 and 20, whose walks both branch at the root.
     */
    @Test
    void testForgetLastGather() {
        BoundingVolumeHierarchy rowBvh = BoundingVolumeHierarchy.build(triangleRow());
        Query query = rowBvh.newQuery();

        // ===== Equivalence Partitions Tests =====
        // TC01: a subtree kept, then forgotten: the middle pyramid's 2 triangles are gathered one by one
        assertForgetsSubtree(rowBvh, query, query::forgetLastGather, "TC01");
        // TC02: a subtree kept and not forgotten: the middle pyramid keeps it again
        assertKeepsSubtree(rowBvh, query, "TC02");

        // ===== Boundary Values Tests =====
        // TC11: a new query forgets before any gather: the pyramid over all 40 still keeps a subtree
        Query fresh = rowBvh.newQuery();
        fresh.forgetLastGather();
        assertGathersRowSubtree(rowBvh, fresh, "TC11");
    }
}
