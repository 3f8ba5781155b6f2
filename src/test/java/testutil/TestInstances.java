package testutil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import geometries.Geometries;
import geometries.Instance;
import geometries.Intersectable.GeoPoint;
import geometries.Plane;
import geometries.Sphere;
import geometries.TriangleMesh;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;

/**
 * Instances and their in-place copies, the bodies built where the instances put them, which the
 * instance tests compare: the same hits, normals and transmittances within a tolerance.
 */
public final class TestInstances {
    /** Not instantiable. */
    private TestInstances() {
    }

    /** The centre of the light's square of {@link #raysToLight}, above the crowd. */
    public static final Point3D LIGHT = new Point3D(0, 0, 30);
    /** Half of one side of the light's square. */
    public static final Vector LIGHT_A = new Vector(12, 0, 0);
    /** Half of the other side. */
    public static final Vector LIGHT_B = new Vector(0, 12, 0);

    /** Tolerance on points, normals and transmittances found through an instance and on its copy. */
    public static final double DELTA = 1e-7;

    /**
     * The placements the tests use: a translation, a rotation about a slanted axis, a non-uniform
     * scale, and the three in turn.
     */
    public static final List<Transform> PLACEMENTS = List.of(Transform.translate(new Vector(3, -2, 5)),
            Transform.rotate(new Vector(1, 2, 3), 37), Transform.scale(0.5, 2, 1.5),
            Transform.scale(1.5, 0.75, 2).then(Transform.rotateY(-63)).then(Transform.translate(new Vector(-4, 1, 2))));

    /** A similarity (a uniform scale, a turn and a move), under which a sphere stays a sphere. */
    public static final Transform SIMILARITY = Transform.scale(1.5).then(Transform.rotate(new Vector(-1, 1, 2), 50))
            .then(Transform.translate(new Vector(2, 3, -1)));

    /**
     * A mesh built in place: the triangles of a mesh over its vertices moved by a transform, its
     * vertex normals (when it has them) turned as normals are, its UVs and texture the same.
     *
     * @param mesh      the mesh
     * @param transform the transform
     * @return the moved mesh, with the mesh's material and emission
     */
    public static TriangleMesh inPlace(TriangleMesh mesh, Transform transform) {
        double[] vertices = new double[3 * mesh.getVerticesCount()];
        for (int v = 0; v < mesh.getVerticesCount(); ++v) {
            Point3D p = transform.apply(mesh.getVertex(v));
            vertices[3 * v] = p.getX();
            vertices[3 * v + 1] = p.getY();
            vertices[3 * v + 2] = p.getZ();
        }
        TriangleMesh copy = (TriangleMesh) new TriangleMesh(vertices, mesh.indices()).setMaterial(mesh.getMaterial())
                .setEmission(mesh.getEmission());
        double[] normals = mesh.getNormals();
        if (normals != null) {
            for (int v = 0; v < normals.length; v += 3) {
                Vector n = transform.applyToNormal(new Vector(normals[v], normals[v + 1], normals[v + 2]));
                normals[v] = n.getX();
                normals[v + 1] = n.getY();
                normals[v + 2] = n.getZ();
            }
            copy.setNormals(normals);
        }
        if (mesh.getUVs() != null)
            copy.setUVs(mesh.getUVs());
        if (mesh.getTexture() != null)
            copy.setTexture(mesh.getTexture());
        return copy;
    }

    /**
     * A sphere built in place under a similarity: its centre moved, its radius scaled.
     *
     * @param sphere     the sphere
     * @param similarity a transform that scales all directions alike
     * @return the moved sphere, with the sphere's material and emission
     */
    public static Sphere inPlace(Sphere sphere, Transform similarity) {
        double scale = similarity.applyToVector(new Vector(1, 0, 0)).length();
        return (Sphere) new Sphere(similarity.apply(sphere.getCenter()), sphere.getRadius() * scale)
                .setMaterial(sphere.getMaterial()).setEmission(sphere.getEmission());
    }

    /**
     * A grid of n × n × n cubes of side 0.6, one every 1, centred at the origin, as one closed mesh.
     *
     * @param n        the cubes along each axis
     * @param material the mesh's material
     * @return the mesh of 12 n³ triangles
     */
    public static TriangleMesh cubeGrid(int n, Material material) {
        TriangleMesh[] cubes = new TriangleMesh[n * n * n];
        double start = -(n - 1) / 2.0 - 0.3;
        for (int i = 0; i < cubes.length; ++i)
            cubes[i] = TestMeshes.cube(start + i % n, start + i / n % n, start + i / (n * n), 0.6);
        return (TriangleMesh) TestMeshes.merge(cubes).setMaterial(material);
    }

    /**
     * A scene with instances among other bodies, and the same scene with the bodies built in place.
     *
     * @param instanced the scene with instances
     * @param inPlace   the same scene built in place
     */
    public record InstanceScene(Geometries instanced, Geometries inPlace) {
        /**
         * Adds an instance to one scene and its copy to the other.
         *
         * @param instance the instance
         * @param copy     the bodies it stands for, built in place
         */
        void add(Instance instance, TriangleMesh... copy) {
            instanced.add(instance);
            inPlace.add(copy);
        }
    }

