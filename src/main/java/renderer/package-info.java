/**
 * From a scene to a picture: the {@link renderer.Camera} casts a ray through every pixel, the ray tracer
 * ({@link renderer.RayTracerBasic}, also named {@link renderer.BasicRayTracer}) gives the colour each ray
 * sees, and {@link renderer.Render} drives them over the picture, in parallel tiles, into an
 * {@link renderer.ImageWriter}, which writes the PNG.
 * <p>
 * Soft shadows, adaptive soft shadows and anti-aliasing all take their random points from one sampler,
 * {@link renderer.JitteredGrid}, fed by a random stream per pixel, so the same scene and settings give the
 * same picture bit for bit whatever the number of threads. So do the spread reflected and refracted rays of
 * glossy and blurry materials (a material's {@code kG} and {@code kB}), and depth of field (the camera's aperture,
 * {@link renderer.Camera#setApertureSize}); adaptive super-sampling
 * ({@link renderer.Render#setAdaptiveSuperSampling}) traces a pixel's corners and centre first and divides
 * only where they differ.
 */
package renderer;
