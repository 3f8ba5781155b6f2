package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestBundles.segmentPoint;
import static testutil.TestBundles.standard;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import primitives.Transform;
import testutil.TestBundles.RandomBundle;
import testutil.TestInstances;

/**
 * Unit tests for {@link MappedFrustum}: a bundle's pyramid carried into an instance's space keeps
 * every ray of the bundle, and sets aside what the pyramid sets aside there.
 */
class MappedFrustumTest {
    /** The instances' placements, and a mirror (a placement whose determinant is negative). */
    private static final List<Transform> PLACEMENTS = placements();

    private static List<Transform> placements() {
        List<Transform> placements = new ArrayList<>(TestInstances.PLACEMENTS);
        placements.add(Transform.scale(-1, 1, 1).then(Transform.rotateZ(30)));
        return placements;
    }

    /** {@return a point carried by a map's 12 numbers} */
    private static double[] map(double[] m, double... p) {
        double[] out = new double[3];
        for (int row = 0; row < 3; ++row)
            out[row] = m[4 * row] * p[0] + m[4 * row + 1] * p[1] + m[4 * row + 2] * p[2] + m[4 * row + 3];
        return out;
    }

    /** {@return the box around some points} */
    private static double[] box(double[]... points) {
        double[] box = { Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY };
        for (double[] p : points)
            for (int k = 0; k < 3; ++k) {
                box[k] = Math.min(box[k], p[k]);
                box[3 + k] = Math.max(box[3 + k], p[k]);
            }
        return box;
    }

    /** {@return the frustum of a pyramid carried into a placement's body space, by its inverse} */
    private static ShadowFrustum carried(ShadowFrustum world, Transform placement) {
        ShadowFrustum body = new ShadowFrustum();
        assertTrue(new MappedFrustum().set(body, world, placement.inverse().toArray(), placement.toArray()),
                "the pyramid must carry");
        return body;
    }

    /** Test method for {@link MappedFrustum#set}: every ray of a bundle stays in the carried pyramid. */
    @Test
    void testSetKeepsRays() {
        Random rnd = new Random(31);
        ShadowFrustum world = new ShadowFrustum();
        int bundles = 0;

        // ===== Equivalence Partitions Tests =====
        // TC01: 100 random bundles, thin and thick, under each placement: each point of each ray
        // segment, carried into the body's space, is in a box the carried pyramid meets
        for (RandomBundle bundle : RandomBundle.walk(rnd, world, 100)) {
            ++bundles;
            for (Transform placement : PLACEMENTS) {
                double[] toBody = placement.inverse().toArray();
                ShadowFrustum body = carried(world, placement);
                for (double[] segment : bundle.segments()) {
                    double[] point = map(toBody, segmentPoint(rnd, segment));
                    assertTrue(body.meetsBox(box(point), 0), "TC01: a ray's point " + point[0] + ", " + point[1]
                            + ", " + point[2] + " left out under " + placement);
                }
            }
        }
        assertTrue(bundles > 90, "TC01: too few bundles drawn: " + bundles);

        // ===== Boundary Values Tests =====
        // TC11: the identity carries the standard pyramid onto itself: the same answers on boxes
        // just inside and just outside a side (x = z/5 at z = 5: x = 1)
        ShadowFrustum standard = standard();
        ShadowFrustum same = carried(standard, Transform.IDENTITY);
        for (double x : new double[] { 0.99, 1.01, 1.5 }) {
            double[] box = { x, 0, 5, x + 0.001, 0.001, 5.001 };
            assertEquals(standard.meetsBox(box, 0), same.meetsBox(box, 0), "TC11: the identity changed box at " + x);
        }
        // TC12: a pyramid not set (flat) is not carried
        ShadowFrustum flat = new ShadowFrustum();
        assertFalse(flat.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC12: the apex on the base must be flat");
        double[] identity = Transform.IDENTITY.toArray();
        assertFalse(new MappedFrustum().set(new ShadowFrustum(), flat, identity, identity),
                "TC12: a flat pyramid must not be carried");
    }

    /** Test method for {@link MappedFrustum#set}: what the pyramid sets aside stays aside. */
    @Test
    void testSetSetsAside() {
        ShadowFrustum world = standard();
        ShadowFrustum leaving = standard();
        leaving.setBackFace(0, 0, 1);
        // a box beside the standard pyramid (|x| ≤ z/5), and a wide triangle just behind its apex
        double[][] beside = { { 8, -0.5, 4.5 }, { 9, 0.5, 5.5 } };
        double[][] behind = { { -5, -5, -0.01 }, { 5, -5, -0.01 }, { 0, 5, -0.01 } };

        // ===== Equivalence Partitions Tests =====
        for (Transform placement : PLACEMENTS) {
            double[] toBody = placement.inverse().toArray();
            // TC01: the corners of a box 7 beside the pyramid, carried: their box is still set aside (the
            // placements scale by 0.5 to 2, so the gap stays over 3, wider than the corners' box grows)
            double[] corners = box(beside[0], beside[1]);
            List<double[]> carriedCorners = new ArrayList<>();
            for (int c = 0; c < 8; ++c)
                carriedCorners.add(map(toBody, corners[(c & 1) * 3], corners[1 + (c >> 1 & 1) * 3],
                        corners[2 + (c >> 2 & 1) * 3]));
            ShadowFrustum body = carried(world, placement);
            assertFalse(body.meetsBox(box(carriedCorners.toArray(new double[0][])), 0),
                    "TC01: the box beside the pyramid must stay aside under " + placement);
            // TC02: a triangle behind the back face, carried: set aside by the carried back face
            double[] vertices = new double[9];
            for (int v = 0; v < 3; ++v)
                System.arraycopy(map(toBody, behind[v]), 0, vertices, 3 * v, 3);
            ShadowFrustum bodyLeaving = carried(leaving, placement);
            assertTrue(bodyLeaving.hasBackFace(), "TC02: the back face must be carried under " + placement);
            assertFalse(bodyLeaving.meetsTriangle(vertices, 0, 3, 6),
                    "TC02: the triangle behind the back face must stay aside under " + placement);
            // TC03: without a back face, the same triangle is not set aside (it lies around the apex)
            assertTrue(body.meetsTriangle(vertices, 0, 3, 6), "TC03: only the back face sets it aside");
        }

        // ===== Boundary Values Tests =====
        // TC11: a back face across the other way (the base behind it) cannot be placed, carried or not
        ShadowFrustum backwards = standard();
        backwards.setBackFace(0, 0, -1);
        assertFalse(carried(backwards, PLACEMENTS.get(1)).hasBackFace(), "TC11: a back face behind the base");
    }
}
