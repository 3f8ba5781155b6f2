package primitives;

import static primitives.Util.isZero;
import static primitives.Util.requireFinite;
import static primitives.Util.requireNonNull;

/**
 * A non-zero vector in 3D space. Every operation returns a new vector; the one exception is
 * {@link #normalize()}, which normalises the vector itself.
 */
public class Vector {
    /** The sine of the angle below which two vectors are parallel. */
    private static final double PARALLEL_SINE = 1e-10;
    /** Below this length, normalising divides the components by the largest one first. */
    private static final double SAFE_LENGTH_MIN = 1e-140;
    /** Above this length, normalising divides the components by the largest one first. */
    private static final double SAFE_LENGTH_MAX = 1e140;

    double x;
    double y;
    double z;

    /**
     * Creates a vector from its components.
     *
     * @param x the x component
     * @param y the y component
     * @param z the z component
     * @throws IllegalArgumentException for the zero vector (all three components exactly 0) or a NaN or
     *                                  infinite component
     */
    public Vector(double x, double y, double z) {
        this.x = requireFinite(x, "vector x component");
        this.y = requireFinite(y, "vector y component");
        this.z = requireFinite(z, "vector z component");
        if (x == 0 && y == 0 && z == 0)
            throw new IllegalArgumentException("zero vector is not allowed");
    }

    /**
     * Creates the vector from the origin to a point.
     *
     * @param head the vector's head
     * @throws IllegalArgumentException when the head is the origin (zero vector) or null
     */
    public Vector(Point3D head) {
        this(requireNonNull(head, "vector head").x, head.y, head.z);
    }

    /** {@return the x component} */
    public double getX() {
        return x;
    }

    /** {@return the y component} */
    public double getY() {
        return y;
    }

    /** {@return the z component} */
    public double getZ() {
        return z;
    }

    /** {@return the vector's head, the point it reaches from the origin} */
    public Point3D getHead() {
        return new Point3D(x, y, z);
    }

    /**
     * Vector sum.
     *
     * @param other the vector to add
     * @return the new vector (this + other)
     * @throws IllegalArgumentException when the sum is the zero vector or the other vector is null
     */
    public Vector add(Vector other) {
        requireNonNull(other, "vector to add");
        return new Vector(x + other.x, y + other.y, z + other.z);
    }

    /**
     * Vector difference.
     *
     * @param other the vector to subtract
     * @return the new vector (this − other)
     * @throws IllegalArgumentException when the difference is the zero vector or the other vector is null
     */
    public Vector subtract(Vector other) {
        requireNonNull(other, "vector to subtract");
        return new Vector(x - other.x, y - other.y, z - other.z);
    }

    /**
     * Multiplies the vector by a scalar.
     *
     * @param scalar the factor
     * @return the new vector
     * @throws IllegalArgumentException when the factor is zero (zero vector) or not finite
     */
    public Vector scale(double scalar) {
        if (scalar == 0)
            throw new IllegalArgumentException("scaling by zero gives the zero vector");
        return new Vector(x * scalar, y * scalar, z * scalar);
    }

    /**
     * Dot product.
     *
     * @param other the other vector
     * @return this · other
     * @throws IllegalArgumentException when the other vector is null
     */
    public double dotProduct(Vector other) {
        requireNonNull(other, "other vector");
        return x * other.x + y * other.y + z * other.z;
    }

    /**
     * Cross product. The vectors are parallel when the sine of their angle is below 1e-10, whatever
     * their lengths (the test is made on copies divided by their largest component).
     *
     * @param other the other vector
     * @return the new vector this × other
     * @throws IllegalArgumentException when the vectors are parallel (zero vector), the product overflows,
     *                                  or the other vector is null
     */
    public Vector crossProduct(Vector other) {
        requireNonNull(other, "other vector");
        if (isParallel(other))
            throw new IllegalArgumentException("cross product of parallel vectors is the zero vector");
        return new Vector(y * other.z - z * other.y, z * other.x - x * other.z, x * other.y - y * other.x);
    }

    /** Whether the sine of the angle between the vectors is below {@link #PARALLEL_SINE}. */
    private boolean isParallel(Vector other) {
        double m = maxAbs();
        double ax = x / m;
        double ay = y / m;
        double az = z / m;
        double n = other.maxAbs();
        double bx = other.x / n;
        double by = other.y / n;
        double bz = other.z / n;
        double cx = ay * bz - az * by;
        double cy = az * bx - ax * bz;
        double cz = ax * by - ay * bx;
        double sine2 = PARALLEL_SINE * PARALLEL_SINE;
        return cx * cx + cy * cy + cz * cz <= sine2 * (ax * ax + ay * ay + az * az) * (bx * bx + by * by + bz * bz);
    }

    /** {@return the largest magnitude of the components, positive for any vector} */
    private double maxAbs() {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    /**
     * A unit vector orthogonal to this one: this vector crossed with the coordinate axis it leans
     * on least, so the same vector always gives the same answer. The two components used are first
     * divided by the larger of them, so a very long vector cannot overflow the length.
     *
     * @return a new unit vector u with u · this = 0
     */
    public Vector orthogonal() {
        double ax = Math.abs(x);
        double ay = Math.abs(y);
        double az = Math.abs(z);
        if (ax <= ay && ax <= az) // × (1,0,0)
            return unitOf(0, z, -y, Math.max(ay, az));
        if (ay <= az) // × (0,1,0)
            return unitOf(-z, 0, x, Math.max(ax, az));
        return unitOf(y, -x, 0, Math.max(ax, ay)); // × (0,0,1)
    }

    /** The unit vector along (x, y, z), its components first divided by their largest magnitude m. */
    private static Vector unitOf(double x, double y, double z, double m) {
        return new Vector(x / m, y / m, z / m).normalize();
    }

    /** {@return the squared length} */
    public double lengthSquared() {
        return x * x + y * y + z * z;
    }

    /** {@return the length} */
    public double length() {
        return Math.sqrt(lengthSquared());
    }

    /**
     * Normalises this vector in place: the one operation that changes a vector. A very long or very
     * short vector is first divided by its largest component, so its square cannot overflow or
     * vanish: the result is always a unit vector.
     *
     * @return this vector, now of unit length
     */
    public Vector normalize() {
        double length = length();
        if (!(length > SAFE_LENGTH_MIN && length < SAFE_LENGTH_MAX)) {
            double m = maxAbs();
            x /= m;
            y /= m;
            z /= m;
            length = length();
        }
        x /= length;
        y /= length;
        z /= length;
        return this;
    }

    /** {@return a new unit vector in the direction of this one} */
    public Vector normalized() {
        return new Vector(x, y, z).normalize();
    }

    /**
     * Two vectors are equal when every component agrees within the library's tolerance.
     */
    @Override
    public boolean equals(Object obj) {
        if (this == obj)
            return true;
        return obj instanceof Vector other
                && isZero(x - other.x) && isZero(y - other.y) && isZero(z - other.z);
    }

    /** A constant, for the same reason as {@link Point3D#hashCode()}: equality is tolerant. */
    @Override
    public int hashCode() {
        return 37;
    }

    @Override
    public String toString() {
        return "->(" + x + ", " + y + ", " + z + ")";
    }
}
