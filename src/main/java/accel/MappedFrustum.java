package accel;

/**
 * A bundle's pyramid carried into an instance's space by the instance's inverse transform, so that the
 * body can be asked in its own space whether any ray of the bundle may meet it. An affine map takes
 * the pyramid to a pyramid whose base is a parallelogram still, and every ray of the bundle to a ray
 * inside it; it stretches distances by at most its norm, so the thickness grows by that, and it
 * carries the back face's plane by its inverse transpose. The rays' origins, when the bundle leaves a
 * surface on both sides, are not carried: the body's tree then sets nothing aside behind them, which
 * keeps every answer conservative.
 */
final class MappedFrustum {
    private final double[] apex = new double[3];
    private final double[] base = new double[9];
    private final double[] direction = new double[3];

    /**
     * Sets a frustum to a pyramid carried by an affine map.
     *
     * @param target the frustum to set
     * @param world  the bundle's pyramid, in the space the map comes from
     * @param m      the map, 12 numbers (see {@link primitives.Transform#toArray})
     * @return false when the bundle's pyramid is not set or the carried one is flat: target must then
     *         not be asked
     */
    boolean set(ShadowFrustum target, ShadowFrustum world, double[] m) {
        if (!world.isSet())
            return false;
        double[] v = world.vertices();
        mapPoint(m, v[0], v[1], v[2], apex, 0);
        // the corners are c + a + b, c − a + b, c − a − b, c + a − b
        mapPoint(m, (v[3] + v[9]) / 2, (v[4] + v[10]) / 2, (v[5] + v[11]) / 2, base, 0);
        mapVector(m, (v[3] - v[6]) / 2, (v[4] - v[7]) / 2, (v[5] - v[8]) / 2, base, 3);
        mapVector(m, (v[3] - v[12]) / 2, (v[4] - v[13]) / 2, (v[5] - v[14]) / 2, base, 6);
        if (!target.set(apex, base, world.thickness() * norm(m)))
            return false;
        if (world.backFaceDirection(direction))
            setBackFace(target, m);
        return true;
    }

    /** Asks the target for the back face across the world's direction carried by the inverse transpose of m. */
    private void setBackFace(ShadowFrustum target, double[] m) {
        // (L⁻¹)ᵀ = cof(L) / det(L), the cofactor rows r1 × r2, r2 × r0, r0 × r1 of L's rows r0, r1, r2
        double c0x = m[5] * m[10] - m[6] * m[9];
        double c0y = m[6] * m[8] - m[4] * m[10];
        double c0z = m[4] * m[9] - m[5] * m[8];
        double c1x = m[9] * m[2] - m[10] * m[1];
        double c1y = m[10] * m[0] - m[8] * m[2];
        double c1z = m[8] * m[1] - m[9] * m[0];
        double c2x = m[1] * m[6] - m[2] * m[5];
        double c2y = m[2] * m[4] - m[0] * m[6];
        double c2z = m[0] * m[5] - m[1] * m[4];
        double sign = Math.signum(m[0] * c0x + m[1] * c0y + m[2] * c0z);
        double x = direction[0];
        double y = direction[1];
        double z = direction[2];
        target.setBackFace(sign * (c0x * x + c0y * y + c0z * z), sign * (c1x * x + c1y * y + c1z * z),
                sign * (c2x * x + c2y * y + c2z * z));
    }

    /** Writes m times the point (x, y, z) at an array's place. */
    private static void mapPoint(double[] m, double x, double y, double z, double[] out, int at) {
        mapVector(m, x, y, z, out, at);
        out[at] += m[3];
        out[at + 1] += m[7];
        out[at + 2] += m[11];
    }

    /** Writes m's linear part times the vector (x, y, z) at an array's place. */
    private static void mapVector(double[] m, double x, double y, double z, double[] out, int at) {
        out[at] = m[0] * x + m[1] * y + m[2] * z;
        out[at + 1] = m[4] * x + m[5] * y + m[6] * z;
        out[at + 2] = m[8] * x + m[9] * y + m[10] * z;
    }

    /** {@return the Frobenius norm of m's linear part: at least the most it stretches a length} */
    private static double norm(double[] m) {
        double sum = 0;
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col)
                sum += m[4 * row + col] * m[4 * row + col];
        return Math.sqrt(sum);
    }
}
