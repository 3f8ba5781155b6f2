package lighting;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

import static primitives.Util.requireNonNull;

/**
 * A light at infinity shining in one direction with no attenuation, like the sun.
 */
public class DirectionalLight extends Light implements LightSource {
    private final Vector direction;

    /**
     * Creates a directional light.
     *
     * @param intensity the light's intensity
     * @param direction the direction the light shines to (any length)
     */
    public DirectionalLight(Color intensity, Vector direction) {
        super(intensity);
        this.direction = requireNonNull(direction, "light direction").normalized();
    }

    /** {@return the unit direction the light shines to} */
    public Vector getDirection() {
        return direction;
    }

    @Override
    public Color getIntensity(Point3D p) {
        return intensity;
    }

    @Override
    public Vector getL(Point3D p) {
        return direction;
    }

    @Override
    public double getDistance(Point3D p) {
        return Double.POSITIVE_INFINITY;
    }
}
