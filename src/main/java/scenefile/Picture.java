package scenefile;

import java.nio.file.Path;

import primitives.Color;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.Render;
import scene.Scene;

import static primitives.Util.requireNonNull;

/**
 * One picture: a scene, the camera that looks at it, the image's name and size, and how it is rendered.
 *
 * @param name         the image's file name, without extension
 * @param nX           the number of columns
 * @param nY           the number of rows
 * @param scene        the scene
 * @param camera       the camera
 * @param gridInterval the distance in pixels between grid lines drawn over the picture, 0 for none
 * @param settings     soft shadows, anti-aliasing and the seed
 */
public record Picture(String name, int nX, int nY, Scene scene, Camera camera, int gridInterval,
                      RenderSettings settings) {
    /** The colour of the grid lines. */
    public static final Color GRID_COLOR = new Color(java.awt.Color.YELLOW);

    /**
     * Checks the parts.
     *
     * @param name         the image's file name, without extension
     * @param nX           the number of columns, positive
     * @param nY           the number of rows, positive
     * @param scene        the scene
     * @param camera       the camera
     * @param gridInterval the distance in pixels between grid lines, 0 for none
     * @param settings     soft shadows, anti-aliasing and the seed
     * @throws IllegalArgumentException when a part is null, the size is not positive or the grid
     *                                  interval is negative
     */
    public Picture {
        requireNonNull(name, "picture name");
        requireNonNull(scene, "picture scene");
        requireNonNull(camera, "picture camera");
        requireNonNull(settings, "picture render settings");
        ImageWriter.requireSize(nX, nY);
        if (gridInterval < 0)
            throw new IllegalArgumentException("grid interval must not be negative, got " + gridInterval);
    }

    /**
     * A picture with no grid and the default settings.
     *
     * @param name   the image's file name, without extension
     * @param nX     the number of columns
     * @param nY     the number of rows
     * @param scene  the scene
     * @param camera the camera
     */
    public Picture(String name, int nX, int nY, Scene scene, Camera camera) {
        this(name, nX, nY, scene, camera, 0, RenderSettings.DEFAULT);
    }

    /**
     * The same picture with soft shadows, under another name.
     *
     * @param softName the soft picture's file name, without extension
     * @return the soft-shadow picture
     */
    public Picture withSoftShadows(String softName) {
        return new Picture(softName, nX, nY, scene, camera, gridInterval, settings.withSoftShadows(true));
    }

    /**
     * The same picture rendered another way.
     *
     * @param newSettings the settings
     * @return the picture with these settings
     */
    public Picture withSettings(RenderSettings newSettings) {
        return new Picture(name, nX, nY, scene, camera, gridInterval, newSettings);
    }

    /**
     * The same picture at another size (the camera's view plane is unchanged).
     *
     * @param width  the number of columns
     * @param height the number of rows
     * @return the picture at this size
     */
    public Picture withSize(int width, int height) {
        return new Picture(name, width, height, scene, camera, gridInterval, settings);
    }

    /**
     * A render of this picture, ready to run: its image, camera, ray tracer and settings are set.
     *
     * @param file the image file; its extension names the format ({@code .png}, {@code .jpg},
     *             {@code .jpeg} or {@code .bmp})
     * @return the render
     * @throws IllegalArgumentException when the file is null or its extension names no format written here
     */
    public Render newRender(Path file) {
        Render render = new Render().setImageWriter(ImageWriter.forFile(file, nX, nY))
                .setCamera(camera).setRayTracer(new RayTracerBasic(scene));
        return settings.applyTo(render);
    }

    /**
     * Runs a render made by {@link #newRender(Path)}, draws the grid when the picture has one, and
     * writes the PNG file. Whether the file can be written is checked before rendering.
     *
     * @param render the render, perhaps with more settings (threads, progress) than newRender gave it
     * @return the render, its image still in memory for a look at the pixels
     * @throws java.io.UncheckedIOException when the PNG file cannot be written
     */
    public Render render(Render render) {
        render.getImageWriter().checkOutput();
        render.renderImage();
        if (gridInterval > 0)
            render.printGrid(gridInterval, GRID_COLOR);
        render.writeToImage();
        return render;
    }
}
