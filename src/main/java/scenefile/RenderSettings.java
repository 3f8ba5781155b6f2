package scenefile;

import renderer.JitteredGrid;
import renderer.RayTracerBase;
import renderer.Render;

/**
 * How a picture is rendered: soft shadows, shadow rays per light, anti-aliasing, the random seed and
 * the spread rays of glossy and blurry surfaces, and adaptive super-sampling.
 *
 * @param softShadows           whether lights with an area cast soft shadows
 * @param adaptiveSoftShadows   whether a light's square is sampled adaptively (outline first)
 * @param sqrtBeamNum           the number of shadow-ray cells along each side of a light's square, 1 to 1000
 * @param antiAliasing          the number of rays along each side of a pixel, 1 to 1000
 * @param seed                  the seed of the per-pixel random streams
 * @param sqrtGlossRays         the number of spread-ray cells along each side of the square of a glossy or
 *                              blurry surface, 1 to 1000
 * @param adaptiveSuperSampling whether pixels are super-sampled adaptively (corners and centre first)
 */
public record RenderSettings(boolean softShadows, boolean adaptiveSoftShadows, int sqrtBeamNum, int antiAliasing,
                             long seed, int sqrtGlossRays, boolean adaptiveSuperSampling) {
    /** Hard shadows, 9 × 9 cells, one ray per pixel, the default seed, 5 × 5 spread rays, not adaptive. */
    public static final RenderSettings DEFAULT = new RenderSettings(false, false,
            RayTracerBase.DEFAULT_SQRT_BEAM_NUM, 1, RayTracerBase.DEFAULT_SEED);

    /**
     * Checks the counts.
     *
     * @param softShadows           whether lights with an area cast soft shadows
     * @param adaptiveSoftShadows   whether a light's square is sampled adaptively
     * @param sqrtBeamNum           the number of shadow-ray cells along each side of a light's square, 1 to 1000
     * @param antiAliasing          the number of rays along each side of a pixel, 1 to 1000
     * @param seed                  the seed of the per-pixel random streams
     * @param sqrtGlossRays         the number of spread-ray cells along each side of a glossy or blurry
     *                              surface's square, 1 to 1000
     * @param adaptiveSuperSampling whether pixels are super-sampled adaptively
     * @throws IllegalArgumentException when a count is below 1 or above 1000
     */
    public RenderSettings {
        JitteredGrid.requireSqrtSamples(sqrtBeamNum, "sqrtBeamNum");
        JitteredGrid.requireSqrtSamples(antiAliasing, "anti-aliasing (rays along each side of a pixel)");
        JitteredGrid.requireSqrtSamples(sqrtGlossRays, "sqrtGlossRays");
    }

    /**
     * Checks the counts; glossy and blurry surfaces spread the default number of rays
     * ({@link RayTracerBase#DEFAULT_SQRT_GLOSS_RAYS} along each side), and pixels are not super-sampled
     * adaptively.
     *
     * @param softShadows         whether lights with an area cast soft shadows
     * @param adaptiveSoftShadows whether a light's square is sampled adaptively
     * @param sqrtBeamNum         the number of shadow-ray cells along each side of a light's square, 1 to 1000
     * @param antiAliasing        the number of rays along each side of a pixel, 1 to 1000
     * @param seed                the seed of the per-pixel random streams
     * @throws IllegalArgumentException when a count is below 1 or above 1000
     */
    public RenderSettings(boolean softShadows, boolean adaptiveSoftShadows, int sqrtBeamNum, int antiAliasing,
                          long seed) {
        this(softShadows, adaptiveSoftShadows, sqrtBeamNum, antiAliasing, seed, RayTracerBase.DEFAULT_SQRT_GLOSS_RAYS,
                false);
    }

    /**
     * Turns soft shadows on or off.
     *
     * @param on true for soft shadows
     * @return these settings with soft shadows on or off
     */
    public RenderSettings withSoftShadows(boolean on) {
        return new RenderSettings(on, adaptiveSoftShadows, sqrtBeamNum, antiAliasing, seed,
                sqrtGlossRays, adaptiveSuperSampling);
    }

    /**
     * Turns adaptive sampling of lights' squares on or off.
     *
     * @param on true for adaptive sampling of lights' squares
     * @return these settings with adaptive soft shadows on or off
     */
    public RenderSettings withAdaptiveSoftShadows(boolean on) {
        return new RenderSettings(softShadows, on, sqrtBeamNum, antiAliasing, seed,
                sqrtGlossRays, adaptiveSuperSampling);
    }

    /**
     * Sets the number of shadow rays per light.
     *
     * @param n the number of cells along each side of a light's square, 1 to 1000
     * @return these settings with n × n + 1 shadow rays per light
     */
    public RenderSettings withSqrtBeamNum(int n) {
        return new RenderSettings(softShadows, adaptiveSoftShadows, n, antiAliasing, seed,
                sqrtGlossRays, adaptiveSuperSampling);
    }

    /**
     * Sets the number of rays per pixel.
     *
     * @param k the number of rays along each side of a pixel, 1 to 1000
     * @return these settings with k × k rays per pixel
     */
    public RenderSettings withAntiAliasing(int k) {
        return new RenderSettings(softShadows, adaptiveSoftShadows, sqrtBeamNum, k, seed,
                sqrtGlossRays, adaptiveSuperSampling);
    }

    /**
     * Sets the seed of the random streams.
     *
     * @param newSeed the seed of the random streams
     * @return these settings with another seed
     */
    public RenderSettings withSeed(long newSeed) {
        return new RenderSettings(softShadows, adaptiveSoftShadows, sqrtBeamNum, antiAliasing, newSeed,
                sqrtGlossRays, adaptiveSuperSampling);
    }

    /**
     * Sets the number of spread rays of glossy and blurry surfaces.
     *
     * @param n the number of cells along each side of the square of spread rays, 1 to 1000
     * @return these settings with n × n spread rays at the first glossy or blurry surface of a path
     */
    public RenderSettings withSqrtGlossRays(int n) {
        return new RenderSettings(softShadows, adaptiveSoftShadows, sqrtBeamNum, antiAliasing, seed, n,
                adaptiveSuperSampling);
    }

    /**
     * Turns adaptive super-sampling of pixels on or off.
     *
     * @param on true for adaptive super-sampling
     * @return these settings with adaptive super-sampling on or off
     */
    public RenderSettings withAdaptiveSuperSampling(boolean on) {
        return new RenderSettings(softShadows, adaptiveSoftShadows, sqrtBeamNum, antiAliasing, seed, sqrtGlossRays,
                on);
    }

    /**
     * Passes the settings to a render whose ray tracer is set.
     *
     * @param render the render
     * @return the render
     */
    public Render applyTo(Render render) {
        return render.setSoftShadows(softShadows).setAdaptiveSoftShadows(adaptiveSoftShadows)
                .setSqrtBeamNum(sqrtBeamNum).setAntiAliasing(antiAliasing).setSeed(seed)
                .setSqrtGlossRays(sqrtGlossRays).setAdaptiveSuperSampling(adaptiveSuperSampling);
    }
}
