package testutil;

import static testutil.TestRandom.randomPoint;
import static testutil.TestRandom.randomUnit;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import benchmark.SphereMesh;
import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable.GeoPoint;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import geometries.Tube;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Seeded random test scenes shared by the tests of the hierarchy's walks: 20 kinds of scenes of 1 to 2000
 * bodies (spheres, triangles, squares, cylinders, planes, a tube, bodies that are not geometries, nested
 * composites), the dense mesh scene, random points on and in bodies and random rays aimed at them.
 */
public final class TestScenes {
    /** Not instantiable. */
    private TestScenes() {
    }

    /**
     * A random test scene.
     *
     * @param geometries the composite handed to the hierarchy (may nest composites)
     * @param bodies     every body in it, to aim rays at
     * @param size       the half-width of the cube the bodies lie in
     */
    public record TestScene(Geometries geometries, List<Intersectable> bodies, double size) {
    }

    /**
     * A body that is not a {@link Geometry}: it hands the intersections of the body it wraps, so the
     * hierarchy must test it on every ray.
     */
    public static final class Wrapper extends Intersectable {
        private final Intersectable inner;

        /**
         * Wraps a body.
         *
         * @param inner the body
         */
        public Wrapper(Intersectable inner) {
            this.inner = inner;
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            return inner.findGeoIntersections(ray, maxDistance);
        }
    }


    /**
     * A random sphere.
     *
     * @param rnd       the generator
     * @param size      the half-width of the cube its centre lies in
     * @param minRadius the smallest radius
     * @param maxRadius the largest radius
     * @return the sphere
     */
    public static Sphere randomSphere(Random rnd, double size, double minRadius, double maxRadius) {
        return new Sphere(randomPoint(rnd, Point3D.ZERO, size), minRadius + (maxRadius - minRadius) * rnd.nextDouble());
    }

    /**
     * A triangle of nine coordinates.
     *
     * @param v the vertices p1, p2, p3, three coordinates each
     * @return the triangle
     */
    public static Triangle triangle(double[] v) {
        return new Triangle(new Point3D(v[0], v[1], v[2]), new Point3D(v[3], v[4], v[5]), new Point3D(v[6], v[7], v[8]));
    }

    /**
     * A random triangle: its vertices lie in a small cube around a random point.
     *
     * @param rnd     the generator
     * @param size    the half-width of the cube its centre lies in
     * @param maxEdge the half-width of the cube around its centre its vertices lie in
     * @return the triangle
     */
    public static Triangle randomTriangle(Random rnd, double size, double maxEdge) {
        Point3D center = randomPoint(rnd, Point3D.ZERO, size);
        while (true) {
            try {
                return new Triangle(randomPoint(rnd, center, maxEdge), randomPoint(rnd, center, maxEdge),
                        randomPoint(rnd, center, maxEdge));
            } catch (IllegalArgumentException e) {
                // collinear by chance: draw again
            }
        }
    }

    /**
     * A random quadrilateral: a square with a random orientation.
     *
     * @param rnd  the generator
     * @param size the half-width of the cube its centre lies in
     * @return the polygon
     */
    public static Polygon randomSquare(Random rnd, double size) {
        Point3D center = randomPoint(rnd, Point3D.ZERO, size);
        Vector normal = randomUnit(rnd);
        Vector u = normal.crossProduct(Math.abs(normal.getX()) < 0.9 ? new Vector(1, 0, 0) : new Vector(0, 1, 0))
                .normalize().scale(0.1 + rnd.nextDouble());
        Vector v = normal.crossProduct(u);
        return new Polygon(center.add(u), center.add(v), center.add(u.scale(-1)), center.add(v.scale(-1)));
    }

    /**
     * A random cylinder.
     *
     * @param rnd  the generator
     * @param size the half-width of the cube its base lies in
     * @return the cylinder
     */
    public static Cylinder randomCylinder(Random rnd, double size) {
        return new Cylinder(new Ray(randomPoint(rnd, Point3D.ZERO, size), randomUnit(rnd)), 0.2 + rnd.nextDouble(),
                0.5 + 2 * rnd.nextDouble());
    }

