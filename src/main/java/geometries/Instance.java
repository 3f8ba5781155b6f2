package geometries;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import accel.RayState;
import accel.ShadowFrustum;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Texture;
import primitives.Transform;
import primitives.Vector;

import static primitives.Util.requireNonNull;

/**
 * A body placed in the scene by a transform: any {@link Intersectable} (a geometry, a mesh, a
 * {@link Geometries} group, another instance), moved, turned and scaled, non-uniformly too, without
 * a copy. Its hits are in world space and are the body's: the {@link GeoPoint} of a hit names the
 * body hit inside (whose material, emission and texture shade it), at the world point, with the
 * body's normal, surface coordinates and shadow point carried to the world. An instance has no
 * material of its own.
 * <p>
 * The acceleration structure sees an instance as one bounded body, its box the transform of its
 * body's box, and walks the body's own hierarchy in the body's space (a two-level tree): the ray is
 * mapped by the inverse transform. The hierarchy is kept with the body ({@link Intersectable#hierarchy}),
 * so all the instances of one body share it, and with it one scratch space per thread. An instance
 * of an unbounded body (a plane) is unbounded: it stays outside the tree and is tested on every ray.
 */
public final class Instance extends Geometry {
    private final Intersectable body;
    private final Transform transform;
    private final Transform inverse;
    /** The inverse transform's 12 numbers, for the hot path. */
    private final double[] toBody;
    /** The transform's 12 numbers, for the bundles' gather ({@link #mayMeet}). */
    private final double[] toWorld;
    /** The body's hierarchy when last asked for, shared with every instance of the body. */
    private BoundingVolumeHierarchy tree;

    /**
     * Places a body by a transform.
     *
     * @param body      the body
     * @param transform the transform from the body's space to the world
     * @throws IllegalArgumentException when the body or the transform is null
     */
    public Instance(Intersectable body, Transform transform) {
        this.body = requireNonNull(body, "instance's body");
        this.transform = requireNonNull(transform, "instance's transform");
        this.inverse = transform.inverse();
        this.toBody = inverse.toArray();
        this.toWorld = transform.toArray();
    }

    /** {@return the body placed} */
    public Intersectable getBody() {
        return body;
    }

    /** {@return the transform from the body's space to the world} */
    public Transform getTransform() {
        return transform;
    }

    /** {@return the body's version: an instance changes when its body does} */
    @Override
    public long version() {
        return body.version();
    }

    /**
     * The body's hierarchy as the body is now: the one it keeps, shared by its instances. Asked of the
     * body again only when bodies were added to it since.
     */
    BoundingVolumeHierarchy tree() {
        BoundingVolumeHierarchy current = tree;
        if (current == null || !current.isBuiltFrom(body))
            tree = current = body.hierarchy(1);
        return current;
    }

    /**
     * The body's hierarchy as {@link #tree()} last found it, without asking the body's version again:
     * the walks' accessor. An outer hierarchy reads every instance's box ({@link #bounds}, which calls
     * {@link #tree()}) when it is built, and is built again when a body inside an instance grows (its
     * version counts the instance's body), so a ray walks the body as its outer tree saw it.
     */
    private BoundingVolumeHierarchy walked() {
        BoundingVolumeHierarchy current = tree;
        return current != null ? current : tree();
    }

    /**
     * The unit normal at a point of an instance of a single geometry: the body's there, carried to
     * the world. Shading reads the normal of a hit's {@link GeoPoint} instead, which knows the body hit.
     *
     * @param point a point on the surface, in the world
     * @return the outward unit normal there
     * @throws IllegalArgumentException when the body is not a single geometry, or has no normal there
     */
    @Override
    public Vector getNormal(Point3D point) {
        if (!(body instanceof Geometry geometry))
            throw new IllegalArgumentException("an instance of " + body + " has no one normal at a point:"
                    + " ask the GeoPoint of a hit");
        return transform.applyToNormal(geometry.getNormal(inverse.apply(point)));
    }

    /**
     * Refused: an instance shows its body's materials.
     *
     * @param material ignored
     * @return never
     * @throws UnsupportedOperationException always: set the material on the body
     */
    @Override
    public Geometry setMaterial(Material material) {
        throw refused("material");
    }

    /**
     * Refused: an instance shows its body's emission.
     *
     * @param emission ignored
     * @return never
     * @throws UnsupportedOperationException always: set the emission on the body
     */
    @Override
    public Geometry setEmission(Color emission) {
        throw refused("emission");
    }

