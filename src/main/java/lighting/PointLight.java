package lighting;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

import static primitives.Util.isZero;
import static primitives.Util.requireNonNegative;
import static primitives.Util.requireNonNull;

/**
 * A light at a point that shines to all sides, attenuated with distance d by
 * {@code 1 / (kC + kL·d + kQ·d²)}. For soft shadows it may be given an area: a square centred at its
 * position, of edge {@link #setEdgesSize(double)}, its sides along {@link #setUV(Vector, Vector)}
 * (by default the square faces the lit point).
 */
public class PointLight extends Light implements AreaLightSource {
    /** The light's position. */
    protected final Point3D position;
    private double kC = 1;
    private double kL = 0;
    private double kQ = 0;
    private double edges = 0;
    private Vector u;
    private Vector v;

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
     * @throws IllegalArgumentException when the factor is negative or not finite, or it and the other two
     *                                  factors would all be 0
     */
    public PointLight setKc(double kC) {
        this.kC = requireAttenuated(requireNonNegative(kC, "light kC"), kL, kQ);
        return this;
    }

    /**
     * The course's spelling of {@link #setKc(double)}, the same setter.
     *
     * @param kC the constant attenuation factor, 0 or more
     * @return this light
     */
    public PointLight setkC(double kC) {
        return setKc(kC);
    }

    /**
     * Sets the linear attenuation factor.
     *
     * @param kL the factor, 0 or more
     * @return this light
     * @throws IllegalArgumentException when the factor is negative or not finite, or it and the other two
     *                                  factors would all be 0
     */
    public PointLight setKl(double kL) {
        this.kL = requireAttenuated(requireNonNegative(kL, "light kL"), kC, kQ);
        return this;
    }

    /**
     * The course's spelling of {@link #setKl(double)}, the same setter.
     *
     * @param kL the linear attenuation factor, 0 or more
     * @return this light
     */
    public PointLight setkL(double kL) {
        return setKl(kL);
    }

    /**
     * Sets the quadratic attenuation factor.
     *
     * @param kQ the factor, 0 or more
     * @return this light
     * @throws IllegalArgumentException when the factor is negative or not finite, or it and the other two
     *                                  factors would all be 0
     */
    public PointLight setKq(double kQ) {
        this.kQ = requireAttenuated(requireNonNegative(kQ, "light kQ"), kC, kL);
        return this;
    }

    /**
     * The course's spelling of {@link #setKq(double)}, the same setter.
     *
     * @param kQ the quadratic attenuation factor, 0 or more
     * @return this light
     */
    public PointLight setkQ(double kQ) {
        return setKq(kQ);
    }

    /**
     * Checks that an attenuation factor and the other two are not all 0: the light would be infinitely
     * bright at its position. A light without constant attenuation gets kL or kQ first, then kC 0.
     *
     * @param factor the new factor
     * @param other1 one of the other two factors
     * @param other2 the other one
     * @return the new factor
     */
    private static double requireAttenuated(double factor, double other1, double other2) {
        if (factor == 0 && other1 == 0 && other2 == 0)
            throw new IllegalArgumentException("light attenuation kC, kL and kQ must not all be 0 (the light would be"
                    + " infinitely bright): set kL or kQ before setting kC to 0");
        return factor;
    }

    /**
     * Gives the light an area for soft shadows: a square of this edge centred at its position.
     *
     * @param edges the length of the square's edge, 0 or more (0, the default, is a true point light)
     * @return this light
     */
    public PointLight setEdgesSize(double edges) {
        this.edges = requireNonNegative(edges, "light edge size");
        return this;
    }

    /**
     * Places the light's square in space: its sides run along U and V.
     *
     * @param u the direction of one side (any length)
     * @param v the direction of the other side (any length), orthogonal to U
     * @return this light
     * @throws IllegalArgumentException when U and V are not orthogonal
     */
    public PointLight setUV(Vector u, Vector v) {
        Vector unitU = requireNonNull(u, "light U").normalized();
        Vector unitV = requireNonNull(v, "light V").normalized();
        if (!isZero(unitU.dotProduct(unitV)))
            throw new IllegalArgumentException("light U " + u + " and V " + v + " are not orthogonal");
        this.u = unitU;
        this.v = unitV;
        return this;
    }

    /**
     * Whether the square's sides were set with {@link #setUV}: otherwise the light chooses them
     * ({@link #getU(Point3D)}, or a spot light's square around its direction).
     *
     * @return true when U and V were set
     */
    public boolean isUVSet() {
        return u != null;
    }

    /** {@return the light's position} */
    public Point3D getPosition() {
        return position;
    }

    /** {@return the constant attenuation factor} */
    public double getKc() {
        return kC;
    }

    /** {@return the linear attenuation factor} */
    public double getKl() {
        return kL;
    }

    /** {@return the quadratic attenuation factor} */
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
        if (isAt(p))
            throw new IllegalArgumentException("the lit point " + p + " coincides with the light's position");
        return p.subtract(position).normalize();
    }

    /** {@return whether the point is the light's position (within the tolerance of {@link Point3D#equals})} */
    @Override
    public boolean isAt(Point3D p) {
        return requireNonNull(p, "lit point").equals(position);
    }

    @Override
    public double getDistance(Point3D p) {
        return requireNonNull(p, "lit point").distance(position);
    }

    @Override
    public double getEdges() {
        return edges;
    }

    /** {@return the light's position, the centre of its square} */
    @Override
    public Point3D getCenter() {
        return position;
    }

    @Override
    public Vector getU() {
        return u;
    }

    @Override
    public Vector getV() {
        return v;
    }

    /** When U was not set, the square faces the lit point: U is then orthogonal to the light's direction there. */
    @Override
    public Vector getU(Point3D p) {
        Vector setU = getU();
        return setU != null ? setU : getL(p).orthogonal();
    }

    /** When V was not set, the square faces the lit point: V is then l × U. */
    @Override
    public Vector getV(Point3D p) {
        Vector setV = getV();
        if (setV != null)
            return setV;
        Vector l = getL(p);
        return l.crossProduct(l.orthogonal()).normalize();
    }
}
