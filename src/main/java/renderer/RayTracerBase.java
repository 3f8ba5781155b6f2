package renderer;

import primitives.Color;
import primitives.Ray;
import scene.Scene;

import static primitives.Util.requireNonNull;

/**
 * A ray tracer: finds the colour a ray sees in a scene.
 */
public abstract class RayTracerBase {
    /** The scene traced. */
    protected final Scene scene;

    /**
     * Creates a ray tracer for a scene.
     *
     * @param scene the scene
     */
    protected RayTracerBase(Scene scene) {
        this.scene = requireNonNull(scene, "scene");
    }

    /**
     * The colour seen along a ray.
     *
     * @param ray the ray
     * @return the colour it sees (the background when it hits nothing)
     */
    public abstract Color traceRay(Ray ray);
}