    /**
     * Refused: an instance shows its body's textures.
     *
     * @param texture ignored
     * @return never
     * @throws UnsupportedOperationException always: set the texture on the body
     */
    @Override
    public Geometry setTexture(Texture texture) {
        throw refused("texture");
    }

    private static UnsupportedOperationException refused(String what) {
        return new UnsupportedOperationException("an instance shows its body's " + what + ": set it on the body");
    }

    /** {@return the nearest hit of the body, its hierarchy walked in the body's space} */
    @Override
    public double nearestHit(RayState ray) {
        return walked().nearestHit(ray, toBody);
    }

    /** {@return the product of the {@code kT} of the body's hits, each inner body's own} */
    @Override
    public double transmittance(RayState ray) {
        return walked().transmittance(ray, toBody);
    }

    /**
     * Traces some rays of a packet of shadow rays through the body together, its tree walked in the
     * body's space (see {@link BoundingVolumeHierarchy#packetTransmittances(Query, int, double[], double[])}):
     * each listed ray is attenuated as {@link #transmittance} would, and the list keeps those still unblocked.
     *
     * @param query the scratch space of the hierarchy the instance lies in, its packet and frustum set
     * @param count how many rays of its packet are listed
     * @return how many of them are still unblocked
     */
    public int packetTransmittances(Query query, int count) {
        return walked().packetTransmittances(query, count, toBody, toWorld);
    }

    /**
     * Whether a bundle may meet the body: its pyramid carried into the body's space, the body's tree
     * walked with it. So a bundle that passes by the body's triangles, though through its box, is open.
     */
    @Override
    public boolean mayMeet(ShadowFrustum frustum) {
        return walked().mayMeet(frustum, toBody, toWorld);
    }

    /**
     * Whether the body blocks every ray of a bundle: its last {@link #mayMeet} of the bundle found a
     * closed opaque mesh of the body across every ray ({@link BoundingVolumeHierarchy#blocksCarried}).
     *
     * @param frustum the bundle's pyramid, as {@link #mayMeet} was last given it
     * @return true when every ray of the bundle is blocked
     */
    public boolean blocksBundle(ShadowFrustum frustum) {
        return walked().blocksCarried(frustum, toBody);
    }

    /** {@return the body's nearest hit on the ray, carried to the world (the part is not used)} */
    @Override
    public GeoPoint hitPoint(Ray ray, double t, int part) {
        GeoPoint inner = walked().closestHit(toRayState(ray, NO_HIT), toBody);
        return inner == null ? new GeoPoint(this, ray.getPoint(t)) : new InstancePoint(inner, transform, inverse);
    }

    /**
     * Writes the box around the transformed body: the box of the transformed corners of the body's box.
     *
     * @return false when the body is unbounded or empty
     */
    @Override
    public boolean bounds(double[] box, int b) {
        double[] local = new double[6];
        if (!tree().bounds(local))
            return false;
        for (int k = 0; k < 3; ++k) {
            box[b + k] = Double.POSITIVE_INFINITY;
            box[b + 3 + k] = Double.NEGATIVE_INFINITY;
        }
        for (int corner = 0; corner < 8; ++corner) {
            Point3D p = transform.apply(new Point3D(local[(corner & 1) * 3], local[1 + (corner >> 1 & 1) * 3],
                    local[2 + (corner >> 2 & 1) * 3]));
            double[] xyz = { p.getX(), p.getY(), p.getZ() };
            for (int k = 0; k < 3; ++k) {
                box[b + k] = Math.min(box[b + k], xyz[k]);
                box[b + 3 + k] = Math.max(box[b + 3 + k], xyz[k]);
            }
        }
        return true;
    }

    /** The body's intersections with the ray mapped into its space, carried back to the world, nearest first. */
    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        Vector direction = inverse.applyToVector(ray.getDir());
        Ray local = new Ray(inverse.apply(ray.getP0()), direction);
        List<GeoPoint> hits = body.findGeoIntersectionsHelper(local, maxDistance * direction.length());
        if (hits == null)
            return null;
        List<GeoPoint> world = new ArrayList<>(hits.size());
        for (GeoPoint hit : hits)
            world.add(new InstancePoint(hit, transform, inverse));
        Point3D p0 = ray.getP0();
        world.sort(Comparator.comparingDouble(hit -> hit.point.distanceSquared(p0)));
        return world;
    }

    @Override
    public String toString() {
        return "Instance{" + body + " by " + transform + "}";
    }
}
