package renderer;

import java.util.MissingResourceException;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.isZero;
import static primitives.Util.requireNonNegative;
import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * A camera: a position {@code p0}, an orthonormal frame {@code vTo}, {@code vUp},
 * {@code vRight = vTo × vUp}, and a view plane at a distance in front of it through which rays
 * are cast to the pixels of the image.
 * <p>
 * Depth of field: with an aperture (a square of edge {@link #setApertureSize}, centred on {@code p0}
 * in the {@code vRight}/{@code vUp} plane), the rays of a pixel start at jittered points of the
 * aperture (n × n of them, n set by {@link #setSqrtApertureRays}) and all aim at the point where the
 * pixel's pinhole ray meets the focal plane, at {@link #setFocalDistance} along {@code vTo}: what lies on that
 * plane is sharp, the rest blurs in proportion to its distance from it. Without a focal distance the
 * view plane is in focus. An aperture of 0, the default, is the pinhole camera.
 */
public class Camera {
    /** The default square root of the number of rays through the aperture: 9 × 9 = 81, as for shadow rays. */
    public static final int DEFAULT_SQRT_APERTURE_RAYS = 9;
    /**
     * The largest aperture size and focal distance, 1e100 (as for the numbers of a scene file): the rays'
     * starting points and directions then stay far from overflowing.
     */
    public static final double MAX_LENS_SIZE = 1e100;
    /** The sine of the angle between vTo and vUp below which {@link #orthogonalUp} takes them for parallel. */
    private static final double PARALLEL_SINE = 1e-6;
    /** The fewest and (one past) the most decimals {@link #orthogonalUp} rounds to. */
    private static final int MIN_UP_DECIMALS = 4;
    private static final int MAX_UP_DECIMALS = 16;

    private final Point3D p0;
    private final Vector vTo;
    private final Vector vUp;
    private final Vector vRight;
    private double width;
    private double height;
    private double distance;
    private double focalDistance;
    private double apertureSize;
    private JitteredGrid apertureGrid = new JitteredGrid(DEFAULT_SQRT_APERTURE_RAYS);

    /**
     * Creates a camera; it keeps unit copies of the direction vectors.
     *
     * @param p0  the camera's position
     * @param vTo the direction it looks to
     * @param vUp its up direction, orthogonal to {@code vTo}
     * @throws IllegalArgumentException when {@code vTo} and {@code vUp} are not orthogonal; the message
     *                                  says what {@code vUp} would be ({@link #orthogonalUp})
     */
    public Camera(Point3D p0, Vector vTo, Vector vUp) {
        this.p0 = requireNonNull(p0, "camera position");
        requireNonNull(vTo, "camera vTo");
        requireNonNull(vUp, "camera vUp");
        this.vTo = vTo.normalized();
        this.vUp = vUp.normalized();
        if (!isZero(this.vTo.dotProduct(this.vUp)))
            throw new IllegalArgumentException("camera vTo " + vTo + " and vUp " + vUp + " are not orthogonal: "
                    + upHint(vTo, vUp));
        this.vRight = this.vTo.crossProduct(this.vUp).normalize();
    }

    /**
     * A camera at a point, aimed at another: {@code vTo} is the unit direction from {@code from} to
     * {@code to}, {@code vUp} the part of {@code up} orthogonal to it, normalized (not rounded, unlike
     * {@link #orthogonalUp}), and {@code vRight = vTo × vUp}. {@code lookAt((0, 0, 10), (0, 0, 0), (0, 1, 0))}
     * is the course's camera looking down −z.
     *
     * @param from where the camera is
     * @param to   the point it looks at
     * @param up   the direction up (any length, not parallel to {@code to − from})
     * @return the camera, its view plane not yet set
     * @throws IllegalArgumentException when a parameter is null, the two points coincide, or {@code up}
     *                                  is parallel to the direction (within a millionth of a radian)
     */
    public static Camera lookAt(Point3D from, Point3D to, Vector up) {
        requireNonNull(from, "lookAt from");
        requireNonNull(to, "lookAt to");
        requireNonNull(up, "lookAt up");
        if (from.equals(to))
            throw new IllegalArgumentException("lookAt from and to are the same point " + from
                    + ": the camera has no direction to look to");
        Vector vTo = to.subtract(from).normalize();
        double[] part = orthogonalPart(vTo, up.normalized());
        if (part == null)
            throw new IllegalArgumentException("lookAt up " + up + " is parallel to the direction from " + from
                    + " to " + to + ": no part of it is orthogonal to the direction");
        return new Camera(from, vTo, new Vector(part[0], part[1], part[2]));
    }

    /**
     * The part of a unit up vector orthogonal to a unit direction, normalized (Gram–Schmidt).
     *
     * @return its x, y and z, or null when the two are parallel within {@link #PARALLEL_SINE}
     */
    private static double[] orthogonalPart(Vector to, Vector up) {
        double dot = to.dotProduct(up);
        double x = up.getX() - dot * to.getX();
        double y = up.getY() - dot * to.getY();
        double z = up.getZ() - dot * to.getZ();
        double sine = Math.sqrt(x * x + y * y + z * z);
        return sine < PARALLEL_SINE ? null : new double[] {x / sine, y / sine, z / sine};
    }

    /** What vUp would be, for the message refusing a vUp that is not orthogonal to vTo. */
    private static String upHint(Vector vTo, Vector vUp) {
        try {
            return "the part of vUp orthogonal to vTo, normalized, is " + orthogonalUp(vTo, vUp);
        } catch (IllegalArgumentException e) {
            return "vUp is parallel to vTo, and one orthogonal to it is " + vTo.orthogonal();
        }
    }

    /**
     * The up direction a camera looking along {@code vTo} takes for a {@code vUp} that is not quite
     * orthogonal to it: the part of {@code vUp} orthogonal to {@code vTo}, normalized, and rounded to
     * the fewest decimals (4 at least) with which it is still orthogonal to {@code vTo} as the
     * constructor checks it. {@code orthogonalUp(new Vector(0, -0.1, -1), new Vector(0, 1, 0))} is
     * (0, 0.995, -0.0995), which a camera looking slightly down accepts.
     *
     * @param vTo the direction the camera looks to
     * @param vUp the up direction wanted
     * @return a new vector orthogonal to {@code vTo}, of length 1 up to its rounding
     * @throws IllegalArgumentException when a vector is null, or {@code vUp} is parallel to {@code vTo}
     *                                  (within a millionth of a radian): no part of it is orthogonal
     */
    public static Vector orthogonalUp(Vector vTo, Vector vUp) {
        Vector to = requireNonNull(vTo, "camera vTo").normalized();
        Vector up = requireNonNull(vUp, "camera vUp").normalized();
        double[] part = orthogonalPart(to, up);
        if (part == null)
            throw new IllegalArgumentException("camera vUp " + vUp + " is parallel to vTo " + vTo
                    + ": no part of it is orthogonal to vTo");
        for (int decimals = MIN_UP_DECIMALS; decimals < MAX_UP_DECIMALS; ++decimals) {
            Vector rounded = new Vector(round(part[0], decimals), round(part[1], decimals), round(part[2], decimals));
            if (isZero(to.dotProduct(rounded.normalized())))
                return rounded;
        }
        return new Vector(part[0], part[1], part[2]);
    }

    /** {@return the number rounded to this many decimals, half up} */
    private static double round(double value, int decimals) {
        double scale = Math.pow(10, decimals);
        return Math.round(value * scale) / scale;
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

    /**
     * Sets the distance from the camera to the plane in focus, along {@code vTo} (depth of field).
     *
     * @param focalDistance the distance, positive, at most {@link #MAX_LENS_SIZE}; until set, the view
     *                      plane's distance
     * @return this camera
     * @throws IllegalArgumentException when the distance is not positive, not finite or too large
     */
    public Camera setFocalDistance(double focalDistance) {
        this.focalDistance = requireFocalDistance(focalDistance, "focal distance");
        return this;
    }

    /**
     * Sets the edge of the camera's square aperture (depth of field): the wider, the more what lies off
     * the focal plane blurs.
     *
     * @param apertureSize the edge, 0 (the default: a pinhole camera, everything sharp) to
     *                     {@link #MAX_LENS_SIZE}
     * @return this camera
     * @throws IllegalArgumentException when the size is negative, not finite or too large
     */
    public Camera setApertureSize(double apertureSize) {
        this.apertureSize = requireApertureSize(apertureSize, "aperture size");
        return this;
    }

    /**
     * Checks a focal distance.
     *
     * @param focalDistance the distance
     * @param what          what it is, for the message
     * @return the distance
     * @throws IllegalArgumentException when it is not positive, not finite or more than {@link #MAX_LENS_SIZE}
     */
    public static double requireFocalDistance(double focalDistance, String what) {
        return requireLensSize(requirePositive(focalDistance, what), what);
    }

    /**
     * Checks an aperture size.
     *
     * @param apertureSize the size
     * @param what         what it is, for the message
     * @return the size
     * @throws IllegalArgumentException when it is negative, not finite or more than {@link #MAX_LENS_SIZE}
     */
    public static double requireApertureSize(double apertureSize, String what) {
        return requireLensSize(requireNonNegative(apertureSize, what), what);
    }

    private static double requireLensSize(double size, String what) {
        if (size > MAX_LENS_SIZE)
            throw new IllegalArgumentException(what + " must be at most " + MAX_LENS_SIZE + ", got " + size);
        return size;
    }

    /**
     * Sets the number of rays through the aperture for each point of a pixel: the aperture's square is
     * divided into n × n cells, and one ray starts at a jittered point of each.
     *
     * @param sqrtApertureRays n, 1 to {@link JitteredGrid#MAX_SQRT_SAMPLES} ({@link #DEFAULT_SQRT_APERTURE_RAYS}
     *                         by default)
     * @return this camera
     * @throws IllegalArgumentException when n is less than 1 or more than {@link JitteredGrid#MAX_SQRT_SAMPLES}
     */
    public Camera setSqrtApertureRays(int sqrtApertureRays) {
        JitteredGrid.requireSqrtSamples(sqrtApertureRays, "sqrtApertureRays (aperture rays along each side)");
        this.apertureGrid = new JitteredGrid(sqrtApertureRays);
        return this;
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

    /** {@return the distance to the plane in focus (the view plane's distance until set)} */
    public double getFocalDistance() {
        return focalDistance == 0 ? distance : focalDistance;
    }

    /** {@return the edge of the square aperture (0: a pinhole camera)} */
    public double getApertureSize() {
        return apertureSize;
    }

    /** {@return whether the camera has an aperture, and so depth of field} */
    public boolean hasAperture() {
        return apertureSize > 0;
    }

    /** {@return the square root of the number of rays through the aperture per point of a pixel} */
    public int getSqrtApertureRays() {
        return apertureGrid.getSqrtSamples();
    }

    /** {@return the grid the rays' starting points on the aperture come from} */
    public JitteredGrid getApertureGrid() {
        return apertureGrid;
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
        requirePixelPoint(nX, nY, j, i, dx, dy);
        return new Ray(p0, direction(distance, xJ(nX, j, dx), yI(nY, i, dy)));
    }

    /**
     * Casts a ray of depth of field: from a point of the aperture to the point where the pinhole ray
     * through a point inside a pixel meets the focal plane.
     *
     * @param nX the number of columns in the image
     * @param nY the number of rows in the image
     * @param j  the pixel's column, 0 at the left
     * @param i  the pixel's row, 0 at the top
     * @param dx the point's offset from the pixel's left edge, as a fraction of its width (0..1)
     * @param dy the point's offset from the pixel's top edge, as a fraction of its height (0..1)
     * @param u  the ray's start along the aperture's edge in the vRight direction, as a fraction of it (0..1)
     * @param v  the ray's start along the aperture's edge in the vUp direction, as a fraction of it (0..1)
     * @return the ray from the aperture point through the focal point
     * @throws IllegalArgumentException for a non-positive image size, a pixel outside it, or an offset
     *                                  outside 0..1
     * @throws MissingResourceException when the view plane size or distance was not set
     */
    public Ray constructRayThroughAperture(int nX, int nY, int j, int i, double dx, double dy, double u, double v) {
        requirePixelPoint(nX, nY, j, i, dx, dy);
        if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1))
            throw new IllegalArgumentException("aperture offset (" + u + ", " + v + ") is outside 0..1");
        double scale = getFocalDistance() / distance;
        double right = (u - 0.5) * apertureSize;
        double up = (v - 0.5) * apertureSize;
        Point3D start = new Point3D(p0.getX() + right * vRight.getX() + up * vUp.getX(),
                p0.getY() + right * vRight.getY() + up * vUp.getY(),
                p0.getZ() + right * vRight.getZ() + up * vUp.getZ());
        return new Ray(start, direction(distance * scale, xJ(nX, j, dx) * scale - right,
                yI(nY, i, dy) * scale - up));
    }

    private void requirePixelPoint(int nX, int nY, int j, int i, double dx, double dy) {
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
    }

    /** The horizontal offset on the view plane of a point in column j, rightwards from the centre. */
    private double xJ(int nX, int j, double dx) {
        return (j + dx - nX / 2.0) * width / nX;
    }

    /** The vertical offset on the view plane of a point in row i, upwards from the centre. */
    private double yI(int nY, int i, double dy) {
        return -(i + dy - nY / 2.0) * height / nY;
    }

    /** The vector forward · vTo + right · vRight + up · vUp. */
    private Vector direction(double forward, double right, double up) {
        return new Vector(forward * vTo.getX() + right * vRight.getX() + up * vUp.getX(),
                forward * vTo.getY() + right * vRight.getY() + up * vUp.getY(),
                forward * vTo.getZ() + right * vRight.getZ() + up * vUp.getZ());
    }
}
