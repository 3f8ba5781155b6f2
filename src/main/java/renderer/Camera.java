package renderer;

import java.util.MissingResourceException;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.isZero;
import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * A pinhole camera: a position {@code p0}, an orthonormal frame {@code vTo}, {@code vUp},
 * {@code vRight = vTo × vUp}, and a view plane at a distance in front of it through which rays
 * are cast to the pixels of the image.
 */
public class Camera {
    private final Point3D p0;
    private final Vector vTo;
    private final Vector vUp;
    private final Vector vRight;
    private double width;
    private double height;
    private double distance;

    /**
     * Creates a camera; it keeps unit copies of the direction vectors.
     *
     * @param p0  the camera's position
     * @param vTo the direction it looks to
     * @param vUp its up direction, orthogonal to {@code vTo}
     * @throws IllegalArgumentException when {@code vTo} and {@code vUp} are not orthogonal
     */
    public Camera(Point3D p0, Vector vTo, Vector vUp) {
        this.p0 = requireNonNull(p0, "camera position");
        requireNonNull(vTo, "camera vTo");
        requireNonNull(vUp, "camera vUp");
        this.vTo = vTo.normalized();
        this.vUp = vUp.normalized();
        if (!isZero(this.vTo.dotProduct(this.vUp)))
            throw new IllegalArgumentException("camera vTo " + vTo + " and vUp " + vUp + " are not orthogonal");
        this.vRight = this.vTo.crossProduct(this.vUp).normalize();
    }

    /**
     * Sets the size of the view plane (the report's name; {@link #setViewPlaneSize} is the course's).
     *
     * @param width  its width, positive
     * @param height its height, positive
     * @return this camera
     * @throws IllegalArgumentException when a size is not positive or not finite
     */
    public Camera setVpSize(double width, double height) {
        this.width = requirePositive(width, "view plane width");
        this.height = requirePositive(height, "view plane height");
        return this;
    }

    /**
     * Sets the size of the view plane: the course's name for {@link #setVpSize}, the same setter.
     *
     * @param width  its width, positive
     * @param height its height, positive
     * @return this camera
     * @throws IllegalArgumentException when a size is not positive or not finite
     */
    public Camera setViewPlaneSize(double width, double height) {
        return setVpSize(width, height);
    }

    /**
     * Sets the distance from the camera to the view plane (the report's name; {@link #setDistance}
     * is the course's).
     *
     * @param distance the distance, positive
     * @return this camera
     * @throws IllegalArgumentException when the distance is not positive or not finite
     */
    public Camera setVpDistance(double distance) {
        this.distance = requirePositive(distance, "view plane distance");
        return this;
    }

    /**
     * Sets the distance from the camera to the view plane: the course's name for
     * {@link #setVpDistance}, the same setter.
     *
     * @param distance the distance, positive
     * @return this camera
     * @throws IllegalArgumentException when the distance is not positive or not finite
     */
    public Camera setDistance(double distance) {
        return setVpDistance(distance);
    }

    /** {@return the position} */
    public Point3D getP0() {
        return p0;
    }

    /** {@return the unit forward direction} */
    public Vector getVTo() {
        return vTo;
    }

    /** {@return the unit up direction} */
    public Vector getVUp() {
        return vUp;
    }

    /** {@return the unit right direction, vTo × vUp} */
    public Vector getVRight() {
        return vRight;
    }

    /** {@return the view plane width (0 until set)} */
    public double getWidth() {
        return width;
    }

    /** {@return the view plane height (0 until set)} */
    public double getHeight() {
        return height;
    }

    /** {@return the view plane distance (0 until set)} */
    public double getDistance() {
        return distance;
    }

    /**
     * Casts the ray from the camera through the centre of a pixel.
     *
     * @param nX number of columns in the image
     * @param nY number of rows in the image
     * @param j  the pixel's column, 0 at the left
     * @param i  the pixel's row, 0 at the top
     * @return the ray from the camera through the pixel's centre
     * @throws IllegalArgumentException       for a non-positive image size or a pixel outside it
     * @throws MissingResourceException when the view plane size or distance was not set
     */
    public Ray constructRayThroughPixel(int nX, int nY, int j, int i) {
        return constructRayThroughPixel(nX, nY, j, i, 0.5, 0.5);
    }

    /**
     * Casts the ray from the camera through a point inside a pixel.
     *
     * @param nX number of columns in the image
     * @param nY number of rows in the image
     * @param j  the pixel's column, 0 at the left
     * @param i  the pixel's row, 0 at the top
     * @param dx the point's offset from the pixel's left edge, as a fraction of its width (0..1)
     * @param dy the point's offset from the pixel's top edge, as a fraction of its height (0..1)
     * @return the ray from the camera through that point
     * @throws IllegalArgumentException       for a non-positive image size, a pixel outside it, or an
     *                                        offset outside 0..1
     * @throws MissingResourceException when the view plane size or distance was not set
     */
    public Ray constructRayThroughPixel(int nX, int nY, int j, int i, double dx, double dy) {
        if (nX <= 0 || nY <= 0)
            throw new IllegalArgumentException("image size must be positive, got " + nX + "x" + nY);
        if (j < 0 || j >= nX || i < 0 || i >= nY)
            throw new IllegalArgumentException("pixel (" + j + ", " + i + ") is outside the " + nX + "x" + nY + " image");
        if (!(dx >= 0 && dx <= 1 && dy >= 0 && dy <= 1))
            throw new IllegalArgumentException("pixel offset (" + dx + ", " + dy + ") is outside 0..1");
        if (width == 0 || height == 0)
            throw new MissingResourceException("camera view plane size is not set", "Camera", "vpSize");
        if (distance == 0)
            throw new MissingResourceException("camera view plane distance is not set", "Camera", "vpDistance");
        double xJ = (j + dx - nX / 2.0) * width / nX;
        double yI = -(i + dy - nY / 2.0) * height / nY;
        return new Ray(p0, new Vector(
                distance * vTo.getX() + xJ * vRight.getX() + yI * vUp.getX(),
                distance * vTo.getY() + xJ * vRight.getY() + yI * vUp.getY(),
                distance * vTo.getZ() + xJ * vRight.getZ() + yI * vUp.getZ()));
    }
}
