package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import benchmark.SphereMesh;
import geometries.Geometries;
import geometries.TriangleMesh;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Vector;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link LightSquare}: a bundle's shadow rays traced together, in one packet or in two.
 */
class LightSquareTest {
    private static final Point3D POINT = Point3D.ZERO;
    private static final Vector NORMAL = new Vector(0, 0, 1);
    private static final PointLight LIGHT = new PointLight(new Color(100, 100, 100), new Point3D(0, 0, 50))
            .setEdgesSize(20).setUV(new Vector(1, 0, 0), new Vector(0, 1, 0));

    /** A light square at the origin of the floor, toward {@link #LIGHT}, gathered over a hierarchy. */
    private static LightSquare square(BoundingVolumeHierarchy bvh, Query query) {
        LightSquare square = new LightSquare().setPoint(POINT, NORMAL, LIGHT.getL(POINT), bvh, query);
        square.setSquare(LIGHT);
        return square;
    }

    /**
     * Test method for {@link LightSquare#visibility(double, double[], JitteredGrid)}: all the rays in one
     * packet, in serpentine order, sum to the same bits as the outline's packet and the inner cells'.
     */
    @Test
    void testVisibilityOfAllRays() {
        // a transparent tessellated ball over part of the light's square: its many triangles make the
        // bundle keep a subtree, and its rays cross it twice (0.25), once near its rim, or miss it
        TriangleMesh ball = SphereMesh.mesh(new Point3D(6, 2, 25), 6, 24, 48);
        ball.setMaterial(new Material().setKt(0.5));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(new Geometries(ball));
        Query query = bvh.newQuery();
        double distance = LIGHT.getDistance(POINT);
        // ===== Equivalence Partitions Tests =====
        for (int k : new int[] { 9, 4 }) {
            JitteredGrid grid = new JitteredGrid(k);
            double[] samples = new double[2 * k * k];
            grid.sampleUnchecked(new SplitMix64(k), samples);
            double one = square(bvh, query).visibility(distance, samples, grid);
            LightSquare square = square(bvh, query);
            double two = square.outlineVisibility(distance, samples, grid) + square.innerVisibility(samples, grid);
            // TC01 (k = 9), TC02 (k = 4): a penumbra, the same sum either way
            assertTrue(one > 1 && one < k * k, "TC0" + (k == 9 ? 1 : 2) + ": a penumbra, got " + one);
            assertEquals(two, one, 0, "TC0" + (k == 9 ? 1 : 2) + ": one packet and two must sum alike");
        }

        // ===== Boundary Values Tests =====
        // TC11: k = 1: the centre's ray and the one sample's
        JitteredGrid single = new JitteredGrid(1);
        double[] point = { 0.5, 0.5 };
        double one = square(bvh, query).visibility(distance, point, single);
        LightSquare square = square(bvh, query);
        assertEquals(square.outlineVisibility(distance, point, single) + square.innerVisibility(point, single), one, 0,
                "TC11: k = 1 alike");
    }
}
