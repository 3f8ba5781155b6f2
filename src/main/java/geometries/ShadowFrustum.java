package geometries;

/**
 * The pyramid a bundle of shadow rays sweeps: every ray leaves one origin (the apex) and ends on a
 * parallelogram (a light's square, the base). A box or a plane that the pyramid does not meet meets
 * none of the rays, so a hierarchy can set bodies aside for the whole bundle at once: the frustum
 * culling of packet ray tracers.
 * <p>
 * The pyramid may have a thickness: rays that start up to that far from the apex and end as far
 * from the base (shadow rays moved off the surface on either side of it) stay within that distance
 * of the pyramid. The tests are conservative: a body is set aside only when it is outside the
 * pyramid by more than the thickness plus a margin (a small fraction of the pyramid's size), so
 * rounding in the rays' own arithmetic never hides a blocker. An instance is scratch space, set
 * again for every bundle, and used by one thread.
 */
public final class ShadowFrustum {
    /** How far outside, relative to the pyramid's size, a box or plane must be to be set aside. */
    private static final double MARGIN = 1e-7;
    /** How near, relative to the pyramid's size, an inner point may come to a face before the pyramid counts as flat. */
    private static final double FLAT = 1e-9;
    private static final int PLANES = 5;

    /** The four sides and the base, as (unit outward normal, offset): outside where n·x − offset > margin. */
    private final double[] planes = new double[4 * PLANES];
    /** The apex and the four corners of the base, three coordinates each. */
    private final double[] vertices = new double[15];
    /** The box around the vertices, {minX, minY, minZ, maxX, maxY, maxZ}. */
    private final double[] hull = new double[6];
    /** The thickness plus the margin: how far outside a face a box or plane must be. */
    private double margin;
    /** The least distance of an inner point from a face, below which the pyramid counts as flat. */
    private double flatness;
    /** Whether the last {@link #set} succeeded: until one does, every box and plane may meet the pyramid. */
    private boolean valid;

    /** Creates the scratch space of a pyramid; {@link #set} places it. */
    public ShadowFrustum() {
    }

    /**
     * Sets the pyramid from an apex to the parallelogram c ± a ± b.
     *
     * @param ox the apex, x
     * @param oy the apex, y
     * @param oz the apex, z
     * @param cx the centre of the base, x
     * @param cy the centre of the base, y
     * @param cz the centre of the base, z
     * @param ax half of one side of the base, x
     * @param ay half of one side of the base, y
     * @param az half of one side of the base, z
     * @param bx half of the other side of the base, x
     * @param by half of the other side of the base, y
     * @param bz half of the other side of the base, z
     * @param thickness how far the rays may stray from the pyramid, 0 or more
     * @return false when the pyramid is flat (the apex in the base's plane, or a degenerate base):
     *         it then sets nothing aside
     * @throws IllegalArgumentException when the thickness is negative or not a number
     */
    public boolean set(double ox, double oy, double oz, double cx, double cy, double cz,
                       double ax, double ay, double az, double bx, double by, double bz, double thickness) {
        if (!(thickness >= 0))
            throw new IllegalArgumentException("the thickness of a shadow frustum must be 0 or more, got " + thickness);
        setVertex(0, ox, oy, oz);
        setVertex(1, cx + ax + bx, cy + ay + by, cz + az + bz);
        setVertex(2, cx - ax + bx, cy - ay + by, cz - az + bz);
        setVertex(3, cx - ax - bx, cy - ay - by, cz - az - bz);
        setVertex(4, cx + ax - bx, cy + ay - by, cz + az - bz);
        double size = setHull();
        margin = MARGIN * size + thickness;
        flatness = FLAT * size;
        valid = false;
        for (int side = 0; side < 4; ++side)
            if (!setPlane(side, 1 + side, 1 + (side + 1) % 4, cx, cy, cz))
                return false;
        double nx = ay * bz - az * by;
        double ny = az * bx - ax * bz;
        double nz = ax * by - ay * bx;
        valid = setPlane(4, nx, ny, nz, nx * cx + ny * cy + nz * cz, ox, oy, oz);
        return valid;
    }

