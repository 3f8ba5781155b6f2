package testutil;

import renderer.ImageWriter;

/**
 * Comparisons of rendered images that several test classes make.
 */
public final class TestImages {
    /** Not instantiable. */
    private TestImages() {
    }

    /**
     * The number of pixels that differ between two rendered images of the same size.
     *
     * @param a one image
     * @param b the other, as large
     * @return how many of their pixels differ
     */
    public static int differentPixels(ImageWriter a, ImageWriter b) {
        int count = 0;
        for (int y = 0; y < a.getNy(); ++y)
            for (int x = 0; x < a.getNx(); ++x)
                if (!a.getPixel(x, y).equals(b.getPixel(x, y)))
                    ++count;
        return count;
    }
}
