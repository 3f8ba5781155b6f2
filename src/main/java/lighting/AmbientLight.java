package lighting;

import primitives.Color;

import static primitives.Util.requireNonNegative;
import static primitives.Util.requireNonNull;

/**
 * The ambient light: a uniform intensity {@code Ia·kA} added to every lit point.
 */
public class AmbientLight extends Light {
    /**
     * Creates an ambient light of intensity Ia·kA.
     *
     * @param Ia the original intensity
     * @param kA the attenuation factor, 0 or more
     */
    public AmbientLight(Color Ia, double kA) {
        super(requireNonNull(Ia, "ambient light colour").scale(requireNonNegative(kA, "ambient light kA")));
    }

    /** Creates a black (absent) ambient light. */
    public AmbientLight() {
        super(Color.BLACK);
    }
}