    /**
     * Sets the box around the vertices.
     *
     * @return the pyramid's size: its largest coordinate plus the box's three extents
     */
    private double setHull() {
        double size = 0;
        for (int k = 0; k < 3; ++k) {
            hull[k] = Double.POSITIVE_INFINITY;
            hull[3 + k] = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < 5; ++i) {
                double x = vertices[3 * i + k];
                hull[k] = Math.min(hull[k], x);
                hull[3 + k] = Math.max(hull[3 + k], x);
                size = Math.max(size, Math.abs(x));
            }
        }
        for (int k = 0; k < 3; ++k)
            size += hull[3 + k] - hull[k];
        return size;
    }

    private void setVertex(int i, double x, double y, double z) {
        vertices[3 * i] = x;
        vertices[3 * i + 1] = y;
        vertices[3 * i + 2] = z;
    }

    /** The side through the apex and two neighbouring corners, facing away from the base's centre. */
    private boolean setPlane(int side, int i, int j, double cx, double cy, double cz) {
        double[] v = vertices;
        double ix = v[3 * i] - v[0];
        double iy = v[3 * i + 1] - v[1];
        double iz = v[3 * i + 2] - v[2];
        double jx = v[3 * j] - v[0];
        double jy = v[3 * j + 1] - v[1];
        double jz = v[3 * j + 2] - v[2];
        double nx = iy * jz - iz * jy;
        double ny = iz * jx - ix * jz;
        double nz = ix * jy - iy * jx;
        return setPlane(side, nx, ny, nz, nx * v[0] + ny * v[1] + nz * v[2], cx, cy, cz);
    }

    /**
     * Stores a plane n·x = offset, normalised and turned so that a given inner point is inside.
     *
     * @return false when the plane is degenerate or the inner point (nearly) on it
     */
    private boolean setPlane(int plane, double nx, double ny, double nz, double offset, double x, double y,
                             double z) {
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(length > 0))
            return false;
        double distance = (nx * x + ny * y + nz * z - offset) / length;
        if (!(Math.abs(distance) > flatness))
            return false;
        double scale = distance > 0 ? -1 / length : 1 / length;
        int p = 4 * plane;
        planes[p] = nx * scale;
        planes[p + 1] = ny * scale;
        planes[p + 2] = nz * scale;
        planes[p + 3] = offset * scale;
        return true;
    }

    /**
     * Whether an axis-aligned box may meet the pyramid.
     *
     * @param boxes  an array of boxes, {minX, minY, minZ, maxX, maxY, maxZ} each
     * @param offset where the box starts in the array
     * @return false only when the box lies outside the pyramid by more than the thickness and margin
     *         (never after a refused {@link #set})
     */
    public boolean meetsBox(double[] boxes, int offset) {
        return meetsBox(boxes[offset], boxes[offset + 1], boxes[offset + 2], boxes[offset + 3], boxes[offset + 4],
                boxes[offset + 5]);
    }

    /**
     * {@link #meetsBox(double[], int)} for a box kept in floats.
     *
     * @param boxes  an array of boxes, {minX, minY, minZ, maxX, maxY, maxZ} each
     * @param offset where the box starts in the array
     * @return false only when the box lies outside the pyramid by more than the thickness and margin
     *         (never after a refused {@link #set})
     */
    public boolean meetsBox(float[] boxes, int offset) {
        return meetsBox(boxes[offset], boxes[offset + 1], boxes[offset + 2], boxes[offset + 3], boxes[offset + 4],
                boxes[offset + 5]);
    }

    /** Whether the box from (x0, y0, z0) to (x1, y1, z1) may meet the pyramid, see {@link #meetsBox(double[], int)}. */
    private boolean meetsBox(double x0, double y0, double z0, double x1, double y1, double z1) {
        if (!valid)
            return true;
        double m = margin;
        double[] h = hull;
        if (x0 > h[3] + m || y0 > h[4] + m || z0 > h[5] + m || x1 < h[0] - m || y1 < h[1] - m || z1 < h[2] - m)
            return false;
        double[] pl = planes;
        for (int p = 0; p < 4 * PLANES; p += 4) {
            double nx = pl[p];
            double ny = pl[p + 1];
            double nz = pl[p + 2];
            // the box's corner farthest inside the plane
            double x = nx > 0 ? x0 : x1;
            double y = ny > 0 ? y0 : y1;
            double z = nz > 0 ? z0 : z1;
            if (nx * x + ny * y + nz * z - pl[p + 3] > m)
                return false;
        }
        return true;
    }

    /**
     * Whether a triangle, as the renderer's closed test takes it (grown by {@link Triangle}'s
     * barycentric tolerance: each vertex p moved by τ·((p − q) + (p − r)), q and r the other two),
     * may meet the pyramid. It is set aside when its three grown vertices lie outside one face of the
     * pyramid (a side or the base) by more than the thickness and margin: the triangle, their convex
     * hull, then lies outside it too.
     *
     * @param vertices the coordinates of the vertices, three doubles each
     * @param p1       where the first vertex's x lies in vertices
     * @param p2       where the second vertex's x lies
     * @param p3       where the third vertex's x lies
     * @return false only when no ray of the bundle can meet the triangle (never after a refused
     *         {@link #set})
     */
    public boolean meetsTriangle(double[] vertices, int p1, int p2, int p3) {
        if (!valid)
            return true;
        double[] pl = planes;
        for (int p = 0; p < 4 * PLANES; p += 4)
            if (outside(pl[p], pl[p + 1], pl[p + 2], pl[p + 3], vertices, p1, p2, p3))
                return false;
        return true;
    }

    /**
     * Whether the three grown vertices of a triangle (see {@link #meetsTriangle}) lie outside a face
     * n·x = offset by more than the margin. A grown vertex's distance follows from the vertices'
     * distances, the distance being affine.
     */
    private boolean outside(double nx, double ny, double nz, double offset, double[] vertices, int p1, int p2,
                            int p3) {
        double d1 = nx * vertices[p1] + ny * vertices[p1 + 1] + nz * vertices[p1 + 2] - offset;
        double d2 = nx * vertices[p2] + ny * vertices[p2 + 1] + nz * vertices[p2 + 2] - offset;
        double d3 = nx * vertices[p3] + ny * vertices[p3 + 1] + nz * vertices[p3 + 2] - offset;
        double tau = Triangle.BARYCENTRIC_TOLERANCE;
        double m = margin;
        return d1 + tau * ((d1 - d2) + (d1 - d3)) > m && d2 + tau * ((d2 - d1) + (d2 - d3)) > m
                && d3 + tau * ((d3 - d1) + (d3 - d2)) > m;
    }

    /**
     * Whether a plane may meet the pyramid.
     *
     * @param nx the plane's unit normal, x
     * @param ny the plane's unit normal, y
     * @param nz the plane's unit normal, z
     * @param qx a point on the plane, x
     * @param qy a point on the plane, y
     * @param qz a point on the plane, z
     * @return false only when all of the pyramid lies on one side of the plane, farther than the
     *         thickness and margin (never after a refused {@link #set})
     */
    public boolean meetsPlane(double nx, double ny, double nz, double qx, double qy, double qz) {
        if (!valid)
            return true;
        double[] v = vertices;
        boolean above = false;
        boolean below = false;
        for (int i = 0; i < 15; i += 3) {
            double d = nx * (v[i] - qx) + ny * (v[i + 1] - qy) + nz * (v[i + 2] - qz);
            above |= d >= -margin;
            below |= d <= margin;
        }
        return above && below;
    }
}
