package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertPrintable;

import java.io.IOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;
import org.junit.jupiter.api.io.TempDir;

import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Point3D;
import primitives.Vector;
import testutil.TestFiles;

/**
 * Unit tests for {@link ObjMesh}: reading OBJ files (quads, triangles, relative indices) into triangles,
 * skipping degenerate faces, and refusing bad input with a message that names the file and the problem.
 */
class ObjMeshTest {
    /** A folder of the test, for generated files. */
    @TempDir
    Path folder;

    /**
     * The path of a test OBJ file in src/test/resources/obj.
     *
     * @param name the file's name
     * @return its path
     */
    private static Path resource(String name) {
        URL url = ObjMeshTest.class.getResource("/obj/" + name);
        assertNotNull(url, "missing test resource obj/" + name);
        try {
            return Path.of(url.toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The area of a triangle: half the length of the cross product of two edges. */
    private static double area(Triangle t) {
        List<Point3D> v = t.getVertices();
        return v.get(1).subtract(v.get(0)).crossProduct(v.get(2).subtract(v.get(0))).length() / 2;
    }

    /** The total area of triangles. */
    private static double totalArea(List<Triangle> triangles) {
        double sum = 0;
        for (Triangle t : triangles)
            sum += area(t);
        return sum;
    }

    /** The centroid of a triangle. */
    private static Point3D centroid(Triangle t) {
        List<Point3D> v = t.getVertices();
        return new Point3D((v.get(0).getX() + v.get(1).getX() + v.get(2).getX()) / 3,
                (v.get(0).getY() + v.get(1).getY() + v.get(2).getY()) / 3,
                (v.get(0).getZ() + v.get(1).getZ() + v.get(2).getZ()) / 3);
    }

    /**
     * Checks a triangle's vertices, in order.
     *
     * @param expected the expected vertices
     * @param actual   the triangle
     * @param tc       the test case label
     */
    private static void assertVertices(List<Point3D> expected, Triangle actual, String tc) {
        assertEquals(expected, actual.getVertices(), tc + ": wrong triangle vertices");
    }

    /**
     * Checks a cube read with a scale and a position: 12 triangles whose vertices are the cube's 8
     * corners (each used), whose total area is the cube's surface and whose normals point outward.
     *
     * @param triangles the triangles read
     * @param scale     the scale (corners at ±scale from the centre)
     * @param centre    the position (the cube's centre)
     * @param tc        the test case label
     */
    private static void assertCube(List<Triangle> triangles, double scale, Point3D centre, String tc) {
        assertEquals(12, triangles.size(), tc + ": a cube of 6 quads must give 12 triangles");
        List<Point3D> corners = new ArrayList<>();
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2)
                for (int sz = -1; sz <= 1; sz += 2)
                    corners.add(new Point3D(centre.getX() + sx * scale, centre.getY() + sy * scale,
                            centre.getZ() + sz * scale));
        Set<Integer> used = new HashSet<>();
        for (Triangle t : triangles) {
            for (Point3D p : t.getVertices()) {
                int corner = corners.indexOf(p);
                assertTrue(corner >= 0, tc + ": vertex " + p + " is not a corner of the cube");
                used.add(corner);
            }
            Vector normal = t.getPlane().getNormal();
            assertEquals(1, normal.length(), 1e-10, tc + ": normal must be a unit vector");
            Vector outward = centroid(t).subtract(centre).normalize();
            assertTrue(normal.dotProduct(outward) > 0.5, tc + ": normal " + normal + " of " + t
                    + " must point out of the cube (counter-clockwise winding seen from outside)");
        }
        assertEquals(8, used.size(), tc + ": every corner of the cube must be used");
        double edge = 2 * scale;
        assertEquals(6 * edge * edge, totalArea(triangles), 1e-9, tc + ": wrong total area");
    }

    /**
     * Asserts that reading a file throws an IllegalArgumentException whose one-line message names the
     * file and contains the given words.
     *
     * @param read  the reading
     * @param file  the file the message must name
     * @param tc    the test case label
     * @param words the words the message must contain
     */
    private static void assertBad(Executable read, Path file, String tc, String... words) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, read, tc + ": must throw");
        assertMessage(e, file.toString(), tc);
        for (String word : words)
            assertMessage(e, word, tc);
        assertFalse(e.getMessage().contains("\n") || e.getMessage().contains("\r"),
                tc + ": message must be one line, got: " + e.getMessage());
    }

