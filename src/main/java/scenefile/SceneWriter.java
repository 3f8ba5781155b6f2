package scenefile;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import geometries.Tube;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.CheckerTexture;
import primitives.Color;
import primitives.FileReplacement;
import primitives.ImageTexture;
import primitives.Material;
import primitives.Point3D;
import primitives.Texture;
import primitives.Vector;
import renderer.Camera;
import scene.Scene;

import static primitives.Util.requireNonNull;

/**
 * Writes a {@link Picture} as a scene file in the format of the scene schema {@code scenefile/scene.xsd}, which
 * {@link SceneLoader#load(Path)} reads back into the same picture: a scene built in Java can be saved,
 * shared and rendered from the command line.
 *
 * <pre>{@code
 * SceneWriter.write(picture, Path.of("scenes/myScene.xml"));
 * }</pre>
 *
 * The file is short and readable: one element per line, indented, in a fixed order; only the attributes
 * whose values differ from the schema's defaults; each number in its shortest text that reads back as the
 * same double ({@code 0.3}, {@code 75 127 90}), and each direction in its simplest form whose normalised
 * vector is the same ({@code 1 1 -2} for the unit vector the library keeps). Writing the same picture
 * twice gives the same text.
 * <p>
 * The scene's own name is not written: the file has one name, the picture's, which the loader gives both
 * the picture and its scene. A flat untextured {@link TriangleMesh} is written as a group of its triangles,
 * a smooth or textured one as a {@code <triangle-mesh>} of its vertices, triangles, normals and UVs; an
 * image texture's file is named relative to the scene file's folder ({@link #write}) or by its absolute
 * path ({@link #toXml}).
 */
public final class SceneWriter {
    private static final String INDENT = "    ";
    /** The largest integer factor tried when looking for a direction's simplest form. */
    private static final int MAX_DIRECTION_FACTOR = 12;
    /** The most decimals a direction's simplest form may have. */
    private static final int MAX_DIRECTION_DECIMALS = 3;
    /** The largest factor tried when nudging a unit vector to normalise to itself. */
    private static final int MAX_NUDGE_SCALE = 99;

    private SceneWriter() {
    }

