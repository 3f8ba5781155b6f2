package primitives;

import static primitives.Util.requireNonNegative;
import static primitives.Util.requirePositive;

/**
 * An immutable RGB colour with non-negative double components on the 0..255 scale; components may
 * exceed 255 while light adds up and are clamped only when converted to {@link java.awt.Color}.
 * Sums, products and quotients that would overflow stay at the largest double (a light far too
 * bright is white, not an error).
 */
public class Color {
    /** Black: no light. */
    public static final Color BLACK = new Color(0, 0, 0);

    private final double r;
    private final double g;
    private final double b;

    /**
     * Creates a colour from its components.
     *
     * @param r red, 0 or more
     * @param g green, 0 or more
     * @param b blue, 0 or more
     * @throws IllegalArgumentException for a negative, NaN or infinite component
     */
    public Color(double r, double g, double b) {
        this.r = requireNonNegative(r, "red component");
        this.g = requireNonNegative(g, "green component");
        this.b = requireNonNegative(b, "blue component");
    }

    /**
     * Creates a colour from an AWT colour.
     *
     * @param other the AWT colour
     */
    public Color(java.awt.Color other) {
        this(Util.requireNonNull(other, "colour").getRed(), other.getGreen(), other.getBlue());
    }

    /** {@return the red component} */
    public double getR() {
        return r;
    }

    /** {@return the green component} */
    public double getG() {
        return g;
    }

    /** {@return the blue component} */
    public double getB() {
        return b;
    }

    /**
     * Adds a colour to this one: the same as {@link #add(Color...)} with one colour, without its array.
     *
     * @param color the colour to add
     * @return the new colour, the component-wise sum
     * @throws IllegalArgumentException when the colour is null
     */
    public Color add(Color color) {
        Util.requireNonNull(color, "colour to add");
        return saturated(r + color.r, g + color.g, b + color.b);
    }

    /**
     * Adds colours to this one.
     *
     * @param colors the colours to add
     * @return the new colour, the component-wise sum
     * @throws IllegalArgumentException when the array or one of the colours is null
     */
    public Color add(Color... colors) {
        Util.requireNonNull(colors, "colours to add");
        double rr = r;
        double rg = g;
        double rb = b;
        for (Color c : colors) {
            Util.requireNonNull(c, "colour to add");
            rr += c.r;
            rg += c.g;
            rb += c.b;
        }
        return saturated(rr, rg, rb);
    }

    /**
     * Scales the colour.
     *
     * @param k the factor, 0 or more
     * @return the new colour
     * @throws IllegalArgumentException for a negative or non-finite factor
     */
    public Color scale(double k) {
        requireNonNegative(k, "colour scale factor");
        return saturated(r * k, g * k, b * k);
    }

    /**
     * Divides the colour.
     *
     * @param k the divisor, positive
     * @return the new colour
     * @throws IllegalArgumentException for a divisor that is not positive
     */
    public Color reduce(double k) {
        requirePositive(k, "colour reduce divisor");
        return saturated(r / k, g / k, b / k);
    }

    /** The colour of the result of arithmetic on finite components, an overflow kept at the largest double. */
    private static Color saturated(double r, double g, double b) {
        return new Color(Math.min(r, Double.MAX_VALUE), Math.min(g, Double.MAX_VALUE), Math.min(b, Double.MAX_VALUE));
    }

    /** {@return the AWT colour, each component truncated to an integer and clamped to 0..255} */
    public java.awt.Color getColor() {
        return new java.awt.Color(getRGB());
    }

    /**
     * {@return the colour packed in an int as 0xRRGGBB, each component truncated to an integer and clamped
     * to 0..255, as in {@link #getColor()} (whose {@code getRGB()} adds an opaque alpha, 0xFF000000)}
     */
    public int getRGB() {
        return clamp(r) << 16 | clamp(g) << 8 | clamp(b);
    }

    private static int clamp(double component) {
        return (int) Math.min(255, component);
    }

    @Override
    public boolean equals(Object obj) {
        if (this == obj)
            return true;
        return obj instanceof Color other
                && Util.isZero(r - other.r) && Util.isZero(g - other.g) && Util.isZero(b - other.b);
    }

    @Override
    public int hashCode() {
        return 41;
    }

    @Override
    public String toString() {
        return "rgb(" + r + ", " + g + ", " + b + ")";
    }
}
