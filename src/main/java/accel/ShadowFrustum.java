package accel;

import geometries.Triangle;
import geometries.Plane;
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
 * <p>
 * The surface the rays leave lies around the apex, where no face of the pyramid sets it aside: a
 * back face ({@link #setBackFace}) does when every ray leaves the surface on one side, and the rays'
 * two ray origins ({@link #setOrigins}) do when they leave it on both sides.
 * <p>
 * Whether the pyramid passes through a closed mesh's core, and the mesh blocks the whole bundle, is
 * told by {@link CoreCrossing} from the pyramid's vertices and margin.
 */
public final class ShadowFrustum {
    /** How far outside, relative to the pyramid's size, a box or plane must be to be set aside. */
    private static final double MARGIN = 1e-7;
    /** How near, relative to the pyramid's size, an inner point may come to a face before the pyramid counts as flat. */
    private static final double FLAT = 1e-9;
    /** What {@link #originOf} answers for a ray that starts at p + n and leaves to n's side. */
    static final int ABOVE = 1;
    /** What {@link #originOf} answers for a ray that starts at p − n and leaves to the other side. */
    static final int BELOW = 2;
    /** The pyramid's faces: four sides and the base. */
    private static final int PLANES = 5;
    /** The states of {@link #backFace}. */
    private static final int NO_BACK_FACE = 0;
    private static final int BACK_FACE_ASKED = 1;
    private static final int BACK_FACE_PLACED = 2;

    /**
     * The four sides and the base, then the back face ({@link #setBackFace}), as (unit outward normal,
     * offset): outside where n·x − offset > margin.
     */
    private final double[] planes = new double[4 * (PLANES + 1)];
    /** The back face since the last {@link #set}: none, asked for but not placed yet, or placed in {@link #planes}. */
    private int backFace;
    /** The direction of the back face asked for ({@link #setBackFace}). */
    private double backX;
    private double backY;
    private double backZ;
    /** The apex and the four corners of the base, three coordinates each. */
    private final double[] vertices = new double[15];
    /** The box around the vertices, {minX, minY, minZ, maxX, maxY, maxZ}. */
    private final double[] hull = new double[6];
    /** How far the rays may stray from the pyramid, as the last {@link #set} was given it. */
    private double thickness;
    /** The thickness plus the margin: how far outside a face a box or plane must be. */
    private double margin;
    /** The margin alone, for rounding: how far behind a ray's origin a triangle must be ({@link RayOrigins#behind}). */
    private double rounding;
    /** The rays' two origins when they leave a surface on both sides ({@link #setOrigins}). */
    private final RayOrigins origins = new RayOrigins();
    /** The least distance of an inner point from a face, below which the pyramid counts as flat. */
    private double flatness;
    /** Whether the last {@link #set} succeeded: until one does, every box and plane may meet the pyramid. */
    private boolean valid;
    /** How many times the pyramid was changed ({@link #set}, a back face or ray origins told): see {@link #serial}. */
    private long serial;

    /** Creates the scratch space of a pyramid; {@link #set} places it. */
    public ShadowFrustum() {
    }

    /**
     * Sets the pyramid from an apex to the parallelogram c ± a ± b.
     *
     * @param apex      the apex: x, y, z
     * @param base      the base: its centre c, half of one side a and half of the other side b, three
     *                  coordinates each (cx, cy, cz, ax, ay, az, bx, by, bz)
     * @param thickness how far the rays may stray from the pyramid, 0 or more
     * @return false when the pyramid is flat (the apex in the base's plane, or a degenerate base):
     *         it then sets nothing aside
     * @throws IllegalArgumentException when the apex does not have 3 numbers or the base 9, or the
     *                                  thickness is negative or not a number
     */
    public boolean set(double[] apex, double[] base, double thickness) {
        if (apex == null || apex.length != 3)
            throw new IllegalArgumentException("the apex of a shadow frustum must have 3 coordinates");
        if (base == null || base.length != 9)
            throw new IllegalArgumentException("the base of a shadow frustum must have 9 numbers: c, a and b");
        if (!(thickness >= 0))
            throw new IllegalArgumentException("the thickness of a shadow frustum must be 0 or more, got " + thickness);
        ++serial;
        setVertices(apex, base);
        this.thickness = thickness;
        double size = setHull();
        rounding = MARGIN * size;
        margin = rounding + thickness;
        origins.clear();
        flatness = FLAT * size;
        valid = false;
        for (int side = 0; side < 4; ++side)
            if (!setSide(side, 1 + side, 1 + (side + 1) % 4, base))
                return false;
        double nx = base[4] * base[8] - base[5] * base[7];
        double ny = base[5] * base[6] - base[3] * base[8];
        double nz = base[3] * base[7] - base[4] * base[6];
        storePlane(4, nx, ny, nz, nx * base[0] + ny * base[1] + nz * base[2]);
        valid = orientPlane(4, vertices, 0);
        backFace = NO_BACK_FACE;
        return valid;
    }

    /** Sets the apex and the base's corners c + a + b, c − a + b, c − a − b and c + a − b, in that order. */
    private void setVertices(double[] apex, double[] base) {
        System.arraycopy(apex, 0, vertices, 0, 3);
        for (int k = 0; k < 3; ++k) {
            double c = base[k];
            double a = base[3 + k];
            double b = base[6 + k];
            vertices[3 + k] = c + a + b;
            vertices[6 + k] = c - a + b;
            vertices[9 + k] = c - a - b;
            vertices[12 + k] = c + a - b;
        }
    }

    /**
     * Asks for a back face of the pyramid of the last {@link #set}: the plane through the apex across a
     * direction, set when the whole base lies ahead of it along that direction by more than the margin.
     * The pyramid lies ahead of that plane, so what lies behind it by more than the thickness and
     * margin meets no ray: the surface a bundle of shadow rays leaves, seen from an apex a little off
     * it, with the normal as the direction. Plane-by-plane tests miss such a triangle when it lies
     * around the apex, outside the pyramid but not outside any one of its other faces. The back face
     * sets triangles aside ({@link #meetsTriangle}), not boxes: a box of the surface's triangles
     * around the apex mostly reaches over the plane, and every box would pay a sixth test. It is placed
     * when first needed ({@link #hasBackFace}), so a bundle that meets no triangle does not pay for it.
     * The next {@link #set} takes the back face away.
     *
     * @param nx the direction, x
     * @param ny the direction, y
     * @param nz the direction, z
     */
    public void setBackFace(double nx, double ny, double nz) {
        ++serial;
        backX = nx;
        backY = ny;
        backZ = nz;
        backFace = BACK_FACE_ASKED;
    }

    /**
     * Whether the pyramid has a back face: one was asked for since the last {@link #set}
     * ({@link #setBackFace}) and could be placed, the pyramid set, the direction a finite non-zero
     * vector and the base ahead of the plane. Places it on the first call after it is asked for.
     *
     * @return true when the back face is placed
     */
    public boolean hasBackFace() {
        if (backFace == BACK_FACE_ASKED)
            backFace = placeBackFace() ? BACK_FACE_PLACED : NO_BACK_FACE;
        return backFace == BACK_FACE_PLACED;
    }

    /** Places the back face asked for in {@link #planes}; false, placing nothing, when it cannot be. */
    private boolean placeBackFace() {
        double length = Math.sqrt(backX * backX + backY * backY + backZ * backZ);
        if (!valid || !(length > 0) || length == Double.POSITIVE_INFINITY)
            return false;
        double inverse = 1 / length;
        double ux = backX * inverse;
        double uy = backY * inverse;
        double uz = backZ * inverse;
        double[] v = vertices;
        for (int i = 3; i < 15; i += 3)
            if (!(ux * (v[i] - v[0]) + uy * (v[i + 1] - v[1]) + uz * (v[i + 2] - v[2]) > margin))
                return false;
        int p = 4 * PLANES;
        planes[p] = -ux;
        planes[p + 1] = -uy;
        planes[p + 2] = -uz;
        planes[p + 3] = -(ux * v[0] + uy * v[1] + uz * v[2]);
        return true;
    }

    /**
     * Sets the box around the vertices.
     *
     * @return the pyramid's size: its largest coordinate plus the box's three extents
     */
    private double setHull() {
        // comparisons, not Math.min and Math.max: C2's intrinsics for doubles cost several times more
        double size = 0;
        for (int k = 0; k < 3; ++k) {
            double low = vertices[k];
            double high = low;
            for (int i = 3 + k; i < 15; i += 3) {
                double x = vertices[i];
                low = x < low ? x : low;
                high = x > high ? x : high;
            }
            hull[k] = low;
            hull[3 + k] = high;
            double reach = high > -low ? high : -low;
            size = reach > size ? reach : size;
        }
        for (int k = 0; k < 3; ++k)
            size += hull[3 + k] - hull[k];
        return size;
    }

    /** The side through the apex and two neighbouring corners, facing away from the base's centre (its first three numbers). */
    private boolean setSide(int side, int i, int j, double[] base) {
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
        storePlane(side, nx, ny, nz, nx * v[0] + ny * v[1] + nz * v[2]);
        return orientPlane(side, base, 0);
    }

    /** Stores a plane n·x = offset at its place in {@link #planes}, as it comes: {@link #orientPlane} places it. */
    private void storePlane(int plane, double nx, double ny, double nz, double offset) {
        int p = 4 * plane;
        planes[p] = nx;
        planes[p + 1] = ny;
        planes[p + 2] = nz;
        planes[p + 3] = offset;
    }

    /**
     * Normalises a plane {@link #storePlane stored} and turns it so that an inner point is inside.
     *
     * @param plane the plane
     * @param inner the inner point's array
     * @param at    where its three coordinates start
     * @return false when the plane is degenerate or the inner point (nearly) on it
     */
    private boolean orientPlane(int plane, double[] inner, int at) {
        int p = 4 * plane;
        double nx = planes[p];
        double ny = planes[p + 1];
        double nz = planes[p + 2];
        double offset = planes[p + 3];
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(length > 0))
            return false;
        double distance = (nx * inner[at] + ny * inner[at + 1] + nz * inner[at + 2] - offset) / length;
        if (!(Math.abs(distance) > flatness))
            return false;
        double scale = distance > 0 ? -1 / length : 1 / length;
        planes[p] = nx * scale;
        planes[p + 1] = ny * scale;
        planes[p + 2] = nz * scale;
        planes[p + 3] = offset * scale;
        return true;
    }

    /**
     * Tells the pyramid the surface a bundle of shadow rays leaves, as a renderer moves their origins
     * off it: by a vector n on the side each ray leaves to. When all the rays leave to one side, they
     * start at the apex and the back face across n (or −n) is asked for ({@link #setBackFace}); when
     * they leave to both, the ray origins are set ({@link #setOrigins}).
     *
     * @param side 1 when every ray leaves to n's side, −1 when every ray leaves to the other, 0 when
     *             they leave to both
     * @param px   the point p the rays leave, x
     * @param py   the same for y
     * @param pz   the same for z
     * @param nx   the offset n of the ray origins, x
     * @param ny   the same for y
     * @param nz   the same for z
     */
    public void setLeaving(int side, double px, double py, double pz, double nx, double ny, double nz) {
        if (side != 0)
            setBackFace(side * nx, side * ny, side * nz);
        else
            setOrigins(px, py, pz, nx, ny, nz);
    }

    /**
     * Tells where the bundle's rays start, when they leave a surface on both sides of it (the pyramid's
     * base straddles the surface's plane, and no back face can be set): a ray that leaves to the side
     * a vector n points to starts at p + n, one that leaves to the other side at p − n, one along the
     * surface at p. A triangle of the surface around p then lies behind each of the two ray origins, and
     * the rays from there need not test it ({@link #originsBehind}, {@link #originOf}): a hierarchy
     * leaves it out of the bundle ({@link #behindOrigins}) and traces a ray from neither origin alone.
     * The next {@link #set} forgets the ray origins.
     *
     * @param px the point p the rays leave, x
     * @param py the same for y
     * @param pz the same for z
     * @param nx the offset n of the ray origins, x
     * @param ny the same for y
     * @param nz the same for z
     */
    public void setOrigins(double px, double py, double pz, double nx, double ny, double nz) {
        ++serial;
        origins.set(px, py, pz, nx, ny, nz);
    }

    /** {@return where a ray of the bundle starts: {@link #ABOVE}, {@link #BELOW} or 0, see {@link RayOrigins#originOf}} */
    int originOf(double ox, double oy, double oz, double dx, double dy, double dz) {
        return origins.originOf(ox, oy, oz, dx, dy, dz);
    }

    /**
     * {@return the ray origins a triangle lies behind, see {@link RayOrigins#behind(double[], int, double)}:
     * its data, p1, e1 and e2, at data[at]}
     */
    int originsBehind(double[] data, int at) {
        return origins.behind(data, at, rounding);
    }

    /** {@return whether a triangle lies behind both ray origins, see {@link RayOrigins#behindBoth}} */
    boolean behindOrigins(double[] vertices, int p1, int p2, int p3) {
        return origins.behindBoth(vertices, p1, p2, p3, rounding);
    }

    /**
     * {@return whether {@link #behindOrigins} has set a triangle aside since the ray origins were set: a ray
     * from neither origin may still meet it, so the bundle is not open}
     */
    boolean leftBehindOrigins() {
        return origins.leftBehind();
    }

    /** {@return whether ray origins are set ({@link #setOrigins}): a ray from neither then tests every body} */
    boolean hasOrigins() {
        return origins.isSet();
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

    /** {@return the apex and the four corners of the base, three coordinates each: the frustum's own array, not to be changed} */
    double[] vertices() {
        return vertices;
    }

    /** {@return the thickness plus the margin: how far inside a body's core a ray must pass to count} */
    double margin() {
        return margin;
    }

    /** {@return how far the rays may stray from the pyramid, as the last {@link #set} was given it} */
    double thickness() {
        return thickness;
    }

    /**
     * The direction of the back face asked for since the last {@link #set} ({@link #setBackFace}).
     *
     * @param direction where its three numbers go
     * @return false, with nothing written, when none was asked for, or it could not be placed
     */
    boolean backFaceDirection(double[] direction) {
        if (backFace == NO_BACK_FACE)
            return false;
        direction[0] = backX;
        direction[1] = backY;
        direction[2] = backZ;
        return true;
    }

    /** {@return whether the last {@link #set} succeeded} */
    boolean isSet() {
        return valid;
    }

    /** {@return a number that changes whenever the pyramid does: what was found for it holds while it stays} */
    long serial() {
        return serial;
    }

    /**
     * How far beyond the base's plane a box reaches: the largest signed distance of its corners from the
     * plane, negative when the whole box lies on the apex's side.
     *
     * @param boxes  an array of boxes, {minX, minY, minZ, maxX, maxY, maxZ} each
     * @param offset where the box starts in the array
     * @return the distance
     */
    double beyondBase(double[] boxes, int offset) {
        int p = 4 * (PLANES - 1);
        double farthest = -planes[p + 3];
        for (int k = 0; k < 3; ++k)
            farthest += planes[p + k] * boxes[offset + (planes[p + k] > 0 ? 3 : 0) + k];
        return farthest;
    }

    /** Whether the box from (x0, y0, z0) to (x1, y1, z1) may meet the pyramid, see {@link #meetsBox(double[], int)}. */
    private boolean meetsBox(double x0, double y0, double z0, double x1, double y1, double z1) {
        if (!valid)
            return true;
        double m = margin;
        double[] h = hull;
        // one branch for the six tests (| evaluates them all): their outcomes are hard to predict
        if (x0 > h[3] + m | y0 > h[4] + m | z0 > h[5] + m | x1 < h[0] - m | y1 < h[1] - m | z1 < h[2] - m)
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
     * pyramid (a side, the base, or the back face when set) by more than the thickness and margin: the
     * triangle, their convex hull, then lies outside it too. When the rays' origins are set, a triangle
     * behind both is set aside as well ({@link #behindOrigins}): only a ray from neither may meet it.
     *
     * @param vertices the coordinates of the vertices, three doubles each
     * @param p1       where the first vertex's x lies in vertices
     * @param p2       where the second vertex's x lies
     * @param p3       where the third vertex's x lies
     * @return false only when no ray of the bundle from its apex or its ray origins can meet the triangle
     *         (never after a refused {@link #set}, unless ray origins were set since)
     */
    public boolean meetsTriangle(double[] vertices, int p1, int p2, int p3) {
        if (behindOrigins(vertices, p1, p2, p3))
            return false;
        if (!valid)
            return true;
        if (hasBackFace() && outside(PLANES, vertices, p1, p2, p3))
            return false; // first: it sets aside the many triangles around the apex
        for (int plane = 0; plane < PLANES; ++plane)
            if (outside(plane, vertices, p1, p2, p3))
                return false;
        return true;
    }

    /**
     * Whether the three grown vertices of a triangle (see {@link #meetsTriangle}) lie outside a face
     * n·x = offset by more than the margin. A grown vertex's distance follows from the vertices'
     * distances, the distance being affine.
     */
    private boolean outside(int plane, double[] vertices, int p1, int p2, int p3) {
        int p = 4 * plane;
        double nx = planes[p];
        double ny = planes[p + 1];
        double nz = planes[p + 2];
        double offset = planes[p + 3];
        double d1 = nx * vertices[p1] + ny * vertices[p1 + 1] + nz * vertices[p1 + 2] - offset;
        double d2 = nx * vertices[p2] + ny * vertices[p2 + 1] + nz * vertices[p2 + 2] - offset;
        double d3 = nx * vertices[p3] + ny * vertices[p3 + 1] + nz * vertices[p3 + 2] - offset;
        double m = margin;
        return grown(d1, d2, d3) > m && grown(d2, d1, d3) > m && grown(d3, d1, d2) > m;
    }

    /**
     * The distance of a triangle's vertex from a plane once the triangle is grown by {@link Triangle}'s
     * barycentric tolerance τ (the vertex p moved by τ·((p − q) + (p − r))): the distance is affine.
     *
     * @param d     the vertex's distance
     * @param other the distance of another vertex
     * @param third the distance of the third
     * @return the grown vertex's distance
     */
    static double grown(double d, double other, double third) {
        return d + Triangle.BARYCENTRIC_TOLERANCE * ((d - other) + (d - third));
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
