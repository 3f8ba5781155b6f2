package testutil;

import java.nio.file.Path;

/**
 * The small animated scene several test classes render: a blue sphere of radius 20 at (30, 0, 0) in a
 * group that spins a full turn about y over the run, seen from (0, 0, 200) down −z on a 60 × 60 view
 * plane at 100 — so at time 0 it is right of centre, at 0.5 left of it — on 24 × 24 pixels.
 */
public final class TestAnimations {
    /** The scene file's text, with a place ({@code %s}) for more elements of {@code <scene>}. */
    public static final String SPINNING = """
            <scene background-color="0 0 0">
              <camera p0="0 0 200" vTo="0 0 -1" vUp="0 1 0" vp-width="60" vp-height="60" vp-distance="100"/>
              <image width="24" height="24"/>
              <ambient-light color="255 255 255" kA="0.1"/>
              <lights><directional-light color="300 300 300" direction="0 0 -1"/></lights>
              %s
              <geometries>
                <geometries name="ring">
                  <transform spin-y="360"/>
                  <sphere center="30 0 0" radius="20" emission="0 0 200" kD="0.5"/>
                </geometries>
              </geometries>
            </scene>
            """;
    /** The pixel (column and row) of the sphere's centre at time 0; at time 0.5 it is at its mirror, 24 − 1 − x. */
    public static final int[] SPHERE_AT_START = {18, 12};

    /** Not instantiable. */
    private TestAnimations() {
    }

    /**
     * Writes the spinning scene.
     *
     * @param folder the folder, created when missing
     * @param name   the file's name
     * @param more   more elements of {@code <scene>}, such as an {@code <animation>}, or ""
     * @return the file
     */
    public static Path spinning(Path folder, String name, String more) {
        return TestFiles.write(folder, name, SPINNING.formatted(more));
    }

    /**
     * Whether a pixel is the sphere's: mostly blue.
     *
     * @param rgb the pixel's RGB
     * @return true when its blue is above 100 and above its red and green
     */
    public static boolean isSphere(int rgb) {
        int r = rgb >> 16 & 0xFF;
        int g = rgb >> 8 & 0xFF;
        int b = rgb & 0xFF;
        return b > 100 && b > r && b > g;
    }
}
