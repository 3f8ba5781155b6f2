package app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestCommands.run;
import static testutil.TestImages.samePixels;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.regex.MatchResult;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import picocli.CommandLine;

import scenefile.ObjMesh;
import testutil.TestCommands.Result;
import testutil.TestFiles;

import static testutil.TestAssertions.assertPrintable;

/**
 * Tests for {@link RenderCommand}: the command runs in this process, its out and err writers captured;
 * the pictures are small and go to {@code target/test-cli/} (never {@code images/}).
 */
class RenderCommandTest {
    /** Where the tests' scene files and pictures go. */
    private static final Path FOLDER = Path.of("target", "test-cli");
    /** The seed of the fuzz test's mutations. */
    private static final long FUZZ_SEED = 13;
    /** How many mutated scene files the fuzz test runs. */
    private static final int FUZZ_CASES = 400;
    /** Values the fuzz test puts in place of a number or an attribute's value. */
    private static final List<String> FUZZ_VALUES = List.of("1e308", "-1e308", "1.7976931348623157e308", "4.9e-324",
            "1e-320", "0", "-0", "-1", "1e100", "1e101", "1e-200", "NaN", "INF", "99999999999", "2147483648", "46341",
            "1001", "x", "", "1 2", "0 0 0", "1e400", "0.0000000001");
    /** Characters the fuzz test inserts. */
    private static final String FUZZ_CHARACTERS = "<>&\"'/= \n\u0000\u00e9";
    /** Element names the fuzz test puts in place of another. */
    private static final List<String> FUZZ_ELEMENTS = List.of("sphere", "triangle", "polygon", "plane", "tube",
            "cylinder", "mesh", "geometries", "camera", "image", "render", "point-light", "spot-light",
            "directional-light", "lights", "scene");
    private static final Pattern NUMBER = Pattern.compile("(?<=[\" ])-?\\d+(\\.\\d+)?([eE][-+]?\\d+)?(?=[\" ])");
    private static final Pattern VALUE = Pattern.compile("=\"[^\"]*\"");
    private static final Pattern NAME = Pattern.compile("(?<=</?)[a-z-]+");
    /** How long the killed render runs, in milliseconds: it is still rendering or writing then. */
    private static final long KILL_DELAY_MS = 1500;

    /**
     * The test scene: a grey floor, a blue sphere above it, and a square light of edge 80 casting the
     * sphere's shadow on the floor; 300 × 200 pixels, hard shadows, 9 × 9 beams.
     */
    private static final String SCENE = """
            <scene background-color="20 20 40">
              <camera p0="0 0 1000" vTo="0 0 -1" vUp="0 1 0" vp-width="300" vp-height="200" vp-distance="1000"/>
              <image width="300" height="200"/>
              %s
              <ambient-light color="255 255 255" kA="0.1"/>
              <lights>
                <point-light color="600 600 600" position="50 50 300" kL="0.0001" edge="80" u="1 0 0" v="0 1 0"/>
              </lights>
              <geometries>
                <polygon vertices="-150 -150 -200  150 -150 -200  150 150 -200  -150 150 -200" kD="0.6"/>
                <sphere center="0 0 -100" radius="50" emission="0 0 120" kD="0.5" kS="0.5" nShininess="30"/>
              </geometries>
            </scene>
            """;

    private static Path sceneFile;

    /** Writes the test scene (with the file's own settings, hard shadows) into the test folder. */
    @BeforeAll
    static void writeScene() {
        sceneFile = writeScene("cliScene.xml", "");
    }

    private static Path writeScene(String name, String renderElement) {
        return TestFiles.write(FOLDER, name, SCENE.formatted(renderElement));
    }

    /** An empty folder of this name under the test folder, emptied of an earlier run's files. */
    private static Path freshFolder(String name) throws IOException {
        Path folder = FOLDER.resolve(name);
        if (Files.exists(folder))
            try (var paths = Files.walk(folder)) {
                for (Path path : paths.sorted(Comparator.reverseOrder()).toList())
                    Files.delete(path);
            }
        return Files.createDirectories(folder);
    }

    /** Runs the command in this process, not on a terminal. */

    /** Renders the test scene to target/test-cli/NAME.png with more arguments, checking that it succeeds. */
    private static Result render(String name, String... args) {
        String[] all = new String[args.length + 3];
        all[0] = sceneFile.toString();
        all[1] = "-o";
        all[2] = FOLDER.resolve(name + ".png").toString();
        System.arraycopy(args, 0, all, 3, args.length);
        Result result = run(all);
        assertEquals(0, result.code(), "render " + Arrays.toString(args) + " failed: " + result.err());
        return result;
    }

    private static BufferedImage image(String name) throws IOException {
        return ImageIO.read(FOLDER.resolve(name + ".png").toFile());
    }

    /** A number printed after a label in the command's report, e.g. "Shadow rays:  1234". */
    private static long reported(Result result, String label) {
        Matcher m = Pattern.compile("(?m)^" + Pattern.quote(label) + "\\s+(\\d+)").matcher(result.out());
        assertTrue(m.find(), "no '" + label + "' in the report: " + result.out());
        return Long.parseLong(m.group(1));
    }

    private static long shadowRays(Result result) {
        return reported(result, "Shadow rays:");
    }

    /** Checks a failure printed exactly one line, with no stack trace, and no progress bar. */
    private static void assertOneLine(Result result, String tc) {
        assertEquals(1, result.errLines().size(), tc + ": not one line on the error stream: " + result.err());
        assertTrue(result.err().endsWith(System.lineSeparator()), tc + ": the line is not ended");
        assertNoStackTrace(result, tc);
        assertFalse(result.err().contains("Rendering"), tc + ": the progress bar started");
        assertEquals("", result.out(), tc + ": nothing should go to the output stream");
    }

    private static void assertNoStackTrace(Result result, String tc) {
        assertFalse(result.err().contains("\tat "), tc + ": stack trace printed: " + result.err());
        assertFalse(result.err().contains("Exception"), tc + ": exception class name printed: " + result.err());
    }

