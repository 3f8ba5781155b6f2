package primitives;

import java.util.Arrays;

import static primitives.Util.requireFinite;
import static primitives.Util.requireNonNull;

/**
 * An immutable affine transform of space: a 3 × 3 linear part and a translation, p ↦ A p + t. Build
 * one from the factories ({@link #translate}, {@link #scale}, {@link #rotate}, …) and chain them with
 * {@link #then}: {@code Transform.scale(2).then(Transform.rotateY(30)).then(Transform.translate(v))}
 * scales first, then turns, then moves. Only invertible transforms exist: every transform knows its
 * {@link #inverse()}, which takes world points back into a body's own space and gives normals their
 * inverse transpose ({@link #applyToNormal}).
 */
public final class Transform {
    /** The transform that leaves every point where it is. */
    public static final Transform IDENTITY = new Transform(new double[] { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 });

    /** Below this size of the determinant, relative to the matrix's largest entry cubed, it is singular. */
    private static final double SINGULAR = 1e-12;

    /** Row-major 3 × 4: a00 a01 a02 t0, a10 a11 a12 t1, a20 a21 a22 t2. */
    private final double[] m;
    /** The same layout for the inverse transform. */
    private final double[] inv;

    /** A transform with its matrix, the inverse computed; refuses a singular matrix. */
    private Transform(double[] m) {
        this.m = m;
        this.inv = invert(m);
    }

    /** A transform with a matrix and its known inverse. */
    private Transform(double[] m, double[] inv) {
        this.m = m;
        this.inv = inv;
    }

    /**
     * A translation.
     *
     * @param offset how far every point moves
     * @return the translation by the offset
     * @throws IllegalArgumentException when the offset is null
     */
    public static Transform translate(Vector offset) {
        requireNonNull(offset, "translation");
        return new Transform(new double[] { 1, 0, 0, offset.x, 0, 1, 0, offset.y, 0, 0, 1, offset.z });
    }

    /**
     * A uniform scale about the origin.
     *
     * @param factor the factor (negative mirrors through the origin)
     * @return the scale
     * @throws IllegalArgumentException when the factor is 0, NaN or infinite
     */
    public static Transform scale(double factor) {
        return scale(factor, factor, factor);
    }

    /**
     * A scale about the origin along each axis (negative factors mirror).
     *
     * @param sx the factor along x
     * @param sy the factor along y
     * @param sz the factor along z
     * @return the scale
     * @throws IllegalArgumentException when a factor is 0, NaN or infinite
     */
    public static Transform scale(double sx, double sy, double sz) {
        requireScale(sx, "x");
        requireScale(sy, "y");
        requireScale(sz, "z");
        return regular(new Transform(new double[] { sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, sz, 0 },
                new double[] { 1 / sx, 0, 0, 0, 0, 1 / sy, 0, 0, 0, 0, 1 / sz, 0 }));
    }

    /** Refuses a scale factor that is not a finite non-zero number. */
    private static void requireScale(double factor, String axis) {
        requireFinite(factor, "scale factor along " + axis);
        if (factor == 0)
            throw new IllegalArgumentException("scale factor along " + axis + " must not be 0: it would flatten space");
    }

    /**
     * A rotation about an axis through the origin, counter-clockwise when the axis points at the viewer
     * (the right-hand rule). Multiples of 90° are exact.
     *
     * @param axis    the axis (any length)
     * @param degrees the angle
     * @return the rotation
     * @throws IllegalArgumentException when the axis is null or the angle is NaN or infinite (the axis
     *                                  cannot be zero: {@link Vector} refuses it)
     */
    public static Transform rotate(Vector axis, double degrees) {
        Vector u = requireNonNull(axis, "rotation axis").normalized();
        double[] sc = sinCos(degrees);
        double s = sc[0];
        double c = sc[1];
        double k = 1 - c;
        // Rodrigues: R = c I + s [u]× + (1 − c) u uᵀ
        double[] r = {
                c + k * u.x * u.x, k * u.x * u.y - s * u.z, k * u.x * u.z + s * u.y, 0,
                k * u.y * u.x + s * u.z, c + k * u.y * u.y, k * u.y * u.z - s * u.x, 0,
                k * u.z * u.x - s * u.y, k * u.z * u.y + s * u.x, c + k * u.z * u.z, 0 };
        return new Transform(r, transposeOfRotation(r));
    }

