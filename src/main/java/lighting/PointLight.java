package lighting;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

import static primitives.Util.requireNonNegative;
import static primitives.Util.requireNonNull;

/**
 * A light at a point that shines to all sides, attenuated with distance d by
 * {@code 1 / (kC + kL·d + kQ·d²)}.
 */
public class PointLight extends Light implements LightSource {
    /** The light's position. */
    protected final Point3D position;
    private double kC = 1;
    private double kL = 0;
    private double kQ = 0;

    /**
     * Creates a point light with no attenuation (kC 1, kL 0, kQ 0).
     *
     * @param intensity the light's intensity
     * @param position  the light's position
     */
    public PointLight(Color intensity, Point3D position) {
        super(intensity);
        this.position = requireNonNull(position, "light position");
    }

    /**
     * Sets the constant attenuation factor.
     *
     * @param kC the factor, 0 or more
     * @return this light
     */
    public PointLight setKc(double kC) {
        this.kC = requireNonNegative(kC, "light kC");
        return this;
    }

    /**
     * Sets the linear attenuation factor.
     *
     * @param kL the factor, 0 or more
     * @return this light
     */
    public PointLight setKl(double kL) {
        this.kL = requireNonNegative(kL, "light kL");
        return this;
    }

    /**
     * Sets the quadratic attenuation factor.
     *
     * @param kQ the factor, 0 or more
     * @return this light
     */
    public PointLight setKq(double kQ) {
        this.kQ = requireNonNegative(kQ, "light kQ");
        return this;
    }

    /** @return the light's position */
    public Point3D getPosition() {
        return position;
    }

    /** @return the constant attenuation factor */
    public double getKc() {
        return kC;
    }

    /** @return the linear attenuation factor */
    public double getKl() {
        return kL;
    }

    /** @return the quadratic attenuation factor */
    public double getKq() {
        return kQ;
    }

    @Override
    public Color getIntensity(Point3D p) {
        double dSquared = requireNonNull(p, "lit point").distanceSquared(position);
        double attenuation = kC + kL * Math.sqrt(dSquared) + kQ * dSquared;
        if (!(attenuation > 0))
            throw new IllegalArgumentException("light attenuation kC + kL·d + kQ·d² is zero at " + p
                    + ": set kC, kL or kQ above zero");
        return intensity.reduce(attenuation);
    }

    @Override
    public Vector getL(Point3D p) {
        if (requireNonNull(p, "lit point").equals(position))
            throw new IllegalArgumentException("the lit point " + p + " coincides with the light's position");
        return p.subtract(position).normalize();
    }

    @Override
    public double getDistance(Point3D p) {
        return requireNonNull(p, "lit point").distance(position);
    }
}
