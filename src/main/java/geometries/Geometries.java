package geometries;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;

import accel.BoundingVolumeHierarchy;
import primitives.Ray;

/**
 * A composite of intersectable objects, itself intersectable: the scene's collection of bodies. Its
 * queries list the points body by body, in the order the bodies were added, each body's nearest first;
 * they are not sorted across bodies (the renderer asks its hierarchy for the nearest hit instead).
 */
public class Geometries extends Intersectable {
    private final List<Intersectable> items = new ArrayList<>();
    /** The composites among the items, which {@link #version()} walks. */
    private final List<Geometries> composites = new ArrayList<>();
    /** How many times objects were added to this composite itself. */
    private long additions;
    /** The renderer's hierarchy over the bodies, as they were when it was built (see {@link #hierarchy}). */
    private BoundingVolumeHierarchy hierarchy;

    /**
     * Creates a composite holding the given objects.
     *
     * @param geometries the objects (none for an empty composite)
     */
    public Geometries(Intersectable... geometries) {
        add(geometries);
    }

    /**
     * Adds objects to the composite: all of them, or none when one is refused.
     *
     * @param geometries the objects to add
     * @return this composite
     * @throws IllegalArgumentException when the array or an object is null, or an object is this composite
     *                                  or a composite that holds it, directly or inside another: the
     *                                  composite would contain itself, and every walk of it would not end
     */
    public Geometries add(Intersectable... geometries) {
        if (geometries == null)
            throw new IllegalArgumentException("geometries to add must not be null");
        for (Intersectable geometry : geometries) {
            if (geometry == null)
                throw new IllegalArgumentException("a geometry to add is null");
            if (geometry instanceof Geometries composite && composite.reaches(this))
                throw new IllegalArgumentException("a Geometries cannot be added to itself, nor to a Geometries it"
                        + " holds (directly or inside another): it would contain itself");
        }
        Collections.addAll(items, geometries);
        for (Intersectable geometry : geometries)
            if (geometry instanceof Geometries composite)
                composites.add(composite);
        ++additions;
        return this;
    }

    /**
     * Whether a composite is this one or among those it holds, at any depth: a walk with a stack of its
     * own (a deep nesting overflows no call stack) that visits each composite once (one held in many
     * places is not walked again).
     */
    private boolean reaches(Geometries target) {
        Deque<Geometries> open = new ArrayDeque<>(List.of(this));
        Set<Geometries> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        while (!open.isEmpty()) {
            Geometries composite = open.pop();
            if (composite == target)
                return true;
            if (seen.add(composite))
                open.addAll(composite.composites);
        }
        return false;
    }

    /**
     * A number that grows whenever an object is added to this composite or to any composite nested
     * in it: the sum of their counts of additions (composites are never taken out, so the sum only
     * grows). A hierarchy built over the composite compares it to know whether it is out of date.
     *
     * @return the version of the composite's contents
     */
    public long version() {
        long version = additions;
        for (Geometries composite : composites)
            version += composite.version();
        return version;
    }

    /**
     * The renderer's bounding volume hierarchy over the bodies, kept with them so that every ray
     * tracer of the scene shares it (a course test makes a new tracer for every picture): built on
     * the first call, and again only when bodies were added since (see {@link #version()}).
     *
     * @param threads how many threads may share a build, 1 or more
     * @return the hierarchy over the bodies as they are now
     * @throws IllegalArgumentException when threads is below 1
     */
    public synchronized BoundingVolumeHierarchy hierarchy(int threads) {
        if (threads < 1)
            throw new IllegalArgumentException("threads must be 1 or more, got " + threads);
        if (hierarchy == null || !hierarchy.isBuiltFrom(this))
            hierarchy = BoundingVolumeHierarchy.build(this, threads);
        return hierarchy;
    }

    /** {@return the objects held, as an unmodifiable list} */
    public List<Intersectable> getGeometries() {
        return Collections.unmodifiableList(items);
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        List<GeoPoint> result = null;
        for (Intersectable item : items) {
            List<GeoPoint> found = item.findGeoIntersectionsHelper(ray, maxDistance);
            if (found != null) {
                if (result == null)
                    result = new ArrayList<>(found);
                else
                    result.addAll(found);
            }
        }
        return result;
    }
}
