package testutil;

import java.util.Random;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/** Random points and directions shared by the seeded random tests. */
public final class TestRandom {
    /** Not instantiable. */
    private TestRandom() {
    }

    /**
     * A random unit vector, uniform over the sphere (three Gaussian draws, drawn again while their
     * length is 1e-3 or less).
     *
     * @param rnd the generator
     * @return the vector
     */
    public static Vector randomUnit(Random rnd) {
        while (true) {
            double x = rnd.nextGaussian();
            double y = rnd.nextGaussian();
            double z = rnd.nextGaussian();
            double length = Math.sqrt(x * x + y * y + z * z);
            if (length > 1e-3)
                return new Vector(x / length, y / length, z / length);
        }
    }

    /**
     * A random point in the cube [-size, size]³ around a centre.
     *
     * @param rnd    the generator
     * @param center the cube's centre
     * @param size   the cube's half-width
     * @return the point
     */
    public static Point3D randomPoint(Random rnd, Point3D center, double size) {
        return new Point3D(center.getX() + size * (2 * rnd.nextDouble() - 1),
                center.getY() + size * (2 * rnd.nextDouble() - 1),
                center.getZ() + size * (2 * rnd.nextDouble() - 1));
    }

    /**
     * A ray aimed at a point from a random start at a distance from it, uniform over the sphere.
     *
     * @param rnd      the generator
     * @param target   the point aimed at
     * @param distance the distance of the start from the point, positive
     * @return the ray
     */
    public static Ray rayThrough(Random rnd, Point3D target, double distance) {
        Point3D start = target.add(randomUnit(rnd).scale(distance));
        return new Ray(start, target.subtract(start));
    }

    /**
     * A random parameter in [−1, 1], a quarter of the time exactly ±1 (an edge or corner of a square
     * c + s·a + r·b).
     *
     * @param rnd the generator
     * @return the parameter
     */
    public static double edgeOrInner(Random rnd) {
        return rnd.nextInt(4) == 0 ? (rnd.nextBoolean() ? 1 : -1) : 2 * rnd.nextDouble() - 1;
    }
}
