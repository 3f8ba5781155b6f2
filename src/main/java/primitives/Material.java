package primitives;

import static primitives.Util.requireFinite;
import static primitives.Util.requireNonNegative;

/**
 * The surface properties of a geometry in the Phong model: diffuse {@code kD}, specular {@code kS},
 * transparency {@code kT}, reflection {@code kR} and shininess {@code nShininess}, plus the glossiness
 * {@code kG} of its reflection and the blurriness {@code kB} of its transparency. All default to 0.
 * <p>
 * Glossiness and blurriness spread the reflected and refracted rays: the rays pass through a square
 * perpendicular to the sharp (mirror or straight-through) ray, at unit distance along it, whose
 * half-edge is {@code kG} (or {@code kB}). Both are in [0, 1]: 0 is the sharp mirror and the clear
 * glass, and 1 spreads rays up to 45° off the sharp ray along the square's axes.
 * <p>
 * Real glass: with an index of refraction ({@link #setIor}, 1 or more; none by default) the refracted
 * ray bends by Snell's law, entering and leaving the body, and where it cannot leave (total internal
 * reflection) its share {@code kT} goes to the reflection. With Fresnel on ({@link #setFresnel}), the
 * share {@code kT} splits between reflection and refraction by Schlick's approximation of the Fresnel
 * equations, about 4 % reflected at normal incidence on glass of ior 1.5 and almost all near grazing.
 * Without an ior, refracted rays go straight through, as in the course.
 */
public class Material {
    private double kD;
    private double kS;
    private double kT;
    private double kR;
    private int nShininess;
    private double kG;
    private double kB;
    /** The index of refraction, or 0 when there is none (the course's straight-through refraction). */
    private double ior;
    private boolean fresnel;

    /** Creates a material with every factor 0: a black body that neither reflects nor lets light through. */
    public Material() {
    }

    /**
     * Sets the diffuse factor.
     *
     * @param kD diffuse attenuation, 0 or more
     * @return this material
     */
    public Material setKd(double kD) {
        this.kD = requireNonNegative(kD, "material kD");
        return this;
    }

    /**
     * The course's spelling of {@link #setKd(double)}, the same setter.
     *
     * @param kD diffuse attenuation, 0 or more
     * @return this material
     */
    public Material setkD(double kD) {
        return setKd(kD);
    }

    /**
     * Sets the specular factor.
     *
     * @param kS specular attenuation, 0 or more
     * @return this material
     */
    public Material setKs(double kS) {
        this.kS = requireNonNegative(kS, "material kS");
        return this;
    }

    /**
     * The course's spelling of {@link #setKs(double)}, the same setter.
     *
     * @param kS specular attenuation, 0 or more
     * @return this material
     */
    public Material setkS(double kS) {
        return setKs(kS);
    }

    /**
     * Sets the transparency factor.
     *
     * @param kT transparency, in [0, 1]
     * @return this material
     */
    public Material setKt(double kT) {
        this.kT = requireFraction(kT, "material kT");
        return this;
    }

    /**
     * The course's spelling of {@link #setKt(double)}, the same setter.
     *
     * @param kT transparency, in [0, 1]
     * @return this material
     */
    public Material setkT(double kT) {
        return setKt(kT);
    }

    /**
     * Sets the reflection factor.
     *
     * @param kR reflection, in [0, 1]
     * @return this material
     */
    public Material setKr(double kR) {
        this.kR = requireFraction(kR, "material kR");
        return this;
    }

    /**
     * The course's spelling of {@link #setKr(double)}, the same setter.
     *
     * @param kR reflection, in [0, 1]
     * @return this material
     */
    public Material setkR(double kR) {
        return setKr(kR);
    }

    /**
     * Sets the shininess exponent.
     *
     * @param nShininess the exponent, 0 or more
     * @return this material
     */
    public Material setShininess(int nShininess) {
        if (nShininess < 0)
            throw new IllegalArgumentException("material shininess must not be negative, got " + nShininess);
        this.nShininess = nShininess;
        return this;
    }

    /**
     * The course's spelling of {@link #setShininess(int)}, the same setter.
     *
     * @param nShininess the exponent, 0 or more
     * @return this material
     */
    public Material setnShininess(int nShininess) {
        return setShininess(nShininess);
    }

