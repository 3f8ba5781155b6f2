package scenefile;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.NoSuchElementException;
import java.util.regex.Pattern;

import de.javagl.obj.FloatTuple;
import de.javagl.obj.Obj;
import de.javagl.obj.ObjFace;
import de.javagl.obj.ObjReader;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Point3D;
import primitives.Printable;

import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * Reads a triangle mesh from a Wavefront OBJ file (with the de.javagl:obj library) into a flat
 * {@link TriangleMesh}: the file's vertices once each, its triangles as indices into them.
 * <p>
 * The file is read as UTF-8, without a byte-order mark at its start (bytes that are not UTF-8, which
 * can only stand in a comment or a name, are read as U+FFFD). It must be a regular file: a pipe or a
 * device, which could keep the reading waiting forever, is refused.
 * <p>
 * Only the vertices ({@code v}) and the faces ({@code f}) count; texture coordinates, normals,
 * groups and materials are ignored. Face indices may be absolute (1-based) or relative (negative,
 * counted back from the last vertex read). The library reads coordinates as {@code float}s.
 * A face of more than three vertices is taken as a convex polygon and split into a fan of
 * triangles around its first vertex, which keeps the face's winding. A triangle that is degenerate
 * (coincident or collinear vertices, refused by {@link Triangle} and {@link TriangleMesh}) is
 * skipped, and so is a face of fewer than three vertices: real OBJ files contain such faces, and
 * they have no area to render.
 */
public final class ObjMesh {
    /** The longest line of an OBJ file, in characters: room for a face of tens of thousands of vertices. */
    public static final int MAX_LINE_LENGTH = 1 << 20;
    /** How many characters are read at a time. */
    private static final int BUFFER_SIZE = 1 << 16;
    /** The byte-order mark, which some editors write at the start of a UTF-8 file. */
    private static final char BYTE_ORDER_MARK = '\uFEFF';

    private ObjMesh() {
    }

    /**
     * Reads the triangles of an OBJ file as they are (scale 1, at the origin), as {@link Triangle}
     * objects: the form this method has always had. A large mesh is lighter as {@link #readMesh(Path)}.
     *
     * @param file the OBJ file
     * @return the file's triangles, in the order of its faces
     * @throws IllegalArgumentException when the file is null, missing, unreadable or malformed, or
     *                                  has no triangle that is not degenerate
     */
    public static List<Triangle> read(Path file) {
        return readMesh(file).getTriangles();
    }

    /**
     * Reads the triangles of an OBJ file, scaled and moved, as {@link Triangle} objects: the form this
     * method has always had. A large mesh is lighter as {@link #readMesh(Path, double, Point3D)}.
     *
     * @param file     the OBJ file
     * @param scale    the factor applied to every vertex, a finite positive number
     * @param position where the file's origin goes
     * @return the file's triangles (each vertex placed), in the order of its faces
     * @throws IllegalArgumentException as {@link #readMesh(Path, double, Point3D)}
     */
    public static List<Triangle> read(Path file, double scale, Point3D position) {
        return readMesh(file, scale, position).getTriangles();
    }

    /**
     * Reads the triangles of an OBJ file as they are: scale 1, at the origin.
     *
     * @param file the OBJ file
     * @return the mesh of the file's vertices and triangles, in the order of its faces
     * @throws IllegalArgumentException when the file is null, missing, unreadable or malformed, or
     *                                  has no triangle that is not degenerate
     */
    public static TriangleMesh readMesh(Path file) {
        return readMesh(file, 1, Point3D.ZERO);
    }

