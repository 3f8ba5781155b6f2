package accel;

/**
 * Whether every ray of a shadow bundle passes through a core of a closed mesh, one of its inner
 * boxes ({@link InnerBoxes}), on its way to a base outside the mesh's box. Each such ray passes
 * through the inside of the mesh and ends outside it, so it crosses the mesh's surface: an opaque
 * closed mesh blocks the whole bundle, and no ray of it is traced. The tests are conservative, as
 * the pyramid's own ({@link ShadowFrustum}): a core counts only when the rays pass inside it by
 * more than the pyramid's thickness and margin.
 */
final class CoreCrossing {
    /** Not instantiable. */
    private CoreCrossing() {
    }

    /**
     * Whether every ray of the bundle passes through an inner box of a closed mesh ({@link InnerBoxes})
     * before its end: the box lies wholly before the base's plane by the thickness and margin, and each
     * of the four rays from the apex to the base's corners passes through it shrunk by them.
     * The rays from the apex through a convex box fill a convex cone, which then holds every ray of
     * the pyramid; a ray that strays from the pyramid by up to the thickness passes through the box
     * itself. The base must lie outside the mesh's box too ({@link #baseOutside}): the caller's test.
     *
     * @param frustum the bundle's pyramid
     * @param boxes   an array of boxes, {minX, minY, minZ, maxX, maxY, maxZ} each
     * @param offset  where the inner box starts in the array
     * @return true when every ray passes through the box; false when that is not sure (always after
     *         a refused {@link ShadowFrustum#set})
     */
    static boolean crossesBox(ShadowFrustum frustum, double[] boxes, int offset) {
        double m = frustum.margin();
        for (int k = 0; k < 3; ++k)
            if (!(boxes[offset + k] + m <= boxes[offset + 3 + k] - m))
                return false;
        if (!(frustum.isSet() && frustum.beyondBase(boxes, offset) < -m))
            return false;
        for (int i = 3; i < 15; i += 3)
            if (!segmentThrough(frustum.vertices(), i, boxes, offset, m))
                return false;
        return true;
    }

    /**
     * Whether the segment from the apex to the pyramid's vertex at i (a corner of the base) passes
     * through a box shrunk by a margin (closed).
     */
    private static boolean segmentThrough(double[] v, int i, double[] boxes, int offset, double shrink) {
        double enter = 0;
        double leave = 1;
        for (int k = 0; k < 3; ++k) {
            double low = boxes[offset + k] + shrink;
            double high = boxes[offset + 3 + k] - shrink;
            double a = v[k];
            double d = v[i + k] - a;
            if (d == 0) {
                if (a < low || a > high)
                    return false;
                continue;
            }
            double s0 = (low - a) / d;
            double s1 = (high - a) / d;
            enter = Math.max(enter, Math.min(s0, s1));
            leave = Math.min(leave, Math.max(s0, s1));
        }
        return enter <= leave;
    }

    /**
     * Whether the base, grown by the thickness and margin, lies outside a box.
     *
     * @param frustum the bundle's pyramid
     * @param box     an array of boxes, {minX, minY, minZ, maxX, maxY, maxZ} each
     * @param offset  where the box starts in the array
     * @return true when the base lies outside the box
     */
    static boolean baseOutside(ShadowFrustum frustum, double[] box, int offset) {
        double[] v = frustum.vertices();
        double margin = frustum.margin();
        for (int k = 0; k < 3; ++k) {
            double low = Math.min(Math.min(v[3 + k], v[6 + k]), Math.min(v[9 + k], v[12 + k]));
            double high = Math.max(Math.max(v[3 + k], v[6 + k]), Math.max(v[9 + k], v[12 + k]));
            if (high + margin < box[offset + k] || low - margin > box[offset + 3 + k])
                return true;
        }
        return false;
    }
}
