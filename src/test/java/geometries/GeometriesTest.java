package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.Comparator;
import java.util.List;

import org.junit.jupiter.api.Test;

import accel.BoundingVolumeHierarchy;
import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.Geometries}.
 */
class GeometriesTest {
    /** Sphere around the origin, radius 1: a ray down the z axis hits it at z = 1 and z = -1. */
    private final Sphere sphere = new Sphere(Point3D.ZERO, 1);
    /** Triangle at z = -3 around the z axis: hit at (0,0,-3). */
    private final Triangle triangle = new Triangle(new Point3D(-1, -1, -3), new Point3D(1, -1, -3),
            new Point3D(0, 1, -3));
    /** Plane z = -5: hit at (0,0,-5). */
    private final Plane plane = new Plane(new Point3D(0, 0, -5), new Vector(0, 0, 1));
    /** All three shapes. */
    private final Geometries all = new Geometries(sphere, triangle, plane);

    /**
     * A ray down the z axis from a height.
     *
     * @param z the start height
     * @return the ray from (0,0,z) toward (0,0,-1)
     */
    private static Ray downFrom(double z) {
        return new Ray(new Point3D(0, 0, z), new Vector(0, 0, -1));
    }

    /**
     * Sorts points by decreasing z, so lists found in any order can be compared.
     *
     * @param points the points
     * @return a sorted copy
     */
    private static List<Point3D> byZ(List<Point3D> points) {
        return points.stream().sorted(Comparator.comparingDouble(Point3D::getZ).reversed()).toList();
    }

    /**
     * Test method for {@link geometries.Geometries#findIntersections(primitives.Ray)}.
     */
    @Test
    void testFindIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: some shapes are hit (triangle and plane, not the sphere: 2 points)
        List<Point3D> result = all.findIntersections(downFrom(-2));
        assertEquals(List.of(new Point3D(0, 0, -3), new Point3D(0, 0, -5)), byZ(result),
                "TC01: wrong points when some shapes are hit");

        // ===== Boundary Values Tests =====
        // TC11: empty collection (0 points)
        assertNull(new Geometries().findIntersections(downFrom(10)), "TC11: an empty collection must give null");

        // TC12: no shape is hit (the ray goes away from all of them: 0 points)
        assertNull(all.findIntersections(new Ray(new Point3D(0, 0, 10), new Vector(0, 0, 1))),
                "TC12: no shape hit must give null");

        // TC13: only one shape is hit (the plane: 1 point (0,0,-5))
        assertEquals(List.of(new Point3D(0, 0, -5)), all.findIntersections(downFrom(-4)),
                "TC13: wrong point when only one shape is hit");