    /**
     * Reads the triangles of an OBJ file, scaled and moved: each vertex v of the file becomes
     * position + scale·v. Degenerate triangles are skipped (see the class comment).
     *
     * @param file     the OBJ file
     * @param scale    the factor applied to every vertex, a finite positive number
     * @param position where the file's origin goes
     * @return the mesh of the file's vertices (each placed) and triangles, in the order of its faces
     * @throws IllegalArgumentException when an argument is null, the scale is not a finite positive
     *                                  number, the file is missing, unreadable or malformed (for
     *                                  instance a bad number or a face index out of range), or it
     *                                  has no triangle that is not degenerate
     */
    public static TriangleMesh readMesh(Path file, double scale, Point3D position) {
        requireNonNull(file, "OBJ file");
        requirePositive(scale, "scale of OBJ file " + Printable.of(file));
        requireNonNull(position, "position of OBJ file " + Printable.of(file));

        Obj obj = parse(file);
        Point3D[] vertices = vertices(obj, file, scale, position);
        int faceCount = obj.getNumFaces();
        int[] triangles = new int[3 * faceCount];
        int length = 0;
        for (int f = 0; f < faceCount; ++f) {
            ObjFace face = obj.getFace(f);
            int first = face.getVertexIndex(0); // checked by FaceIndexChecker
            for (int k = 1; k + 1 < face.getNumVertices(); ++k) {
                int second = face.getVertexIndex(k);
                int third = face.getVertexIndex(k + 1);
                if (TriangleMesh.isDegenerate(vertices[first], vertices[second], vertices[third]))
                    continue; // skipped on purpose: see the class comment
                if (length == triangles.length)
                    triangles = Arrays.copyOf(triangles, 2 * length);
                triangles[length++] = first;
                triangles[length++] = second;
                triangles[length++] = third;
            }
        }
        if (length == 0)
            throw failure("OBJ file " + file + " has no triangles"
                    + (faceCount == 0 ? "" : " (all its " + faceCount + " faces are degenerate)"), null);
        return new TriangleMesh(coordinates(vertices), Arrays.copyOf(triangles, length));
    }

    /** {@return the points' coordinates, three doubles each} */
    private static double[] coordinates(Point3D[] points) {
        double[] coordinates = new double[3 * points.length];
        for (int i = 0; i < points.length; ++i) {
            coordinates[3 * i] = points[i].getX();
            coordinates[3 * i + 1] = points[i].getY();
            coordinates[3 * i + 2] = points[i].getZ();
        }
        return coordinates;
    }

    /**
     * Reads the file with the library, after {@link FaceIndexChecker checking its lines and face
     * indices}; every failure becomes a one-line message naming the file.
     */
    private static Obj parse(Path file) {
        if (Files.exists(file) && !Files.isRegularFile(file))
            throw failure("bad OBJ file " + file + ": " + (Files.isDirectory(file) ? "it is a folder"
                    : "it is not a regular file but a pipe or a device, which could keep the reading waiting"), null);
        String text;
        try {
            text = checkedText(file);
        } catch (NoSuchFileException e) {
            throw failure("OBJ file not found: " + file, e);
        } catch (IOException e) {
            throw failure("bad OBJ file " + file + ": " + reason(e), e);
        }
        try {
            return ObjReader.read(new StringReader(text));
        } catch (IOException | RuntimeException e) {
            throw failure("bad OBJ file " + file + ": " + reason(e), e);
        }
    }

    /**
     * The failure to read an OBJ file. Its message quotes the file's name and maybe its text, made
     * {@link Printable printable}: a control character in them reaches no terminal.
     *
     * @param message what is wrong, naming the file
     * @param cause   the exception that revealed it, or null
     * @return the exception to throw
     */
    private static IllegalArgumentException failure(String message, Throwable cause) {
        return new IllegalArgumentException(Printable.of(message), cause);
    }

    /** The library's complaint, on one line. */
    private static String reason(Exception e) {
        if (e instanceof NoSuchElementException)
            return "a vertex line (v, vt or vn) has no coordinates";
        if (e instanceof AccessDeniedException)
            return "permission denied";
        Throwable cause = e instanceof NumberFormatException ? e : e.getCause();
        if (cause instanceof NumberFormatException)
            return ("bad number: " + cause.getMessage()).replaceAll("\\R", " ");
        String message = e.getMessage();
        if (message == null || message.isBlank())
            message = "it cannot be read";
        return message.replaceAll("\\R", " ");
    }