    /**
     * A random scene of the kind a scene index names (20 kinds, 1 to 2000 bodies).
     *
     * @param rnd   the generator
     * @param index which scene, 0..19
     * @return the scene
     */
    public static TestScene randomScene(Random rnd, int index) {
        List<Intersectable> bodies = new ArrayList<>();
        double size = 10;
        switch (index) {
        case 0 -> bodies.add(randomSphere(rnd, size, 1, 3));
        case 1 -> bodies.add(randomTriangle(rnd, size, 5));
        case 2 -> {
            for (int i = 0; i < 3; ++i)
                bodies.add(randomSphere(rnd, size, 0.5, 3));
            bodies.add(new Plane(new Point3D(0, -12, 0), new Vector(0.1, 1, 0.2)));
        }
        case 3 -> {
            for (int i = 0; i < 4; ++i)
                bodies.add(randomTriangle(rnd, size, 4));
        }
        case 4 -> {
            for (int i = 0; i < 5; ++i)
                bodies.add(i % 2 == 0 ? randomSphere(rnd, size, 0.5, 2) : randomTriangle(rnd, size, 3));
        }
        case 5 -> {
            for (int i = 0; i < 16; ++i)
                bodies.add(i % 2 == 0 ? randomSphere(rnd, size, 0.5, 2) : randomTriangle(rnd, size, 3));
            bodies.add(randomCylinder(rnd, size));
            bodies.add(new Plane(new Point3D(0, 0, -13), new Vector(0, 0, 1)));
        }
        case 6 -> {
            for (int i = 0; i < 50; ++i)
                bodies.add(randomSphere(rnd, size, 0.2, 2));
        }
        case 7 -> {
            for (int i = 0; i < 50; ++i)
                bodies.add(randomTriangle(rnd, size, 3));
        }
        case 8 -> {
            for (int i = 0; i < 200; ++i)
                bodies.add(i % 3 == 0 ? randomSphere(rnd, size, 0.1, 1) : randomTriangle(rnd, size, 1.5));
        }
        case 9 -> {
            for (int i = 0; i < 500; ++i)
                bodies.add(i % 2 == 0 ? randomSphere(rnd, size, 0.05, 0.8) : randomTriangle(rnd, size, 1));
            bodies.add(randomCylinder(rnd, size));
            bodies.add(randomSquare(rnd, size));
            bodies.add(new Tube(new Ray(new Point3D(0, 0, 0), new Vector(1, 1, 0)), 0.5));
            bodies.add(new Plane(new Point3D(0, 11, 0), new Vector(0, -1, 0)));
        }
        case 10 -> {
            for (int i = 0; i < 1000; ++i)
                bodies.add(i % 2 == 0 ? randomSphere(rnd, size, 0.05, 0.5) : randomTriangle(rnd, size, 0.8));
        }
        case 11 -> {
            for (int i = 0; i < 2000; ++i)
                bodies.add(i % 4 == 0 ? randomSphere(rnd, size, 0.05, 0.4) : randomTriangle(rnd, size, 0.6));
        }
        case 12 -> { // many tiny triangles
            for (int i = 0; i < 2000; ++i)
                bodies.add(randomTriangle(rnd, size, 1e-2));
        }
        case 13, 14 -> { // every body's box has the same centre
            Point3D c = new Point3D(1, -2, 0.5);
            int n = index == 13 ? 300 : 1000;
            for (int i = 0; i < n; ++i) {
                if (i % 2 == 0) {
                    bodies.add(new Sphere(c, 0.1 + 8 * rnd.nextDouble()));
                    continue;
                }
                Vector a = randomUnit(rnd).scale(0.5 + 8 * rnd.nextDouble());
                Vector b = new Vector(a.getX() * (2 * rnd.nextDouble() - 1), a.getY() * (2 * rnd.nextDouble() - 1),
                        a.getZ() * (2 * rnd.nextDouble() - 1));
                try {
                    bodies.add(new Triangle(c.add(a), c.add(a.scale(-1)), c.add(b)));
                } catch (IllegalArgumentException e) {
                    // collinear by chance: skip it
                }
            }
        }
        case 17 -> { // two far clusters
            for (int i = 0; i < 400; ++i) {
                Point3D c = new Point3D(i % 2 == 0 ? -9 : 9, 0, 0);
                bodies.add(i % 3 == 0 ? new Sphere(randomPoint(rnd, c, 1), 0.05 + 0.2 * rnd.nextDouble())
                        : new Triangle(randomPoint(rnd, c, 1), randomPoint(rnd, c, 1), randomPoint(rnd, c, 1)));
            }
        }
        case 18 -> { // big and small overlapping spheres
            for (int i = 0; i < 300; ++i)
                bodies.add(randomSphere(rnd, size, 0.01, i % 10 == 0 ? 5 : 0.5));
        }
        default -> { // 15, 16, 19: filled below
        }
        }
        if (index == 15 || index == 16)
            return nestedScene(rnd, index == 15 ? 300 : 60, size);
        if (index == 19) {
            for (int i = 0; i < 100; ++i)
                bodies.add(i % 3 == 0 ? randomSquare(rnd, size) : randomTriangle(rnd, size, 2));
            bodies.add(new Wrapper(randomSphere(rnd, size, 1, 3)));
            bodies.add(new Wrapper(new Geometries(randomTriangle(rnd, size, 3), randomSphere(rnd, size, 0.5, 1))));
        }
        return new TestScene(new Geometries(bodies.toArray(new Intersectable[0])), bodies, size);
    }

