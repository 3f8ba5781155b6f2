package accel;

import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Intersectable.GeoPoint;
import geometries.TriangleMesh;
import java.util.ArrayList;
import java.util.List;

import primitives.Ray;

/**
 * The bodies the hierarchy tests: those of the tree's leaves, in leaf order, each held by reference
 * (its geometry and its part: a mesh's triangle is two ints and its box in floats, no object and no
 * copy of its vertices), the unbounded ones tested on every ray, and the intersectables that are not
 * {@link Geometry}s.
 */
final class LeafBodies {
    /** The geometries whose bodies are in the tree: each a body, or a mesh of many. */
    final Geometry[] owners;
    /** Per body of the tree, in leaf order: its geometry in {@link #owners}. */
    final int[] bodyOwner;
    /**
     * Per body of the tree, in leaf order: its triangle when its geometry is a mesh; else −1 − the
     * place of its box in {@link #wholeBounds}.
     */
    final int[] bodyPart;
    /**
     * The padded boxes of the tree's bodies that are whole geometries, not a mesh's triangles (whose
     * boxes are in {@link #triangleBounds}).
     */
    final double[] wholeBounds;
    /**
     * Per body of the tree that is a mesh's triangle, in leaf order: its padded box in floats, rounded
     * outward (so it holds the box in doubles), for {@link #meets}: half the memory of doubles.
     * A bundle may then gather a triangle more, never one less: every ray's answer stays the same.
     */
    final float[] triangleBounds;
    final Geometry[] unbounded;
    final Intersectable[] others;
    /** The course-style triangles packed into a mesh of the tree, or null. */
    private final PackedTriangles packed;

    /**
     * Keeps the bodies in the leaf order of a build.
     *
     * @param unbounded the bodies outside the tree
     * @param others    the intersectables that are not geometries
     * @param packed    the course-style triangles packed into a mesh of the tree, or null
     * @param builder   the build over the tree's geometries, done
     * @param threads   the number of threads that share the work
     */
    LeafBodies(Geometry[] unbounded, Intersectable[] others, PackedTriangles packed, BvhBuilder builder,
               int threads) {
        this.owners = builder.owners;
        this.packed = packed;
        this.unbounded = unbounded;
        this.others = others;
        this.bodyOwner = builder.order;
        this.bodyPart = builder.parts;
        this.wholeBounds = wholeBounds(builder.boxes);
        this.triangleBounds = new float[6 * bodyPart.length];
        BvhBuilder.runInChunks(bodyPart.length, threads, (from, to) -> placeTriangles(builder.boxes, from, to));
    }

    /**
     * Sorts the bodies of a composite: bounded geometries, unbounded ones, and intersectables that
     * are not geometries.
     */
    static void flatten(Intersectable item, List<Geometry> bounded, List<Geometry> infinite,
                        List<Intersectable> generic, double[] box) {
        if (item instanceof Geometries composite)
            for (Intersectable child : composite.getGeometries())
                flatten(child, bounded, infinite, generic, box);
        else if (item instanceof Geometry geometry)
            (geometry.bounds(box, 0) ? bounded : infinite).add(geometry);
        else
            generic.add(item);
    }

    /**
     * Sets the boxes of the mesh's triangles among bodies [from, to) of the tree, in leaf order.
     *
     * @param boxes the padded box of every body of the tree, in leaf order
     * @param from  the first body
     * @param to    one past the last
     */
    private void placeTriangles(double[] boxes, int from, int to) {
        for (int b = from; b < to; ++b) {
            int part = bodyPart[b];
            if (part >= 0)
                BvhNodes.roundOutward(boxes, triangleBounds, 6 * b);
        }
    }

    /**
     * Keeps the boxes of the tree's whole bodies, and numbers them in {@link #bodyPart}.
     *
     * @param boxes the padded box of every body of the tree, in leaf order
     * @return the boxes of the bodies that are not a mesh's triangles, in leaf order
     */
    private double[] wholeBounds(double[] boxes) {
        int count = 0;
        for (int part : bodyPart)
            if (part < 0)
                ++count;
        double[] whole = new double[6 * count];
        int slot = 0;
        for (int b = 0; b < bodyPart.length; ++b)
            if (bodyPart[b] < 0) {
                System.arraycopy(boxes, 6 * b, whole, 6 * slot, 6);
                bodyPart[b] = -1 - slot++;
            }
        return whole;
    }

