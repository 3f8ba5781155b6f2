package renderer;

import scene.Scene;

/**
 * The course's other name for {@link RayTracerBasic}: the same tracer, usable wherever it is
 * (for example {@link Render#setRayTracer}), so test files written against either name compile.
 */
public class BasicRayTracer extends RayTracerBasic {

    /**
     * Creates a ray tracer for a scene.
     *
     * @param scene the scene
     * @throws IllegalArgumentException when the scene is null
     */
    public BasicRayTracer(Scene scene) {
        super(scene);
    }
}
