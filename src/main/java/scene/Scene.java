package scene;

import java.util.List;

import geometries.Geometries;
import lighting.AmbientLight;
import lighting.LightSource;
import primitives.Color;

import static primitives.Util.requireNonNull;

/**
 * What a picture shows: the bodies, the lights, the ambient light and the background colour.
 * Its fields are public, as in the course; the setters return the scene for chaining.
 */
public class Scene {
    /** The scene's name. */
    public final String name;
    /** The colour of rays that hit nothing (black by default). */
    public Color background = Color.BLACK;
    /** The ambient light (none by default). */
    public AmbientLight ambientLight = new AmbientLight();
    /** The bodies. */
    public Geometries geometries = new Geometries();
    /** The light sources: a list that refuses null, until another list is set. */
    public List<LightSource> lights = new LightList();

    /**
     * Creates an empty scene.
     *
     * @param name the scene's name
     */
    public Scene(String name) {
        this.name = requireNonNull(name, "scene name");
    }

    /**
     * Sets the background colour.
     *
     * @param background the colour of rays that hit nothing
     * @return this scene
     */
    public Scene setBackground(Color background) {
        this.background = requireNonNull(background, "scene background");
        return this;
    }

    /**
     * Sets the ambient light.
     *
     * @param ambientLight the ambient light
     * @return this scene
     */
    public Scene setAmbientLight(AmbientLight ambientLight) {
        this.ambientLight = requireNonNull(ambientLight, "scene ambient light");
        return this;
    }

    /**
     * Sets the bodies.
     *
     * @param geometries the bodies
     * @return this scene
     */
    public Scene setGeometries(Geometries geometries) {
        this.geometries = requireNonNull(geometries, "scene geometries");
        return this;
    }

    /**
     * Sets the light sources.
     *
     * @param lights the light sources
     * @return this scene
     * @throws IllegalArgumentException when the list is null or holds null
     */
    public Scene setLights(List<LightSource> lights) {
        this.lights = requireLights(lights);
        return this;
    }

    /**
     * Checks that the scene can be rendered as its public fields are now: none of them null, and no null
     * among the lights. A renderer calls this before any pixel, since the fields may have been assigned
     * directly (and a list set with {@link #setLights} changed since).
     *
     * @throws IllegalArgumentException naming the field, or the index of a null light
     */
    public void requireComplete() {
        requireNonNull(background, "scene.background");
        requireNonNull(ambientLight, "scene.ambientLight");
        requireNonNull(geometries, "scene.geometries");
        requireLights(lights);
    }

    /** Checks a list of lights: not null, and no null in it; returns it. */
    private static List<LightSource> requireLights(List<LightSource> lights) {
        requireNonNull(lights, "scene.lights");
        for (int i = 0; i < lights.size(); ++i)
            requireLight(lights.get(i), i);
        return lights;
    }

    /**
     * Checks a light of the scene's list.
     *
     * @param light the light
     * @param index its place in the list
     * @return the light
     * @throws IllegalArgumentException when the light is null
     */
    static LightSource requireLight(LightSource light, int index) {
        if (light == null)
            throw new IllegalArgumentException("scene.lights must not hold null (at index " + index
                    + "): every light must be a light source");
        return light;
    }
}
