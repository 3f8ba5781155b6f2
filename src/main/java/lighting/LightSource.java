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
     */
    Vector getL(Point3D p);

    /**
     * The distance from the light to a point.
     *
     * @param p the lit point
     * @return the distance ({@link Double#POSITIVE_INFINITY} for a light at infinity)
     */
    double getDistance(Point3D p);
}
