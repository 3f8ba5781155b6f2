package app;

import renderer.Camera;
import scene.Scene;

import static primitives.Util.requireNonNull;

/**
 * One picture of the gallery: a scene, the camera that looks at it, and the image's name and size.
 *
 * @param name         the image's file name, without extension
 * @param nX           the number of columns
 * @param nY           the number of rows
 * @param scene        the scene
 * @param camera       the camera
 * @param gridInterval the distance in pixels between grid lines drawn over the picture, 0 for none
 * @param softShadows  whether lights with an area cast soft shadows
 */
public record Picture(String name, int nX, int nY, Scene scene, Camera camera, int gridInterval, boolean softShadows) {
    /** Checks the parts. */
    public Picture {
        requireNonNull(name, "picture name");
        requireNonNull(scene, "picture scene");
        requireNonNull(camera, "picture camera");
        if (nX <= 0 || nY <= 0)
            throw new IllegalArgumentException("picture size must be positive, got " + nX + "x" + nY);
        if (gridInterval < 0)
            throw new IllegalArgumentException("grid interval must not be negative, got " + gridInterval);
    }

    /**
     * A picture with no grid.
     *
     * @param name   the image's file name, without extension
     * @param nX     the number of columns
     * @param nY     the number of rows
     * @param scene  the scene
     * @param camera the camera
     */
    public Picture(String name, int nX, int nY, Scene scene, Camera camera) {
        this(name, nX, nY, scene, camera, 0, false);
    }

    /**
     * The same picture with soft shadows, under another name.
     *
     * @param softName the soft picture's file name, without extension
     * @return the soft-shadow picture
     */
    public Picture withSoftShadows(String softName) {
        return new Picture(softName, nX, nY, scene, camera, gridInterval, true);
    }
}