    /**
     * A rotation about the x axis (y turns toward z).
     *
     * @param degrees the angle
     * @return the rotation
     * @throws IllegalArgumentException when the angle is NaN or infinite
     */
    public static Transform rotateX(double degrees) {
        return rotate(new Vector(1, 0, 0), degrees);
    }

    /**
     * A rotation about the y axis (z turns toward x).
     *
     * @param degrees the angle
     * @return the rotation
     * @throws IllegalArgumentException when the angle is NaN or infinite
     */
    public static Transform rotateY(double degrees) {
        return rotate(new Vector(0, 1, 0), degrees);
    }

    /**
     * A rotation about the z axis (x turns toward y).
     *
     * @param degrees the angle
     * @return the rotation
     * @throws IllegalArgumentException when the angle is NaN or infinite
     */
    public static Transform rotateZ(double degrees) {
        return rotate(new Vector(0, 0, 1), degrees);
    }

    /** {sin, cos} of an angle in degrees, exact at multiples of 90°. */
    private static double[] sinCos(double degrees) {
        double d = requireFinite(degrees, "rotation angle") % 360;
        if (d < 0)
            d += 360;
        if (d % 90 == 0)
            return switch ((int) (d / 90)) {
                case 0 -> new double[] { 0, 1 };
                case 1 -> new double[] { 1, 0 };
                case 2 -> new double[] { 0, -1 };
                default -> new double[] { -1, 0 };
            };
        double radians = Math.toRadians(d);
        return new double[] { Math.sin(radians), Math.cos(radians) };
    }

    /** The inverse of a rotation: its transpose. */
    private static double[] transposeOfRotation(double[] r) {
        return new double[] { r[0], r[4], r[8], 0, r[1], r[5], r[9], 0, r[2], r[6], r[10], 0 };
    }

    /**
     * This transform, then another one.
     *
     * @param next the transform applied after this one
     * @return the composition: p ↦ next(this(p))
     * @throws IllegalArgumentException when next is null, or the composition is singular (numerically)
     */
    public Transform then(Transform next) {
        requireNonNull(next, "next transform");
        return regular(new Transform(compose(next.m, m), compose(inv, next.inv)));
    }

    /** {@return the matrix of p ↦ a(b(p))} */
    private static double[] compose(double[] a, double[] b) {
        double[] r = new double[12];
        for (int row = 0; row < 3; row++) {
            int i = 4 * row;
            for (int col = 0; col < 4; col++)
                r[i + col] = a[i] * b[col] + a[i + 1] * b[4 + col] + a[i + 2] * b[8 + col];
            r[i + 3] += a[i + 3];
        }
        return r;
    }

    /** {@return the inverse transform: it takes every point back where this one found it} */
    public Transform inverse() {
        return new Transform(inv, m);
    }

    /**
     * Moves a point.
     *
     * @param p the point
     * @return A p + t
     * @throws IllegalArgumentException when the point is null
     */
    public Point3D apply(Point3D p) {
        requireNonNull(p, "point");
        return new Point3D(row(m, 0, p.x, p.y, p.z) + m[3], row(m, 1, p.x, p.y, p.z) + m[7],
                row(m, 2, p.x, p.y, p.z) + m[11]);
    }

    /**
     * Transforms a direction: the linear part alone, no translation, not normalised.
     *
     * @param v the vector
     * @return A v
     * @throws IllegalArgumentException when the vector is null
     */
    public Vector applyToVector(Vector v) {
        requireNonNull(v, "vector");
        return new Vector(row(m, 0, v.x, v.y, v.z), row(m, 1, v.x, v.y, v.z), row(m, 2, v.x, v.y, v.z));
    }