    /**
     * A scene whose bodies are spread over composites nested three deep, some of them empty, with a
     * plane and a cylinder.
     *
     * @param rnd   the generator
     * @param n     the number of spheres and triangles
     * @param size  the half-width of the cube the bodies lie in
     * @return the scene
     */
    public static TestScene nestedScene(Random rnd, int n, double size) {
        Geometries root = new Geometries();
        List<Geometries> composites = new ArrayList<>(List.of(root));
        for (int i = 0; i < 3; ++i) {
            Geometries child = new Geometries();
            root.add(child);
            composites.add(child);
            for (int j = 0; j < 2; ++j) {
                Geometries grandchild = new Geometries(new Geometries());
                child.add(grandchild);
                composites.add(grandchild);
            }
        }
        List<Intersectable> bodies = new ArrayList<>();
        for (int i = 0; i < n; ++i) {
            Intersectable body = i % 2 == 0 ? randomSphere(rnd, size, 0.1, 1.5) : randomTriangle(rnd, size, 2);
            composites.get(rnd.nextInt(composites.size())).add(body);
            bodies.add(body);
        }
        Plane plane = new Plane(new Point3D(0, 0, -11), new Vector(0.2, 0.1, 1));
        Cylinder cylinder = randomCylinder(rnd, size);
        composites.get(3).add(plane);
        composites.get(5).add(new Geometries(cylinder));
        bodies.add(plane);
        bodies.add(cylinder);
        return new TestScene(root, bodies, size);
    }

    /**
     * A random point on or in a body, to aim a ray at.
     *
     * @param rnd  the generator
     * @param body the body
     * @return the point
     */
    public static Point3D pointIn(Random rnd, Intersectable body) {
        if (body instanceof Sphere sphere)
            return sphere.getCenter().add(randomUnit(rnd).scale(sphere.getRadius() * (0.01 + 0.98 * rnd.nextDouble())));
        if (body instanceof Polygon polygon) {
            List<Point3D> vertices = polygon.getVertices();
            double[] weights = new double[vertices.size()];
            double sum = 0;
            for (int i = 0; i < weights.length; ++i)
                sum += weights[i] = -Math.log(1 - rnd.nextDouble());
            double x = 0;
            double y = 0;
            double z = 0;
            for (int i = 0; i < weights.length; ++i) {
                x += weights[i] / sum * vertices.get(i).getX();
                y += weights[i] / sum * vertices.get(i).getY();
                z += weights[i] / sum * vertices.get(i).getZ();
            }
            return new Point3D(x, y, z);
        }
        if (body instanceof Cylinder cylinder)
            return cylinder.getAxisRay().getPoint(cylinder.getHeight() * rnd.nextDouble());
        if (body instanceof Wrapper wrapper)
            return pointIn(rnd, wrapper.inner);
        if (body instanceof Geometries composite)
            return pointIn(rnd, composite.getGeometries().get(0));
        return randomPoint(rnd, Point3D.ZERO, 5);
    }

    /**
     * A random ray through a scene: from anywhere around or inside it, half of them aimed at a point
     * of a random body, some along a coordinate axis.
     *
     * @param rnd   the generator
     * @param scene the scene
     * @return the ray
     */
    public static Ray randomRay(Random rnd, TestScene scene) {
        List<Intersectable> bodies = scene.bodies();
        double choice = rnd.nextDouble();
        Point3D origin = choice < 0.15 ? pointIn(rnd, bodies.get(rnd.nextInt(bodies.size())))
                : randomPoint(rnd, Point3D.ZERO, 1.5 * scene.size());
        double aim = rnd.nextDouble();
        if (aim < 0.1) {
            double sign = rnd.nextBoolean() ? 1 : -1;
            double zero = rnd.nextBoolean() ? 0.0 : -0.0;
            int axis = rnd.nextInt(3);
            return new Ray(origin,
                    new Vector(axis == 0 ? sign : zero, axis == 1 ? sign : zero, axis == 2 ? sign : zero));
        }
        if (aim < 0.6) {
            Point3D target = pointIn(rnd, bodies.get(rnd.nextInt(bodies.size())));
            if (target.distance(origin) > 1e-6)
                return new Ray(origin, target.subtract(origin));
        }
        return new Ray(origin, randomUnit(rnd));
    }

    /**
     * Sets a random kT on a body (on the body inside a wrapper or a composite).
     *
     * @param body the body
     * @param kts  the kT values to draw from
     * @param rnd  the generator
     */
    public static void setKt(Intersectable body, double[] kts, Random rnd) {
        if (body instanceof Geometry geometry)
            geometry.setMaterial(new Material().setKt(kts[rnd.nextInt(kts.length)]));
        else if (body instanceof Wrapper wrapper)
            setKt(wrapper.inner, kts, rnd);
        else if (body instanceof Geometries composite)
            for (Intersectable child : composite.getGeometries())
                setKt(child, kts, rnd);
    }