    /**
     * Asserts that reading a file with {@link ObjMesh#read(Path)} fails as {@link #assertBad} says.
     *
     * @param file  the file
     * @param tc    the test case label
     * @param words the words the message must contain
     */
    private static void assertBadFile(Path file, String tc, String... words) {
        assertBad(() -> ObjMesh.read(file), file, tc, words);
    }

    /**
     * Test method for {@link ObjMesh#read(Path, double, Point3D)} and {@link ObjMesh#read(Path)} on a cube
     * of quads.
     */
    @Test
    void testReadCube() {
        Path cube = resource("cube.obj");

        // ===== Equivalence Partitions Tests =====
        // TC01: cube scaled by 2 at (10,0,0): 12 triangles, corners at (10±2, ±2, ±2), area 6·4² = 96
        assertCube(ObjMesh.read(cube, 2, new Point3D(10, 0, 0)), 2, new Point3D(10, 0, 0), "TC01");

        // TC02: read(file) is scale 1 at the origin: corners at ±1, area 24
        assertCube(ObjMesh.read(cube), 1, Point3D.ZERO, "TC02");

        // TC03: the example scene's model scenes/models/cube.obj: the same cube, 12 triangles, area 24
        assertCube(ObjMesh.read(Path.of("scenes", "models", "cube.obj")), 1, Point3D.ZERO, "TC03");

        // TC04: a position off every axis (-3,5,7) and scale 0.5: corners at (-3±0.5, 5±0.5, 7±0.5), area 6
        assertCube(ObjMesh.read(cube, 0.5, new Point3D(-3, 5, 7)), 0.5, new Point3D(-3, 5, 7), "TC04");

        // ===== Boundary Values Tests =====
        // TC11: a tiny scale 0.001: corners at ±0.001, area 6·0.002² = 2.4e-5
        assertCube(ObjMesh.read(cube, 0.001, Point3D.ZERO), 0.001, Point3D.ZERO, "TC11");
    }