        // TC14: all shapes are hit (2 + 1 + 1 = 4 points)
        List<Point3D> every = all.findIntersections(downFrom(10));
        assertEquals(4, every.size(), "TC14: wrong number of points when all shapes are hit");
        assertEquals(List.of(new Point3D(0, 0, 1), new Point3D(0, 0, -1), new Point3D(0, 0, -3), new Point3D(0, 0, -5)),
                byZ(every), "TC14: wrong points when all shapes are hit");
    }

    /**
     * Test method for {@link geometries.Geometries#findIntersections(primitives.Ray)}: the points come body by
     * body in the order the bodies were added, each body's nearest first, not sorted across bodies.
     */
    @Test
    void testIntersectionsBodyByBody() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the plane added first, then the sphere nearer the ray's start: the plane's (0, 0, -5), then the
        // sphere's (0, 0, 1) and (0, 0, -1), nearest first
        assertEquals(List.of(new Point3D(0, 0, -5), new Point3D(0, 0, 1), new Point3D(0, 0, -1)),
                new Geometries(plane, sphere).findIntersections(downFrom(10)), "TC01: wrong points or order");

        // ===== Boundary Values Tests =====
        // TC10: a single sphere in a composite: its two points nearest first, (0, 0, 1) then (0, 0, -1)
        assertEquals(List.of(new Point3D(0, 0, 1), new Point3D(0, 0, -1)),
                new Geometries(sphere).findIntersections(downFrom(10)), "TC10: wrong points or order");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray)} on a composite:
     * each point names the shape it lies on, also through a nested composite.
     */
    @Test
    void testFindGeoIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: every GeoPoint names the shape hit (4 GeoPoints)
        List<GeoPoint> result = all.findGeoIntersections(downFrom(10));
        assertEquals(4, result.size(), "TC01: wrong number of GeoPoints");
        assertTrue(result.contains(new GeoPoint(sphere, new Point3D(0, 0, 1))), "TC01: missing the sphere's first point");
        assertTrue(result.contains(new GeoPoint(sphere, new Point3D(0, 0, -1))), "TC01: missing the sphere's second point");
        assertTrue(result.contains(new GeoPoint(triangle, new Point3D(0, 0, -3))), "TC01: missing the triangle's point");
        assertTrue(result.contains(new GeoPoint(plane, new Point3D(0, 0, -5))), "TC01: missing the plane's point");

        // TC02: a composite nested in a composite is searched too (4 GeoPoints, the plane named)
        Geometries nested = new Geometries(sphere, new Geometries(triangle, new Geometries(plane)));
        List<GeoPoint> nestedResult = nested.findGeoIntersections(downFrom(10));
        assertEquals(4, nestedResult.size(), "TC02: wrong number of GeoPoints through nested composites");
        assertTrue(nestedResult.contains(new GeoPoint(plane, new Point3D(0, 0, -5))),
                "TC02: missing the plane's point through nested composites");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray, double)} on a composite.
     */
    @Test
    void testFindGeoIntersectionsMaxDistance() {
        // the ray from (0,0,10) meets the shapes at distances 9, 11, 13 and 15
        Ray ray = downFrom(10);

        // ===== Equivalence Partitions Tests =====
        // TC01: max distance 12 keeps only the sphere's two points
        List<GeoPoint> result = all.findGeoIntersections(ray, 12);
        assertEquals(2, result.size(), "TC01: wrong number of points within distance 12");
        assertTrue(result.stream().allMatch(gp -> gp.geometry == sphere), "TC01: only the sphere is within distance 12");

        // TC02: max distance 14 keeps the sphere and the triangle (3 points)
        assertEquals(3, all.findGeoIntersections(ray, 14).size(), "TC02: wrong number of points within distance 14");

        // TC03: max distance before every shape (null)
        assertNull(all.findGeoIntersections(ray, 5), "TC03: nothing within distance 5 must give null");

        // ===== Boundary Values Tests =====
        // TC11: max distance exactly at the farthest point (the plane at 15): all 4 points
        assertEquals(4, all.findGeoIntersections(ray, 15).size(), "TC11: a point exactly at the max distance must count");

        // TC12: max distance exactly at the nearest point (the sphere's top at 9): 1 point
        assertEquals(List.of(new GeoPoint(sphere, new Point3D(0, 0, 1))), all.findGeoIntersections(ray, 9),
                "TC12: a point exactly at the max distance must count");
    }

    /**
     * Test method for {@link geometries.Geometries#add(geometries.Intersectable...)}.
     */
    @Test
    void testAdd() {
        // ===== Equivalence Partitions Tests =====
        // TC01: add returns the composite itself and keeps the shapes in order
        Geometries g = new Geometries();
        assertSame(g, g.add(sphere, plane), "TC01: add must return the composite itself");
        assertSame(g, g.add(triangle), "TC01: add must return the composite itself");
        assertEquals(List.of(sphere, plane, triangle), g.getGeometries(), "TC01: wrong shapes held");

        // TC02: the list of shapes cannot be changed from outside
        assertThrows(UnsupportedOperationException.class, () -> g.getGeometries().clear(),
                "TC02: the list of shapes must be unmodifiable");

        // TC03: a null shape among others is rejected and nothing is added
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> g.add(sphere, null),
                "TC03: a null shape must throw");
        assertMessage(e, "null", "TC03");
        assertEquals(3, g.getGeometries().size(), "TC03: a rejected add must not add anything");

        // ===== Boundary Values Tests =====
        // TC11: a single null shape is rejected
        e = assertThrows(IllegalArgumentException.class, () -> g.add((Intersectable) null),
                "TC11: a null shape must throw");
        assertMessage(e, "null", "TC11");

        // TC12: a null array is rejected
        e = assertThrows(IllegalArgumentException.class, () -> g.add((Intersectable[]) null),
                "TC12: a null array must throw");
        assertMessage(e, "null", "TC12");

        // TC13: the constructor rejects a null shape too
        assertThrows(IllegalArgumentException.class, () -> new Geometries(sphere, null),
                "TC13: a null shape in the constructor must throw");

        // TC14: adding nothing leaves the composite unchanged
        assertSame(g, g.add(), "TC14: add must return the composite itself");
        assertEquals(3, g.getGeometries().size(), "TC14: adding nothing must not change the composite");
    }

    /**
     * Test method for {@link geometries.Geometries#add(geometries.Intersectable...)}: a composite that would
     * contain itself is refused when it is added, not found by a stack overflow later.
     */
    @Test
    void testAddCycles() {
        String cycle = "it would contain itself";
        Ray ray = new Ray(new Point3D(0, 0, -5), new Vector(0, 0, 1));
        // ===== Equivalence Partitions Tests =====
        // TC01: a composite added to itself
        Geometries g = new Geometries(sphere);
        assertMessage(assertThrows(IllegalArgumentException.class, () -> g.add(g), "TC01: g.add(g) must be refused"),
                "a Geometries cannot be added to itself", "TC01");
        // TC02: a composite added to one it holds: b holds a, then a.add(b)
        Geometries a = new Geometries(sphere);
        Geometries b = new Geometries(a);
        assertMessage(assertThrows(IllegalArgumentException.class, () -> a.add(b), "TC02: a.add(b) must be refused"),
                cycle, "TC02");
        // TC03 (own): three levels, c holds b holds a: a.add(c) is refused, and with it a sphere of the same call
        Geometries c = new Geometries(b);
        assertThrows(IllegalArgumentException.class, () -> a.add(plane, c), "TC03: a.add(plane, c) must be refused");
        assertEquals(List.of(sphere), a.getGeometries(), "TC03: nothing of a refused add may be added");
        // TC04: after the refusals every query still ends: the ray meets the sphere twice through c
        assertEquals(2, c.findIntersections(ray).size(), "TC04: wrong intersections");
        assertEquals(3, c.version(), "TC04: wrong version: one addition to each of a, b and c");
        // TC05: a cycle through an instance: e holds f, which holds an instance of e; then e.add(f), and
        // e.add of an instance of an instance of e, are refused
        Geometries e = new Geometries(sphere);
        Geometries f = new Geometries(new Instance(e, primitives.Transform.rotateX(30)));
        assertMessage(assertThrows(IllegalArgumentException.class, () -> e.add(f), "TC05: e.add(f) must be refused"),
                cycle, "TC05");
        Instance twice = new Instance(new Instance(e, primitives.Transform.scale(2)), primitives.Transform.IDENTITY);
        assertThrows(IllegalArgumentException.class, () -> e.add(twice), "TC05: an instance of e in e must be refused");

        // ===== Boundary Values Tests =====
        // TC11: one composite held in two places (no cycle) is allowed: d holds a directly and through b
        Geometries d = new Geometries(a, b);
        assertEquals(4, d.findIntersections(ray).size(), "TC11: the sphere is met twice through each place");
        // TC12: an empty composite added to itself is refused too
        Geometries empty = new Geometries();
        assertThrows(IllegalArgumentException.class, () -> empty.add(empty), "TC12: empty.add(empty) must be refused");
        // TC13 (own): a chain of 100,000 composites is checked without a stack overflow, and its cycle refused
        Geometries top = new Geometries();
        Geometries bottom = top;
        for (int k = 0; k < 100_000; ++k) {
            Geometries next = new Geometries();
            bottom.add(next);
            bottom = next;
        }
        Geometries deepest = bottom;
        assertThrows(IllegalArgumentException.class, () -> deepest.add(top), "TC13: the deep cycle must be refused");
    }

    /** Test method for {@link geometries.Geometries#version()}. */
    @Test
    void testVersion() {
        Geometries inner = new Geometries(sphere);
        Geometries outer = new Geometries(inner);
        long start = outer.version();

        // ===== Equivalence Partitions Tests =====
        // TC01: reading it changes nothing (the same number twice)
        assertEquals(start, outer.version(), "TC01: an unchanged composite must keep its version");
        // TC02: a body added to the composite itself: a larger number
        outer.add(plane);
        long afterOuter = outer.version();
        assertTrue(afterOuter > start, "TC02: adding to the composite must raise its version");
        // TC03: a body added to a nested composite: a larger number for the outer one too
        inner.add(triangle);
        assertTrue(outer.version() > afterOuter, "TC03: adding to a nested composite must raise the version");

        // TC04: a body added to a composite inside an instance: a larger number for the outer one too
        Geometries placed = new Geometries(sphere);
        outer.add(new Instance(placed, primitives.Transform.translate(new Vector(1, 0, 0))));
        long withInstance = outer.version();
        placed.add(triangle);
        assertTrue(outer.version() > withInstance, "TC04: adding inside an instance must raise the version");

        // ===== Boundary Values Tests =====
        // TC11: a composite nested twice, then added to: counted in both places, still larger
        long before = outer.version();
        outer.add(inner);
        long twice = outer.version();
        assertTrue(twice > before, "TC11: nesting a composite must raise the version");
        inner.add(sphere);
        assertTrue(outer.version() > twice, "TC11: adding to a composite nested twice must raise the version");
    }

    /** Test method for {@link geometries.Geometries#hierarchy(int)}: built once, shared, built again after an addition. */
    @Test
    void testHierarchy() {
        Geometries inner = new Geometries(sphere);
        Geometries outer = new Geometries(inner, plane);

        // ===== Equivalence Partitions Tests =====
        // TC01: asked twice (on 2 threads, then 1) with nothing added: the same hierarchy, over 1 bounded body
        BoundingVolumeHierarchy first = outer.hierarchy(2);
        assertSame(first, outer.hierarchy(1), "TC01: an unchanged composite must keep its hierarchy");
        assertEquals(1, first.getBoundedCount(), "TC01: the sphere is the one bounded body");
        // TC02: a body added to the composite itself: a new hierarchy, over 2 bounded bodies
        outer.add(triangle);
        BoundingVolumeHierarchy second = outer.hierarchy(1);
        assertNotSame(first, second, "TC02: adding to the composite must build again");
        assertEquals(2, second.getBoundedCount(), "TC02: the sphere and the triangle are bounded");
        // TC03: a body added to a nested composite: a new hierarchy, over 3 bounded bodies
        inner.add(new Sphere(new Point3D(5, 0, 0), 1));
        BoundingVolumeHierarchy third = outer.hierarchy(1);
        assertNotSame(second, third, "TC03: adding to a nested composite must build again");
        assertEquals(3, third.getBoundedCount(), "TC03: both spheres and the triangle are bounded");

        // ===== Boundary Values Tests =====
        // TC11: an empty composite: a hierarchy of 0 nodes, kept
        Geometries empty = new Geometries();
        assertEquals(0, empty.hierarchy(1).getNodesCount(), "TC11: an empty composite has no nodes");
        assertSame(empty.hierarchy(1), empty.hierarchy(1), "TC11: an empty composite keeps its hierarchy");
        // TC12: 0 threads: refused, naming the threads
        assertMessage(assertThrows(IllegalArgumentException.class, () -> outer.hierarchy(0), "TC12: 0 threads"),
                "threads", "TC12");
    }
}
