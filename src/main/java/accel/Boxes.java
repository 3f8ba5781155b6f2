package accel;

/**
 * Axis-aligned boxes kept in flat arrays of doubles, six numbers each (x0, y0, z0, x1, y1, z1), as the
 * build and the closed meshes' caps use them. An empty box has +∞ lows and −∞ highs: growing it by a
 * point or a box gives that point's or that box's.
 */
final class Boxes {
    private Boxes() {
    }

    /** {@return an array of count empty boxes} */
    static double[] empty(int count) {
        double[] boxes = new double[6 * count];
        for (int b = 0; b < boxes.length; b += 6)
            clear(boxes, b);
        return boxes;
    }

    /** Makes the box at b empty. */
    static void clear(double[] boxes, int b) {
        for (int k = 0; k < 3; ++k) {
            boxes[b + k] = Double.POSITIVE_INFINITY;
            boxes[b + 3 + k] = Double.NEGATIVE_INFINITY;
        }
    }

    /** Grows the box at b around a point. */
    static void include(double[] boxes, int b, double x, double y, double z) {
        boxes[b] = Math.min(boxes[b], x);
        boxes[b + 1] = Math.min(boxes[b + 1], y);
        boxes[b + 2] = Math.min(boxes[b + 2], z);
        boxes[b + 3] = Math.max(boxes[b + 3], x);
        boxes[b + 4] = Math.max(boxes[b + 4], y);
        boxes[b + 5] = Math.max(boxes[b + 5], z);
    }

    /** Grows the box at b of boxes around the box at o of other (an empty other changes nothing). */
    static void grow(double[] boxes, int b, double[] other, int o) {
        if (other[o] > other[o + 3])
            return; // an empty box
        for (int k = 0; k < 3; ++k) {
            boxes[b + k] = Math.min(boxes[b + k], other[o + k]);
            boxes[b + 3 + k] = Math.max(boxes[b + 3 + k], other[o + 3 + k]);
        }
    }

    /** Grows every box of boxes by a distance on each side. */
    static void pad(double[] boxes, double by) {
        for (int b = 0; b < boxes.length; b += 6)
            for (int k = 0; k < 3; ++k) {
                boxes[b + k] -= by;
                boxes[b + 3 + k] += by;
            }
    }

    /** {@return the axis (0, 1 or 2 for x, y, z) along which the box at b is longest, the first of equals} */
    static int widestAxis(double[] boxes, int b) {
        double x = boxes[b + 3] - boxes[b];
        double y = boxes[b + 4] - boxes[b + 1];
        double z = boxes[b + 5] - boxes[b + 2];
        return x >= y && x >= z ? 0 : y >= z ? 1 : 2;
    }

    /** {@return half the surface area of the box at b (the surface-area heuristic's measure)} */
    static double halfArea(double[] boxes, int b) {
        double x = boxes[b + 3] - boxes[b];
        double y = boxes[b + 4] - boxes[b + 1];
        double z = boxes[b + 5] - boxes[b + 2];
        return x * y + y * z + z * x;
    }

    /** {@return the longest side of the box at b} */
    static double extent(double[] boxes, int b) {
        return Math.max(boxes[b + 3] - boxes[b], Math.max(boxes[b + 4] - boxes[b + 1], boxes[b + 5] - boxes[b + 2]));
    }
}