    /**
     * The scene the hierarchy tests trace through: an opaque grid of cubes placed four times, once more
     * transparent, a transparent group (a sphere and a box) placed by a similarity, an instance of an
     * instance, a crowd of 48 small turned and stretched boxes under the light (more than a bundle
     * keeps one by one), random spheres and a floor plane, shared by both scenes.
     *
     * @param rnd the generator (for the spheres)
     * @return the two scenes
     */
    public static InstanceScene scene(Random rnd) {
        InstanceScene scene = new InstanceScene(new Geometries(), new Geometries());
        TriangleMesh grid = cubeGrid(3, new Material().setKd(0.5));
        for (int i = 0; i < PLACEMENTS.size(); ++i) {
            Transform placed = PLACEMENTS.get(i).then(Transform.translate(new Vector(8 * Math.cos(i), 8 * Math.sin(i), 0)));
            scene.add(new Instance(grid, placed), inPlace(grid, placed));
        }
        TriangleMesh glassGrid = cubeGrid(2, new Material().setKt(0.6));
        Transform stretched = PLACEMENTS.get(3).then(Transform.translate(new Vector(0, 0, -6)));
        scene.add(new Instance(glassGrid, stretched), inPlace(glassGrid, stretched));
        Sphere glass = (Sphere) new Sphere(Point3D.ZERO, 1).setMaterial(new Material().setKt(0.5));
        TriangleMesh box = (TriangleMesh) TestMeshes.cuboid(-2, -0.5, -0.5, -1.2, 0.5, 0.5)
                .setMaterial(new Material().setKt(0.3));
        scene.instanced.add(new Instance(new Geometries(glass, box), SIMILARITY));
        scene.inPlace.add(inPlace(glass, SIMILARITY), inPlace(box, SIMILARITY));
        Transform outer = Transform.rotateZ(90).then(Transform.translate(new Vector(-7, -6, 3)));
        scene.add(new Instance(new Instance(grid, PLACEMENTS.get(2)), outer), inPlace(grid, PLACEMENTS.get(2).then(outer)));
        TriangleMesh small = (TriangleMesh) TestMeshes.cube(-0.5, -0.5, -0.5, 1).setMaterial(new Material().setKt(0.8));
        for (int i = 0; i < 48; ++i) {
            Transform placed = Transform.scale(0.3, 0.6, 0.2).then(Transform.rotate(new Vector(1, i, 2), 7 * i))
                    .then(Transform.translate(new Vector(-3.2 + 0.9 * (i % 8), -2.4 + 0.9 * (i / 8), 12)));
            scene.add(new Instance(small, placed), inPlace(small, placed));
        }
        for (int i = 0; i < 5; ++i) {
            Sphere sphere = TestScenes.randomSphere(rnd, 10, 0.5, 1.5);
            sphere.setMaterial(new Material().setKt(0.7));
            scene.instanced.add(sphere);
            scene.inPlace.add(sphere);
        }
        Plane floor = new Plane(new Point3D(0, 0, -15), new Vector(0, 0, 1));
        scene.instanced.add(floor);
        scene.inPlace.add(floor);
        return scene;
    }

    /**
     * A random ray through the scene's middle: aimed at a point of the cube [−12, 12]³ from 60 away.
     *
     * @param rnd the generator
     * @return the ray
     */
    public static Ray randomRay(Random rnd) {
        return TestRandom.rayThrough(rnd, TestRandom.randomPoint(rnd, Point3D.ZERO, 12), 60);
    }

    /**
     * Asserts that a hit through an instance is the copy's: both null, or at the same point with the
     * same normal and the same material (the body's: the copy shares it).
     *
     * @param copy     the hit on the copy
     * @param instance the hit through the instance
     * @param message  the failure message
     */
    public static void assertSameHit(GeoPoint copy, GeoPoint instance, String message) {
        if (copy == null) {
            assertNull(instance, message + ": no hit expected");
            return;
        }
        assertNotNull(instance, message + ": a hit expected at " + copy.point);
        assertEquals(0, copy.point.distance(instance.point), DELTA, message + ": wrong point");
        assertEquals(1, copy.getNormal().dotProduct(instance.getNormal()), DELTA, message + ": wrong normal");
        assertSame(copy.geometry.getMaterial(), instance.geometry.getMaterial(), message + ": wrong material");
    }

    /**
     * Random points of a light's square above the scene and the rays to them from a point.
     *
     * @param rnd   the generator
     * @param from  where the rays start
     * @param count     how many rays
     * @param distances the list their distances to the square are added to
     * @return the rays
     */
    public static List<Ray> raysToLight(Random rnd, Point3D from, int count, List<Double> distances) {
        List<Ray> rays = new ArrayList<>();
        for (int r = 0; r < count; ++r) {
            Point3D target = TestBundles.squarePoint(rnd, LIGHT, LIGHT_A, LIGHT_B);
            rays.add(new Ray(from, target.subtract(from)));
            distances.add(target.distance(from));
        }
        return rays;
    }
}
