package lighting;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

import primitives.Color;

/**
 * Unit tests for the abstract {@link lighting.Light}, through an anonymous subclass and through
 * {@link lighting.AmbientLight}.
 */
class LightTest {
    /** Test method for {@link lighting.Light#Light(primitives.Color)} and {@link lighting.Light#getIntensity()}. */
    @Test
    void testConstructorAndGetIntensity() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a light keeps the intensity it was given, (10, 20, 30)
        Color c = new Color(10, 20, 30);
        Light light = new Light(c) {
        };
        assertEquals(new Color(10, 20, 30), light.getIntensity(), "TC01: wrong intensity");
        // TC02: through AmbientLight with kA 1 the intensity is Ia, (10, 20, 30)
        assertEquals(new Color(10, 20, 30), new AmbientLight(c, 1).getIntensity(), "TC02: wrong intensity");

        // ===== Boundary Values Tests =====
        // TC10: a black light is allowed, intensity (0, 0, 0)
        assertEquals(Color.BLACK, new Light(Color.BLACK) {
        }.getIntensity(), "TC10: black light must keep black intensity");
        // TC11: a null intensity is rejected, the message names "intensity"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Light(null) {
        }, "TC11: null intensity must be rejected");
        assertMessage(e, "intensity", "TC11");
    }
}
