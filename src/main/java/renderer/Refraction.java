package renderer;

import primitives.Vector;

/**
 * What happens to a ray where it meets the surface of a body with an index of refraction: the
 * direction it bends to by Snell's law, n1·sin θ1 = n2·sin θ2, or total internal reflection when
 * there is none; and the share of its light that is reflected, by Schlick's approximation of the
 * Fresnel equations, R(θ) = R0 + (1 − R0)(1 − cos θ)^5 with R0 = ((n1 − n2)/(n1 + n2))², θ the angle
 * in the less dense medium. The surface is taken to part the body from empty space (ior 1): which side
 * a ray comes from says whether it enters or leaves.
 */
final class Refraction {
    /** The unit direction of the refracted ray, x, y and z, when there is one. */
    private final double tx;
    private final double ty;
    private final double tz;
    /** Whether the ray cannot leave: total internal reflection. */
    private final boolean total;
    /** The share of the light reflected (Schlick's approximation), 1 for total internal reflection. */
    private final double reflectance;

    /**
     * The refraction of a ray at a surface point.
     *
     * @param v   the unit direction of the incoming ray
     * @param n   the unit normal of the surface, outward
     * @param ior the body's index of refraction, 1 or more
     * @throws IllegalArgumentException when the ray runs along the surface (v ⊥ n)
     */
    Refraction(Vector v, Vector n, double ior) {
        double vn = v.dotProduct(n);
        if (vn == 0)
            throw new IllegalArgumentException("a ray along the surface neither enters nor leaves it");
        boolean entering = vn < 0;
        double n1 = entering ? 1 : ior;
        double n2 = entering ? ior : 1;
        double side = entering ? 1 : -1; // the normal turned toward the incoming ray: side · n
        double eta = n1 / n2;
        double cosIncident = -vn * side;
        double sinTransmittedSquared = eta * eta * (1 - cosIncident * cosIncident);
        total = sinTransmittedSquared > 1;
        if (total) {
            tx = ty = tz = Double.NaN;
            reflectance = 1;
            return;
        }
        double cosTransmitted = Math.sqrt(1 - sinTransmittedSquared);
        double along = (eta * cosIncident - cosTransmitted) * side;
        tx = eta * v.getX() + along * n.getX();
        ty = eta * v.getY() + along * n.getY();
        tz = eta * v.getZ() + along * n.getZ();
        reflectance = schlick(n1, n2, Math.min(cosIncident, cosTransmitted));
    }

    /**
     * Schlick's approximation of the share of light a surface between two media reflects.
     *
     * @param n1  the index of refraction on the incoming side
     * @param n2  the index of refraction on the other side
     * @param cos the cosine of the angle from the normal in the less dense medium (the larger angle)
     * @return R0 + (1 − R0)(1 − cos)^5, with R0 = ((n1 − n2)/(n1 + n2))²
     */
    static double schlick(double n1, double n2, double cos) {
        double r0 = (n1 - n2) / (n1 + n2);
        r0 *= r0;
        double m = 1 - cos;
        return r0 + (1 - r0) * m * m * m * m * m;
    }

    /** {@return true when the ray cannot leave the body: total internal reflection} */
    boolean isTotal() {
        return total;
    }

    /** {@return the unit direction of the refracted ray; not for total internal reflection} */
    Vector direction() {
        return new Vector(tx, ty, tz);
    }

    /** {@return the share of the light reflected by Schlick's approximation; 1 for total internal reflection} */
    double reflectance() {
        return reflectance;
    }
}