    /**
     * A random point on the surface of a body (up to rounding), to put a bundle's apex on.
     *
     * @param rnd  the generator
     * @param body the body
     * @return the point
     */
    public static Point3D pointOn(Random rnd, Intersectable body) {
        if (body instanceof Sphere sphere)
            return sphere.getCenter().add(randomUnit(rnd).scale(sphere.getRadius()));
        if (body instanceof Tube tube) { // and Cylinder: a point of the side
            Ray axis = tube.getAxisRay();
            double t = tube instanceof Cylinder cylinder ? cylinder.getHeight() * rnd.nextDouble()
                    : 10 * (2 * rnd.nextDouble() - 1);
            return axis.getPoint(t).add(perpendicular(rnd, axis.getDir()).scale(tube.getRadius()));
        }
        if (body instanceof Plane plane)
            return plane.getQ0().add(perpendicular(rnd, plane.getNormal()).scale(0.1 + 10 * rnd.nextDouble()));
        if (body instanceof Wrapper wrapper)
            return pointOn(rnd, wrapper.inner);
        if (body instanceof Geometries composite)
            return pointOn(rnd, composite.getGeometries().get(0));
        return pointIn(rnd, body); // a polygon's inner points lie on it
    }

    /**
     * A random unit vector orthogonal to a direction.
     *
     * @param rnd the generator
     * @param dir the direction
     * @return the vector
     */
    public static Vector perpendicular(Random rnd, Vector dir) {
        while (true) {
            Vector cross = dir.crossProduct(randomUnit(rnd));
            if (cross.length() > 1e-3)
                return cross.normalize();
        }
    }

    /**
     * A dense triangle mesh: a sphere of radius 6 cut into 960 triangles, with 6 small spheres around
     * it and a floor plane below.
     *
     * @param rnd the generator
     * @return the scene
     */
    public static TestScene meshScene(Random rnd) {
        return meshScene(rnd, false);
    }

    /**
     * The dense mesh scene of {@link #meshScene(Random)}, its sphere's triangles as {@link Triangle}s or
     * as one {@link TriangleMesh} (the scene's bodies to start bundles on are the triangles all the same).
     *
     * @param rnd    the generator
     * @param asMesh whether the sphere is a {@link TriangleMesh}
     * @return the scene
     */
    public static TestScene meshScene(Random rnd, boolean asMesh) {
        List<Intersectable> bodies = new ArrayList<>(SphereMesh.triangles(Point3D.ZERO, 6, 16, 32));
        Geometries geometries = asMesh ? new Geometries(SphereMesh.mesh(Point3D.ZERO, 6, 16, 32))
                : new Geometries(bodies.toArray(new Intersectable[0]));
        for (int i = 0; i < 7; ++i) {
            Geometry body = i < 6 ? new Sphere(Point3D.ZERO.add(randomUnit(rnd).scale(8 + rnd.nextDouble())),
                    0.3 + rnd.nextDouble()) : new Plane(new Point3D(0, -7, 0), new Vector(0, 1, 0));
            bodies.add(body);
            geometries.add(body);
        }
        return new TestScene(geometries, bodies, 8);
    }

    /**
     * A row of 40 small triangles at z = 0, triangle i around (i, 0, 0) (x from i − 0.1 to i + 0.1,
     * y from −0.1 to 0.1): its hierarchy's root splits it between triangles 19 and 20.
     *
     * @return the composite
     */
    public static Geometries triangleRow() {
        Geometries row = new Geometries();
        for (int i = 0; i < 40; ++i)
            row.add(new Triangle(new Point3D(i - 0.1, -0.1, 0), new Point3D(i + 0.1, -0.1, 0), new Point3D(i, 0.1, 0)));
        return row;
    }

    /**
     * Composites without a body: an empty one, and one of empty composites.
     *
     * @return new composites
     */
    public static List<Geometries> emptyComposites() {
        return List.of(new Geometries(), new Geometries(new Geometries(), new Geometries(new Geometries())));
    }

    /**
     * The centroid of a triangle, a point on it.
     *
     * @param triangle the triangle
     * @return the centroid
     */
    public static Point3D centroid(Triangle triangle) {
        List<Point3D> v = triangle.getVertices();
        return new Point3D((v.get(0).getX() + v.get(1).getX() + v.get(2).getX()) / 3,
                (v.get(0).getY() + v.get(1).getY() + v.get(2).getY()) / 3,
                (v.get(0).getZ() + v.get(1).getZ() + v.get(2).getZ()) / 3);
    }
}
