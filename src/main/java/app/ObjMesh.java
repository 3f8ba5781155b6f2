package app;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.NoSuchElementException;

import de.javagl.obj.FloatTuple;
import de.javagl.obj.Obj;
import de.javagl.obj.ObjFace;
import de.javagl.obj.ObjReader;
import geometries.Triangle;
import primitives.Point3D;

import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * Reads a triangle mesh from a Wavefront OBJ file (with the de.javagl:obj library).
 * <p>
 * Only the vertices ({@code v}) and the faces ({@code f}) count; texture coordinates, normals,
 * groups and materials are ignored. Face indices may be absolute (1-based) or relative (negative,
 * counted back from the last vertex read). The library reads coordinates as {@code float}s.
 * A face of more than three vertices is taken as a convex polygon and split into a fan of
 * triangles around its first vertex, which keeps the face's winding. A triangle that is degenerate
 * (coincident or collinear vertices, refused by {@link Triangle}) is skipped, and so is a face of
 * fewer than three vertices: real OBJ files contain such faces, and they have no area to render.
 */
public final class ObjMesh {
    private ObjMesh() {
    }

    /**
     * Reads the triangles of an OBJ file as they are: scale 1, at the origin.
     *
     * @param file the OBJ file
     * @return the triangles, in the order of the file's faces (a new list the caller owns)
     * @throws IllegalArgumentException when the file is null, missing, unreadable or malformed, or
     *                                  has no triangle that is not degenerate
     */
    public static List<Triangle> read(Path file) {
        return read(file, 1, Point3D.ZERO);
    }

    /**
     * Reads the triangles of an OBJ file, scaled and moved: each vertex v of the file becomes
     * position + scale·v. Degenerate triangles are skipped (see the class comment).
     *
     * @param file     the OBJ file
     * @param scale    the factor applied to every vertex, a finite positive number
     * @param position where the file's origin goes
     * @return the triangles, in the order of the file's faces (a new list the caller owns)
     * @throws IllegalArgumentException when an argument is null, the scale is not a finite positive
     *                                  number, the file is missing, unreadable or malformed (for
     *                                  instance a bad number or a face index out of range), or it
     *                                  has no triangle that is not degenerate
     */
    public static List<Triangle> read(Path file, double scale, Point3D position) {
        requireNonNull(file, "OBJ file");
        requirePositive(scale, "scale of OBJ file " + file);
        requireNonNull(position, "position of OBJ file " + file);

        Obj obj = parse(file);
        Point3D[] vertices = vertices(obj, file, scale, position);
        int faceCount = obj.getNumFaces();
        List<Triangle> triangles = new ArrayList<>(faceCount + faceCount / 2);
        for (int f = 0; f < faceCount; ++f) {
            ObjFace face = obj.getFace(f);
            int n = face.getNumVertices();
            int[] indices = new int[n];
            for (int k = 0; k < n; ++k)
                indices[k] = vertexIndex(face, k, f, vertices.length, file);
            for (int k = 1; k + 1 < n; ++k)
                addTriangle(triangles, vertices[indices[0]], vertices[indices[k]], vertices[indices[k + 1]]);
        }
        if (triangles.isEmpty())
            throw new IllegalArgumentException("OBJ file " + file + " has no triangles"
                    + (faceCount == 0 ? "" : " (all its " + faceCount + " faces are degenerate)"));
        return triangles;
    }

    /** Reads the file with the library, turning every failure into a one-line message naming the file. */
    private static Obj parse(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            return ObjReader.read(in);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException("OBJ file not found: " + file, e);
        } catch (IOException | RuntimeException e) {
            throw new IllegalArgumentException("bad OBJ file " + file + ": " + reason(e), e);
        }
    }

    /** The library's complaint, on one line. */
    private static String reason(Exception e) {
        if (e instanceof NoSuchElementException)
            return "a vertex line (v, vt or vn) has no coordinates";
        Throwable cause = e instanceof NumberFormatException ? e : e.getCause();
        if (cause instanceof NumberFormatException)
            return ("bad number: " + cause.getMessage()).replaceAll("\\R", " ");
        String message = e.getMessage();
        if (message == null || message.isBlank())
            message = e.getClass().getSimpleName();
        return message.replaceAll("\\R", " ");
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
                throw new IllegalArgumentException("bad OBJ file " + file + ": vertex " + (i + 1) + " has "
                        + v.getDimensions() + " coordinates instead of 3");
            try {
                vertices[i] = new Point3D(x0 + scale * v.getX(), y0 + scale * v.getY(), z0 + scale * v.getZ());
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("bad OBJ file " + file + ": vertex " + (i + 1) + " " + v
                        + " scaled by " + scale + " and moved to " + position + ": " + e.getMessage(), e);
            }
        }
        return vertices;
    }

    /** The 0-based index of a face's vertex, checked against the number of vertices. */
    private static int vertexIndex(ObjFace face, int k, int f, int vertexCount, Path file) {
        int index = face.getVertexIndex(k);
        if (index < 0)
            throw new IllegalArgumentException("bad OBJ file " + file + ": face " + (f + 1)
                    + " refers to a vertex before the first one (relative index too far back)");
        if (index >= vertexCount)
            throw new IllegalArgumentException("bad OBJ file " + file + ": face " + (f + 1)
                    + " refers to vertex " + (index + 1) + ", but the file has " + vertexCount + " vertices");
        return index;
    }

    /** Adds the triangle unless it is degenerate (the constructor refuses coincident or collinear vertices). */
    private static void addTriangle(List<Triangle> triangles, Point3D p1, Point3D p2, Point3D p3) {
        try {
            triangles.add(new Triangle(p1, p2, p3));
        } catch (IllegalArgumentException degenerate) {
            // skipped on purpose: see the class comment
        }
    }
}
