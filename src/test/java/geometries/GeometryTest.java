package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static testutil.TestAssertions.assertMessage;

import java.util.List;

import org.junit.jupiter.api.Test;

import primitives.CheckerTexture;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Texture;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.Geometry}: emission, material and texture defaults and setters.
 */
class GeometryTest {

    /**
     * A minimal concrete geometry: normal (0,0,1) everywhere, never hit.
     */
    private static class Dummy extends Geometry {
        @Override
        public Vector getNormal(Point3D point) {
            return new Vector(0, 0, 1);
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            return null;
        }
    }

    /**
     * Test method for {@link geometries.Geometry#getEmission()} and {@link geometries.Geometry#getMaterial()} defaults.
     */
    @Test
    void testDefaults() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a new geometry emits black
        Geometry g = new Dummy();
        assertEquals(Color.BLACK, g.getEmission(), "TC01: default emission must be black");

        // TC02: a new geometry has a material with every factor 0
        Material m = g.getMaterial();
        assertEquals(0, m.getKd(), 1e-10, "TC02: default kD must be 0");
        assertEquals(0, m.getKs(), 1e-10, "TC02: default kS must be 0");
        assertEquals(0, m.getKt(), 1e-10, "TC02: default kT must be 0");
        assertEquals(0, m.getKr(), 1e-10, "TC02: default kR must be 0");
        assertEquals(0, m.getShininess(), "TC02: default shininess must be 0");

        // TC03: the defaults hold for real shapes too (a sphere)
        Sphere s = new Sphere(Point3D.ZERO, 1);
        assertEquals(Color.BLACK, s.getEmission(), "TC03: a sphere's default emission must be black");
        assertEquals(0, s.getMaterial().getKd(), 1e-10, "TC03: a sphere's default kD must be 0");

        // ===== Boundary Values Tests =====
        // TC11: two geometries do not share one (mutable) default material
        assertNotSame(g.getMaterial(), s.getMaterial(), "TC11: default materials must not be shared");
        g.getMaterial().setKd(0.5);
        assertEquals(0, s.getMaterial().getKd(), 1e-10, "TC11: changing one default material changed another");
    }

    /**
     * Test method for {@link geometries.Geometry#setEmission(primitives.Color)}.
     */
    @Test
    void testSetEmission() {
        Geometry g = new Dummy();

        // ===== Equivalence Partitions Tests =====
        // TC01: the setter returns the geometry itself and the getter gives the colour (10,20,30)
        assertSame(g, g.setEmission(new Color(10, 20, 30)), "TC01: setEmission must return this");
        assertEquals(new Color(10, 20, 30), g.getEmission(), "TC01: wrong emission after set");

        // TC02: null is rejected and the old colour stays
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> g.setEmission(null),
                "TC02: null emission must throw");
        assertMessage(e, "emission", "TC02");
        assertEquals(new Color(10, 20, 30), g.getEmission(), "TC02: a rejected set must not change the emission");

        // ===== Boundary Values Tests =====
        // TC11: setting black back is accepted
        g.setEmission(Color.BLACK);
        assertEquals(Color.BLACK, g.getEmission(), "TC11: wrong emission after setting black");
    }

    /**
     * Test method for {@link geometries.Geometry#setMaterial(primitives.Material)}.
     */
    @Test
    void testSetMaterial() {
        Geometry g = new Dummy();
        Material m = new Material().setKd(0.4).setKs(0.6).setShininess(30);

        // ===== Equivalence Partitions Tests =====
        // TC01: the setter returns the geometry itself and the getter gives that material
        assertSame(g, g.setMaterial(m), "TC01: setMaterial must return this");
        assertSame(m, g.getMaterial(), "TC01: wrong material after set");
        assertEquals(0.4, g.getMaterial().getKd(), 1e-10, "TC01: wrong kD after set");
        assertEquals(30, g.getMaterial().getShininess(), "TC01: wrong shininess after set");

        // TC02: null is rejected and the old material stays
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> g.setMaterial(null),
                "TC02: null material must throw");
        assertMessage(e, "material", "TC02");
        assertSame(m, g.getMaterial(), "TC02: a rejected set must not change the material");

        // TC03: the setters chain (course style): emission then material on one shape
        Sphere s = new Sphere(Point3D.ZERO, 1);
        Geometry chained = s.setEmission(new Color(1, 2, 3)).setMaterial(m);
        assertSame(s, chained, "TC03: chained setters must return the same shape");
        assertEquals(new Color(1, 2, 3), s.getEmission(), "TC03: wrong emission after chaining");
        assertSame(m, s.getMaterial(), "TC03: wrong material after chaining");
    }

    /** Test method for {@link geometries.Geometry#setTexture(primitives.Texture)}. */
    @Test
    void testSetTexture() {
        Texture checker = new CheckerTexture(Color.BLACK, new Color(255, 255, 255), 1);
        Sphere sphere = new Sphere(Point3D.ZERO, 1);
        // ===== Equivalence Partitions Tests =====
        // TC01: no texture by default; the setter returns the body, the getter gives the texture
        assertNull(sphere.getTexture(), "TC01: no texture by default");
        assertSame(sphere, sphere.setTexture(checker), "TC01: setTexture must return this");
        assertSame(checker, sphere.getTexture(), "TC01: wrong texture after set");
        // TC02: a body without surface coordinates (a tube, this dummy) refuses a texture
        Tube tube = new Tube(new Ray(Point3D.ZERO, new Vector(0, 0, 1)), 1);
        assertMessage(assertThrows(IllegalArgumentException.class, () -> tube.setTexture(checker),
                "TC02: a tube has no surface coordinates"), "surface coordinates", "TC02");
        assertThrows(IllegalArgumentException.class, () -> new Dummy().setTexture(checker), "TC02: the dummy");
        assertThrows(UnsupportedOperationException.class, () -> new Dummy().getUV(Point3D.ZERO), "TC02: no UV");
        // TC03: a mesh refuses a texture until it has UVs
        TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 });
        assertMessage(assertThrows(IllegalArgumentException.class, () -> mesh.setTexture(checker),
                "TC03: a mesh without UVs"), "setUVs", "TC03");
        assertSame(mesh, mesh.setUVs(new double[] { 0, 0, 1, 0, 0, 1 }).setTexture(checker), "TC03: with UVs");
        // ===== Boundary Values Tests =====
        // TC11: null is refused and the texture stays
        assertMessage(assertThrows(IllegalArgumentException.class, () -> sphere.setTexture(null),
                "TC11: null texture"), "texture", "TC11");
        assertSame(checker, sphere.getTexture(), "TC11: a refused texture must not change it");
    }
}
