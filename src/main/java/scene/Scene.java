package scene;

import java.util.ArrayList;
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
    /** The light sources. */
    public List<LightSource> lights = new ArrayList<>();

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
     */
    public Scene setLights(List<LightSource> lights) {
        requireNonNull(lights, "scene lights");
        for (LightSource light : lights)
            requireNonNull(light, "a scene light");
        this.lights = lights;
        return this;
    }
}
