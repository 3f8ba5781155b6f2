package accel;

import geometries.Geometry;
import geometries.TriangleMesh;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * One ray's numbers for a walk of the hierarchy: its origin, unit direction, the direction's inverse
 * and sign bits (set by {@link #invert}, for the slab test), the distance that counts, and the running
 * answer: the closest hit so far, or the transmittance so far and the product below which it is 0.
 * The bodies' own tests ({@link Geometry#nearestHit(RayState)}) read its ray through the accessors.
 */
public final class RayState {
    /** What {@link #boxEntry} answers for a ray that misses the box: no entry distance is negative. */
    public static final double MISSED = -1;

    double ox;
    double oy;
    double oz;
    double dx;
    double dy;
    double dz;
    double ix;
    double iy;
    double iz;
    /** The axes along which the ray goes backwards: bit 0 for x, 1 for y, 2 for z. */
    int negative;
    /** The distance that counts: in a closest-hit walk, the nearest hit so far. */
    double maxT;
    /** Below this transmittance the answer is 0. */
    double minK;
    /** The transmittance so far. */
    double ktr;
    /** The body of the closest hit so far, or null. */
    Geometry geometry;
    /** The part of {@link #geometry} hit (a mesh's triangle), or −1. */
    int part;
    /** Room for the data of a mesh's triangle under test, made at the first. */
    private double[] triangle;

    /**
     * Sets the ray.
     *
     * @param ox   the origin, x
     * @param oy   the origin, y
     * @param oz   the origin, z
     * @param dx   the unit direction, x
     * @param dy   the unit direction, y
     * @param dz   the unit direction, z
     * @param maxT the distance that counts
     * @return this ray
     */
    public RayState set(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        this.dx = dx;
        this.dy = dy;
        this.dz = dz;
        this.maxT = maxT;
        return this;
    }

    /**
     * {@return room for one triangle's data ({@link TriangleMesh#TRIANGLE_DATA} doubles), so that a
     * mesh's triangle is tested on the ray without an allocation after the first}
     */
    public double[] triangleScratch() {
        if (triangle == null)
            triangle = new double[TriangleMesh.TRIANGLE_DATA];
        return triangle;
    }

    /** {@return the ray as the course's {@link Ray}} */
    Ray toRay() {
        return new Ray(new Point3D(ox, oy, oz), new Vector(dx, dy, dz));
    }

    /** {@return the origin, x} */
    public double ox() {
        return ox;
    }

    /** {@return the origin, y} */
    public double oy() {
        return oy;
    }

    /** {@return the origin, z} */
    public double oz() {
        return oz;
    }

    /** {@return the unit direction, x} */
    public double dx() {
        return dx;
    }

    /** {@return the unit direction, y} */
    public double dy() {
        return dy;
    }

    /** {@return the unit direction, z} */
    public double dz() {
        return dz;
    }

    /** {@return the distance that counts: a body's hit beyond it is none} */
    public double maxT() {
        return maxT;
    }

    /**
     * Sets the inverse of the direction and its sign bits, for {@link #boxEntry}.
     *
     * @return this ray
     */
    public RayState invert() {
        ix = 1 / dx;
        iy = 1 / dy;
        iz = 1 / dz;
        negative = (dx < 0 ? 1 : 0) | (dy < 0 ? 2 : 0) | (dz < 0 ? 4 : 0);
        return this;
    }

    /**
     * Where the ray enters a box between its origin and a distance, or {@link #MISSED}: the slab test
     * ({@link #slabEntry}) on the box's numbers. Needs {@link #invert}.
     *
     * @param box  the boxes: x0, y0, z0, x1, y1, z1 each
     * @param b    where the box lies in it
     * @param maxT the largest distance that counts
     * @return the distance (0 or more) where the ray enters the box, or {@link #MISSED}
     */
    public double boxEntry(double[] box, int b, double maxT) {
        return slabEntry(box[b], box[b + 1], box[b + 2], box[b + 3], box[b + 4], box[b + 5], maxT);
    }

    /** {@link #boxEntry(double[], int, double)} for boxes in floats (a node's). */
    double boxEntry(float[] box, int b, double maxT) {
        return slabEntry(box[b], box[b + 1], box[b + 2], box[b + 3], box[b + 4], box[b + 5], maxT);
    }

    /**
     * Where the ray enters a box [x0, x1] × [y0, y1] × [z0, z1] between its origin and maxT (the slab
     * test), or {@link #MISSED} when it does not meet the box there. Each slab is entered at its near
     * face (the low one for a positive direction component, so for +0.0, and the high one for a
     * negative component, so for −0.0) and left at the far one. The slabs' intervals are intersected
     * with {@link Math#max} and {@link Math#min}, which the JIT compiles without branches (a ray's
     * box tests are hard to predict). A direction component of ±0 makes the inverse ±∞: a ray outside
     * the slab then gets an empty interval, one inside it (−∞, +∞), and one lying exactly in a face's
     * plane gets 0·∞ = NaN there, which the min and max carry to the answer; only then is the test
     * made again by {@link #slabEntrySkippingNaN}. Small enough for the JIT to inline into every walk.
     */
    private double slabEntry(double x0, double y0, double z0, double x1, double y1, double z1, double maxT) {
        double ix = this.ix;
        double iy = this.iy;
        double iz = this.iz;
        double nearX = ((ix < 0 ? x1 : x0) - ox) * ix;
        double farX = ((ix < 0 ? x0 : x1) - ox) * ix;
        double nearY = ((iy < 0 ? y1 : y0) - oy) * iy;
        double farY = ((iy < 0 ? y0 : y1) - oy) * iy;
        double nearZ = ((iz < 0 ? z1 : z0) - oz) * iz;
        double farZ = ((iz < 0 ? z0 : z1) - oz) * iz;
        double near = Math.max(Math.max(nearX, nearY), Math.max(nearZ, 0));
        double far = Math.min(Math.min(farX, farY), Math.min(farZ, maxT));
        if (near <= far)
            return near;
        return near == near && far == far ? MISSED : slabEntrySkippingNaN(nearX, farX, nearY, farY, nearZ, farZ, maxT);
    }

    /**
     * {@link #slabEntry} for a ray lying exactly in a face's plane, from the slabs' entry and exit
     * distances: the comparisons skip a slab's NaN, so the slab (closed) does not restrict the interval.
     */
    private static double slabEntrySkippingNaN(double nearX, double farX, double nearY, double farY, double nearZ,
                                               double farZ, double maxT) {
        double near = nearX > 0 ? nearX : 0;
        double far = farX < maxT ? farX : maxT;
        near = nearY > near ? nearY : near;
        far = farY < far ? farY : far;
        near = nearZ > near ? nearZ : near;
        far = farZ < far ? farZ : far;
        return near <= far ? near : MISSED;
    }

    /**
     * Starts a transmittance: 1 so far.
     *
     * @param minK below this product the answer is 0
     */
    void startTransmittance(double minK) {
        this.minK = minK;
        this.ktr = 1;
    }

    /** Multiplies the transmittance by a factor; false once the light is blocked (below minK or 0). */
    boolean attenuate(double factor) {
        ktr *= factor;
        return ktr > 0 && ktr >= minK;
    }

    /**
     * Multiplies the transmittance by a body's transparency along the ray up to its distance.
     *
     * @return false once the light is blocked (below minK or 0)
     */
    boolean attenuateBy(Geometry body) {
        return attenuate(body.transmittance(this));
    }

    /** Starts a closest-hit query: nothing hit yet, up to the ray's distance ({@link Geometry#NO_HIT} for any hit). */
    void startClosestHit() {
        geometry = null;
    }

    /**
     * Sets this ray as another seen in the space of an affine map (an instance's body's, from the
     * world), its distance carried along: the origin mapped, the direction mapped and normalised. A
     * distance t along the other ray is then t · scale along this one.
     *
     * @param ray the ray to map
     * @param m   the map's 12 numbers, row-major 3 × 4 (see {@link primitives.Transform#toArray})
     * @return the scale: the length of the mapped direction
     */
    double setMapped(RayState ray, double[] m) {
        double x = ray.ox;
        double y = ray.oy;
        double z = ray.oz;
        ox = m[0] * x + m[1] * y + m[2] * z + m[3];
        oy = m[4] * x + m[5] * y + m[6] * z + m[7];
        oz = m[8] * x + m[9] * y + m[10] * z + m[11];
        x = ray.dx;
        y = ray.dy;
        z = ray.dz;
        double lx = m[0] * x + m[1] * y + m[2] * z;
        double ly = m[4] * x + m[5] * y + m[6] * z;
        double lz = m[8] * x + m[9] * y + m[10] * z;
        double scale = Math.sqrt(lx * lx + ly * ly + lz * lz);
        dx = lx / scale;
        dy = ly / scale;
        dz = lz / scale;
        maxT = ray.maxT * scale;
        return scale;
    }

    /** Keeps a body (and its part, or −1) hit at distance t when it is nearer than the nearest so far. */
    void keepNearer(double t, Geometry body, int part) {
        if (t < maxT) {
            maxT = t;
            geometry = body;
            this.part = part;
        }
    }
}
