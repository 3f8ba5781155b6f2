package primitives;

import static primitives.Util.requireNonNegative;

/**
 * The surface properties of a geometry in the Phong model: diffuse {@code kD}, specular {@code kS},
 * transparency {@code kT}, reflection {@code kR} and shininess {@code nShininess}. All default to 0.
 */
public class Material {
    private double kD;
    private double kS;
    private double kT;
    private double kR;
    private int nShininess;

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

    private static double requireFraction(double value, String what) {
        if (requireNonNegative(value, what) > 1)
            throw new IllegalArgumentException(what + " must be at most 1, got " + value);
        return value;
    }

    @Override
    public String toString() {
        return "Material{kD=" + kD + ", kS=" + kS + ", kT=" + kT + ", kR=" + kR + ", nShininess=" + nShininess + "}";
    }
}
