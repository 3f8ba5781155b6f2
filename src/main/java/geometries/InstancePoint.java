package geometries;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Transform;
import primitives.Vector;

/**
 * A hit on an {@link Instance}: the hit on its body, found in the body's space, carried to the world.
 * It names the body hit inside (so shading reads that body's material), lies at the world point, and
 * answers with the inner hit's normal (by the inverse transpose), surface coordinates and shadow
 * point, carried to the world when shading asks.
 */
final class InstancePoint extends GeoPoint {
    /** The hit in the body's space. */
    private final GeoPoint inner;
    private final Transform transform;
    private final Transform inverse;

    /**
     * Carries a hit on a body to the world.
     *
     * @param inner     the hit, in the body's space
     * @param transform the instance's transform, from the body's space to the world
     * @param inverse   its inverse
     */
    InstancePoint(GeoPoint inner, Transform transform, Transform inverse) {
        super(inner.geometry, transform.apply(inner.point));
        this.inner = inner;
        this.transform = transform;
        this.inverse = inverse;
    }

    /** {@return the inner hit's normal carried to the world} */
    @Override
    public Vector getNormal() {
        return transform.applyToNormal(inner.getNormal());
    }

    /** {@return the inner hit's surface coordinates} */
    @Override
    public double[] getUV() {
        return inner.getUV();
    }

    /** {@return the inner hit's shadow point for the light's direction in the body's space, carried to the world} */
    @Override
    public Point3D getShadowPoint(Vector l) {
        Point3D shadow = inner.getShadowPoint(inverse.applyToVector(l).normalize());
        return shadow == inner.point ? point : transform.apply(shadow);
    }

    /** {@return the inner hit's face normal carried to the world, or null} */
    @Override
    public Vector getFaceNormal() {
        Vector face = inner.getFaceNormal();
        return face == null ? null : transform.applyToNormal(face);
    }

    @Override
    public String toString() {
        return "InstancePoint{" + inner + " carried to " + point + "}";
    }
}
