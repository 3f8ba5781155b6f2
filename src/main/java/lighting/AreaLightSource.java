package lighting;

import primitives.Point3D;
import primitives.Vector;

/**
 * A light with an area: a square of edge {@link #getEdges()} centred at {@link #getCenter()}, its
 * sides along the unit vectors {@link #getU()} and {@link #getV()}. Soft shadows sample this square.
 */
public interface AreaLightSource extends LightSource {
    /** {@return the length of the square's edge, 0 for a light with no area} */
    double getEdges();

    /** {@return the centre of the square} */
    Point3D getCenter();

    /** {@return the unit vector along one side of the square, or null when it was not set (see {@link #getU(Point3D)})} */
    Vector getU();

    /** {@return the unit vector along the other side of the square, or null when it was not set (see {@link #getV(Point3D)})} */
    Vector getV();

    /**
     * The square's first side as seen from a lit point: {@link #getU()} when it is set, otherwise
     * a side of the square that faces the point.
     *
     * @param p the lit point
     * @return a unit vector along one side of the square
     */
    Vector getU(Point3D p);

    /**
     * The square's second side as seen from a lit point, orthogonal to {@link #getU(Point3D)}.
     *
     * @param p the lit point
     * @return a unit vector along the other side of the square
     */
    Vector getV(Point3D p);
}