    /**
     * Test method for {@link RenderCommand#call()}: scene files of smooth textured meshes and of glass render
     * from the command line, and a missing texture is one line naming it.
     */
    @Test
    void testMeshesTexturesAndGlass() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: the gallery's Spot (an OBJ file with vt, its texture) and glass sphere render, 60 pixels wide
        for (String name : new String[] { "spotSmoothFlat", "glassSphereChecker" }) {
            Result result = run(Path.of("scenes", name + ".xml").toString(), "-o", FOLDER.resolve(name + ".png").toString(),
                    "--width", "60");
            assertEquals(0, result.code(), "TC01: " + name + " failed: " + result.err());
            assertEquals(40, image(name).getHeight(), "TC01: " + name + " keeps its proportions");
        }
        // ===== Boundary Values Tests =====
        // TC11: a texture file that is missing: exit 2, one line naming the scene file's line and the image
        Path missing = TestFiles.write(FOLDER, "missingTexture.xml", "<scene><geometries><sphere center=\"0 0 -100\""
                + " radius=\"10\"><image-texture file=\"nowhere.png\"/></sphere></geometries></scene>\n");
        Result result = run(missing.toString(), "-o", FOLDER.resolve("missingTexture.png").toString());
        assertEquals(2, result.code(), "TC11: a missing texture must exit 2");
        assertOneLine(result, "TC11");
        assertTrue(result.err().contains(missing + ":1:") && result.err().contains("nowhere.png"),
                "TC11: the line must name the scene file and the image: " + result.err());
    }

    /** Test method for {@link RenderCommand#call()}: a render succeeds and reports what it did. */
    @Test
    void testRender() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: a 40 x 40 render: exit 0, a 40 x 40 PNG, 1600 primary rays, the report on out, the bar on err
        Path png = FOLDER.resolve("render40.png");
        Files.deleteIfExists(png);
        Result result = render("render40", "--width", "40", "--height", "40");
        assertTrue(Files.exists(png), "TC01: no image written");
        BufferedImage image = image("render40");
        assertEquals(40, image.getWidth(), "TC01: wrong image width");
        assertEquals(40, image.getHeight(), "TC01: wrong image height");
        assertEquals(1600, reported(result, "Primary rays:"), "TC01: wrong primary ray count");
        assertTrue(shadowRays(result) > 0, "TC01: no shadow rays counted");
        assertTrue(result.out().contains("Image:        " + png.toAbsolutePath().normalize()),
                "TC01: the image file is not reported: " + result.out());
        assertTrue(result.out().contains("Size:         40 x 40 pixels"), "TC01: the size is not reported");
        assertTrue(result.out().matches("(?s).*Time: +\\d+\\.\\d{3} s.*"), "TC01: the time is not reported");
        assertTrue(result.out().matches("(?s).*Rays/second: +\\d+.*"), "TC01: rays per second not reported");
        assertTrue(result.err().contains("Rendering 100%"), "TC01: no progress bar on the error stream: "
                + result.err());
        assertFalse(result.out().contains("Rendering"), "TC01: the progress bar went to the output stream");
        assertFalse(result.err().contains("\r"), "TC01: a bar redrawn in place while not on a terminal");

        // TC02: anti-aliasing 2: 2 x 2 rays per pixel
        result = render("render40aa", "--width", "40", "--height", "40", "--aa", "2");
        assertEquals(6400, reported(result, "Primary rays:"), "TC02: --aa 2 should trace 6400 primary rays");

        // TC03: on a terminal the bar redraws its line (carriage returns) and ends with a line break; the
        // note on the light's edge (hard shadows) comes before it
        result = run(true, sceneFile.toString(), "-o", FOLDER.resolve("render40term.png").toString(),
                "--width", "40", "--height", "40");
        assertEquals(0, result.code(), "TC03: wrong exit code");
        String bar = result.err().substring(result.err().indexOf(System.lineSeparator()) + System.lineSeparator().length());
        assertTrue(result.err().startsWith(sceneFile + ": <point-light> has edge 80"), "TC03: " + result.err());
        assertTrue(bar.startsWith("\rRendering"), "TC03: bar not redrawn in place: " + result.err());
        assertTrue(result.err().endsWith(System.lineSeparator()), "TC03: the bar's line is not ended");
        assertEquals(1600, reported(result, "Primary rays:"), "TC03: wrong primary ray count");

        // ===== Boundary Values Tests =====
        // TC11: a 1 x 1 picture
        result = render("render1", "--width", "1", "--height", "1");
        assertEquals(1, image("render1").getWidth(), "TC11: wrong image width");
        assertEquals(1, reported(result, "Primary rays:"), "TC11: one pixel, one primary ray");
    }

    /** Test method for the size options: one of them alone keeps the scene's aspect ratio (300 x 200). */
    @Test
    void testSize() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: --width 60 alone gives 60 x 40
        render("width60", "--width", "60");
        assertEquals(60, image("width60").getWidth(), "TC01: wrong width");
        assertEquals(40, image("width60").getHeight(), "TC01: the height should follow the aspect ratio");
        // TC02: --height 50 alone gives 75 x 50
        render("height50", "--height", "50");
        assertEquals(75, image("height50").getWidth(), "TC02: the width should follow the aspect ratio");
        assertEquals(50, image("height50").getHeight(), "TC02: wrong height");
        // TC03: both given: exactly that size, whatever the ratio
        render("size30x45", "--width", "30", "--height", "45");
        assertEquals(30, image("size30x45").getWidth(), "TC03: wrong width");
        assertEquals(45, image("size30x45").getHeight(), "TC03: wrong height");

        // ===== Boundary Values Tests =====
        // TC11: --width 1 alone: the height rounds to 1 (0.67), never 0
        render("width1", "--width", "1");
        assertEquals(1, image("width1").getWidth(), "TC11: wrong width");
        assertEquals(1, image("width1").getHeight(), "TC11: the height must be at least 1");
    }

    /**
     * Test method for the shadow options: the shadow ray count is exact — one ray per light per lit
     * point with hard shadows, sqrtBeamNum² + 1 with soft ones — and options override the file.
     */
    @Test
    void testShadowOptions() {
        String[] size = {"--width", "40", "--height", "40"};
        long hard = shadowRays(render("hard", size));
        assertTrue(hard > 100, "hard shadows should trace a ray per lit floor and sphere point, got " + hard);

        // ===== Equivalence Partitions Tests =====
        // TC01: --soft-shadows with --beams 2: 2² + 1 = 5 rays per lit point
        assertEquals(5 * hard, shadowRays(render("soft2", concat(size, "--soft-shadows", "--beams", "2"))),
                "TC01: --beams 2 should trace 5 shadow rays per lit point");
        // TC02: --beams 3: 10 rays per lit point
        assertEquals(10 * hard, shadowRays(render("soft3", concat(size, "--soft-shadows", "--beams", "3"))),
                "TC02: --beams 3 should trace 10 shadow rays per lit point");
        // TC03: --soft-shadows alone keeps the file's 9 beams: 82 rays per lit point
        assertEquals(82 * hard, shadowRays(render("soft9", concat(size, "--soft-shadows"))),
                "TC03: the file's 9 beams should trace 82 shadow rays per lit point");
        // TC04: a file with soft shadows and 2 beams, no options: the file's settings (5 rays per lit point)
        Path softFile = writeScene("cliSoftScene.xml", "<render soft-shadows=\"true\" beams=\"2\"/>");
        Result result = run(softFile.toString(), "-o", FOLDER.resolve("fileSoft.png").toString(), "--width", "40",
                "--height", "40");
        assertEquals(0, result.code(), "TC04: wrong exit code: " + result.err());
        assertEquals(5 * hard, shadowRays(result), "TC04: the file's soft shadows and beams are not kept");
        // TC05: the same file with --no-soft-shadows: hard shadows again
        result = run(softFile.toString(), "-o", FOLDER.resolve("fileHard.png").toString(), "--width", "40",
                "--height", "40", "--no-soft-shadows");
        assertEquals(0, result.code(), "TC05: wrong exit code: " + result.err());
        assertEquals(hard, shadowRays(result), "TC05: --no-soft-shadows should trace one ray per lit point");
        // TC06: --adaptive with 3 beams: each lit point traces the outline (9 rays) or all 10
        long adaptive = shadowRays(render("adaptive3", concat(size, "--soft-shadows", "--adaptive", "--beams", "3")));
        assertTrue(adaptive >= 9 * hard && adaptive < 10 * hard,
                "TC06: adaptive sampling should trace 9 or 10 rays per lit point, got " + adaptive + " for " + hard);

        // ===== Boundary Values Tests =====
        // TC11: --beams 1: 1² + 1 = 2 rays per lit point
        assertEquals(2 * hard, shadowRays(render("soft1", concat(size, "--soft-shadows", "--beams", "1"))),
                "TC11: --beams 1 should trace 2 shadow rays per lit point");
    }

    /** Test method for --soft-shadows: the penumbra has greys between the hard picture's shadow and light. */
    @Test
    void testSoftShadowsPicture() throws IOException {
        render("penumbraHard", "--width", "60", "--height", "40", "--no-soft-shadows");
        render("penumbraSoft", "--width", "60", "--height", "40", "--soft-shadows");
        BufferedImage hard = image("penumbraHard");
        BufferedImage soft = image("penumbraSoft");
        int lighter = 0;
        int darker = 0;
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 60; ++x) {
                int difference = grey(soft.getRGB(x, y)) - grey(hard.getRGB(x, y));
                if (difference > 5)
                    ++lighter;
                else if (difference < -5)
                    ++darker;
            }
        // ===== Equivalence Partitions Tests =====
        // TC01: some points of the hard shadow are partly lit with soft shadows
        assertTrue(lighter > 0, "TC01: no partly lit point in the soft shadow");
        // TC02: some lit points of the hard picture are partly shadowed with soft shadows
        assertTrue(darker > 0, "TC02: no partly shadowed point around the soft shadow");
    }

    private static int grey(int rgb) {
        return ((rgb >> 16) & 0xFF) + ((rgb >> 8) & 0xFF) + (rgb & 0xFF);
    }

    /** Test method for --threads and --seed: threads do not change the picture, the seed changes the jitter. */
    @Test
    void testThreadsAndSeed() throws IOException {
        String[] soft = {"--width", "40", "--height", "40", "--soft-shadows", "--beams", "3"};
        render("threads1", concat(soft, "--threads", "1"));
        render("threads3", concat(soft, "--threads", "3"));
        render("seed7", concat(soft, "--seed", "7"));
        // ===== Equivalence Partitions Tests =====
        // TC01: one thread and three threads give the same pixels
        assertTrue(samePixels(image("threads1"), image("threads3")), "TC01: the threads changed the picture");
        // TC02: another seed gives other jittered shadow rays, so other penumbra pixels
        assertFalse(samePixels(image("threads1"), image("seed7")), "TC02: --seed did not change the jitter");
        // ===== Boundary Values Tests =====
        // TC11: --threads 0: one thread per core, the same picture
        render("threads0", concat(soft, "--threads", "0"));
        assertTrue(samePixels(image("threads1"), image("threads0")), "TC11: --threads 0 changed the picture");
    }

    private static String[] concat(String[] first, String... more) {
        String[] all = Arrays.copyOf(first, first.length + more.length);
        System.arraycopy(more, 0, all, first.length, more.length);
        return all;
    }

    /**
     * Test method for {@link RenderCommand#call()}: --gloss-rays sets the spread rays of glossy and
     * blurry surfaces (the floor made a glossy mirror), and its help.
     */
    @Test
    void testGlossRays() {
        String glossy = SCENE.replace("kD=\"0.6\"", "kD=\"0.6\" kR=\"0.5\" kG=\"0.1\"");
        assertNotEquals(SCENE, glossy, "the test scene's floor was not found");
        Path file = TestFiles.write(FOLDER, "cliGlossScene.xml", glossy.formatted(""));
        String[] size = {"--width", "60", "--height", "40"};
        long twoByTwo = reported(run(concat(new String[]{file.toString(), "-o", FOLDER.resolve("gloss2.png").toString(),
                "--gloss-rays", "2"}, size)), "Spread rays:");
        long threeByThree = reported(run(concat(new String[]{file.toString(), "-o",
                FOLDER.resolve("gloss3.png").toString(), "--gloss-rays", "3"}, size)), "Spread rays:");
        // ===== Equivalence Partitions Tests =====
        // TC01: each floor pixel spreads 2 × 2 or 3 × 3 rays: the counts are as 4 to 9
        assertTrue(twoByTwo > 0, "TC01: the glossy floor must spread rays");
        assertEquals(9 * twoByTwo, 4 * threeByThree, "TC01: --gloss-rays 3 must spread 9/4 as many rays as 2");
        // TC02: without the option the file's gloss-rays (2) is kept
        Path twoFile = TestFiles.write(FOLDER, "cliGlossScene2.xml", glossy.formatted("<render gloss-rays=\"2\"/>"));
        assertEquals(twoByTwo, reported(run(concat(new String[]{twoFile.toString(), "-o",
                FOLDER.resolve("gloss-file.png").toString()}, size)), "Spread rays:"),
                "TC02: the file's gloss-rays must be kept");
        // TC03: the help lists --gloss-rays
        assertTrue(run("--help").out().contains("--gloss-rays=G"), "TC03: the help does not list --gloss-rays");
        // TC04: a scene with no glossy or blurry surface reports no spread rays
        assertFalse(render("no-gloss", size).out().contains("Spread rays:"), "TC04: no spread rays to report");

        // ===== Boundary Values Tests =====
        // TC11: --gloss-rays 0 and 1001 are bad arguments: exit 2, one line naming the option
        for (String bad : List.of("0", "1001")) {
            Result result = run(file.toString(), "-o", FOLDER.resolve("gloss-bad.png").toString(), "--gloss-rays", bad);
            assertEquals(2, result.code(), "TC11: --gloss-rays " + bad + " must exit with 2");
            assertOneLine(result, "TC11");
            assertTrue(result.err().contains("--gloss-rays must be between 1 and 1000"),
                    "TC11: the line must name --gloss-rays and its bounds: " + result.err());
        }
    }

    /**
     * Test method for --adaptive-aa, --aperture, --focus and --aperture-rays: ray counts, pictures and bad values.
     */
    @Test
    void testPictureImprovementOptions() throws IOException {
        String[] size = {"--width", "40", "--height", "40"};
        int pixels = 40 * 40;
        // ===== Equivalence Partitions Tests =====
        // TC01: --aa 4 traces 16 rays a pixel; with --adaptive-aa between 5 (flat) and 16 a pixel on average
        assertEquals(16L * pixels, reported(render("aa4", concat(size, "--aa", "4")), "Primary rays:"),
                "TC01: --aa 4 should trace 16 rays a pixel");
        long adaptive = reported(render("adaptiveAa4", concat(size, "--aa", "4", "--adaptive-aa")), "Primary rays:");
        assertTrue(adaptive >= 5L * pixels && adaptive < 16L * pixels, "TC01: --adaptive-aa traced " + adaptive);
        // TC02: --aperture 40 --focus 1100 --aperture-rays 2: 4 rays a pixel, and the picture blurs
        assertEquals(4L * pixels, reported(render("lens", concat(size, "--aperture", "40", "--focus", "1100",
                "--aperture-rays", "2")), "Primary rays:"), "TC02: 2 x 2 aperture rays a pixel");
        render("pinhole", size);
        assertFalse(samePixels(image("pinhole"), image("lens")), "TC02: --aperture did not change the picture");
        // TC03: depth of field and adaptive super-sampling together: 1 and 3 threads give the same pixels
        String[] both = concat(size, "--aperture", "40", "--focus", "1100", "--aperture-rays", "2", "--aa", "2",
                "--adaptive-aa", "--soft-shadows", "--beams", "2");
        render("improvements1", concat(both, "--threads", "1"));
        render("improvements3", concat(both, "--threads", "3"));
        assertTrue(samePixels(image("improvements1"), image("improvements3")), "TC03: the threads changed the picture");
        // TC04: --help lists the options
        String help = run("--help").out().replaceAll("\\s+", " ");
        for (String option : List.of("--[no-]adaptive-aa", "--aperture=A", "--focus=F", "--aperture-rays=N"))
            assertTrue(help.contains(option), "TC04: the help does not list " + option + ":\n" + help);

        // ===== Boundary Values Tests =====
        // TC11: --aperture 0 is the pinhole camera, and --no-adaptive-aa with --aa 4 traces 16 rays a pixel
        render("aperture0", concat(size, "--aperture", "0"));
        assertTrue(samePixels(image("pinhole"), image("aperture0")), "TC11: --aperture 0 changed the picture");
        assertEquals(16L * pixels, reported(render("notAdaptive", concat(size, "--aa", "4", "--no-adaptive-aa")),
                "Primary rays:"), "TC11: --no-adaptive-aa should trace every ray");
        // TC12: bad values are one line naming the option, exit code 2
        String scene = sceneFile.toString();
        String png = FOLDER.resolve("badLens.png").toString();
        assertBadArgument("TC12", "--aperture must not be negative, got -1.0", scene, "-o", png, "--aperture", "-1");
        assertBadArgument("TC12", "--aperture must be a finite number, got NaN", scene, "-o", png, "--aperture", "NaN");
        assertBadArgument("TC12", "--focus must be positive, got 0.0", scene, "-o", png, "--focus", "0");
        assertBadArgument("TC12", "--aperture must be at most 1.0E100, got 1.0E308", scene, "-o", png, "--aperture",
                "1e308");
        assertBadArgument("TC12", "--focus must be at most 1.0E100, got 1.0E308", scene, "-o", png, "--focus", "1e308");
        assertBadArgument("TC12", "--aperture-rays must be between 1 and 1000, got 0", scene, "-o", png,
                "--aperture-rays", "0");
        assertFalse(Files.exists(Path.of(png)), "TC12: an image was written despite bad arguments");
    }

    /** Test method for --help and --version. */
    @Test
    void testHelp() {
        // ===== Equivalence Partitions Tests =====
        // TC01: --help: exit 0, the usage with every option on out, nothing on err
        Result result = run("--help");
        assertEquals(0, result.code(), "TC01: --help should exit with 0");
        assertEquals("", result.err(), "TC01: --help wrote to the error stream");
        for (String option : List.of("Usage: java -jar target/raytracer.jar", "SCENE.xml", "-o, --output",
                "--width", "--height", "--[no-]soft-shadows", "--[no-]adaptive", "--beams", "--aa", "--seed", "--threads",
                "-q, --quiet", "--preview", "-h, --help", "-V, --version", "png, jpg, jpeg or bmp"))
            assertTrue(result.out().replaceAll("\\s+", " ").contains(option), "TC01: the help does not list " + option + ":\n" + result.out());
        assertTrue(result.out().replaceAll("\\s+", " ").contains("in the current directory"),
                "TC01: the help should say where the image goes by default");
        // TC02: --version: exit 0, the build's version, as the pom gives it ("raytracer 1.0.0")
        result = run("--version");
        assertEquals(0, result.code(), "TC02: --version should exit with 0");
        assertEquals("raytracer " + buildVersion(), result.out().strip(), "TC02: wrong version line");
    }

    /**
     * The project's version, as the pom gives it.
     *
     * @return the text of the pom's first {@code <version>} element
     */
    private static String buildVersion() {
        try {
            Matcher m = Pattern.compile("<version>([^<]+)</version>").matcher(Files.readString(Path.of("pom.xml")));
            assertTrue(m.find(), "no version in the pom");
            return m.group(1);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Test method for {@link RenderCommand#call()} with no scene file: no arguments print the usage, and
     * {@code --gallery [FOLDER]} renders the gallery (its bad uses are one line each).
     */
    @Test
    void testUsageAndGallery() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: no arguments: exit 2, the usage on err (the synopsis, SCENE.xml and --gallery), nothing on out
        Result result = run();
        assertEquals(2, result.code(), "TC01: no arguments should exit with 2");
        assertTrue(result.err().startsWith("Usage: java -jar target/raytracer.jar"), "TC01: no usage: " + result.err());
        String usage = result.err().replaceAll("\\s+", " ");
        for (String part : List.of("[SCENE.xml]", "--gallery[=FOLDER]", "Exit codes:"))
            assertTrue(usage.contains(part), "TC01: the usage does not show " + part + ": " + result.err());
        assertEquals("", result.out(), "TC01: the usage must go to the error stream");
        // TC02: options but no scene file: one line naming what is missing
        result = run("--width", "30");
        assertEquals(2, result.code(), "TC02: no scene file should exit with 2");
        assertOneLine(result, "TC02");
        assertTrue(result.err().startsWith("Missing required parameter: 'SCENE.xml' (or --gallery)"),
                "TC02: wrong message: " + result.err());
        // TC03: --gallery into a folder that cannot be made: one line naming the first picture, nothing written
        Path notAFolder = Files.writeString(freshFolder("gallery").resolve("file.txt"), "not a folder");
        result = run("--gallery", notAFolder.toString(), "--threads", "1");
        assertEquals(2, result.code(), "TC03: an unwritable gallery folder should exit with 2");
        assertOneLine(result, "TC03");
        assertTrue(result.err().startsWith(notAFolder.resolve("baseRenderTwoColors.png") + ": cannot write image"),
                "TC03: the line must name the first picture: " + result.err());
        // TC04: --gallery with a scene file, or with an option of a scene's: one line each
        result = run("--gallery", FOLDER.resolve("gallery").toString(), sceneFile.toString());
        assertEquals(2, result.code(), "TC04: --gallery with a scene file should exit with 2");
        assertOneLine(result, "TC04");
        assertTrue(result.err().startsWith("give a scene file or --gallery, not both"), "TC04: " + result.err());
        result = run("--gallery", FOLDER.resolve("gallery").toString(), "--width", "30");
        assertEquals(2, result.code(), "TC04: --gallery with --width should exit with 2");
        assertOneLine(result, "TC04");
        assertTrue(result.err().startsWith("--width does not go with --gallery"), "TC04: " + result.err());
        try (var files = Files.list(FOLDER.resolve("gallery"))) {
            assertEquals(List.of(notAFolder), files.toList(), "TC04: a picture was written");
        }

        // ===== Boundary Values Tests =====
        // TC11: --gallery without a folder: images/, the folder the gallery is kept in (parsed, not rendered)
        CommandLine commandLine = new CommandLine(new RenderCommand());
        assertEquals(Path.of("images"), commandLine.parseArgs("--gallery").matchedOptionValue("--gallery", null),
                "TC11: --gallery alone must render into images/");
        // TC12: --gallery with --threads out of bounds: one line naming --threads
        result = run("--gallery", FOLDER.resolve("gallery").toString(), "--threads", "-1");
        assertEquals(2, result.code(), "TC12: --threads -1 should exit with 2");
        assertOneLine(result, "TC12");
        assertTrue(result.err().startsWith("--threads must be 0 (one per core) to"), "TC12: " + result.err());
    }

    /**
     * Test method for {@link RenderCommand#call()}: a light with an edge while soft shadows are off gets
     * one note on the error stream (its square is ignored), which {@code --quiet} silences.
     */
    @Test
    void testIgnoredEdgeNote() {
        String note = sceneFile + ": <point-light> has edge 80 but soft shadows are off: add soft-shadows=\"true\""
                + " to <render> or --soft-shadows";
        // ===== Equivalence Partitions Tests =====
        // TC01: the test scene (hard shadows, a light of edge 80): the note, once, before the bar
        Result result = render("note", "--width", "20");
        assertEquals(note, result.errLines().get(0), "TC01: wrong note: " + result.err());
        assertEquals(1, result.errLines().stream().filter(line -> line.contains("has edge")).count(),
                "TC01: the note must be printed once: " + result.err());
        assertFalse(result.out().contains("has edge"), "TC01: the note must go to the error stream");
        // TC02: --soft-shadows: the edge is used, no note
        result = render("note-soft", "--width", "20", "--soft-shadows", "--beams", "2");
        assertFalse(result.err().contains("has edge"), "TC02: no note with soft shadows on: " + result.err());
        // TC03: a file with soft shadows on: no note; --no-soft-shadows on it: the note
        Path soft = writeScene("noteSoft.xml", "<render soft-shadows=\"true\" beams=\"2\"/>");
        String png = FOLDER.resolve("note-file.png").toString();
        result = run(soft.toString(), "-o", png, "--width", "20");
        assertEquals(0, result.code(), "TC03: wrong exit code: " + result.err());
        assertFalse(result.err().contains("has edge"), "TC03: no note with the file's soft shadows: " + result.err());
        result = run(soft.toString(), "-o", png, "--width", "20", "--no-soft-shadows");
        assertTrue(result.errLines().get(0).startsWith(soft + ": <point-light> has edge 80 but soft shadows are off"),
                "TC03: --no-soft-shadows must give the note: " + result.err());
        // TC04: lights without an edge: no note
        Path pointLights = TestFiles.write(FOLDER, "noteNoEdge.xml", SCENE.formatted("").replace(" edge=\"80\"", ""));
        result = run(pointLights.toString(), "-o", png, "--width", "20");
        assertEquals(0, result.code(), "TC04: wrong exit code: " + result.err());
        assertFalse(result.err().contains("has edge"), "TC04: no note without an edge: " + result.err());

        // ===== Boundary Values Tests =====
        // TC11: --quiet silences the note
        result = run(sceneFile.toString(), "-o", png, "--width", "20", "--quiet");
        assertEquals("", result.out() + result.err(), "TC11: --quiet must silence the note");
        // TC12: a spot light of edge 0 first, then one of edge 2.5: the note names the second, once
        Path second = TestFiles.write(FOLDER, "noteSecond.xml", SCENE.formatted("").replace("<lights>", "<lights>"
                + "<spot-light color=\"100 100 100\" position=\"0 0 300\" direction=\"0 0 -1\"/>")
                .replace("edge=\"80\"", "edge=\"2.5\""));
        result = run(second.toString(), "-o", png, "--width", "20");
        assertEquals(second + ": <point-light> has edge 2.5 but soft shadows are off: add soft-shadows=\"true\" to"
                + " <render> or --soft-shadows", result.errLines().get(0), "TC12: wrong note: " + result.err());
        assertEquals(1, result.errLines().stream().filter(line -> line.contains("has edge")).count(),
                "TC12: one note for the scene: " + result.err());
    }

    /** Test method for the image formats: the output file's extension chooses PNG, JPEG or BMP. */
    @Test
    void testFormats() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: .jpg, .jpeg and .bmp give 30 x 20 images that ImageIO reads back in those formats
        for (String extension : List.of(".jpg", ".jpeg", ".bmp")) {
            Path file = FOLDER.resolve("format" + extension);
            Files.deleteIfExists(file);
            Result result = run(sceneFile.toString(), "-o", file.toString(), "--width", "30", "--quiet");
            assertEquals(0, result.code(), "TC01: " + extension + " failed: " + result.err());
            BufferedImage image = ImageIO.read(file.toFile());
            assertNotNull(image, "TC01: ImageIO cannot read the " + extension + " file back");
            assertEquals(30, image.getWidth(), "TC01: wrong width of the " + extension + " image");
            assertEquals(20, image.getHeight(), "TC01: wrong height of the " + extension + " image");
            String format = ImageIO.getImageReaders(ImageIO.createImageInputStream(file.toFile())).next().getFormatName();
            assertEquals(extension.equals(".bmp") ? "bmp" : "jpeg", format.toLowerCase(Locale.ROOT),
                    "TC01: wrong format written for " + extension);
        }

        // ===== Boundary Values Tests =====
        // TC11: an upper-case extension (.PNG) is a PNG
        Path upper = FOLDER.resolve("upper.PNG");
        assertEquals(0, run(sceneFile.toString(), "-o", upper.toString(), "--width", "30", "--quiet").code(),
                "TC11: .PNG must be accepted");
        assertEquals("png", ImageIO.getImageReaders(ImageIO.createImageInputStream(upper.toFile())).next()
                .getFormatName().toLowerCase(Locale.ROOT), "TC11: .PNG must be written as a PNG");
    }

    /** Test method for --quiet and --preview. */
    @Test
    void testQuietAndPreview() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: --quiet: exit 0, the image written, nothing on either stream
        Path quiet = FOLDER.resolve("quiet.png");
        Files.deleteIfExists(quiet);
        Result result = run(true, sceneFile.toString(), "-o", quiet.toString(), "--width", "30", "--quiet");
        assertEquals(0, result.code(), "TC01: --quiet failed: " + result.err());
        assertTrue(Files.exists(quiet), "TC01: no image written");
        assertEquals("", result.out(), "TC01: --quiet printed a report");
        assertEquals("", result.err(), "TC01: --quiet printed a progress bar");
        // TC02: --preview with no display (the tests run headless): one line says so, and the picture is
        // rendered and reported anyway
        Path previewed = FOLDER.resolve("previewed.png");
        Files.deleteIfExists(previewed);
        result = run(sceneFile.toString(), "-o", previewed.toString(), "--width", "30", "--preview");
        assertEquals(0, result.code(), "TC02: --preview without a display must still render: " + result.err());
        assertTrue(Files.exists(previewed), "TC02: no image written");
        assertTrue(result.errLines().get(0).endsWith("there is no display to show the preview window on; rendering"
                + " without it"), "TC02: no line about the missing display: " + result.err());
        assertEquals(600, reported(result, "Primary rays:"), "TC02: the render is not reported");

        // ===== Boundary Values Tests =====
        // TC11: --quiet --preview with no display: nothing printed at all, and a bad option is still one line
        result = run(sceneFile.toString(), "-o", previewed.toString(), "--width", "30", "--preview", "--quiet");
        assertEquals(0, result.code(), "TC11: wrong exit code");
        assertEquals("", result.out() + result.err(), "TC11: --quiet must silence the missing display's line");
        assertBadArgument("TC11", "--beams must be between 1 and 1000", sceneFile.toString(), "--quiet",
                "--beams", "0");
    }

    /** Test method for {@link RenderCommand#outputFile()}: the default image file. */
    @Test
    void testOutputFile() {
        // ===== Equivalence Partitions Tests =====
        // TC01: no -o: the scene file's name with .png, in the current directory
        RenderCommand command = new RenderCommand();
        new CommandLine(command).parseArgs(Path.of("some", "dir", "scene.xml").toString());
        assertEquals(Path.of("scene.png"), command.outputFile(), "TC01: wrong default image file");
        // TC02: -o given: that file
        command = new RenderCommand();
        new CommandLine(command).parseArgs("scene.xml", "-o", Path.of("out", "x.png").toString());
        assertEquals(Path.of("out", "x.png"), command.outputFile(), "TC02: -o is not used");
        // ===== Boundary Values Tests =====
        // TC11: a scene file not ending with .xml keeps its whole name
        command = new RenderCommand();
        new CommandLine(command).parseArgs("scene.txt");
        assertEquals(Path.of("scene.txt.png"), command.outputFile(), "TC11: wrong default image file");
    }

    /** Test method for bad arguments: exit code 2, a one-line message, the usage hint, no image. */
    @Test
    void testBadArguments() throws IOException {
        String scene = sceneFile.toString();
        String png = FOLDER.resolve("badArgument.png").toString();
        Files.deleteIfExists(Path.of(png));
        // ===== Equivalence Partitions Tests =====
        // TC01: an unknown option
        assertBadArgument("TC01", "Unknown option: '--bogus'", scene, "-o", png, "--bogus");
        // TC02: an output file of a format not written here (GIF): the supported extensions are listed
        assertBadArgument("TC02", "must end with one of .bmp, .jpeg, .jpg, .png", scene, "-o",
                FOLDER.resolve("out.gif").toString());
        // TC03: no scene file
        assertBadArgument("TC03", "Missing required parameter: 'SCENE.xml'", "-o", png);
        // TC04: a width that is not a number
        assertBadArgument("TC04", "Invalid value for option '--width'", scene, "-o", png, "--width", "abc");
        // TC05: a negative width
        assertBadArgument("TC05", "--width must be 1 or more, got -1", scene, "-o", png, "--width", "-1");
        // TC06: two scene files
        assertBadArgument("TC06", "Unmatched argument", scene, scene, "-o", png);

        // ===== Boundary Values Tests =====
        // TC11: --beams 0
        assertBadArgument("TC11", "--beams must be between 1 and 1000, got 0", scene, "-o", png, "--beams", "0");
        // TC12: --aa 0
        assertBadArgument("TC12", "--aa must be between 1 and 1000, got 0", scene, "-o", png, "--aa", "0");
        // TC13: --height 0
        assertBadArgument("TC13", "--height must be 1 or more, got 0", scene, "-o", png, "--height", "0");
        // TC14: --threads -1
        assertBadArgument("TC14", "--threads must be 0", scene, "-o", png, "--threads", "-1");
        // TC15: an output file named just ".png", and one with no extension
        assertBadArgument("TC15", "must end with one of", scene, "-o", FOLDER.resolve(".png").toString());
        assertBadArgument("TC15", "must end with one of", scene, "-o", FOLDER.resolve("png").toString());
        assertFalse(Files.exists(Path.of(png)), "an image was written despite bad arguments");
    }

    private static void assertBadArgument(String tc, String message, String... args) {
        Result result = run(args);
        assertEquals(2, result.code(), tc + ": bad arguments should exit with 2");
        assertOneLine(result, tc);
        assertTrue(result.err().contains(message), tc + ": wrong message: " + result.err());
        assertTrue(result.err().contains("(see 'java -jar target/raytracer.jar --help')"),
                tc + ": no --help hint: " + result.err());
    }

    /**
     * Test method for input quoted in what the command prints: arguments, scene files and file names with
     * control characters reach the terminal as visible escapes, never as commands.
     */
    @Test
    void testControlCharactersQuoted() throws IOException {
        Path folder = freshFolder("control");
        String png = folder.resolve("out.png").toString();
        // ===== Equivalence Partitions Tests =====
        // TC01: an unknown option holding ESC ] 0 ; x BEL (an xterm title): "'--\x1B]0;x\x07'"
        Result result = run(sceneFile.toString(), "-o", png, "--\u001b]0;x\u0007");
        assertEquals(2, result.code(), "TC01: a bad argument should exit with 2");
        assertOneLine(result, "TC01");
        assertPrintable(result.err(), "'--\\x1B]0;x\\x07'", "TC01");
        // TC02: an XML 1.1 scene file whose attribute holds ESC [ 2 J (clear the screen): "'\x1B[2J'"
        Path scene = TestFiles.write(folder, "clear.xml", "<?xml version=\"1.1\"?>\n<scene><geometries><sphere"
                + " center=\"0 0 0\" radius=\"&#x1B;[2J\"/></geometries></scene>");
        assertBadScene("TC02", scene, ":2:", "got '\\x1B[2J'");
        // TC03 (own): an image file whose name holds a C1 control (CSI): the report names it printably
        result = run(sceneFile.toString(), "-o", folder.resolve("csi\u009b2J.png").toString(), "--width", "6");
        assertEquals(0, result.code(), "TC03: the picture must be written: " + result.err());
        assertPrintable(result.out(), "csi\\x9B2J.png", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: a missing scene file whose name is a single ESC: "\x1B: no such scene file"
        result = run(folder.resolve("\u001b").toString(), "-o", png);
        assertEquals(2, result.code(), "TC11: a missing scene file should exit with 2");
        assertPrintable(result.err(), "\\x1B: no such scene file", "TC11");
        // TC12 (own): an image file name ending with a tab, of an unknown format: "out.gif\t"
        result = run(sceneFile.toString(), "-o", folder.resolve("out.gif\t").toString());
        assertEquals(2, result.code(), "TC12: a bad format should exit with 2");
        assertPrintable(result.err(), "out.gif\\t must end with one of", "TC12");
    }

    /** Test method for the limits of the options: too large a grid or picture is one line, exit code 2. */
    @Test
    void testLimits() {
        String scene = sceneFile.toString();
        String png = FOLDER.resolve("limits.png").toString();
        // ===== Equivalence Partitions Tests =====
        // TC01: --beams 30000 (a grid of 900 million cells, out of memory before) names the bound
        assertBadArgument("TC01", "--beams must be between 1 and 1000, got 30000", scene, "-o", png, "--beams", "30000");
        // TC02: --beams 1000000 (a negative array size before)
        assertBadArgument("TC02", "--beams must be between 1 and 1000, got 1000000", scene, "-o", png, "--beams",
                "1000000");
        // TC03: --width 2147483647: the height follows, and the picture cannot be held
        assertBadArgument("TC03", "--width/--height: image size 2147483647x1431655765 is too large", scene, "-o", png,
                "--width", "2147483647");
        // ===== Boundary Values Tests =====
        // TC11: --beams 46341 and --aa 46341, whose squares overflow an int
        assertBadArgument("TC11", "--beams must be between 1 and 1000, got 46341", scene, "-o", png, "--beams", "46341");
        assertBadArgument("TC11", "--aa must be between 1 and 1000, got 46341", scene, "-o", png, "--aa", "46341");
        // TC12: --beams 1001, one past the bound
        assertBadArgument("TC12", "--beams must be between 1 and 1000, got 1001", scene, "-o", png, "--beams", "1001");
        // TC13: --threads 1025, one past the bound
        assertBadArgument("TC13", "--threads must be 0 (one per core) to 1024, got 1025", scene, "-o", png,
                "--threads", "1025");
    }

    /** Test method for bad scene files: exit code 2 and one line naming the file, the place and the problem. */
    @Test
    void testBadSceneFiles(@TempDir Path folder) throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: a missing file
        Path missing = folder.resolve("missing.xml");
        assertBadScene("TC01", missing, missing + ": ", "no such");
        // TC02: malformed XML (an element not closed)
        assertBadScene("TC02", TestFiles.write(folder, "malformed.xml", "<scene>\n  <geometries>\n</scene>\n"),
                ":3:", "</geometries>");
        // TC03: an unknown element
        assertBadScene("TC03", TestFiles.write(folder, "element.xml", geometries("<cube center=\"0 0 0\"/>")),
                ":3:", "<cube>");
        // TC04: an unknown attribute
        assertBadScene("TC04", TestFiles.write(folder, "attribute.xml",
                geometries("<sphere center=\"0 0 0\" radius=\"5\" colour=\"1 2 3\"/>")), ":3:", "'colour'");
        // TC05: a bad number
        assertBadScene("TC05", TestFiles.write(folder, "number.xml",
                geometries("<sphere center=\"0 0 0\" radius=\"five\"/>")), ":3:", "'five'");
        // TC06: a zero vector
        assertBadScene("TC06", TestFiles.write(folder, "zero.xml",
                geometries("<plane q0=\"0 0 0\" normal=\"0 0 0\"/>")), ":3:", "zero vector");
        // TC07: a concave polygon
        assertBadScene("TC07", TestFiles.write(folder, "concave.xml",
                geometries("<polygon vertices=\"0 0 0  10 0 0  2 2 0  0 10 0\"/>")), ":3:", "convex");
        // TC08: a missing .obj file
        assertBadScene("TC08", TestFiles.write(folder, "mesh.xml", geometries("<mesh file=\"nowhere.obj\"/>")),
                ":3:", "nowhere.obj");

        // ===== Boundary Values Tests =====
        // TC11: an empty file
        assertBadScene("TC11", TestFiles.write(folder, "empty.xml", ""), ": ", "");
        // TC12: a folder instead of a file
        assertBadScene("TC12", folder, folder.toString(), "");
        try (var files = Files.list(folder)) {
            assertTrue(files.noneMatch(f -> f.toString().endsWith(".png")), "an image was written for a bad file");
        }
    }

    /** A scene whose third line is this body, in its geometries. */
    private static String geometries(String body) {
        return "<scene>\n  <geometries>\n    " + body + "\n  </geometries>\n</scene>\n";
    }

    private static void assertBadScene(String tc, Path file, String where, String problem) {
        Result result = run(file.toString(), "-o", file.resolveSibling("out.png").toString(), "--width", "10");
        assertEquals(2, result.code(), tc + ": a bad scene file should exit with 2: " + result.err());
        assertOneLine(result, tc);
        String line = result.errLines().get(0);
        assertTrue(line.startsWith(file.toString()), tc + ": the message does not start with the file: " + line);
        assertTrue(line.contains(where), tc + ": the message does not give the place " + where + ": " + line);
        assertTrue(line.contains(problem), tc + ": the message does not name " + problem + ": " + line);
    }

    /** Test method for an image that cannot be written: checked before rendering, one line, exit code 2. */
    @Test
    void testUnwritableImage() throws IOException {
        Path folder = freshFolder("unwritable");
        // ===== Equivalence Partitions Tests =====
        // TC01: the image's folder is a regular file: the line names the image, no progress bar started
        Path notAFolder = Files.writeString(folder.resolve("file.txt"), "not a folder");
        assertUnwritable("TC01", notAFolder.resolve("out.png"), "cannot write image");
        // TC02: an existing folder, not empty, named out.png: refused, the folder and its file stay
        Path full = folder.resolve("full.png");
        Path inside = TestFiles.write(full, "keep.txt", "keep");
        assertUnwritable("TC02", full, "is a folder");
        assertEquals("keep", Files.readString(inside), "TC02: the folder's file must stay");
        // TC03: the output is checked before the scene file is read: with a missing scene too, the image is named
        Result result = run(folder.resolve("missing.xml").toString(), "-o", full.toString());
        assertEquals(2, result.code(), "TC03: wrong exit code");
        assertTrue(result.err().startsWith(full + ": cannot write image"), "TC03: the image must be named first: "
                + result.err());

        // ===== Boundary Values Tests =====
        // TC11: an existing empty folder named out.png: refused, not deleted
        Path empty = Files.createDirectory(folder.resolve("empty.png"));
        assertUnwritable("TC11", empty, "is a folder");
        assertTrue(Files.isDirectory(empty), "TC11: the empty folder must stay");
    }

    private static void assertUnwritable(String tc, Path png, String problem) {
        Result result = run(sceneFile.toString(), "-o", png.toString(), "--width", "10", "--height", "10");
        assertEquals(2, result.code(), tc + ": an unwritable image should exit with 2");
        assertOneLine(result, tc);
        assertTrue(result.err().startsWith(png + ": cannot write image"), tc + ": the line must name the image: "
                + result.err());
        assertTrue(result.err().contains(problem), tc + ": the line must say " + problem + ": " + result.err());
    }

    /** Test method for scene files whose numbers or sizes overflow: one line with the place, exit code 2. */
    @Test
    void testOverflowingScenes() throws IOException {
        Path folder = freshFolder("overflow");
        // ===== Equivalence Partitions Tests =====
        // TC01: a view plane 1e308 wide, or 1e308 away
        assertBadScene("TC01", TestFiles.write(folder, "width.xml", "<scene>\n<camera vp-width=\"1e308\"/>\n</scene>"),
                ":2:", "<camera>: attribute 'vp-width' is too large");
        assertBadScene("TC01", TestFiles.write(folder, "distance.xml",
                "<scene>\n<camera vp-distance=\"1e308\"/>\n</scene>"), ":2:", "<camera>: attribute 'vp-distance'");
        // TC02: kS 1e308 and kQ the largest double
        assertBadScene("TC02", TestFiles.write(folder, "kS.xml", geometries("<sphere center=\"0 0 -100\" radius=\"50\""
                + " kS=\"1e308\"/>")), ":3:", "<sphere>: attribute 'kS' is too large");
        assertBadScene("TC02", TestFiles.write(folder, "kQ.xml", "<scene>\n<lights>\n<point-light color=\"1 1 1\""
                + " position=\"0 0 0\" kQ=\"1.7976931348623157e308\"/>\n</lights>\n</scene>"), ":3:", "attribute 'kQ'");
        // TC03: a point light whose kC, kL and kQ are all 0
        assertBadScene("TC03", TestFiles.write(folder, "attenuation.xml", "<scene>\n<lights>\n<point-light color="
                + "\"1 1 1\" position=\"0 0 0\" kC=\"0\" kL=\"0\" kQ=\"0\"/>\n</lights>\n</scene>"), ":3:",
                "light attenuation kC, kL and kQ must not all be 0");
        // TC04: 100,000 nested <geometries>
        assertBadScene("TC04", TestFiles.write(folder, "nested.xml", "<scene>" + "<geometries>".repeat(100_000)
                + "</geometries>".repeat(100_000) + "</scene>"), ":1:", "nested too deeply");
        // TC05: a number of 1,000,000 digits
        assertBadScene("TC05", TestFiles.write(folder, "digits.xml", geometries("<sphere center=\"0 0 0\" radius=\""
                + "9".repeat(1_000_000) + "\"/>")), ":3:", "1000000 characters long");
        // TC06: a mesh whose file has no line breaks, like /dev/zero
        TestFiles.write(folder, "zeros.obj", "\0".repeat(ObjMesh.MAX_LINE_LENGTH + 1));
        assertBadScene("TC06", TestFiles.write(folder, "zeros.xml", geometries("<mesh file=\"zeros.obj\"/>")), ":3:",
                "zeros.obj:1: the line is longer than");
        // TC07: an OBJ face index beyond the int range: the OBJ file's line too
        TestFiles.write(folder, "wrap.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967299\n");
        assertBadScene("TC07", TestFiles.write(folder, "wrap.xml", geometries("<mesh file=\"wrap.obj\"/>")), ":3:",
                "wrap.obj:4: a face refers to vertex 4294967299");
        // TC08: an unknown encoding and a file cut inside the XML declaration, each with a place
        assertBadScene("TC08", TestFiles.write(folder, "encoding.xml", "<?xml version=\"1.0\" encoding=\"UTF-9\"?>"
                + "\n<scene/>\n"), ":1:1:", "unknown character encoding 'UTF-9'");
        assertBadScene("TC08", TestFiles.write(folder, "cut.xml", "<?xml version=\"1.0\" enc"), ":1:", "");
        // ===== Boundary Values Tests =====
        // TC11: a plane normal (0, 1e-200, 0) is not a zero vector: the scene renders
        Path tiny = TestFiles.write(folder, "tiny.xml", geometries("<plane q0=\"0 -50 0\" normal=\"0 1e-200 0\"/>"));
        Result result = run(tiny.toString(), "-o", folder.resolve("tiny.png").toString(), "--width", "10");
        assertEquals(0, result.code(), "TC11: a tiny normal must render: " + result.err());
    }

    /**
     * Test method for {@link Main}'s process: not enough memory for the picture, a German locale, a scene
     * from the standard input and a kill while rendering, each in a JVM of its own.
     */
    @Test
    void testSeparateProcess() throws IOException, InterruptedException {
        Path folder = freshFolder("process");
        // ===== Equivalence Partitions Tests =====
        // TC01: an 8000 x 8000 picture with 128 MB of memory: one line naming the size and the options
        Process process = java(folder, List.of("-Xmx128m"), sceneFile.toString(), "-o",
                folder.resolve("big.png").toString(), "--width", "8000", "--height", "8000");
        assertProcessFailure("TC01", process, "not enough memory for a 8000 x 8000 picture");
        // TC02: with a German locale, the parser's message is in English
        Path german = TestFiles.write(folder, "german.xml", "<scene>\n</scenex>\n");
        process = java(folder, List.of("-Duser.language=de", "-Duser.country=DE"), german.toString(), "-o",
                folder.resolve("german.png").toString());
        assertProcessFailure("TC02", process, "The end-tag for element type \"scene\" must end with a '>' delimiter");
        // TC03: the scene read from /dev/stdin, a pipe (read once: a second reading found it empty before)
        Path piped = folder.resolve("piped.png");
        process = java(folder, List.of(), "/dev/stdin", "-o", piped.toString(), "--width", "12", "-q");
        try (var stdin = process.getOutputStream()) {
            stdin.write(Files.readAllBytes(sceneFile));
        }
        String err = new String(process.getErrorStream().readAllBytes());
        assertEquals(0, process.waitFor(), "TC03: a scene from a pipe must render: " + err);
        assertEquals(12, ImageIO.read(piped.toFile()).getWidth(), "TC03: the picture must be written");
        // TC04: in the C locale, a scene file named with a non-ASCII letter: one line saying what to set
        Map<String, String> cLocale = Map.of("LC_ALL", "C", "LANG", "C");
        Path accented = Files.copy(sceneFile, folder.resolve("sc\u00e8ne.xml"), StandardCopyOption.REPLACE_EXISTING);
        process = java(folder, cLocale, List.of(), accented.toString(), "-o", folder.resolve("c.png").toString());
        String advice = "run with a UTF-8 locale, e.g. LC_ALL=C.UTF-8";
        assertProcessFailure("TC04", process, "Invalid value for positional parameter at index 0 (SCENE.xml): the file"
                + " name '" + folder + "/sc", advice);
        // TC05 (own): ... and a scene file naming a mesh so: the mesh's element, and the locale to set
        Path meshScene = TestFiles.write(folder, "meshC.xml", geometries("<mesh file=\"mod\u00e8le.obj\"/>"));
        process = java(folder, cLocale, List.of(), meshScene.toString(), "-o", folder.resolve("c.png").toString());
        assertProcessFailure("TC05", process, meshScene + ":3:", "<mesh>: the file name 'mod", advice);

        // ===== Boundary Values Tests =====
        // TC11: a render killed (SIGKILL) while running leaves the old picture whole
        Path png = folder.resolve("killed.png");
        assertEquals(0, run(sceneFile.toString(), "-o", png.toString(), "--width", "30").code(), "TC11: first render");
        process = java(folder, List.of(), sceneFile.toString(), "-o", png.toString(), "--width", "1200", "--aa", "3");
        Thread.sleep(KILL_DELAY_MS);
        process.destroyForcibly().waitFor();
        BufferedImage left = ImageIO.read(png.toFile());
        assertTrue(left != null && (left.getWidth() == 30 || left.getWidth() == 1200),
                "TC11: the picture must be the old one or the new one, whole");
    }

    /** Starts {@link Main} in a JVM of its own, with these JVM options and arguments; its err is read later. */
    private static Process java(Path folder, List<String> options, String... args) throws IOException {
        return java(folder, Map.of(), options, args);
    }

    /**
     * Starts {@link Main} in a JVM of its own, with these environment variables (beside this JVM's), JVM
     * options and arguments; its err is read later.
     */
    private static Process java(Path folder, Map<String, String> environment, List<String> options, String... args)
            throws IOException {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(options);
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), Main.class.getName()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).redirectOutput(folder.resolve("out.txt").toFile());
        builder.environment().putAll(environment);
        return builder.start();
    }

    private static void assertProcessFailure(String tc, Process process, String... messages) throws IOException,
            InterruptedException {
        String err = new String(process.getErrorStream().readAllBytes());
        assertEquals(2, process.waitFor(), tc + ": the process should exit with 2: " + err);
        Result result = new Result(2, "", err);
        assertEquals(1, result.errLines().size(), tc + ": not one line: " + err);
        assertNoStackTrace(result, tc);
        for (String message : messages)
            assertTrue(err.contains(message), tc + ": wrong message, without \"" + message + "\": " + err);
    }

    /**
     * Test method for {@link RenderCommand#call()} on mutated scene files: the gallery's files with
     * numbers, values and names replaced, characters inserted or deleted, lines repeated and ends cut,
     * from a fixed seed. Each run exits with 0, or with 2 and one line naming the file, never a trace.
     */
    @Test
    void testFuzzedSceneFiles() throws IOException {
        Path folder = FOLDER.resolve("fuzz");
        List<String> scenes = new ArrayList<>();
        try (var files = Files.list(Path.of("scenes"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".xml")).sorted().toList())
                scenes.add(Files.readString(file));
        }
        TestFiles.write(folder.resolve("models"), "cube.obj", Files.readString(Path.of("scenes", "models", "cube.obj")));
        Random random = new Random(FUZZ_SEED);
        int failures = 0;
        for (int c = 0; c < FUZZ_CASES; ++c) {
            String text = scenes.get(random.nextInt(scenes.size()));
            for (int m = random.nextInt(3); m >= 0; --m)
                text = mutate(text, random);
            Path file = TestFiles.write(folder, "fuzz" + c + ".xml", text);
            Result result = run(file.toString(), "-o", folder.resolve("fuzz.png").toString(), "--width", "6",
                    "--height", "6", "--beams", "2", "--aa", "1", "--threads", "1");
            // ===== Equivalence Partitions Tests =====
            // TC01: a mutated file renders (exit 0), or is refused with one line naming it (exit 2)
            String tc = "TC01: " + file;
            if (result.code() == 0)
                continue;
            ++failures;
            assertEquals(2, result.code(), tc + ": exit code 0 or 2 expected: " + result.err());
            assertOneLine(result, tc);
            assertTrue(result.err().startsWith(file + ":"), tc + ": the line must name the file: " + result.err());
        }
        // TC02: the mutations hit: most files are refused, some still render
        assertTrue(failures > FUZZ_CASES / 2 && failures < FUZZ_CASES, "TC02: " + failures + " of " + FUZZ_CASES
                + " files refused");
    }

    /** One random mutation of a scene file's text. */
    private static String mutate(String text, Random random) {
        int at = random.nextInt(text.length() + 1);
        return switch (random.nextInt(11)) { // numbers most often: they reach the library
            case 0, 1, 2, 3 -> replace(text, NUMBER, FUZZ_VALUES.get(random.nextInt(FUZZ_VALUES.size())), random);
            case 4, 5 -> replace(text, VALUE, "=\"" + FUZZ_VALUES.get(random.nextInt(FUZZ_VALUES.size())) + "\"", random);
            case 6 -> replace(text, NAME, FUZZ_ELEMENTS.get(random.nextInt(FUZZ_ELEMENTS.size())), random);
            case 7 -> text.substring(0, at);
            case 8 -> text.substring(0, at) + text.substring(Math.min(text.length(), at + 1 + random.nextInt(20)));
            case 9 -> text.substring(0, at) + FUZZ_CHARACTERS.charAt(random.nextInt(FUZZ_CHARACTERS.length()))
                    + text.substring(at);
            default -> {
                List<String> lines = new ArrayList<>(text.lines().toList());
                int line = random.nextInt(lines.size());
                lines.add(line, lines.get(line));
                yield String.join("\n", lines);
            }
        };
    }

    /** The text with one random match of the pattern replaced. */
    private static String replace(String text, Pattern pattern, String replacement, Random random) {
        List<MatchResult> matches = pattern.matcher(text).results().toList();
        if (matches.isEmpty())
            return text;
        MatchResult match = matches.get(random.nextInt(matches.size()));
        return text.substring(0, match.start()) + replacement + text.substring(match.end());
    }
}