    /**
     * Sets the glossiness: how far reflected rays spread around the mirror direction (see the class
     * comment for the geometry).
     *
     * @param kG the half-edge of the square of reflected rays at unit distance, in [0, 1]; 0 is a sharp mirror
     * @return this material
     */
    public Material setKg(double kG) {
        this.kG = requireFraction(kG, "material kG (glossiness)");
        return this;
    }

    /**
     * The course's spelling of {@link #setKg(double)}, the same setter.
     *
     * @param kG the glossiness, in [0, 1]
     * @return this material
     */
    public Material setkG(double kG) {
        return setKg(kG);
    }

    /**
     * Sets the blurriness: how far refracted rays spread around the straight-through direction (see
     * the class comment for the geometry).
     *
     * @param kB the half-edge of the square of refracted rays at unit distance, in [0, 1]; 0 is clear glass
     * @return this material
     */
    public Material setKb(double kB) {
        this.kB = requireFraction(kB, "material kB (blurriness)");
        return this;
    }

    /**
     * The course's spelling of {@link #setKb(double)}, the same setter.
     *
     * @param kB the blurriness, in [0, 1]
     * @return this material
     */
    public Material setkB(double kB) {
        return setKb(kB);
    }

    /**
     * Sets the index of refraction: the refracted rays bend by Snell's law (see the class comment).
     *
     * @param ior the body's index of refraction relative to the space around it, 1 or more (glass is
     *            about 1.5, water 1.33, diamond 2.42)
     * @return this material
     * @throws IllegalArgumentException when ior is less than 1, NaN or infinite
     */
    public Material setIor(double ior) {
        if (!(requireFinite(ior, "material ior (index of refraction)") >= 1))
            throw new IllegalArgumentException("material ior (index of refraction) must be at least 1, got " + ior);
        this.ior = ior;
        return this;
    }

    /**
     * Turns the Fresnel split of the transparency on or off: with it, the share {@code kT} of the light
     * divides between reflection and refraction by Schlick's approximation (see the class comment).
     *
     * @param fresnel true for the Fresnel split; it needs an index of refraction ({@link #setIor} first)
     * @return this material
     * @throws IllegalArgumentException when turned on for a material with no index of refraction
     */
    public Material setFresnel(boolean fresnel) {
        if (fresnel && !hasIor())
            throw new IllegalArgumentException("material Fresnel needs an index of refraction: call setIor first");
        this.fresnel = fresnel;
        return this;
    }

    /** {@return the diffuse factor} */
    public double getKd() {
        return kD;
    }

    /** {@return the specular factor} */
    public double getKs() {
        return kS;
    }

    /** {@return the transparency factor} */
    public double getKt() {
        return kT;
    }

    /** {@return the reflection factor} */
    public double getKr() {
        return kR;
    }

    /** {@return the shininess exponent} */
    public int getShininess() {
        return nShininess;
    }

    /** {@return the glossiness: the half-edge of the square of reflected rays at unit distance} */
    public double getKg() {
        return kG;
    }

    /** {@return the blurriness: the half-edge of the square of refracted rays at unit distance} */
    public double getKb() {
        return kB;
    }

    /** {@return the index of refraction, or 0 when there is none} */
    public double getIor() {
        return ior;
    }

    /** {@return true when the material has an index of refraction: its refracted rays bend} */
    public boolean hasIor() {
        return ior != 0;
    }

    /** {@return true when the transparency splits between reflection and refraction by Schlick's approximation} */
    public boolean isFresnel() {
        return fresnel;
    }

    private static double requireFraction(double value, String what) {
        if (requireNonNegative(value, what) > 1)
            throw new IllegalArgumentException(what + " must be at most 1, got " + value);
        return value;
    }

    @Override
    public String toString() {
        return "Material{kD=" + kD + ", kS=" + kS + ", kT=" + kT + ", kR=" + kR + ", nShininess=" + nShininess
                + ", kG=" + kG + ", kB=" + kB + (hasIor() ? ", ior=" + ior + ", fresnel=" + fresnel : "") + "}";
    }
}
