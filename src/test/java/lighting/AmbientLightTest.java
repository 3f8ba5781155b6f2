package lighting;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

import primitives.Color;

/**
 * Unit tests for {@link lighting.AmbientLight}.
 */
class AmbientLightTest {
    /** Test method for {@link lighting.AmbientLight#AmbientLight(primitives.Color, double)}. */
    @Test
    void testConstructorIaKa() {
        // ===== Equivalence Partitions Tests =====
        // TC01: intensity is Ia·kA, (100, 50, 20)·0.5 = (50, 25, 10)
        assertColor(50, 25, 10, new AmbientLight(new Color(100, 50, 20), 0.5).getIntensity(),
                "TC01: wrong intensity");
        // TC02: the course's ambient white ×0.15 gives (38.25, 38.25, 38.25)
        assertColor(38.25, 38.25, 38.25, new AmbientLight(new Color(255, 255, 255), 0.15).getIntensity(),
                "TC02: wrong intensity");
        // TC03: kA above 1 amplifies, (10, 20, 30)·2.5 = (25, 50, 75)
        assertColor(25, 50, 75, new AmbientLight(new Color(10, 20, 30), 2.5).getIntensity(),
                "TC03: wrong intensity");
        // TC04: a negative kA is rejected, the message names "kA"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new AmbientLight(new Color(10, 10, 10), -0.5), "TC04: negative kA must be rejected");
        assertMessage(e, "kA", "TC04");
        // TC05: a null colour is rejected, the message names the "colour"
        e = assertThrows(IllegalArgumentException.class, () -> new AmbientLight(null, 0.5),
                "TC05: null colour must be rejected");
        assertMessage(e, "colour", "TC05");
        // TC06: a NaN or infinite kA is rejected, the message names "kA"
        e = assertThrows(IllegalArgumentException.class,
                () -> new AmbientLight(new Color(10, 10, 10), Double.NaN), "TC06: NaN kA must be rejected");
        assertMessage(e, "kA", "TC06");
        e = assertThrows(IllegalArgumentException.class,
                () -> new AmbientLight(new Color(10, 10, 10), Double.POSITIVE_INFINITY),
                "TC06: infinite kA must be rejected");
        assertMessage(e, "kA", "TC06");

        // ===== Boundary Values Tests =====
        // TC10: kA 0 gives black (0, 0, 0)
        assertColor(0, 0, 0, new AmbientLight(new Color(100, 50, 20), 0).getIntensity(), "TC10: kA 0 must be black");
        // TC11: kA 1 gives Ia itself (100, 50, 20)
        assertColor(100, 50, 20, new AmbientLight(new Color(100, 50, 20), 1).getIntensity(), "TC11: kA 1 must give Ia");
        // TC12: a black Ia gives black (0, 0, 0) whatever kA
        assertColor(0, 0, 0, new AmbientLight(Color.BLACK, 0.7).getIntensity(), "TC12: black Ia must be black");
        // TC13: a slightly negative kA is still rejected, the message names "kA"
        e = assertThrows(IllegalArgumentException.class,
                () -> new AmbientLight(new Color(10, 10, 10), -1e-12), "TC13: kA -1e-12 must be rejected");
        assertMessage(e, "kA", "TC13");
    }

    /** Test method for {@link lighting.AmbientLight#AmbientLight()}. */
    @Test
    void testConstructorDefault() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the no-argument ambient light is black (0, 0, 0)
        AmbientLight light = new AmbientLight();
        assertColor(0, 0, 0, light.getIntensity(), "TC01: default ambient light must be black");
        assertEquals(Color.BLACK, light.getIntensity(), "TC01: default ambient light must equal Color.BLACK");
    }
}