    /**
     * Writes a picture into a scene file, creating the file's folders; an old file is replaced whole
     * ({@link FileReplacement}).
     *
     * @param picture the picture
     * @param file    the scene file (normally named {@code <picture name>.xml})
     * @throws IllegalArgumentException when the picture has a body or light the format cannot express
     * @throws UncheckedIOException     when the file cannot be written; the message names the file
     */
    public static void write(Picture picture, Path file) {
        requireNonNull(file, "scene file");
        String xml = toXml(picture, file.toAbsolutePath().getParent());
        try {
            FileReplacement.replace(file, f -> Files.writeString(f, xml, StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the scene file " + file + ": " + e, e);
        }
    }

    /**
     * The text of a picture's scene file.
     *
     * @param picture the picture
     * @return the XML text, ending with a line break
     * @throws IllegalArgumentException when the picture has a body or light the format cannot express
     */
    public static String toXml(Picture picture) {
        return toXml(picture, null);
    }

    /**
     * The text of a picture's scene file, its image textures' files named relative to a folder.
     *
     * @param picture the picture
     * @param folder  the scene file's folder, or null to name the files by their absolute paths
     */
    private static String toXml(Picture picture, Path folder) {
        requireNonNull(picture, "picture");
        Scene scene = picture.scene();
        if (picture.name().isEmpty())
            throw new IllegalArgumentException("a scene file cannot express an empty picture name");
        Xml xml = new Xml(folder);
        xml.text.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        xml.start("scene").attribute("name", escape(picture.name()))
                .attribute("background-color", color(scene.background), "0 0 0").open();
        camera(xml, picture.camera());
        xml.start("image").attribute("width", Integer.toString(picture.nX()), "500")
                .attribute("height", Integer.toString(picture.nY()), "500")
                .attribute("grid", Integer.toString(picture.gridInterval()), "0").emptyOrNothing();
        RenderSettings settings = picture.settings();
        xml.start("render").attribute("soft-shadows", Boolean.toString(settings.softShadows()), "false")
                .attribute("adaptive", Boolean.toString(settings.adaptiveSoftShadows()), "false")
                .attribute("beams", Integer.toString(settings.sqrtBeamNum()),
                        Integer.toString(RenderSettings.DEFAULT.sqrtBeamNum()))
                .attribute("anti-aliasing", Integer.toString(settings.antiAliasing()), "1")
                .attribute("seed", Long.toString(settings.seed()), Long.toString(RenderSettings.DEFAULT.seed()))
                .attribute("gloss-rays", Integer.toString(settings.sqrtGlossRays()),
                        Integer.toString(RenderSettings.DEFAULT.sqrtGlossRays()))
                .attribute("adaptive-super-sampling", Boolean.toString(settings.adaptiveSuperSampling()), "false")
                .emptyOrNothing();
        // the ambient light keeps only Ia·kA: written as the colour, with kA = 1
        xml.start("ambient-light").attribute("color", color(scene.ambientLight.getIntensity()), "0 0 0")
                .emptyOrNothing();
        if (!scene.lights.isEmpty()) {
            xml.start("lights").open();
            for (LightSource light : scene.lights)
                light(xml, light);
            xml.close("lights");
        }
        List<Intersectable> bodies = scene.geometries.getGeometries();
        if (!bodies.isEmpty())
            geometries(xml, bodies);
        xml.close("scene");
        return xml.text.toString();
    }

    private static void camera(Xml xml, Camera camera) {
        if (!(camera.getWidth() > 0 && camera.getHeight() > 0 && camera.getDistance() > 0))
            throw new IllegalArgumentException("the camera's view plane size and distance must be set, got "
                    + camera.getWidth() + "x" + camera.getHeight() + " at " + camera.getDistance());
        xml.start("camera").attribute("p0", point(camera.getP0()), "0 0 0")
                .attribute("vTo", direction(camera.getVTo()), "0 0 -1")
                .attribute("vUp", direction(camera.getVUp()), "0 1 0")
                .attribute("vp-width", number(camera.getWidth()), "500")
                .attribute("vp-height", number(camera.getHeight()), "500")
                .attribute("vp-distance", number(camera.getDistance()), "100")
                .attribute("aperture", number(camera.getApertureSize()), "0")
                .attribute("focal-distance", number(camera.getFocalDistance()), number(camera.getDistance()))
                .attribute("aperture-rays", Integer.toString(camera.getSqrtApertureRays()),
                        Integer.toString(Camera.DEFAULT_SQRT_APERTURE_RAYS)).emptyOrNothing();
    }

    private static void light(Xml xml, LightSource light) {
        Class<?> type = requireNonNull(light, "a scene light").getClass();
        if (type == DirectionalLight.class) {
            DirectionalLight directional = (DirectionalLight) light;
            xml.start("directional-light").attribute("color", color(directional.getIntensity()))
                    .attribute("direction", direction(directional.getDirection())).empty();
        } else if (type == PointLight.class) {
            PointLight point = (PointLight) light;
            xml.start("point-light").attribute("color", color(point.getIntensity()))
                    .attribute("position", point(point.getPosition()));
            attenuationAndSquare(xml, point);
            xml.empty();
        } else if (type == SpotLight.class) {
            SpotLight spot = (SpotLight) light;
            xml.start("spot-light").attribute("color", color(spot.getIntensity()))
                    .attribute("position", point(spot.getPosition()))
                    .attribute("direction", direction(spot.getDirection()))
                    .attribute("narrow-beam", number(spot.getNarrowBeam()), "1");
            attenuationAndSquare(xml, spot);
            xml.empty();
        } else
            throw new IllegalArgumentException("a scene file cannot express the light type " + type.getName());
    }

    /** Writes a light's attenuation and square; its sides only when they were set, not chosen by the light. */
    private static void attenuationAndSquare(Xml xml, PointLight light) {
        xml.attribute("kC", number(light.getKc()), "1").attribute("kL", number(light.getKl()), "0")
                .attribute("kQ", number(light.getKq()), "0").attribute("edge", number(light.getEdges()), "0");
        if (light.isUVSet())
            xml.attribute("u", direction(light.getU())).attribute("v", direction(light.getV()));
    }

    private static void geometries(Xml xml, List<? extends Intersectable> bodies) {
        if (bodies.isEmpty()) {
            xml.start("geometries").empty();
            return;
        }
        xml.start("geometries").open();
        for (Intersectable body : bodies)
            body(xml, body);
        xml.close("geometries");
    }

    private static void body(Xml xml, Intersectable body) {
        Class<?> type = requireNonNull(body, "a body").getClass();
        if (type == Geometries.class) {
            geometries(xml, ((Geometries) body).getGeometries());
            return;
        }
        // a flat mesh: a group of its triangles, each with the mesh's surface (a scene file names no OBJ file
        // for it); a smooth or textured one, its vertices and triangles with their normals and UVs
        if (type == TriangleMesh.class) {
            TriangleMesh mesh = (TriangleMesh) body;
            if (!mesh.isSmooth() && mesh.getUVs() == null && mesh.getTexture() == null) {
                geometries(xml, mesh.getTriangles());
                return;
            }
            xml.start("triangle-mesh").attribute("vertices", numbers(mesh.coordinates()))
                    .attribute("triangles", Arrays.stream(mesh.indices()).mapToObj(Integer::toString)
                            .collect(Collectors.joining(" ")));
            if (mesh.isSmooth())
                xml.attribute("normals", numbers(mesh.getNormals()));
            if (mesh.getUVs() != null)
                xml.attribute("uvs", numbers(mesh.getUVs()));
        } else if (type == Sphere.class) {
            Sphere sphere = (Sphere) body;
            xml.start("sphere").attribute("center", point(sphere.getCenter()))
                    .attribute("radius", number(sphere.getRadius()));
        } else if (type == Triangle.class) {
            List<Point3D> vertices = ((Triangle) body).getVertices();
            xml.start("triangle").attribute("p0", point(vertices.get(0))).attribute("p1", point(vertices.get(1)))
                    .attribute("p2", point(vertices.get(2)));
        } else if (type == Polygon.class) {
            StringBuilder vertices = new StringBuilder();
            for (Point3D vertex : ((Polygon) body).getVertices())
                vertices.append(vertices.length() == 0 ? "" : " ").append(point(vertex));
            xml.start("polygon").attribute("vertices", vertices.toString());
        } else if (type == Plane.class) {
            Plane plane = (Plane) body;
            xml.start("plane").attribute("q0", point(plane.getQ0()))
                    .attribute("normal", direction(plane.getNormal()));
        } else if (type == Tube.class) {
            Tube tube = (Tube) body;
            xml.start("tube").attribute("p0", point(tube.getAxisRay().getP0()))
                    .attribute("dir", direction(tube.getAxisRay().getDir()))
                    .attribute("radius", number(tube.getRadius()));
        } else if (type == Cylinder.class) {
            Cylinder cylinder = (Cylinder) body;
            xml.start("cylinder").attribute("p0", point(cylinder.getAxisRay().getP0()))
                    .attribute("dir", direction(cylinder.getAxisRay().getDir()))
                    .attribute("radius", number(cylinder.getRadius()))
                    .attribute("height", number(cylinder.getHeight()));
        } else
            throw new IllegalArgumentException("a scene file cannot express the body type " + type.getName());
        surface(xml, (Geometry) body);
        texture(xml, ((Geometry) body).getTexture());
    }

    /** Ends a body's element: empty, or with its texture inside. */
    private static void texture(Xml xml, Texture texture) {
        if (texture == null) {
            xml.empty();
            return;
        }
        String body = xml.element;
        xml.open();
        if (texture.getClass() == ImageTexture.class) {
            ImageTexture image = (ImageTexture) texture;
            xml.start("image-texture").attribute("file", escape(xml.path(image.getFile())))
                    .attribute("size", number(image.getSize()), "1").empty();
        } else if (texture.getClass() == CheckerTexture.class) {
            CheckerTexture checker = (CheckerTexture) texture;
            xml.start("checker-texture").attribute("color1", color(checker.getColor1()))
                    .attribute("color2", color(checker.getColor2()))
                    .attribute("size", number(checker.getSize()), "1").empty();
        } else
            throw new IllegalArgumentException("a scene file cannot express the texture type "
                    + texture.getClass().getName());
        xml.close(body);
    }

    private static void surface(Xml xml, Geometry body) {
        Material material = body.getMaterial();
        xml.attribute("emission", color(body.getEmission()), "0 0 0")
                .attribute("kD", number(material.getKd()), "0").attribute("kS", number(material.getKs()), "0")
                .attribute("kT", number(material.getKt()), "0").attribute("kR", number(material.getKr()), "0")
                .attribute("kG", number(material.getKg()), "0").attribute("kB", number(material.getKb()), "0")
                .attribute("nShininess", Integer.toString(material.getShininess()), "0");
        if (material.hasIor())
            xml.attribute("ior", number(material.getIor()));
        xml.attribute("fresnel", Boolean.toString(material.isFresnel()), "false");
    }

    // ===== values =====

    /**
     * The shortest decimal text that reads back as exactly this double, in the schema's number syntax.
     *
     * @param value a finite number
     * @return its text: {@code 0.3}, {@code 75}, {@code 0.00001}, {@code 1E-12}
     */
    static String number(double value) {
        if (!Double.isFinite(value))
            throw new IllegalArgumentException("a scene file cannot express the number " + value);
        if (value == 0) // also -0: the sign of a zero does not change a picture
            return "0";
        BigDecimal exact = new BigDecimal(value);
        for (int digits = 1; ; ++digits) { // 17 significant digits always read back exactly
            BigDecimal rounded = exact.round(new MathContext(digits, RoundingMode.HALF_EVEN));
            if (rounded.doubleValue() == value)
                return text(rounded.stripTrailingZeros());
        }
    }

    /** A decimal in plain notation, or in scientific notation when that saves more than six characters. */
    private static String text(BigDecimal decimal) {
        String plain = decimal.toPlainString();
        String scientific = decimal.toString().replace("E+", "E");
        return plain.length() <= scientific.length() + 6 ? plain : scientific;
    }

    /** {@return numbers in their shortest texts, one space apart} */
    private static String numbers(double[] values) {
        return Arrays.stream(values).mapToObj(SceneWriter::number).collect(Collectors.joining(" "));
    }

    private static String triple(double x, double y, double z) {
        return number(x) + " " + number(y) + " " + number(z);
    }

    private static String point(Point3D point) {
        return triple(point.getX(), point.getY(), point.getZ());
    }

    private static String color(Color color) {
        return triple(color.getR(), color.getG(), color.getB());
    }

    /**
     * The simplest text of a direction whose normalised vector is exactly this unit vector — the library
     * normalises every direction it is given, so {@code 1 1 -2} stands for (1, 1, -2) / √6 bit for bit.
     * The candidates are the vector scaled to make one component ±1, ±2, … ±12, rounded to at most three
     * decimals; of those that normalise exactly to the vector, the one with the fewest digits is written
     * ({@code 0 1 0.1}, not {@code 0 10 1}), then the one with the smallest factor, then the shortest
     * ({@code 1 1 -2}, not {@code 0.5 0.5 -1}). When none does, the vector itself is written, nudged to
     * normalise to itself.
     *
     * @param unit a unit vector kept by the library
     * @return its text
     */
    static String direction(Vector unit) {
        double[] xyz = { unit.getX(), unit.getY(), unit.getZ() };
        String best = null;
        int bestDigits = Integer.MAX_VALUE;
        int bestFactor = Integer.MAX_VALUE;
        for (double divisor : xyz) {
            if (divisor == 0)
                continue;
            for (int factor = 1; factor <= MAX_DIRECTION_FACTOR; ++factor)
                for (int decimals = 0; decimals <= MAX_DIRECTION_DECIMALS; ++decimals) {
                    double x = rounded(xyz[0] * factor / Math.abs(divisor), decimals);
                    double y = rounded(xyz[1] * factor / Math.abs(divisor), decimals);
                    double z = rounded(xyz[2] * factor / Math.abs(divisor), decimals);
                    if (normalisesTo(x, y, z, unit)) {
                        String text = triple(x, y, z);
                        int digits = digits(text);
                        if (digits < bestDigits || digits == bestDigits && (factor < bestFactor
                                || factor == bestFactor && text.length() < best.length())) {
                            best = text;
                            bestDigits = digits;
                            bestFactor = factor;
                        }
                        break; // more decimals only lengthen the text
                    }
                }
        }
        return best != null ? best : nearUnit(unit);
    }

    /** A number rounded to some decimals, half to even. */
    private static double rounded(double value, int decimals) {
        return BigDecimal.valueOf(value).setScale(decimals, RoundingMode.HALF_EVEN).doubleValue();
    }

    /** The number of digits of numbers' texts, without leading zeros: 3 for {@code 0 0.2 -1}, 4 for {@code 0 10 1}. */
    private static int digits(String numbers) {
        int count = 0;
        for (String number : numbers.split(" ")) {
            String digits = number.replaceFirst("^-?[0.]*", "").replaceFirst("E.*", "").replace(".", "");
            count += digits.isEmpty() ? 1 : digits.length(); // 0 is one digit
        }
        return count;
    }

    /**
     * A vector near this unit vector (a unit in the last place away), or near a small odd multiple of it,
     * whose normalised vector is exactly the unit vector: normalising a unit vector again may move it by a
     * unit in the last place. The vector itself when the search fails.
     */
    private static String nearUnit(Vector unit) {
        for (int scale = 1; scale <= MAX_NUDGE_SCALE; scale += 2) { // even scales repeat smaller ones
            double[] xs = around(scale * unit.getX());
            double[] ys = around(scale * unit.getY());
            double[] zs = around(scale * unit.getZ());
            for (double x : xs)
                for (double y : ys)
                    for (double z : zs)
                        if (normalisesTo(x, y, z, unit))
                            return triple(x, y, z);
        }
        return triple(unit.getX(), unit.getY(), unit.getZ());
    }

    /** A number, then its neighbours a unit in the last place up and down. */
    private static double[] around(double value) {
        return new double[] { value, Math.nextUp(value), Math.nextDown(value) };
    }

    /** Whether the library, normalising the vector (x, y, z), gets exactly the unit vector. */
    private static boolean normalisesTo(double x, double y, double z, Vector unit) {
        return same(new Vector(x, y, z).normalized(), unit);
    }

    /** Whether two vectors have exactly the same components. */
    private static boolean same(Vector a, Vector b) {
        return a.getX() == b.getX() && a.getY() == b.getY() && a.getZ() == b.getZ();
    }

    /**
     * Escapes text for an attribute value: the XML markup characters, and tabs and line breaks (which a
     * parser would turn into spaces otherwise).
     *
     * @param text the text
     * @return the escaped text
     * @throws IllegalArgumentException when the text has a character XML 1.0 cannot hold
     */
    private static String escape(String text) {
        StringBuilder escaped = new StringBuilder();
        for (int k = 0; k < text.length(); ++k) {
            char c = text.charAt(k);
            switch (c) {
                case '&' -> escaped.append("&amp;");
                case '<' -> escaped.append("&lt;");
                case '>' -> escaped.append("&gt;");
                case '"' -> escaped.append("&quot;");
                case '\t' -> escaped.append("&#9;");
                case '\n' -> escaped.append("&#10;");
                case '\r' -> escaped.append("&#13;");
                default -> {
                    if (c < 0x20 || c == 0xFFFE || c == 0xFFFF)
                        throw new IllegalArgumentException("a scene file cannot express the character U+"
                                + String.format("%04X", (int) c) + " in the name " + text.strip());
                    escaped.append(c);
                }
            }
        }
        return escaped.toString();
    }

    /** The text being written: elements one per line, indented by their depth. */
    private static final class Xml {
        private final StringBuilder text = new StringBuilder();
        /** The scene file's folder, which files are named relative to; null for absolute paths. */
        private final Path folder;
        /** The name of the element started last. */
        private String element;
        private int depth;
        /** Where the element being started begins in the text. */
        private int elementStart;
        private boolean hasAttributes;

        /** @param folder the scene file's folder, which files are named relative to; null for absolute paths */
        Xml(Path folder) {
            this.folder = folder;
        }

        /** {@return a file's name in the scene file: relative to its folder when it can be, else absolute} */
        String path(Path file) {
            Path absolute = file.toAbsolutePath().normalize();
            if (folder != null && absolute.getRoot() != null && absolute.getRoot().equals(folder.getRoot()))
                return folder.normalize().relativize(absolute).toString().replace(File.separatorChar, '/');
            return absolute.toString();
        }

        /** Begins an element's start tag on a new line. */
        Xml start(String name) {
            element = name;
            elementStart = text.length();
            hasAttributes = false;
            text.append(INDENT.repeat(depth)).append('<').append(name);
            return this;
        }

        /** Adds an attribute (its value already escaped or plain). */
        Xml attribute(String name, String value) {
            text.append(' ').append(name).append("=\"").append(value).append('"');
            hasAttributes = true;
            return this;
        }

        /** Adds an attribute unless its value is the schema's default. */
        Xml attribute(String name, String value, String schemaDefault) {
            return value.equals(schemaDefault) ? this : attribute(name, value);
        }

        /** Ends the start tag of an element with children. */
        Xml open() {
            text.append(">\n");
            ++depth;
            return this;
        }

        /** Ends an element with no children. */
        void empty() {
            text.append("/>\n");
        }

        /** Ends an element with no children, or takes it back when it has no attributes either. */
        void emptyOrNothing() {
            if (hasAttributes)
                empty();
            else
                text.setLength(elementStart);
        }

        /** Writes the end tag of an element with children. */
        void close(String name) {
            --depth;
            text.append(INDENT.repeat(depth)).append("</").append(name).append(">\n");
        }

    }
}