    /**
     * Transforms a surface normal: by the inverse transpose of the linear part, which keeps it
     * perpendicular to the transformed surface under any scale, then normalised.
     *
     * @param n the normal
     * @return the unit normal (A⁻¹)ᵀ n / |(A⁻¹)ᵀ n|
     * @throws IllegalArgumentException when the normal is null
     */
    public Vector applyToNormal(Vector n) {
        requireNonNull(n, "normal");
        return new Vector(column(inv, 0, n.x, n.y, n.z), column(inv, 1, n.x, n.y, n.z),
                column(inv, 2, n.x, n.y, n.z)).normalize();
    }

    /**
     * The matrix as numbers, for code that transforms many points without objects: row-major 3 × 4,
     * {a00, a01, a02, t0, a10, a11, a12, t1, a20, a21, a22, t2}.
     *
     * @return a copy of the 12 numbers
     */
    public double[] toArray() {
        return m.clone();
    }

    /** {@return a row of a matrix's linear part times (x, y, z)} */
    private static double row(double[] a, int row, double x, double y, double z) {
        int i = 4 * row;
        return a[i] * x + a[i + 1] * y + a[i + 2] * z;
    }

    /** {@return a column of a matrix's linear part times (x, y, z): a row of its transpose} */
    private static double column(double[] a, int col, double x, double y, double z) {
        return a[col] * x + a[4 + col] * y + a[8 + col] * z;
    }

    /**
     * The inverse of an affine matrix: the linear part's inverse by its cofactors, and −A⁻¹ t.
     *
     * @throws IllegalArgumentException when the matrix is singular or not finite
     */
    private static double[] invert(double[] a) {
        double c00 = a[5] * a[10] - a[6] * a[9];
        double c01 = a[6] * a[8] - a[4] * a[10];
        double c02 = a[4] * a[9] - a[5] * a[8];
        double f = 1 / requireRegular(a);
        double[] r = {
                c00 * f, (a[2] * a[9] - a[1] * a[10]) * f, (a[1] * a[6] - a[2] * a[5]) * f, 0,
                c01 * f, (a[0] * a[10] - a[2] * a[8]) * f, (a[2] * a[4] - a[0] * a[6]) * f, 0,
                c02 * f, (a[1] * a[8] - a[0] * a[9]) * f, (a[0] * a[5] - a[1] * a[4]) * f, 0 };
        for (int row = 0; row < 3; row++)
            r[4 * row + 3] = -row(r, row, a[3], a[7], a[11]);
        return r;
    }

    /** {@return a transform whose inverse was given, once its matrix is checked to be regular} */
    private static Transform regular(Transform t) {
        requireRegular(t.m);
        return t;
    }

    /**
     * Refuses a matrix whose determinant is not finite or is negligible against its entries: such a
     * transform flattens space (numerically), and nothing could be taken back through it.
     *
     * @return the determinant
     */
    private static double requireRegular(double[] a) {
        double det = a[0] * (a[5] * a[10] - a[6] * a[9]) + a[1] * (a[6] * a[8] - a[4] * a[10])
                + a[2] * (a[4] * a[9] - a[5] * a[8]);
        double largest = 0;
        for (int i = 0; i < 12; i++)
            if (i % 4 != 3)
                largest = Math.max(largest, Math.abs(a[i]));
        if (!Double.isFinite(det) || Math.abs(det) <= SINGULAR * largest * largest * largest)
            throw new IllegalArgumentException("the transform is singular (determinant " + det
                    + "): it flattens space, so it has no inverse");
        return det;
    }

    /** Equal when their matrices are equal number by number. */
    @Override
    public boolean equals(Object obj) {
        return this == obj || obj instanceof Transform other && Arrays.equals(m, other.m);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(m);
    }

    @Override
    public String toString() {
        return String.format("Transform[[%s %s %s | %s] [%s %s %s | %s] [%s %s %s | %s]]", m[0], m[1], m[2], m[3],
                m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11]);
    }
}
