package accel;

/**
 * A bundle's pyramid carried into an instance's space by the instance's inverse transform, so that the
 * body can be asked in its own space whether any ray of the bundle may meet it. An affine map takes
 * the pyramid to a pyramid whose base is a parallelogram still, and every ray of the bundle to a ray
 * inside it; it stretches distances by at most its norm, so the thickness grows by that, and the
 * back face's plane goes by its inverse transpose (the transpose of the instance's own transform). The rays' origins, when the bundle leaves a
 * surface on both sides, are not carried: the body's tree then sets nothing aside behind them, which
 * keeps every answer conservative.
 */
final class MappedFrustum {
    private final double[] apex = new double[3];
    private final double[] base = new double[9];
    private final double[] direction = new double[3];
    /** The pyramid the last {@link #set} carried, its {@link ShadowFrustum#serial} then, the map, and whether it could. */
    private ShadowFrustum from;
    private long fromSerial;
    private double[] by;
    private boolean carried;

    /**
     * Sets a frustum to a pyramid carried by an affine map.
     *
     * @param target the frustum to set
     * @param world  the bundle's pyramid, in the space the map comes from
     * @param m      the map, 12 numbers (see {@link primitives.Transform#toArray})
     * @param back   the map's inverse, 12 numbers: its transpose carries the back face's direction
     * @return false when the bundle's pyramid is not set or the carried one is flat: target must then
     *         not be asked
     */
    boolean set(ShadowFrustum target, ShadowFrustum world, double[] m, double[] back) {
        from = world;
        fromSerial = world.serial();
        by = m;
        carried = carry(target, world, m, back);
        return carried;
    }

    /**
     * Whether the last {@link #set} carried this pyramid, unchanged since, by this map (the same
     * array): what was found for the carried pyramid then still holds.
     *
     * @param world the bundle's pyramid
     * @param m     the map
     * @return true when the carried pyramid is the one the last set made
     */
    boolean holds(ShadowFrustum world, double[] m) {
        return world == from && world.serial() == fromSerial && m == by;
    }

    /** {@return whether the last {@link #set} could carry its pyramid} */
    boolean isCarried() {
        return carried;
    }

    /** {@link #set}'s work; false when the pyramid is not set or the carried one is flat. */
    private boolean carry(ShadowFrustum target, ShadowFrustum world, double[] m, double[] back) {
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
        if (world.backFaceDirection(direction)) {
            double x = direction[0];
            double y = direction[1];
            double z = direction[2];
            // a plane's normal goes by the inverse transpose of the map: the transpose of back
            target.setBackFace(back[0] * x + back[4] * y + back[8] * z, back[1] * x + back[5] * y + back[9] * z,
                    back[2] * x + back[6] * y + back[10] * z);
        }
        return true;
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
