package lighting;

import primitives.Color;

import static primitives.Util.requireNonNull;

/**
 * A light with an intensity.
 */
public abstract class Light {
    /** The light's intensity. */
    protected final Color intensity;

    /**
     * Creates a light.
     *
     * @param intensity the light's intensity
     */
    protected Light(Color intensity) {
        this.intensity = requireNonNull(intensity, "light intensity");
    }

    /** {@return the light's intensity} */
    public Color getIntensity() {
        return intensity;
    }
}
