package scene;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

/**
 * Unit tests for {@link scene.Scene}.
 */
class SceneTest {
    /** Test method for {@link scene.Scene#Scene(String)}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a new scene keeps its name "test"; black background, black ambient light, no bodies, no lights
        Scene scene = new Scene("test");
        assertEquals("test", scene.name, "TC01: wrong name");
        assertEquals(Color.BLACK, scene.background, "TC01: default background must be black");
        assertNotNull(scene.ambientLight, "TC01: default ambient light must exist");
        assertEquals(Color.BLACK, scene.ambientLight.getIntensity(), "TC01: default ambient light must be black");
        assertNotNull(scene.geometries, "TC01: default geometries must exist");
        assertTrue(scene.geometries.getGeometries().isEmpty(), "TC01: default geometries must be empty");
        assertNotNull(scene.lights, "TC01: default lights must exist");
        assertTrue(scene.lights.isEmpty(), "TC01: default lights must be empty");
        // TC02: the default lights list accepts lights, as course tests do (scene.lights.add): size 1
        LightSource light = new PointLight(new Color(1, 1, 1), Point3D.ZERO);
        scene.lights.add(light);
        assertEquals(List.of(light), scene.lights, "TC02: added light missing");
        // TC03: two scenes do not share their lists: the other scene still has 0 lights
        assertTrue(new Scene("other").lights.isEmpty(), "TC03: scenes must not share the lights list");
        // TC04: a null name is rejected, the message names the "name"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Scene(null),
                "TC04: null name must be rejected");
        assertMessage(e, "name", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: the empty name "" is kept
        assertEquals("", new Scene("").name, "TC10: empty name must be kept");
    }

    /** Test method for {@link scene.Scene#setBackground(primitives.Color)}. */
    @Test
    void testSetBackground() {
        Scene scene = new Scene("test");
        // ===== Equivalence Partitions Tests =====
        // TC01: setBackground returns this and sets (75, 127, 90)
        assertSame(scene, scene.setBackground(new Color(75, 127, 90)), "TC01: setBackground must return this");
        assertEquals(new Color(75, 127, 90), scene.background, "TC01: wrong background");
        // TC02: a null background is rejected, the message names the "background"; (75, 127, 90) kept
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> scene.setBackground(null),
                "TC02: null background must be rejected");
        assertMessage(e, "background", "TC02");
        assertEquals(new Color(75, 127, 90), scene.background, "TC02: rejected background must not change it");
    }

    /** Test method for {@link scene.Scene#setAmbientLight(lighting.AmbientLight)}. */
    @Test
    void testSetAmbientLight() {
        Scene scene = new Scene("test");
        // ===== Equivalence Partitions Tests =====
        // TC01: setAmbientLight returns this and sets the light of intensity (38.25, 38.25, 38.25)
        AmbientLight ambient = new AmbientLight(new Color(255, 255, 255), 0.15);
        assertSame(scene, scene.setAmbientLight(ambient), "TC01: setAmbientLight must return this");
        assertSame(ambient, scene.ambientLight, "TC01: wrong ambient light");
        assertEquals(new Color(38.25, 38.25, 38.25), scene.ambientLight.getIntensity(), "TC01: wrong ambient intensity");
        // TC02: a null ambient light is rejected, the message names the "ambient light"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> scene.setAmbientLight(null), "TC02: null ambient light must be rejected");
        assertMessage(e, "ambient light", "TC02");
        assertSame(ambient, scene.ambientLight, "TC02: rejected ambient light must not change it");
    }

    /** Test method for {@link scene.Scene#setGeometries(geometries.Geometries)}. */
    @Test
    void testSetGeometries() {
        Scene scene = new Scene("test");
        // ===== Equivalence Partitions Tests =====
        // TC01: setGeometries returns this and sets a composite of 1 sphere
        Geometries bodies = new Geometries(new Sphere(Point3D.ZERO, 1));
        assertSame(scene, scene.setGeometries(bodies), "TC01: setGeometries must return this");
        assertSame(bodies, scene.geometries, "TC01: wrong geometries");
        assertEquals(1, scene.geometries.getGeometries().size(), "TC01: wrong number of bodies");
        // TC02: null geometries are rejected, the message names the "geometries"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> scene.setGeometries(null), "TC02: null geometries must be rejected");
        assertMessage(e, "geometries", "TC02");
        assertSame(bodies, scene.geometries, "TC02: rejected geometries must not change them");

        // ===== Boundary Values Tests =====
        // TC10: an empty composite is accepted (0 bodies)
        assertTrue(scene.setGeometries(new Geometries()).geometries.getGeometries().isEmpty(),
                "TC10: empty geometries must be accepted");
    }

    /** Test method for {@link scene.Scene#setLights(java.util.List)}. */
    @Test
    void testSetLights() {
        Scene scene = new Scene("test");
        LightSource point = new PointLight(new Color(100, 100, 100), new Point3D(0, 10, 0));
        LightSource sun = new DirectionalLight(new Color(50, 50, 50), new Vector(0, -1, 0));
        // ===== Equivalence Partitions Tests =====
        // TC01: setLights returns this and sets 2 lights, in order
        List<LightSource> lights = new ArrayList<>(List.of(point, sun));
        assertSame(scene, scene.setLights(lights), "TC01: setLights must return this");
        assertEquals(List.of(point, sun), scene.lights, "TC01: wrong lights");
        // TC02: a null list is rejected, the message names the "lights"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> scene.setLights(null),
                "TC02: null lights must be rejected");
        assertMessage(e, "lights", "TC02");
        // TC03: a list holding a null light is rejected, the message names the "light"
        e = assertThrows(IllegalArgumentException.class, () -> scene.setLights(Arrays.asList(point, null)),
                "TC03: a null light must be rejected");
        assertMessage(e, "light", "TC03");
        assertEquals(List.of(point, sun), scene.lights, "TC03: rejected lights must not change them");

        // ===== Boundary Values Tests =====
        // TC10: an empty list is accepted (0 lights)
        assertTrue(scene.setLights(new ArrayList<>()).lights.isEmpty(), "TC10: empty lights must be accepted");
    }

    /**
     * Test method for the scene's own list of lights, {@code scene.lights}: null is refused at the call that
     * puts it in, not when the picture renders.
     */
    @Test
    void testLightsList() {
        Scene scene = new Scene("test");
        LightSource point = new PointLight(new Color(100, 100, 100), new Point3D(0, 10, 0));
        LightSource sun = new DirectionalLight(new Color(50, 50, 50), new Vector(0, -1, 0));
        // ===== Equivalence Partitions Tests =====
        // TC01: the course's scene.lights.add(light), twice, then removed and inserted: [sun, point]
        scene.lights.add(point);
        scene.lights.add(sun);
        scene.lights.remove(point);
        scene.lights.add(1, point);
        assertEquals(List.of(sun, point), scene.lights, "TC01: wrong lights");
        // TC02: scene.lights.add(null) is refused at once, naming the list and the index 2
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> scene.lights.add(null),
                "TC02: a null light must be refused");
        assertMessage(e, "scene.lights must not hold null (at index 2)", "TC02");
        // TC03: null by set, by addAll and through an iterator, each refused; the lights stay [sun, point]
        assertThrows(IllegalArgumentException.class, () -> scene.lights.set(0, null), "TC03: set(0, null)");
        assertThrows(IllegalArgumentException.class, () -> scene.lights.addAll(Arrays.asList(point, null)),
                "TC03: addAll with a null");
        assertThrows(IllegalArgumentException.class, () -> scene.lights.listIterator().add(null),
                "TC03: an iterator's add(null)");
        assertThrows(IllegalArgumentException.class, () -> scene.lights.replaceAll(light -> null),
                "TC03: replaceAll to null");
        assertEquals(List.of(sun, point), scene.lights, "TC03: nothing must be added, not even the light before the null");

        // ===== Boundary Values Tests =====
        // TC11: null at the front (index 0) of an empty list
        scene.lights.clear();
        assertMessage(assertThrows(IllegalArgumentException.class, () -> scene.lights.add(0, null),
                "TC11: add(0, null) must be refused"), "at index 0", "TC11");
        assertTrue(scene.lights.isEmpty(), "TC11: nothing must be added");
    }

    /** Test method for {@link scene.Scene#requireComplete()}. */
    @Test
    void testRequireComplete() {
        Scene scene = new Scene("test");
        // ===== Equivalence Partitions Tests =====
        // TC01: a new scene is complete
        scene.requireComplete();
        // TC02: a list with a null light assigned to the field: refused, naming the index 1
        LightSource sun = new DirectionalLight(new Color(50, 50, 50), new Vector(0, -1, 0));
        scene.lights = Arrays.asList(sun, null);
        assertMessage(assertThrows(IllegalArgumentException.class, scene::requireComplete,
                "TC02: a null light must be refused"), "scene.lights must not hold null (at index 1)", "TC02");
        // TC03: a list set with setLights that holds null later: refused too
        List<LightSource> lights = new ArrayList<>();
        scene.setLights(lights);
        lights.add(null);
        assertMessage(assertThrows(IllegalArgumentException.class, scene::requireComplete,
                "TC03: a null light added later must be refused"), "at index 0", "TC03");
        // TC04 (own): each public field set to null is named
        scene.lights = null;
        assertMessage(assertThrows(IllegalArgumentException.class, scene::requireComplete, "TC04: null lights"),
                "scene.lights must not be null", "TC04");
        scene.lights = List.of();
        scene.geometries = null;
        assertMessage(assertThrows(IllegalArgumentException.class, scene::requireComplete, "TC04: null geometries"),
                "scene.geometries must not be null", "TC04");
        scene.geometries = new Geometries();
        scene.ambientLight = null;
        assertMessage(assertThrows(IllegalArgumentException.class, scene::requireComplete, "TC04: null ambient"),
                "scene.ambientLight must not be null", "TC04");
        scene.ambientLight = new AmbientLight();
        scene.background = null;
        assertMessage(assertThrows(IllegalArgumentException.class, scene::requireComplete, "TC04: null background"),
                "scene.background must not be null", "TC04");

        // ===== Boundary Values Tests =====
        // TC11: no lights at all (an empty list) is complete
        scene.background = Color.BLACK;
        scene.requireComplete();
    }
}
