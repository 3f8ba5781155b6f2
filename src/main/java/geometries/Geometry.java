package geometries;

import accel.RayState;
import accel.ShadowFrustum;
import java.util.List;

import primitives.Color;
import primitives.Material;
import primitives.Texture;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.requireNonNull;

/**
 * A single body with a surface: it has an emission colour, a material and a normal at each point, and
 * may have a texture, looked up at the surface coordinates (u, v) of each point ({@link #getUV}).
 */
public abstract class Geometry extends Intersectable {
    /** What {@link #nearestHit} returns when the ray misses. */
    public static final double NO_HIT = Double.POSITIVE_INFINITY;

    private Color emission = Color.BLACK;
    private Material material = new Material();
    private Texture texture;

    /** Creates a body with black emission and the default material (all factors 0). */
    protected Geometry() {
    }

    /**
     * The unit normal of the surface at a point on it.
     *
     * @param point a point on the surface
     * @return the outward unit normal there
     * @throws IllegalArgumentException when the point is null, or the body has no normal there (the centre of
     *                                  a sphere, a point on a tube's axis)
     */
    public abstract Vector getNormal(Point3D point);

    /** {@return the emission colour (black by default)} */
    public Color getEmission() {
        return emission;
    }

    /**
     * Sets the emission colour.
     *
     * @param emission the colour the body emits
     * @return this geometry
     */
    public Geometry setEmission(Color emission) {
        this.emission = requireNonNull(emission, "emission colour");
        return this;
    }

    /** {@return the material (all factors 0 by default)} */
    public Material getMaterial() {
        return material;
    }

    /**
     * Sets the material.
     *
     * @param material the surface properties
     * @return this geometry
     */
    public Geometry setMaterial(Material material) {
        this.material = requireNonNull(material, "material");
        return this;
    }

    /** {@return the texture, or null when the body has none (one colour: its emission and material)} */
    public Texture getTexture() {
        return texture;
    }

    /**
     * Gives the body a texture: its colour at each point. The texture tints the diffuse reflection (the
     * texture's colour over 255 multiplies kD channel by channel), and the emission is the texture's
     * colour scaled by the body's emission (emission · colour / 255), so the texture shows in light and,
     * darker, in shadow.
     *
     * @param texture the texture
     * @return this geometry
     * @throws IllegalArgumentException when the texture is null or the body has no surface coordinates
     *                                  (a tube, a cylinder, a mesh without UVs)
     */
    public Geometry setTexture(Texture texture) {
        requireNonNull(texture, "texture");
        if (!hasUV())
            throw new IllegalArgumentException("a texture needs surface coordinates, and " + this + " has none"
                    + (this instanceof TriangleMesh ? " (give the mesh UVs first: setUVs, or an OBJ file with vt)" : ""));
        this.texture = texture;
        return this;
    }

    /**
     * Whether the body has surface coordinates for a texture ({@link #getUV}). The default says no.
     *
     * @return true when {@link #getUV} answers
     */
    protected boolean hasUV() {
        return false;
    }

    /**
     * The surface coordinates (u, v) of a point on the body, where a texture is looked up. The default
     * has none; bodies with them override this and {@link #hasUV}.
     *
     * @param point a point on the surface
     * @return {u, v}
     * @throws UnsupportedOperationException when the body has no surface coordinates
     */
    public double[] getUV(Point3D point) {
        throw new UnsupportedOperationException(this + " has no surface coordinates");
    }

    // The fast path of the acceleration structure: a ray's numbers in a RayState (origin o, unit
    // direction d, the distance that counts). Bodies on the hot path override these with code that
    // allocates nothing; the defaults go through findGeoIntersections.

    /**
     * The distance to the nearest intersection ahead of a ray, within its distance.
     *
     * @param ray the ray: origin, unit direction and the largest distance that counts
     * @return the distance t in (0, maxT], or {@link #NO_HIT} when there is none
     */
    public double nearestHit(RayState ray) {
        Point3D origin = new Point3D(ray.ox(), ray.oy(), ray.oz());
        List<GeoPoint> hits = findGeoIntersectionsHelper(toRay(ray), ray.maxT());
        double nearest = NO_HIT;
        if (hits != null)
            for (GeoPoint hit : hits)
                nearest = Math.min(nearest, hit.point.distance(origin));
        return nearest;
    }

    /** {@return a ray's numbers as the course's {@link Ray}} */
    static Ray toRay(RayState ray) {
        return new Ray(new Point3D(ray.ox(), ray.oy(), ray.oz()), new Vector(ray.dx(), ray.dy(), ray.dz()));
    }

