package geometries;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;

import primitives.Ray;

/**
 * A composite of intersectable objects, itself intersectable: the scene's collection of bodies. Its
 * queries list the points body by body, in the order the bodies were added, each body's nearest first;
 * they are not sorted across bodies (the renderer asks its hierarchy for the nearest hit instead).
 */
public class Geometries extends Intersectable {
    private final List<Intersectable> items = new ArrayList<>();
    /**
     * The items that hold other objects, composites and {@link Instance}s, which {@link #version()}
     * and the cycle check walk.
     */
    private final List<Intersectable> holders = new ArrayList<>();
    /** How many times objects were added to this composite itself. */
    private long additions;

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
     *                                  or one that holds it (a composite or an {@link Instance}), directly
     *                                  or inside another: the composite would contain itself, and every
     *                                  walk of it would not end
     */
    public Geometries add(Intersectable... geometries) {
        if (geometries == null)
            throw new IllegalArgumentException("geometries to add must not be null");
        for (Intersectable geometry : geometries) {
            if (geometry == null)
                throw new IllegalArgumentException("a geometry to add is null");
            if (reaches(geometry, this))
                throw new IllegalArgumentException("a Geometries cannot be added to itself, nor to a Geometries or"
                        + " an Instance it holds (directly or inside another): it would contain itself");
        }
        Collections.addAll(items, geometries);
        for (Intersectable geometry : geometries)
            if (isHolder(geometry))
                holders.add(geometry);
        ++additions;
        return this;
    }

    /** {@return whether an object holds others: a composite, or an instance} */
    private static boolean isHolder(Intersectable item) {
        return item instanceof Geometries || item instanceof Instance;
    }

    /**
     * Whether a composite is an object or among those it holds, at any depth, an instance's body
     * among them: a walk with a stack of its own (a deep nesting overflows no call stack) that visits
     * each holder once (one held in many places is not walked again).
     */
    private static boolean reaches(Intersectable start, Geometries target) {
        Deque<Intersectable> open = new ArrayDeque<>(List.of(start));
        Set<Intersectable> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        while (!open.isEmpty()) {
            Intersectable holder = open.pop();
            if (holder == target)
                return true;
            if (seen.add(holder)) {
                if (holder instanceof Geometries composite)
                    open.addAll(composite.holders);
                else if (holder instanceof Instance instance && isHolder(instance.getBody()))
                    open.push(instance.getBody());
            }
        }
        return false;
    }

    /**
     * A number that grows whenever an object is added to this composite or to any composite nested
     * in it, inside an {@link Instance} too: the sum of their counts of additions (composites are
     * never taken out, so the sum only grows). A hierarchy built over the composite compares it to
     * know whether it is out of date.
     *
     * @return the version of the composite's contents
     */
    @Override
    public long version() {
        long version = additions;
        for (Intersectable holder : holders)
            version += holder.version();
        return version;
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
