package geometries;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import primitives.Ray;

/**
 * A composite of intersectable objects, itself intersectable: the scene's collection of bodies.
 */
public class Geometries extends Intersectable {
    private final List<Intersectable> items = new ArrayList<>();

    /**
     * Creates a composite holding the given objects.
     *
     * @param geometries the objects (none for an empty composite)
     */
    public Geometries(Intersectable... geometries) {
        add(geometries);
    }

    /**
     * Adds objects to the composite.
     *
     * @param geometries the objects to add
     * @return this composite
     */
    public Geometries add(Intersectable... geometries) {
        if (geometries == null)
            throw new IllegalArgumentException("geometries to add must not be null");
        for (Intersectable geometry : geometries)
            if (geometry == null)
                throw new IllegalArgumentException("a geometry to add is null");
        Collections.addAll(items, geometries);
        return this;
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