    /** {@return the numbers of a course {@link Ray} and a distance, for the fast path} */
    static RayState toRayState(Ray ray, double maxDistance) {
        Point3D p0 = ray.getP0();
        Vector dir = ray.getDir();
        return new RayState().set(p0.getX(), p0.getY(), p0.getZ(), dir.getX(), dir.getY(), dir.getZ(), maxDistance);
    }

    /**
     * Whether a distance counts as a hit.
     *
     * @param t    a distance along a ray
     * @param maxT the largest distance that counts
     * @return true when t lies in (0, maxT]
     */
    static boolean within(double t, double maxT) {
        return t > 0 && t <= maxT;
    }

    /**
     * A distance if it counts as a hit.
     *
     * @param t    a distance along a ray
     * @param maxT the largest distance that counts
     * @return t when it lies in (0, maxT], else {@link #NO_HIT}
     */
    static double hitWithin(double t, double maxT) {
        return within(t, maxT) ? t : NO_HIT;
    }

    /**
     * The intersection list of a body a ray crosses at most once, from {@link #nearestHit}.
     *
     * @param ray         the ray
     * @param maxDistance the largest distance that counts
     * @return the one intersection, or null
     */
    public final List<GeoPoint> singleHit(Ray ray, double maxDistance) {
        double t = nearestHit(toRayState(ray, maxDistance));
        return t < NO_HIT ? List.of(new GeoPoint(this, ray.getPoint(t))) : null;
    }

    /**
     * The hit a hierarchy's closest-hit query found on this body at a distance along a ray.
     *
     * @param ray  the ray
     * @param t    the distance of the hit
     * @param part which part of the body was hit (a {@link TriangleMesh}'s triangle), or −1 when the
     *             body was tested as a whole
     * @return the hit: the body and the point (the default ignores the part)
     */
    public GeoPoint hitPoint(Ray ray, double t, int part) {
        return new GeoPoint(this, ray.getPoint(t));
    }

    /**
     * The intersection list of a body a ray crosses at two distances (a sphere, a tube).
     *
     * @param ray         the ray
     * @param t1          the nearer distance (maybe negative or NaN)
     * @param t2          the farther distance (maybe negative or NaN)
     * @param maxDistance the largest distance that counts
     * @return the intersections at the distances in (0, maxDistance], nearest first, or null
     */
    final List<GeoPoint> hitsAt(Ray ray, double t1, double t2, double maxDistance) {
        boolean hit1 = within(t1, maxDistance);
        boolean hit2 = within(t2, maxDistance);
        if (hit1 && hit2)
            return List.of(new GeoPoint(this, ray.getPoint(t1)), new GeoPoint(this, ray.getPoint(t2)));
        if (hit1)
            return List.of(new GeoPoint(this, ray.getPoint(t1)));
        if (hit2)
            return List.of(new GeoPoint(this, ray.getPoint(t2)));
        return null;
    }

    /**
     * The number of intersections ahead of a ray, within its distance.
     *
     * @param ray the ray
     * @return the number of intersections at distances in (0, maxT]
     */
    int hitCount(RayState ray) {
        List<GeoPoint> hits = findGeoIntersectionsHelper(toRay(ray), ray.maxT());
        return hits == null ? 0 : hits.size();
    }

    /**
     * The share of light that passes this body along a ray, within its distance: {@code kT} to the
     * power of the number of intersections ({@link Instance} multiplies the {@code kT} of its body's
     * intersections instead, each body's own).
     *
     * @param ray the ray
     * @return the transparency factor in [0, 1]
     */
    public double transmittance(RayState ray) {
        if (nearestHit(ray) == NO_HIT) // most shadow rays miss: no material read
            return 1;
        double kT = material.getKt();
        if (kT == 0) // opaque: blocked, no need to count the hits
            return 0;
        int count = hitCount(ray);
        return count == 1 ? kT : Math.pow(kT, count);
    }

    /**
     * Whether the body may meet any ray of a shadow bundle: the test of unbounded bodies, and of
     * bounded ones whose boxes meet the bundle's pyramid. The default says yes.
     *
     * @param frustum the pyramid the bundle sweeps
     * @return false only when no ray of the bundle can meet the body
     */
    public boolean mayMeet(ShadowFrustum frustum) {
        return true;
    }

    /**
     * The axis-aligned box around the body.
     *
     * @return {minX, minY, minZ, maxX, maxY, maxZ}, or null for an unbounded body
     */
    public final double[] bounds() {
        double[] box = new double[6];
        return bounds(box, 0) ? box : null;
    }

    /**
     * Writes the axis-aligned box around the body into an array, the way a hierarchy is built
     * without an object per body. The default says the body is unbounded.
     *
     * @param box the array
     * @param b   where the box's six numbers go: {minX, minY, minZ, maxX, maxY, maxZ}
     * @return false for an unbounded body, when nothing is written
     */
    public boolean bounds(double[] box, int b) {
        return false;
    }
}
