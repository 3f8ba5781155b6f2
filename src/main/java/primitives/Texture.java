package primitives;

/**
 * The colour of a surface at its surface coordinates (u, v): a textured body shows it instead of one
 * colour (see {@code geometries.Geometry#setTexture}). Each body says what its coordinates are: a mesh's
 * UVs, a sphere's longitude and latitude, a plane's or a polygon's position in its plane.
 */
@FunctionalInterface
public interface Texture {
    /**
     * The colour at a point of a surface.
     *
     * @param u the point's first surface coordinate
     * @param v the point's second surface coordinate
     * @return the colour there, on the 0..255 scale of {@link Color} (255 leaves the light as it is)
     */
    Color getColor(double u, double v);
}
