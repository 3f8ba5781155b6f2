package primitives;

import static primitives.Util.isZero;
import static primitives.Util.requireFinite;
import static primitives.Util.requireNonNull;

/**
 * An immutable point in 3D Cartesian space.
 */
public class Point3D {
    /** The origin (0, 0, 0). */
    public static final Point3D ZERO = new Point3D(0, 0, 0);

    final double x;
    final double y;
    final double z;

    /**
     * Creates a point from its coordinates.
     *
     * @param x the x coordinate
     * @param y the y coordinate
     * @param z the z coordinate
     * @throws IllegalArgumentException when a coordinate is NaN or infinite
     */
    public Point3D(double x, double y, double z) {
        this.x = requireFinite(x, "point x coordinate");
        this.y = requireFinite(y, "point y coordinate");
        this.z = requireFinite(z, "point z coordinate");
    }

    /** {@return the x coordinate} */
    public double getX() {
        return x;
    }

    /** {@return the y coordinate} */
    public double getY() {
        return y;
    }

    /** {@return the z coordinate} */
    public double getZ() {
        return z;
    }

    /**
     * Moves this point by a vector.
     *
     * @param vector the displacement
     * @return the new point
     * @throws IllegalArgumentException when the vector is null or the result is not finite
     */
    public Point3D add(Vector vector) {
        requireNonNull(vector, "vector to add");
        return new Point3D(x + vector.x, y + vector.y, z + vector.z);
    }

    /**
     * Builds the vector from another point to this one.
     *
     * @param other the tail of the vector
     * @return the vector (this − other)
     * @throws IllegalArgumentException when the points coincide (zero vector) or the point is null
     */
    public Vector subtract(Point3D other) {
        requireNonNull(other, "point to subtract");
        return new Vector(x - other.x, y - other.y, z - other.z);
    }

    /**
     * Squared distance to another point.
     *
     * @param other the other point
     * @return the squared distance
     * @throws IllegalArgumentException when the other point is null
     */
    public double distanceSquared(Point3D other) {
        requireNonNull(other, "other point");
        double dx = x - other.x;
        double dy = y - other.y;
        double dz = z - other.z;
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * Distance to another point.
     *
     * @param other the other point
     * @return the distance
     * @throws IllegalArgumentException when the other point is null
     */
    public double distance(Point3D other) {
        return Math.sqrt(distanceSquared(other));
    }

    /**
     * Two points are equal when every coordinate agrees within the library's tolerance.
     */
    @Override
    public boolean equals(Object obj) {
        if (this == obj)
            return true;
        return obj instanceof Point3D other
                && isZero(x - other.x) && isZero(y - other.y) && isZero(z - other.z);
    }

    /**
     * A constant: equality is tolerant, so no finer hash could agree with it for every pair of
     * points on either side of a rounding boundary. Points still work in hash sets, only slower.
     */
    @Override
    public int hashCode() {
        return 31;
    }

    @Override
    public String toString() {
        return "(" + x + ", " + y + ", " + z + ")";
    }
}