    /** {@return the number of bodies in the tree} */
    int count() {
        return bodyOwner.length;
    }

    /** {@return the geometry of body b of the tree} */
    Geometry owner(int b) {
        return owners[bodyOwner[b]];
    }

    /**
     * The {@code kT} of a mesh's triangle: the mesh's, or for the packed course-style triangles, the
     * triangle's own.
     *
     * @param mesh the mesh
     * @param part the triangle
     * @return its transparency
     */
    double kT(TriangleMesh mesh, int part) {
        return packed != null && packed.isMesh(mesh) ? packed.triangles[part].getMaterial().getKt()
                : mesh.getMaterial().getKt();
    }

    /**
     * The closest hit a walk found, as its body reports it: a packed triangle's is its {@link
     * geometries.Triangle}'s.
     *
     * @param ray   the ray
     * @param state the walk's ray, its closest hit found
     * @return the hit
     */
    GeoPoint hitPoint(Ray ray, RayState state) {
        if (packed != null && packed.isMesh(state.geometry))
            return packed.triangles[state.part].hitPoint(ray, state.maxT, -1);
        return state.geometry.hitPoint(ray, state.maxT, state.part);
    }

    /**
     * Whether body b of the tree may meet a frustum: its padded box does, and then the body itself
     * may ({@link Geometry#mayMeet}: a polygon's plane, and a mesh's triangle's). A mesh's triangle's
     * box is kept in floats, rounded outward: a little larger, never smaller.
     *
     * @param frustum the bundle's pyramid
     * @param b       the body, in leaf order
     * @return false when no ray of the bundle can meet the body
     */
    boolean meets(ShadowFrustum frustum, int b) {
        int part = bodyPart[b];
        if (part < 0)
            return frustum.meetsBox(wholeBounds, 6 * (-1 - part)) && owner(b).mayMeet(frustum);
        return frustum.meetsBox(triangleBounds, 6 * b) && ((TriangleMesh) owner(b)).mayMeet(part, frustum);
    }

    /**
     * The nearest of a hit so far and the hits of the intersectables that are not geometries.
     *
     * @param ray     the ray
     * @param nearest the nearest hit so far, or null
     * @return the nearest hit, or null
     */
    GeoPoint nearestOfOthers(Ray ray, GeoPoint nearest) {
        for (Intersectable other : others)
            nearest = nearer(ray, nearest, other.findGeoIntersections(ray));
        return nearest;
    }

    /**
     * The distance to the nearest hit of the intersectables that are not geometries, within a ray's distance.
     *
     * @param ray the ray
     * @return the distance, or {@link Geometry#NO_HIT}
     */
    double nearestOfOthers(RayState ray) {
        if (others.length == 0)
            return Geometry.NO_HIT;
        Ray course = ray.toRay();
        GeoPoint nearest = nearestOfOthers(course, null);
        double t = nearest == null ? Geometry.NO_HIT : nearest.point.distance(course.getP0());
        return t <= ray.maxT ? t : Geometry.NO_HIT;
    }

    private static GeoPoint nearer(Ray ray, GeoPoint nearest, List<GeoPoint> candidates) {
        if (candidates == null)
            return nearest;
        List<GeoPoint> all = new ArrayList<>(candidates);
        if (nearest != null)
            all.add(nearest);
        return ray.findClosestGeoPoint(all);
    }

    /**
     * Multiplies a transmittance by the {@code kT} of every hit of the intersectables that are not
     * geometries, along a ray up to its distance.
     *
     * @param ray the ray, its minK set
     * @param ktr the transmittance so far
     * @return the transmittance, 0 once it falls below the ray's minK
     */
    double throughOthers(RayState ray, double ktr) {
        if (others.length == 0)
            return ktr;
        Ray shadow = ray.toRay();
        for (Intersectable other : others) {
            List<GeoPoint> hits = other.findGeoIntersections(shadow, ray.maxT);
            if (hits != null)
                for (GeoPoint hit : hits)
                    ktr *= hit.geometry.getMaterial().getKt();
            if (ktr < ray.minK)
                return 0;
        }
        return ktr;
    }
}
