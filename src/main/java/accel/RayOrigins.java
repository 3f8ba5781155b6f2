package accel;

import static accel.ShadowFrustum.ABOVE;
import static accel.ShadowFrustum.BELOW;

/**
 * The two origins of a bundle's shadow rays when they leave a surface on both sides of it (see
 * {@link ShadowFrustum#setOrigins}): a ray that leaves to the side a vector n points to starts at
 * p + n, one that leaves to the other side at p − n. A triangle of the surface around p lies behind
 * both, and the rays from there need not test it; a ray from neither (one along the surface) tests
 * every body. Scratch space of one {@link ShadowFrustum}.
 */
final class RayOrigins {
    /** Whether origins are set, the point p and offset n they were given, and whether a triangle was set aside since. */
    private boolean set;
    private boolean leftBehind;
    private double originX;
    private double originY;
    private double originZ;
    private double offsetX;
    private double offsetY;
    private double offsetZ;

    /** Forgets the origins. */
    void clear() {
        set = false;
        leftBehind = false;
    }

    /** Sets the origins p ± n; a zero n sets none. */
    void set(double px, double py, double pz, double nx, double ny, double nz) {
        originX = px;
        originY = py;
        originZ = pz;
        offsetX = nx;
        offsetY = ny;
        offsetZ = nz;
        set = nx != 0 || ny != 0 || nz != 0;
        leftBehind = false;
    }

    /** {@return whether origins are set} */
    boolean isSet() {
        return set;
    }

    /** {@return whether {@link #behindBoth} has set a triangle aside since the origins were set} */
    boolean leftBehind() {
        return leftBehind;
    }

    /**
     * Where a ray starts.
     *
     * @return {@link ShadowFrustum#ABOVE} for a ray from exactly p + n that leaves to n's side,
     *         {@link ShadowFrustum#BELOW} for a ray from exactly p − n that leaves to the other side,
     *         else 0 (also when no origins are set)
     */
    int originOf(double ox, double oy, double oz, double dx, double dy, double dz) {
        if (!set)
            return 0;
        double side = dx * offsetX + dy * offsetY + dz * offsetZ;
        if (side > 0 && ox == originX + offsetX && oy == originY + offsetY && oz == originZ + offsetZ)
            return ABOVE;
        if (side < 0 && ox == originX - offsetX && oy == originY - offsetY && oz == originZ - offsetZ)
            return BELOW;
        return 0;
    }

    /**
     * The origins a triangle lies behind, grown as the renderer's test takes it (see
     * {@link ShadowFrustum#meetsTriangle}), by more than a rounding margin: behind the plane through
     * p + n across n, which a ray from there leaves forward, or behind the one through p − n across −n.
     * A ray from such an origin cannot meet the triangle.
     *
     * @param vertices the coordinates of the vertices, three doubles each
     * @param p1       where the first vertex's x lies in vertices
     * @param p2       where the second vertex's x lies
     * @param p3       where the third vertex's x lies
     * @param rounding the rounding margin
     * @return {@link ShadowFrustum#ABOVE}, {@link ShadowFrustum#BELOW}, both or 0 (always 0 when no
     *         origins are set)
     */
    int behind(double[] vertices, int p1, int p2, int p3, double rounding) {
        if (!set)
            return 0;
        double x = vertices[p1];
        double y = vertices[p1 + 1];
        double z = vertices[p1 + 2];
        return behind(along(x - originX, y - originY, z - originZ),
                along(vertices[p2] - x, vertices[p2 + 1] - y, vertices[p2 + 2] - z),
                along(vertices[p3] - x, vertices[p3 + 1] - y, vertices[p3 + 2] - z), rounding);
    }

    /**
     * The origins a triangle lies behind, as {@link #behind(double[], int, int, int, double)} finds
     * them, from the triangle's data: p1 and the edges e1 = p2 − p1 and e2 = p3 − p1 (the same numbers
     * as its vertices give, see {@link geometries.TriangleMesh#triangleData}).
     *
     * @param data     the triangle's data, three doubles each for p1, e1 and e2
     * @param at       where p1's x lies in data
     * @param rounding the rounding margin
     * @return {@link ShadowFrustum#ABOVE}, {@link ShadowFrustum#BELOW}, both or 0
     */
    int behind(double[] data, int at, double rounding) {
        if (!set)
            return 0;
        return behind(along(data[at] - originX, data[at + 1] - originY, data[at + 2] - originZ),
                along(data[at + 3], data[at + 4], data[at + 5]), along(data[at + 6], data[at + 7], data[at + 8]),
                rounding);
    }

    /**
     * Whether a triangle lies behind both origins, as {@link #behind} takes it: then only a ray that
     * starts at neither may meet it. Remembers that it said so ({@link #leftBehind}).
     *
     * @return true when it lies behind both (never when no origins are set)
     */
    boolean behindBoth(double[] vertices, int p1, int p2, int p3, double rounding) {
        boolean both = behind(vertices, p1, p2, p3, rounding) == (ABOVE | BELOW);
        leftBehind |= both;
        return both;
    }

    /** {@return the dot product of a vector with the offset n} */
    private double along(double x, double y, double z) {
        return x * offsetX + y * offsetY + z * offsetZ;
    }

    /**
     * The origins a triangle lies behind, from its first vertex's height h above p along n and its
     * edges' heights f and g (all times |n|), its vertices grown by the barycentric tolerance.
     */
    private int behind(double h, double f, double g, double rounding) {
        double h1 = ShadowFrustum.grown(h, h + f, h + g);
        double h2 = ShadowFrustum.grown(h + f, h, h + g);
        double h3 = ShadowFrustum.grown(h + g, h, h + f);
        double square = offsetX * offsetX + offsetY * offsetY + offsetZ * offsetZ;
        double slack = rounding * Math.sqrt(square);
        int behind = Math.max(h1, Math.max(h2, h3)) < square - slack ? ABOVE : 0;
        return Math.min(h1, Math.min(h2, h3)) > slack - square ? behind | BELOW : behind;
    }
}
