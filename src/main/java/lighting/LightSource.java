package lighting;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

/**
 * A light that illuminates points of the scene.
 */
public interface LightSource {
    /**
     * The intensity of this light arriving at a point.
     *
     * @param p the lit point
     * @return the intensity there
     */
    Color getIntensity(Point3D p);

    /**
     * The direction of the light at a point.
     *
     * @param p the lit point
     * @return the unit vector from the light to the point
     * @throws IllegalArgumentException when the point is null, or the light sits there ({@link #isAt})
     */
    Vector getL(Point3D p);

    /**
     * Whether the light sits at a point, where it has no direction: a point light's position (within the
     * tolerance of {@link Point3D#equals}). A renderer gives such a point nothing from this light: the
     * surface around it sees the light edge-on, and so receives nothing from it either.
     *
     * @param p the point
     * @return false by default: a light at infinity sits nowhere
     */
    default boolean isAt(Point3D p) {
        return false;
    }

    /**
     * The distance from the light to a point.
     *
     * @param p the lit point
     * @return the distance ({@link Double#POSITIVE_INFINITY} for a light at infinity)
     */
    double getDistance(Point3D p);
}
