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
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.function.Predicate;

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
 * The vertices ({@code v}) and the faces ({@code f}) make the mesh; groups and materials are ignored.
 * When every face gives its corners texture coordinates ({@code vt}) the mesh gets them as UVs, and when
 * every face gives its corners normals ({@code vn}) the mesh is smooth with them (see {@link Normals}
 * for the choices); then each distinct corner of the file — a position with its texture coordinates
 * and normal — becomes a vertex of the mesh, so a seam of the texture or a sharp edge keeps its two
 * sides apart. Face indices may be absolute (1-based) or relative (negative, counted back from the last
 * vertex, texture coordinate or normal read). The library reads coordinates as {@code float}s.
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

    /** Which normals a mesh read from a file gets. */
    public enum Normals {
        /** The file's normals ({@code vn}), smooth; flat when the file has none. */
        FILE,
        /**
         * The file's normals, or when it has none, normals computed from the faces around each position
         * ({@link TriangleMesh#smoothNormals()} on the file's positions, so that the mesh stays smooth
         * across the seams of its texture).
         */
        SMOOTH,
        /** None: the mesh is flat, whatever the file says. */
        FLAT
    }

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
     * position + scale·v. Degenerate triangles are skipped (see the class comment). The mesh has the
     * file's texture coordinates and normals, when every face has them ({@link Normals#FILE}).
     *
     * @param file     the OBJ file
     * @param scale    the factor applied to every vertex, a finite positive number
     * @param position where the file's origin goes
     * @return the mesh of the file's vertices (each placed) and triangles, in the order of its faces
     * @throws IllegalArgumentException as {@link #readMesh(Path, double, Point3D, Normals)}
     */
    public static TriangleMesh readMesh(Path file, double scale, Point3D position) {
        return readMesh(file, scale, position, Normals.FILE);
    }

    /**
     * Reads the triangles of an OBJ file, scaled and moved, with the normals asked for: each vertex v
     * of the file becomes position + scale·v. Degenerate triangles are skipped (see the class comment).
     *
     * @param file     the OBJ file
     * @param scale    the factor applied to every vertex, a finite positive number
     * @param position where the file's origin goes
     * @param normals  which normals the mesh gets
     * @return the mesh of the file's vertices (each placed) and triangles, in the order of its faces
     * @throws IllegalArgumentException when an argument is null, the scale is not a finite positive
     *                                  number, the file is missing, unreadable or malformed (for
     *                                  instance a bad number, a face index out of range or a normal
     *                                  of length 0), or it has no triangle that is not degenerate
     */
    public static TriangleMesh readMesh(Path file, double scale, Point3D position, Normals normals) {
        requireNonNull(file, "OBJ file");
        requirePositive(scale, "scale of OBJ file " + Printable.of(file));
        requireNonNull(position, "position of OBJ file " + Printable.of(file));
        requireNonNull(normals, "normals of OBJ file " + Printable.of(file));

        Obj obj = parse(file);
        Point3D[] vertices = vertices(obj, file, scale, position);
        Corners corners = new Corners(obj, everyFace(obj, ObjFace::containsTexCoordIndices),
                normals != Normals.FLAT && everyFace(obj, ObjFace::containsNormalIndices));
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
                triangles[length++] = corners.vertex(face, 0);
                triangles[length++] = corners.vertex(face, k);
                triangles[length++] = corners.vertex(face, k + 1);
            }
        }
        if (length == 0)
            throw Printable.refusal("OBJ file " + file + " has no triangles"
                    + (faceCount == 0 ? "" : " (all its " + faceCount + " faces are degenerate)"), null);
        int[] kept = Arrays.copyOf(triangles, length);
        double[] positions = coordinates(vertices);
        TriangleMesh mesh = new TriangleMesh(corners.coordinates(positions), kept);
        corners.shade(mesh, file);
        if (normals == Normals.SMOOTH && !mesh.isSmooth())
            corners.smoothAtPositions(mesh, positions, kept);
        return mesh;
    }

    /** {@return whether every face of the file has this property} */
    private static boolean everyFace(Obj obj, Predicate<ObjFace> property) {
        for (int f = 0; f < obj.getNumFaces(); ++f)
            if (!property.test(obj.getFace(f)))
                return false;
        return obj.getNumFaces() > 0;
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
     * The vertices of a mesh read with texture coordinates or normals: each distinct corner of the file —
     * a position with its texture coordinates and its normal — once, in the order the faces first use
     * them. Without either, a corner is its position, and the vertices are the file's, as they are.
     */
    private static final class Corners {
        private final Obj obj;
        private final boolean uvs;
        private final boolean normals;
        private final Map<Corner, Integer> indices = new HashMap<>();
        private final List<Corner> corners = new ArrayList<>();

        /** A corner of a face: the file's indices (from 0) of its position, texture coordinates and normal (−1: none). */
        private record Corner(int position, int uv, int normal) {
        }

        /**
         * @param obj     the file, as the library read it
         * @param uvs     whether the corners have texture coordinates
         * @param normals whether they have normals
         */
        Corners(Obj obj, boolean uvs, boolean normals) {
            this.obj = obj;
            this.uvs = uvs;
            this.normals = normals;
        }

        /** {@return whether a corner is more than its position} */
        private boolean split() {
            return uvs || normals;
        }

        /** {@return the mesh's vertex of corner k of a face} */
        int vertex(ObjFace face, int k) {
            if (!split())
                return face.getVertexIndex(k);
            Corner corner = new Corner(face.getVertexIndex(k), uvs ? face.getTexCoordIndex(k) : -1,
                    normals ? face.getNormalIndex(k) : -1);
            return indices.computeIfAbsent(corner, added -> {
                corners.add(added);
                return corners.size() - 1;
            });
        }

        /** {@return the coordinates of the mesh's vertices, from those of the file's positions} */
        double[] coordinates(double[] positions) {
            if (!split())
                return positions;
            double[] xyz = new double[3 * corners.size()];
            for (int i = 0; i < corners.size(); ++i)
                System.arraycopy(positions, 3 * corners.get(i).position(), xyz, 3 * i, 3);
            return xyz;
        }

        /** Gives the mesh the file's texture coordinates and normals, when its corners have them. */
        void shade(TriangleMesh mesh, Path file) {
            if (uvs) {
                double[] uv = new double[2 * corners.size()];
                for (int i = 0; i < corners.size(); ++i) {
                    FloatTuple t = obj.getTexCoord(corners.get(i).uv());
                    uv[2 * i] = t.getX();
                    uv[2 * i + 1] = t.getDimensions() > 1 ? t.getY() : 0;
                }
                mesh.setUVs(uv);
            }
            if (normals) {
                double[] xyz = new double[3 * corners.size()];
                for (int i = 0; i < corners.size(); ++i) {
                    int n = corners.get(i).normal();
                    FloatTuple normal = obj.getNormal(n);
                    double x = normal.getX();
                    double y = normal.getY();
                    double z = normal.getZ();
                    double length = Math.sqrt(x * x + y * y + z * z);
                    if (!(length > 0 && length < Double.POSITIVE_INFINITY))
                        throw Printable.refusal("bad OBJ file " + file + ": normal " + (n + 1) + " (vn) "
                                + normal + " has no direction (its length is " + length + ")", null);
                    xyz[3 * i] = x / length;
                    xyz[3 * i + 1] = y / length;
                    xyz[3 * i + 2] = z / length;
                }
                mesh.setNormals(xyz);
            }
        }

        /**
         * Makes the mesh smooth with the normals computed at the file's positions, so that the corners
         * of a position (split by a seam of the texture) share one normal.
         *
         * @param mesh      the mesh of the corners
         * @param positions the file's positions' coordinates
         * @param triangles the mesh's triangles, by its vertices
         */
        void smoothAtPositions(TriangleMesh mesh, double[] positions, int[] triangles) {
            if (!split()) {
                mesh.smoothNormals();
                return;
            }
            int[] byPosition = new int[triangles.length];
            for (int i = 0; i < triangles.length; ++i)
                byPosition[i] = corners.get(triangles[i]).position();
            double[] atPositions = new TriangleMesh(positions, byPosition).smoothNormals().getNormals();
            double[] xyz = new double[3 * corners.size()];
            for (int i = 0; i < corners.size(); ++i)
                System.arraycopy(atPositions, 3 * corners.get(i).position(), xyz, 3 * i, 3);
            mesh.setNormals(xyz);
        }
    }

    /**
     * Reads the file with the library, after {@link FaceIndexChecker checking its lines and face
     * indices}; every failure becomes a one-line message naming the file.
     */
    private static Obj parse(Path file) {
        if (Files.exists(file) && !Files.isRegularFile(file))
            throw Printable.refusal("bad OBJ file " + file + ": " + (Files.isDirectory(file) ? "it is a folder"
                    : "it is not a regular file but a pipe or a device, which could keep the reading waiting"), null);
        String text;
        try {
            text = checkedText(file);
        } catch (NoSuchFileException e) {
            throw Printable.refusal("OBJ file not found: " + file, e);
        } catch (IOException e) {
            throw Printable.refusal("bad OBJ file " + file + ": " + reason(e), e);
        }
        try {
            return ObjReader.read(new StringReader(text));
        } catch (IOException | RuntimeException e) {
            throw Printable.refusal("bad OBJ file " + file + ": " + reason(e), e);
        }
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
                for (int k = start; k < n; ++k)
                    if (buffer[k] == '\n') {
                        appendToLine(line, buffer, start, k, checker);
                        checker.accept(line);
                        text.append(line).append('\n');
                        line.setLength(0);
                        start = k + 1;
                    }
                appendToLine(line, buffer, start, n, checker);
            }
        }
        checker.accept(line);
        checker.finish();
        return text.append(line).toString();
    }

    /** Appends the characters [from, to) of a buffer to the line, refusing a line longer than the limit. */
    private static void appendToLine(StringBuilder line, char[] buffer, int from, int to, FaceIndexChecker checker) {
        if (line.length() + to - from > MAX_LINE_LENGTH)
            throw checker.error("the line is longer than " + MAX_LINE_LENGTH + " characters (is it an OBJ file?)");
        line.append(buffer, from, to - from);
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
                throw Printable.refusal("bad OBJ file " + file + ": vertex " + (i + 1) + " has "
                        + v.getDimensions() + " coordinates instead of 3", null);
            try {
                vertices[i] = new Point3D(x0 + scale * v.getX(), y0 + scale * v.getY(), z0 + scale * v.getZ());
            } catch (IllegalArgumentException e) {
                throw Printable.refusal("bad OBJ file " + file + ": vertex " + (i + 1) + " " + v
                        + " scaled by " + scale + " and moved to " + position + ": " + e.getMessage(), e);
            }
        }
        return vertices;
    }

    /**
     * Checks the face indices of an OBJ file line by line, so that a bad one is reported with its line:
     * an absolute index (from 1) must name one of the file's vertices (texture coordinates, normals),
     * a relative one (negative) one of those before its line. Indices that are not whole numbers are
     * left to the library.
     */
    private static final class FaceIndexChecker {
        /** The statements that define what a face's indices name: positions, texture coordinates, normals. */
        private static final String[] KEYWORDS = { "v", "vt", "vn" };
        /** What each kind of index names, one and many. */
        private static final String[] ONE = { "vertex", "texture coordinate (vt)", "normal (vn)" };
        private static final String[] MANY = { "vertices", "texture coordinates", "normals" };

        private final Path file;
        /** The line being read, from 1. */
        private int lineNumber = 1;
        /** How many of each kind the file has defined so far. */
        private final long[] counts = new long[KEYWORDS.length];
        /** Of each kind, the largest index naming one later in the file than its face, and the line of that face. */
        private final int[] forwardLines = new int[KEYWORDS.length];
        private final long[] forwardIndices = new long[KEYWORDS.length];

        FaceIndexChecker(Path file) {
            this.file = file;
        }

        /** Checks the next line. */
        void accept(CharSequence line) {
            String text = line.toString().strip(); // a line may end with \r
            for (int kind = 0; kind < KEYWORDS.length; ++kind)
                if (starts(text, KEYWORDS[kind]))
                    ++counts[kind];
            if (starts(text, "f"))
                checkFace(text.substring(1).strip());
            ++lineNumber;
        }

        /** Whether the line is a statement of this keyword (v, vt, vn, f). */
        private static boolean starts(String text, String keyword) {
            return text.startsWith(keyword)
                    && (text.length() == keyword.length() || Character.isWhitespace(text.charAt(keyword.length())));
        }

        /**
         * Checks a face's corners, which runs of blanks separate (the blanks of the regular expression
         * {@code \s}; the text is stripped, so it starts and ends with a corner).
         */
        private void checkFace(String corners) {
            int end = corners.length();
            int start = 0;
            while (start < end) {
                int cornerEnd = start;
                while (cornerEnd < end && !isBlank(corners.charAt(cornerEnd)))
                    ++cornerEnd;
                checkCorner(corners, start, cornerEnd);
                start = cornerEnd;
                while (start < end && isBlank(corners.charAt(start)))
                    ++start;
            }
        }

        /** Checks a corner, the characters [from, to) of a text: its indices, which slashes separate. */
        private void checkCorner(String text, int from, int to) {
            for (int kind = 0; kind < KEYWORDS.length && from <= to; ++kind) {
                int indexEnd = from;
                while (indexEnd < to && text.charAt(indexEnd) != '/')
                    ++indexEnd;
                check(text, from, indexEnd, kind);
                from = indexEnd + 1;
            }
        }

        /** {@return whether a character is a blank of the regular expression {@code \s}} */
        private static boolean isBlank(char c) {
            return c == ' ' || c == '\t' || c == '\n' || c == '\u000B' || c == '\f' || c == '\r';
        }

        /** Checks one index, the characters [from, to) of a text: a whole number, or anything the library refuses. */
        private void check(String text, int from, int to, int kind) {
            if (!isWhole(text, from, to))
                return;
            long index;
            try {
                index = Long.parseLong(text, from, to, 10);
            } catch (NumberFormatException e) {
                index = text.charAt(from) == '-' ? Long.MIN_VALUE : Long.MAX_VALUE;
            }
            if (index == 0)
                throw error("a face refers to " + ONE[kind] + " 0; " + MANY[kind] + " count from 1 (or back from -1)");
            if (index > Integer.MAX_VALUE || index < -Integer.MAX_VALUE)
                throw error("a face refers to " + ONE[kind] + " " + text.substring(from, to) + ", beyond any number of "
                        + MANY[kind]);
            if (index < 0 && -index > counts[kind])
                throw error("a face refers to a " + ONE[kind] + " before the first one (relative index " + index
                        + " too far back)");
            if (index > counts[kind] && index > forwardIndices[kind]) {
                forwardLines[kind] = lineNumber;
                forwardIndices[kind] = index;
            }
        }

        /** {@return whether the characters [from, to) of a text are a sign, or none, then ASCII digits} */
        private static boolean isWhole(String text, int from, int to) {
            int digits = from < to && (text.charAt(from) == '+' || text.charAt(from) == '-') ? from + 1 : from;
            if (digits == to)
                return false;
            for (int k = digits; k < to; ++k)
                if (text.charAt(k) < '0' || text.charAt(k) > '9')
                    return false;
            return true;
        }

        /** Checks, at the end of the file, that indices naming later vertices (and so on) name existing ones. */
        void finish() {
            for (int kind = 0; kind < KEYWORDS.length; ++kind)
                if (forwardIndices[kind] > counts[kind]) {
                    lineNumber = forwardLines[kind];
                    throw error("a face refers to " + ONE[kind] + " " + forwardIndices[kind] + ", but the file has "
                            + counts[kind] + " " + MANY[kind]);
                }
        }

        /** A problem at the line being read. */
        IllegalArgumentException error(String problem) {
            return Printable.refusal("bad OBJ file " + file + ":" + lineNumber + ": " + problem, null);
        }
    }
}
