package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static testutil.TestAssertions.assertMessage;

import java.util.List;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link SchemaNames}: the attributes and children of each element, read from the
 * shipped schema.
 */
class SchemaNamesTest {
    /** The emission and material every body has (the schema's attribute group "surface"). */
    private static final List<String> SURFACE = List.of("emission", "kD", "kS", "kT", "kR", "kG", "kB", "nShininess",
            "ior", "fresnel", "name");

    /** Test method for {@link SchemaNames#attributes(String)}. */
    @Test
    void testAttributes() {
        SchemaNames names = SchemaNames.scene();
        // ===== Equivalence Partitions Tests =====
        // TC01: a type of its own attributes: <image> has width, height, grid, in the schema's order
        assertEquals(List.of("width", "height", "grid"), names.attributes("image"), "TC01: wrong attributes");
        // TC02: an attribute group: <sphere> has center and radius, then the surface's
        assertEquals(concat(List.of("center", "radius"), SURFACE), names.attributes("sphere"), "TC02: wrong attributes");
        // TC03: an extension: <spot-light> has the point light's attributes, then its own
        assertEquals(List.of("color", "position", "kC", "kL", "kQ", "edge", "u", "v", "direction", "narrow-beam"),
                names.attributes("spot-light"), "TC03: wrong attributes");
        // TC04: the root's anonymous type: <scene> has name and background-color
        assertEquals(List.of("name", "background-color"), names.attributes("scene"), "TC04: wrong attributes");
        // TC05: a group has only a name
        assertEquals(List.of("name"), names.attributes("geometries"), "TC05: wrong attributes");

        // ===== Boundary Values Tests =====
        // TC11: an element without attributes (<library>), and one the schema does not declare: none
        assertEquals(List.of(), names.attributes("library"), "TC11: <library> has no attributes");
        assertEquals(List.of(), names.attributes("cube"), "TC11: an undeclared element has no attributes");
        // TC12: the names are read once
        assertSame(names, SchemaNames.scene(), "TC12: the schema must be read once");
    }

    /** Test method for {@link SchemaNames#children(String)}. */
    @Test
    void testChildren() {
        SchemaNames names = SchemaNames.scene();
        // ===== Equivalence Partitions Tests =====
        // TC01: the root's children (xs:all), in the schema's order
        assertEquals(List.of("camera", "image", "render", "ambient-light", "lights", "geometries", "library",
                        "animation"),
                names.children("scene"), "TC01: wrong children of <scene>");
        // TC02: a choice, nesting itself through a model group: <geometries> holds every body, <geometries>,
        // <instance> and a transform
        assertEquals(List.of("sphere", "triangle", "polygon", "plane", "tube", "cylinder", "mesh",
                "triangle-mesh", "geometries", "instance", "transform"), names.children("geometries"),
                "TC02: wrong children of <geometries>");
        // TC03: <lights> holds the three lights
        assertEquals(List.of("directional-light", "point-light", "spot-light"), names.children("lights"),
                "TC03: wrong children of <lights>");
        // TC04: model groups inside model groups: <sphere> holds a transform and a texture
        assertEquals(List.of("transform", "image-texture", "checker-texture"), names.children("sphere"),
                "TC04: wrong children of <sphere>");

        // ===== Boundary Values Tests =====
        // TC11: an empty element (<transform>) and an undeclared one: no children
        assertEquals(List.of(), names.children("transform"), "TC11: <transform> has no children");
        assertEquals(List.of(), names.children("cube"), "TC11: an undeclared element has no children");
    }

    /** Test method for {@link SchemaNames#read(String)}. */
    @Test
    void testRead() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the shipped schema read again gives the same names
        assertEquals(SchemaNames.scene().attributes("camera"), SchemaNames.read(SceneParser.SCHEMA).attributes("camera"),
                "TC01: wrong names");
        // ===== Boundary Values Tests =====
        // TC11: a missing schema: an IllegalStateException naming it
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> SchemaNames.read("missing.xsd"),
                "TC11: a missing schema must be refused");
        assertMessage(e, "missing.xsd", "TC11");
    }

    private static List<String> concat(List<String> a, List<String> b) {
        return java.util.stream.Stream.concat(a.stream(), b.stream()).toList();
    }
}
