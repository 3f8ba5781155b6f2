package lighting;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * A point light that shines in a direction: its intensity is multiplied by
 * {@code max(0, dir·l)} raised to the narrow-beam power (1 by default). Unless U and V are set, its
 * square faces along its direction.
 */
public class SpotLight extends PointLight {
    private final Vector direction;
    private final Vector squareU;
    private final Vector squareV;
    private double narrowBeam = 1;

    /**
     * Creates a spot light.
     *
     * @param intensity the light's intensity
     * @param position  the light's position
     * @param direction the direction of the beam's axis (any length)
     */
    public SpotLight(Color intensity, Point3D position, Vector direction) {
        super(intensity, position);
        this.direction = requireNonNull(direction, "spot light direction").normalized();
        this.squareU = this.direction.orthogonal();
        this.squareV = this.direction.crossProduct(squareU).normalize();
    }

    /**
     * Narrows the beam: the spot factor is raised to this power.
     *
     * @param narrowBeam the power, positive (1 is the plain spot, larger is narrower)
     * @return this light
     */
    public SpotLight setNarrowBeam(double narrowBeam) {
        this.narrowBeam = requirePositive(narrowBeam, "spot light narrow beam");
        return this;
    }

    @Override
    public SpotLight setKc(double kC) {
        super.setKc(kC);
        return this;
    }

    @Override
    public SpotLight setKl(double kL) {
        super.setKl(kL);
        return this;
    }

    @Override
    public SpotLight setKq(double kQ) {
        super.setKq(kQ);
        return this;
    }

    @Override
    public SpotLight setkC(double kC) {
        return setKc(kC);
    }

    @Override
    public SpotLight setkL(double kL) {
        return setKl(kL);
    }

    @Override
    public SpotLight setkQ(double kQ) {
        return setKq(kQ);
    }

    @Override
    public SpotLight setEdgesSize(double edges) {
        super.setEdgesSize(edges);
        return this;
    }

    @Override
    public SpotLight setUV(Vector u, Vector v) {
        super.setUV(u, v);
        return this;
    }

    /** {@return the set U, or when it was not set a unit vector orthogonal to the beam's direction} */
    @Override
    public Vector getU() {
        Vector u = super.getU();
        return u != null ? u : squareU;
    }

    /** {@return the set V, or when it was not set direction × U} */
    @Override
    public Vector getV() {
        Vector v = super.getV();
        return v != null ? v : squareV;
    }

    /** {@return the unit direction of the beam's axis} */
    public Vector getDirection() {
        return direction;
    }

    /** {@return the narrow-beam power} */
    public double getNarrowBeam() {
        return narrowBeam;
    }

    @Override
    public Color getIntensity(Point3D p) {
        double factor = Math.max(0, direction.dotProduct(getL(p)));
        if (factor == 0)
            return Color.BLACK;
        return super.getIntensity(p).scale(narrowBeam == 1 ? factor : Math.pow(factor, narrowBeam));
    }
}
