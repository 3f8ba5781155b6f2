package primitives;

import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * A checkerboard: squares of two colours, alternating in u and in v. The square (i, j) holding the point
 * (u, v), i = ⌊u / size⌋ and j = ⌊v / size⌋, has the first colour when i + j is even, the second when it
 * is odd; so the square from (0, 0) to (size, size) has the first colour.
 */
public class CheckerTexture implements Texture {
    private final Color color1;
    private final Color color2;
    private final double size;

    /**
     * Creates a checkerboard.
     *
     * @param color1 the colour of the square at the origin and of every other one
     * @param color2 the colour of the others
     * @param size   the edge of a square in surface coordinates, positive (in scene units on a plane or a
     *               polygon; a fraction of the whole for a mesh's UVs and a sphere's longitude and latitude)
     * @throws IllegalArgumentException when a colour is null or the size is not a finite positive number
     */
    public CheckerTexture(Color color1, Color color2, double size) {
        this.color1 = requireNonNull(color1, "checker texture's first colour");
        this.color2 = requireNonNull(color2, "checker texture's second colour");
        this.size = requirePositive(size, "checker texture's square size");
    }

    @Override
    public Color getColor(double u, double v) {
        long square = (long) Math.floor(u / size) + (long) Math.floor(v / size);
        return (square & 1) == 0 ? color1 : color2;
    }

    /** {@return the colour of the square at the origin} */
    public Color getColor1() {
        return color1;
    }

    /** {@return the colour of the squares next to it} */
    public Color getColor2() {
        return color2;
    }

    /** {@return the edge of a square in surface coordinates} */
    public double getSize() {
        return size;
    }

    @Override
    public String toString() {
        return "CheckerTexture{" + color1 + ", " + color2 + ", size=" + size + "}";
    }
}