    /**
     * The file's text, read as UTF-8 without the byte-order mark, with lines of at most
     * {@link #MAX_LINE_LENGTH} characters (so a file without line breaks is refused, not read into
     * memory) and every face index checked.
     */
    private static String checkedText(Path file) throws IOException {
        StringBuilder text = new StringBuilder();
        StringBuilder line = new StringBuilder();
        FaceIndexChecker checker = new FaceIndexChecker(file);
        char[] buffer = new char[BUFFER_SIZE];
        // a reader of a charset replaces bytes it cannot decode with U+FFFD
        try (Reader in = new InputStreamReader(Files.newInputStream(file), StandardCharsets.UTF_8)) {
            boolean first = true; // the first characters read, which may start with a byte-order mark
            for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                int start = first && buffer[0] == BYTE_ORDER_MARK ? 1 : 0;
                first = false;
                for (int k = start; k < n; ++k) {
                    if (buffer[k] == '\n') {
                        checker.accept(line);
                        text.append(line).append('\n');
                        line.setLength(0);
                    } else if (line.length() == MAX_LINE_LENGTH)
                        throw checker.error("the line is longer than " + MAX_LINE_LENGTH
                                + " characters (is it an OBJ file?)");
                    else
                        line.append(buffer[k]);
                }
            }
        }
        checker.accept(line);
        checker.finish();
        return text.append(line).toString();
    }

    /** Builds every vertex's point once: position + scale·v. */
    private static Point3D[] vertices(Obj obj, Path file, double scale, Point3D position) {
        double x0 = position.getX();
        double y0 = position.getY();
        double z0 = position.getZ();
        Point3D[] vertices = new Point3D[obj.getNumVertices()];
        for (int i = 0; i < vertices.length; ++i) {
            FloatTuple v = obj.getVertex(i);
            if (v.getDimensions() < 3)
                throw failure("bad OBJ file " + file + ": vertex " + (i + 1) + " has "
                        + v.getDimensions() + " coordinates instead of 3", null);
            try {
                vertices[i] = new Point3D(x0 + scale * v.getX(), y0 + scale * v.getY(), z0 + scale * v.getZ());
            } catch (IllegalArgumentException e) {
                throw failure("bad OBJ file " + file + ": vertex " + (i + 1) + " " + v
                        + " scaled by " + scale + " and moved to " + position + ": " + e.getMessage(), e);
            }
        }
        return vertices;
    }

    /**
     * Checks the face indices of an OBJ file line by line, so that a bad one is reported with its line:
     * an absolute index (from 1) must name one of the file's vertices, a relative one (negative) one
     * of the vertices before its line. Indices that are not whole numbers are left to the library.
     */
    private static final class FaceIndexChecker {
        private static final Pattern WHOLE = Pattern.compile("[+-]?\\d+");

        private final Path file;
        /** The line being read, from 1. */
        private int lineNumber = 1;
        private long vertexCount;
        /** The largest index naming a vertex later in the file than its face, and the line of that face. */
        private int forwardLine;
        private long forwardIndex;

        FaceIndexChecker(Path file) {
            this.file = file;
        }

        /** Checks the next line. */
        void accept(CharSequence line) {
            String text = line.toString().strip(); // a line may end with \r
            if (starts(text, 'v'))
                ++vertexCount;
            else if (starts(text, 'f'))
                for (String item : text.substring(1).strip().split("\\s+"))
                    check(item.split("/", -1)[0]);
            ++lineNumber;
        }

        /** Whether the line is a statement of this one-letter keyword (v, f). */
        private static boolean starts(String text, char keyword) {
            return !text.isEmpty() && text.charAt(0) == keyword
                    && (text.length() == 1 || Character.isWhitespace(text.charAt(1)));
        }

        private void check(String item) {
            if (!WHOLE.matcher(item).matches())
                return;
            long index;
            try {
                index = Long.parseLong(item);
            } catch (NumberFormatException e) {
                index = item.startsWith("-") ? Long.MIN_VALUE : Long.MAX_VALUE;
            }
            if (index == 0)
                throw error("a face refers to vertex 0; vertices count from 1 (or back from -1)");
            if (index > Integer.MAX_VALUE || index < -Integer.MAX_VALUE)
                throw error("a face refers to vertex " + item + ", beyond any number of vertices");
            if (index < 0 && -index > vertexCount)
                throw error("a face refers to a vertex before the first one (relative index " + index
                        + " too far back)");
            if (index > vertexCount && index > forwardIndex) {
                forwardLine = lineNumber;
                forwardIndex = index;
            }
        }

        /** Checks, at the end of the file, that indices naming later vertices name existing ones. */
        void finish() {
            if (forwardIndex > vertexCount) {
                lineNumber = forwardLine;
                throw error("a face refers to vertex " + forwardIndex + ", but the file has " + vertexCount
                        + " vertices");
            }
        }

        /** A problem at the line being read. */
        IllegalArgumentException error(String problem) {
            return failure("bad OBJ file " + file + ":" + lineNumber + ": " + problem, null);
        }
    }
}