    /**
     * Test method for {@link ObjMesh#read(Path)}: triangle and quad faces, the fan, relative indices and
     * degenerate faces.
     */
    @Test
    void testReadFaces() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a triangle, a quad (fan of 2) and three degenerate faces (collinear, coincident, 2 vertices):
        // exactly 3 triangles, in file order, area 0.5 + 1 = 1.5
        List<Triangle> mixed = ObjMesh.read(resource("mixed.obj"));
        assertEquals(3, mixed.size(), "TC01: degenerate faces must be skipped, 3 triangles expected");
        assertVertices(List.of(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)), mixed.get(0), "TC01");
        assertVertices(List.of(new Point3D(2, 0, 0), new Point3D(3, 0, 0), new Point3D(3, 1, 0)), mixed.get(1), "TC01");
        assertVertices(List.of(new Point3D(2, 0, 0), new Point3D(3, 1, 0), new Point3D(2, 1, 0)), mixed.get(2), "TC01");
        assertEquals(1.5, totalArea(mixed), 1e-12, "TC01: wrong total area");

        // TC02: relative (negative) indices with texture and normal indices: 2 triangles, at z = 0 and z = 1
        List<Triangle> relative = ObjMesh.read(resource("relative.obj"));
        assertEquals(2, relative.size(), "TC02: 2 triangles expected");
        assertVertices(List.of(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)), relative.get(0), "TC02");
        assertVertices(List.of(new Point3D(0, 0, 1), new Point3D(1, 0, 1), new Point3D(0, 1, 1)), relative.get(1), "TC02");

        // TC03: the fan keeps the face's winding: the counter-clockwise quad's triangles have normal (0,0,1)
        assertEquals(new Vector(0, 0, 1), mixed.get(1).getPlane().getNormal(), "TC03: wrong normal of the fan's 1st triangle");
        assertEquals(new Vector(0, 0, 1), mixed.get(2).getPlane().getNormal(), "TC03: wrong normal of the fan's 2nd triangle");

        // ===== Boundary Values Tests =====
        // TC11: a pentagon whose first three vertices are collinear: the fan's first triangle is skipped, the
        // other two, (0,0,0)(2,0,0)(2,2,0) and (0,0,0)(2,2,0)(0,2,0), cover the square 2x2 (area 4)
        List<Triangle> pentagon = ObjMesh.read(resource("pentagon.obj"));
        assertEquals(2, pentagon.size(), "TC11: the degenerate triangle of the fan must be skipped");
        assertVertices(List.of(new Point3D(0, 0, 0), new Point3D(2, 0, 0), new Point3D(2, 2, 0)), pentagon.get(0), "TC11");
        assertVertices(List.of(new Point3D(0, 0, 0), new Point3D(2, 2, 0), new Point3D(0, 2, 0)), pentagon.get(1), "TC11");
        assertEquals(4, totalArea(pentagon), 1e-12, "TC11: wrong total area");
    }

    /**
     * Test method for {@link ObjMesh#readMesh(Path, double, Point3D)} on a large generated mesh: every vertex is
     * one point shared by the triangles around it.
     *
     * @throws IOException when the test cannot write its file
     */
    @Test
    void testReadLargeMesh() throws IOException {
        // a grid of n x n unit quads in the plane z = 0 with random heights: 2·n² triangles
        int n = 200;
        Random random = new Random(42);
        StringBuilder obj = new StringBuilder();
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
                obj.append("v ").append(i).append(' ').append(j).append(' ').append(random.nextInt(3)).append('\n');
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                int a = j * (n + 1) + i + 1;
                obj.append("f ").append(a).append(' ').append(a + 1).append(' ').append(a + n + 2).append(' ')
                        .append(a + n + 1).append('\n');
            }
        Path file = folder.resolve("grid.obj");
        Files.writeString(file, obj);

        // ===== Equivalence Partitions Tests =====
        // TC01: 200x200 quads, possibly non-planar, split into a fan each: 80000 triangles over the file's
        // 201·201 vertices, each kept once
        TriangleMesh mesh = ObjMesh.readMesh(file, 1, Point3D.ZERO);
        List<Triangle> grid = mesh.getTriangles();
        assertEquals(2 * n * n, grid.size(), "TC01: wrong number of triangles");
        assertEquals((n + 1) * (n + 1), mesh.getVerticesCount(), "TC01: every vertex must be kept once");

        // TC02: one vertex of the file is one vertex of the mesh: the two triangles of a quad share
        // vertices 1 and n+3 (indices 0 and n+2), and the quad to the right shares its left corners
        assertEquals(0, mesh.getVertexIndex(0, 0), "TC02: the first triangle must start at vertex 1");
        assertEquals(0, mesh.getVertexIndex(1, 0), "TC02: vertex 1 must be shared");
        assertEquals(n + 2, mesh.getVertexIndex(0, 2), "TC02: the first triangle's third vertex must be n+3");
        assertEquals(n + 2, mesh.getVertexIndex(1, 1), "TC02: vertex n+3 must be shared");
        assertEquals(mesh.getVertexIndex(0, 1), mesh.getVertexIndex(2, 0), "TC02: vertex 2 must be shared");
        Point3D diagonal = grid.get(0).getVertices().get(2);
        assertEquals(new Point3D(1, 1, diagonal.getZ()), diagonal, "TC02: vertex n+3 must be at x = 1, y = 1");

        // ===== Boundary Values Tests =====
        // TC11: the last triangle is the second half of the last quad: (n-1,n-1), (n,n), (n-1,n) in x and y
        List<Point3D> last = grid.get(grid.size() - 1).getVertices();
        assertEquals(n - 1, last.get(0).getX(), 0, "TC11: wrong x of the last quad's corner");
        assertEquals(n - 1, last.get(0).getY(), 0, "TC11: wrong y of the last quad's corner");
        assertEquals(n, last.get(1).getX(), 0, "TC11: wrong x of the last vertex");
        assertEquals(n, last.get(1).getY(), 0, "TC11: wrong y of the last vertex");
    }

    /**
     * Test method for {@link ObjMesh#read(Path, double, Point3D)}: bad files and bad arguments.
     */
    @Test
    void testBadInput() {
        Path cube = resource("cube.obj");

        // ===== Equivalence Partitions Tests =====
        // TC01: a missing file
        assertBadFile(folder.resolve("missing.obj"), "TC01", "OBJ file not found");

        // TC02: a coordinate that is not a number
        assertBadFile(resource("malformed.obj"), "TC02", "bad OBJ file", "abc");

        // TC03: a face index that is not a number
        assertBadFile(resource("bad-face.obj"), "TC03", "bad OBJ file", "f 1 2 x");

        // TC04: a face index past the last vertex
        assertBadFile(resource("index-out-of-range.obj"), "TC04", "bad OBJ file", "vertex 9", "3 vertices");

        // TC05: a relative index before the first vertex
        assertBadFile(resource("relative-out-of-range.obj"), "TC05", "bad OBJ file", "before the first");

        // TC06: a vertex with two coordinates
        assertBadFile(resource("two-coordinates.obj"), "TC06", "bad OBJ file", "2 coordinates");

        // TC07: a vertex line without coordinates
        assertBadFile(resource("empty-vertex.obj"), "TC07", "bad OBJ file", "no coordinates");

        // TC08: a coordinate too large for a float (infinite)
        assertBadFile(resource("huge.obj"), "TC08", "bad OBJ file", "vertex 2", "finite");

        // TC09: vertices but no faces
        assertBadFile(resource("no-faces.obj"), "TC09", "has no triangles");

        // TC10: only degenerate faces
        assertBadFile(resource("all-degenerate.obj"), "TC10", "has no triangles", "degenerate");

        // TC11: a folder instead of a file
        assertBadFile(folder, "TC11", "bad OBJ file");

        // TC12: negative scale
        assertBad(() -> ObjMesh.read(cube, -1, Point3D.ZERO), cube, "TC12", "scale", "positive");

        // TC13: null file
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ObjMesh.read(null, 1, Point3D.ZERO), "TC13: null file must throw");
        assertMessage(e, "OBJ file must not be null", "TC13");
        e = assertThrows(IllegalArgumentException.class, () -> ObjMesh.read(null), "TC13: null file must throw");
        assertMessage(e, "OBJ file must not be null", "TC13");

        // TC14: null position
        assertBad(() -> ObjMesh.read(cube, 1, null), cube, "TC14", "position", "must not be null");

        // TC15: a coordinate holding ESC ] 0 ; x BEL (an xterm title) is quoted printably: "0\x1B]0;x\x07y"
        Path title = TestFiles.write(folder, "title.obj", "v 0 0 0\u001b]0;x\u0007y\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assertPrintable(assertThrows(IllegalArgumentException.class, () -> ObjMesh.read(title), "TC15: bad number")
                .getMessage(), "0\\x1B]0;x\\x07y", "TC15");
        // TC16 (own): a face holding a C1 control (CSI, U+009B), and a file whose name holds ESC
        Path csi = TestFiles.write(folder, "csi\u001b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \u009b2J\n");
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class, () -> ObjMesh.read(csi),
                "TC16: bad face");
        assertPrintable(bad.getMessage(), "\\x9B2J", "TC16");
        assertPrintable(bad.getMessage(), "csi\\x1B.obj", "TC16");
        // TC17 (own): corners of every form (v, v/vt, v//vn, +v/vt/vn) between tabs and spaces: the normal
        // index past the last normal is named, with its line
        Path forms = TestFiles.write(folder, "forms.obj",
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1\t2/1 \t+3//2\nf 1 2/1/1 +3/1/1\n");
        assertBadFile(forms, "TC17", "forms.obj:6: a face refers to normal (vn) 2, but the file has 1 normals");

        // ===== Boundary Values Tests =====
        // TC21: an empty file
        assertBadFile(resource("empty.obj"), "TC21", "has no triangles");

        // TC22: scale 0
        assertBad(() -> ObjMesh.read(cube, 0, Point3D.ZERO), cube, "TC22", "scale", "positive");

        // TC23: scale NaN and infinite
        assertBad(() -> ObjMesh.read(cube, Double.NaN, Point3D.ZERO), cube, "TC23", "scale", "finite");
        assertBad(() -> ObjMesh.read(cube, Double.POSITIVE_INFINITY, Point3D.ZERO), cube, "TC23", "scale", "finite");

        // TC24: a scale and a position whose sum overflows: vertex 2 (1,-1,-1) lands at x = infinity
        assertBad(() -> ObjMesh.read(cube, Double.MAX_VALUE, new Point3D(Double.MAX_VALUE, 0, 0)), cube, "TC24",
                "bad OBJ file", "vertex 2", "finite");
    }

    /**
     * Test method for {@link ObjMesh#readMesh(Path)}: the file is read as UTF-8 without a byte-order mark,
     * and only a regular file is read: a pipe or a device is refused at once.
     *
     * @throws IOException when the test cannot read back its pipe
     */
    @Test
    void testEncodingAndFileKinds() throws IOException {
        String tetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n";
        // ===== Equivalence Partitions Tests =====
        // TC01: a UTF-8 byte-order mark before the first vertex: 4 vertices, not 3 ("face refers to vertex 4")
        TriangleMesh bom = ObjMesh.readMesh(TestFiles.write(folder, "bom.obj", "\ufeff" + tetrahedron));
        assertEquals(4, bom.getVerticesCount(), "TC01: the first vertex must be read");
        // TC02: ... and the indices are not shifted: triangle 0 is (0,0,0) (1,0,0) (0,1,0), as without the mark
        assertVertices(List.of(Point3D.ZERO, new Point3D(1, 0, 0), new Point3D(0, 1, 0)), bom.getTriangle(0), "TC02");
        // TC03: names and comments in UTF-8 (Hebrew, accents, CJK) are read like any other text
        Path names = TestFiles.write(folder, "names.obj", "# מודל: café\no 立方体\ng כ\u00e9\n" + tetrahedron);
        assertEquals(2, ObjMesh.readMesh(names).getTrianglesCount(), "TC03: a UTF-8 file must be read");
        // TC04: a named pipe (FIFO) is refused at once, naming it, not read (it would wait for a writer forever)
        Path fifo = TestFiles.fifo(folder, "pipe.obj");
        TestFiles.feed(fifo, tetrahedron); // a reader that opens the pipe would read a mesh: the test fails then
        assertBadFile(fifo, "TC04", "bad OBJ file " + fifo, "not a regular file");
        assertEquals(tetrahedron, new String(Files.readAllBytes(fifo), StandardCharsets.UTF_8),
                "TC04: the pipe must not have been read");

        // ===== Boundary Values Tests =====
        // TC11: a file of the byte-order mark alone has no triangles, like an empty one
        assertBadFile(TestFiles.write(folder, "onlyBom.obj", "\ufeff"), "TC11", "has no triangles");
        // TC12: only a mark at the start is dropped: a line that starts with one later is no vertex, 4 vertices
        Path late = TestFiles.write(folder, "lateBom.obj", "# x\n\ufeffv 5 5 5\n" + tetrahedron);
        assertEquals(4, ObjMesh.readMesh(late).getVerticesCount(), "TC12: the line after the start is not a vertex");
        // TC13 (own): bytes that are not UTF-8 (ISO-8859-1 "é" in a comment) do not stop the reading
        Path latin = folder.resolve("latin.obj");
        Files.write(latin, ("# caf\u00e9\n" + tetrahedron).getBytes(StandardCharsets.ISO_8859_1));
        assertEquals(2, ObjMesh.readMesh(latin).getTrianglesCount(), "TC13: a stray byte in a comment must be read");
        // TC14 (own): a device, /dev/null, is refused as not a regular file (it is not an empty OBJ file)
        assertBadFile(Path.of("/dev/null"), "TC14", "not a regular file");
    }

    /** Writes an OBJ file and asserts that reading it fails naming the file, this line and the problem. */
    private void assertBadLine(String name, String text, int line, String tc, String problem) {
        Path file = TestFiles.write(folder, name, text);
        assertBadFile(file, tc, file + ":" + line + ":", problem);
    }

    /**
     * Test method for {@link ObjMesh#read(Path)}: face indices beyond the int range or the vertex list
     * and lines without end are errors naming the file and the line; tiny triangles are kept.
     */
    @Test
    void testIndicesAndLines() {
        String square = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
        // ===== Equivalence Partitions Tests =====
        // TC01: an index beyond the int range (4294967299 = 2^32 + 3) is an error at its line, not vertex 3
        assertBadLine("wraps.obj", square + "f 1 2 4294967299\n", 4, "TC01", "vertex 4294967299");
        // TC02: 99999999999 is named as it is written
        assertBadLine("large.obj", square + "\nf 1 2 99999999999\n", 5, "TC02", "vertex 99999999999");
        // TC03: an index past the vertex list, even when a later face is fine, names its line
        assertBadLine("past.obj", square + "f 1 2 3\nf 1 2 7\nf 1 2 3\n", 5, "TC03",
                "vertex 7, but the file has 3 vertices");
        // TC04: a file without line breaks (a megabyte of zero bytes) is refused, not read into memory
        assertBadLine("zeros.obj", "\0".repeat(ObjMesh.MAX_LINE_LENGTH + 1), 1, "TC04",
                "longer than " + ObjMesh.MAX_LINE_LENGTH);
        // TC05: a triangle whose edges are 1e-9 long, at scale 1, is kept (the tolerance follows its size)
        Path tiny = TestFiles.write(folder, "tiny.obj", "v 0 0 0\nv 1e-9 0 0\nv 0 1e-9 0\nf 1 2 3\n");
        assertEquals(5e-19, area(ObjMesh.readMesh(tiny).getTriangle(0)), 1e-25, "TC05: the tiny triangle must be kept");

        // ===== Boundary Values Tests =====
        // TC11: index 0 (indices count from 1)
        assertBadLine("zero.obj", square + "f 0 1 2\n", 4, "TC11", "vertex 0");
        // TC12: 2147483648 (one past the int range) and -2147483648
        assertBadLine("over.obj", square + "f 1 2 2147483648\n", 4, "TC12", "vertex 2147483648");
        assertBadLine("under.obj", square + "f 1 2 -2147483648\n", 4, "TC12", "vertex -2147483648");
        // TC13: a face naming a vertex defined later in the file is read, and so are lines ending with \r\n
        Path windows = TestFiles.write(folder, "windows.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
        assertEquals(1, ObjMesh.readMesh(windows).getTrianglesCount(), "TC13: lines ending with \\r\\n must be read");
        Path later = TestFiles.write(folder, "later.obj", "v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n");
        assertEquals(1, ObjMesh.readMesh(later).getTrianglesCount(), "TC13: a forward reference must be read");
    }

    /** A square of two triangles in z = 0 with texture coordinates and normals (not unit: the reader normalises them). */
    private static final String SHADED_SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nvn 0 0 2\nvn 0 1 1\n";

    /** Asserts three numbers of an array, from an offset, within 1e-12. */
    private static void assertTriple(double x, double y, double z, double[] array, int offset, String message) {
        assertEquals(x, array[offset], 1e-12, message + " (x)");
        assertEquals(y, array[offset + 1], 1e-12, message + " (y)");
        assertEquals(z, array[offset + 2], 1e-12, message + " (z)");
    }

    /**
     * Test method for {@link ObjMesh#readMesh(Path, double, Point3D, ObjMesh.Normals)}: texture coordinates
     * ({@code vt}) and normals ({@code vn}), each distinct corner of the file a vertex of the mesh.
     */
    @Test
    void testNormalsAndUVs() {
        Path square = TestFiles.write(folder, "shaded.obj", SHADED_SQUARE + "f 1/1/1 2/2/1 3/3/2\nf 1/1/1 3/3/2 4/4/2\n");
        double s = 1 / Math.sqrt(2);
        // ===== Equivalence Partitions Tests =====
        // TC01: four corners, each a position with its vt and vn: 4 vertices, smooth, UVs as in the file,
        // normals normalised
        TriangleMesh mesh = ObjMesh.readMesh(square);
        assertEquals(4, mesh.getVerticesCount(), "TC01: one vertex per distinct corner");
        assertTrue(mesh.isSmooth(), "TC01: a file with vn is smooth");
        assertTriple(0, 0, 1, mesh.getNormals(), 3 * mesh.getVertexIndex(0, 1), "TC01: vn 1 normalised");
        assertTriple(0, s, s, mesh.getNormals(), 3 * mesh.getVertexIndex(1, 2), "TC01: vn 2 normalised");
        assertEquals(1, mesh.getUVs()[2 * mesh.getVertexIndex(0, 2)], 0, "TC01: vt 3's u");
        assertEquals(1, mesh.getUVs()[2 * mesh.getVertexIndex(0, 2) + 1], 0, "TC01: vt 3's v");
        // TC02: a texture seam: position 1 with vt 1 in one face and vt 5 in the other is two vertices
        Path seam = TestFiles.write(folder, "seam.obj", SHADED_SQUARE + "f 1/1/1 2/2/1 3/3/2\nf 1/5/1 3/3/2 4/4/2\n");
        TriangleMesh split = ObjMesh.readMesh(seam);
        assertEquals(5, split.getVerticesCount(), "TC02: a seam splits its position");
        assertEquals(split.getVertex(split.getVertexIndex(0, 0)), split.getVertex(split.getVertexIndex(1, 0)),
                "TC02: the two vertices of a seam lie at one position");
        // TC03: FLAT ignores the normals (the UVs stay); a file without vn is flat
        TriangleMesh flat = ObjMesh.readMesh(square, 1, Point3D.ZERO, ObjMesh.Normals.FLAT);
        assertFalse(flat.isSmooth(), "TC03: FLAT must read no normals");
        assertEquals(8, flat.getUVs().length, "TC03: FLAT keeps the UVs");
        Path textured = TestFiles.write(folder, "textured.obj", SHADED_SQUARE + "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
        assertFalse(ObjMesh.readMesh(textured).isSmooth(), "TC03: without vn the mesh is flat");
        // TC04: SMOOTH computes normals at the file's positions: the two sides of a seam share theirs
        Path tent = TestFiles.write(folder, "tent.obj", "v 0 0 0\nv 1 0 0\nv 1 1 1\nv 0 1 1\nv 0 2 0\nv 1 2 0\n"
                + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 4/1 3/2 6/3\nf 4/1 6/3 5/4\n");
        TriangleMesh smooth = ObjMesh.readMesh(tent, 1, Point3D.ZERO, ObjMesh.Normals.SMOOTH);
        assertEquals(8, smooth.getVerticesCount(), "TC04: the ridge's positions 3 and 4 are split by the seam");
        double[] normals = smooth.getNormals();
        int ridgeFront = smooth.getVertexIndex(1, 2); // position 4 with vt 4
        int ridgeBack = smooth.getVertexIndex(2, 0); // position 4 with vt 1
        assertTriple(0, 0, 1, normals, 3 * ridgeFront, "TC04: the ridge's normal points straight up");
        assertTriple(0, 0, 1, normals, 3 * ridgeBack, "TC04: both sides of the seam share it");
        // TC05: a bad vt or vn index, and a normal of length 0, name the file and the line
        assertBadLine("bad-vt.obj", SHADED_SQUARE + "f 1/1 2/2 3/9\n", 12, "TC05",
                "texture coordinate (vt) 9, but the file has 5 texture coordinates");
        assertBadLine("bad-vn.obj", SHADED_SQUARE + "f 1//1 2//-3 3//1\n", 12, "TC05", "normal (vn) before the first");
        Path zero = TestFiles.write(folder, "zero-vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n");
        assertBadFile(zero, "TC05", "normal 1 (vn)", "no direction");

        // ===== Boundary Values Tests =====
        // TC11: when only some faces have vt (or vn), none count: the file's vertices, no UVs, flat
        Path mixed = TestFiles.write(folder, "some.obj", SHADED_SQUARE + "f 1/1/1 2/2/1 3/3/2\nf 1 3 4\n");
        TriangleMesh some = ObjMesh.readMesh(mixed);
        assertEquals(4, some.getVerticesCount(), "TC11: the file's vertices");
        assertFalse(some.isSmooth(), "TC11: not every face has normals");
        assertEquals(null, some.getUVs(), "TC11: not every face has texture coordinates");
        // TC12: vt 0 is an error at its line
        assertBadLine("vt-zero.obj", SHADED_SQUARE + "f 1/0 2/1 3/1\n", 12, "TC12", "texture coordinate (vt) 0");
    }
}
