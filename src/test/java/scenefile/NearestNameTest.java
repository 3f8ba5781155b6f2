package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link NearestName}: the valid name a misspelt one most likely meant.
 */
class NearestNameTest {
    /** The attributes of a sphere, in the schema's order. */
    private static final List<String> SPHERE = List.of("center", "radius", "emission", "kD", "kS", "kT", "kR", "kG",
            "kB", "nShininess", "ior", "fresnel");
    /** The attributes of an image. */
    private static final List<String> IMAGE = List.of("width", "height", "grid");

    /** Test method for {@link NearestName#of(String, List)}. */
    @Test
    void testOf() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the same name in another case: kd → kD, RADIUS → radius
        assertEquals("kD", NearestName.of("kd", SPHERE), "TC01: kd must be kD");
        assertEquals("radius", NearestName.of("RADIUS", SPHERE), "TC01: RADIUS must be radius");
        // TC02: one letter missing, wrong or swapped: radus, raduis, cender → radius, radius, center
        assertEquals("radius", NearestName.of("radus", SPHERE), "TC02: radus must be radius");
        assertEquals("radius", NearestName.of("raduis", SPHERE), "TC02: raduis must be radius");
        assertEquals("center", NearestName.of("cender", SPHERE), "TC02: cender must be center");
        // TC03: a letter dropped in front: shininess → nShininess
        assertEquals("nShininess", NearestName.of("shininess", SPHERE), "TC03: shininess must be nShininess");
        // TC04: nothing near: null
        assertNull(NearestName.of("colour", SPHERE), "TC04: colour is near nothing of a sphere");
        // TC05: another first letter: no slip of the keyboard (cube is not tube)
        assertNull(NearestName.of("cube", List.of("sphere", "tube")), "TC05: cube must not be tube");

        // ===== Boundary Values Tests =====
        // TC11: edits up to a third of the name's length: 2 of 6 suggest, 3 of 6 do not
        assertEquals("sphere", NearestName.of("sphxrx", List.of("sphere")), "TC11: 2 edits of 6 must suggest");
        assertNull(NearestName.of("sphxxx", List.of("sphere")), "TC11: 3 edits of 6 must not suggest");
        // TC12: a name of one letter is near itself in another case only: U → u, w → none
        assertEquals("u", NearestName.of("U", List.of("u", "v")), "TC12: U must be u");
        assertNull(NearestName.of("w", List.of("u", "v")), "TC12: w must be near neither u nor v");
        // TC13: ties go to the first valid name: kx → kD
        assertEquals("kD", NearestName.of("kx", SPHERE), "TC13: a tie must give the first name");
        // TC14: names of 64 characters get a suggestion, longer ones do not; no valid name gives none
        String valid = "a".repeat(NearestName.MAX_LENGTH);
        assertEquals(valid, NearestName.of("a".repeat(NearestName.MAX_LENGTH - 1) + "b", List.of(valid)),
                "TC14: a 64-character name must get a suggestion");
        assertNull(NearestName.of("a".repeat(NearestName.MAX_LENGTH + 1), List.of(valid)),
                "TC14: a 65-character name must not");
        assertNull(NearestName.of("kd", List.of()), "TC14: no valid name, no suggestion");
        // TC15: the empty name: nothing is near it but a one-letter name
        assertNull(NearestName.of("", SPHERE), "TC15: the empty name is near no sphere attribute");
    }

    /** Test method for {@link NearestName#hint(String, List, String, String)}. */
    @Test
    void testHint() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a near name and few valid ones: both
        assertEquals("; did you mean 'width'? <image> has: width, height, grid",
                NearestName.hint("widht", IMAGE, "'%s'", "<image> has:"), "TC01: wrong hint");
        // TC02: a near name and many valid ones: the near name alone
        assertEquals("; did you mean 'kD'?", NearestName.hint("kd", SPHERE, "'%s'", "<sphere> has:"),
                "TC02: wrong hint");
        // TC03: nothing near, few valid ones: the list, its words as given
        assertEquals("; expected one of: width, height, grid",
                NearestName.hint("size", IMAGE, "<%s>", "expected one of:"), "TC03: wrong hint");
        // TC04: nothing near, many valid ones: nothing
        assertEquals("", NearestName.hint("foo", SPHERE, "'%s'", "<sphere> has:"), "TC04: wrong hint");
        // TC05: an element's name quoted as an element, the list's words starting a sentence
        assertEquals("; did you mean <image>? Expected one of: image, lights",
                NearestName.hint("imag", List.of("image", "lights"), "<%s>", "expected one of:"), "TC05: wrong hint");

        // ===== Boundary Values Tests =====
        // TC11: 11 valid names are listed (a group's children), 12 are not
        List<String> eleven = SPHERE.subList(0, NearestName.MAX_LISTED);
        assertEquals("; it has: " + String.join(", ", eleven), NearestName.hint("foo", eleven, "'%s'", "it has:"),
                "TC11: 11 names must be listed");
        assertEquals("", NearestName.hint("foo", SPHERE.subList(0, NearestName.MAX_LISTED + 1), "'%s'", "it has:"),
                "TC11: 12 names must not be listed");
        // TC12: no valid name: nothing
        assertEquals("", NearestName.hint("foo", List.of(), "'%s'", "it has:"), "TC12: wrong hint");
    }

    /** Test method for {@link NearestName#distance(String, String)}. */
    @Test
    void testDistance() {
        // ===== Equivalence Partitions Tests =====
        // TC01: substitutions, an insertion: kitten → sitting is 3
        assertEquals(3, NearestName.distance("kitten", "sitting"), "TC01: wrong distance");
        // TC02: two neighbouring letters swapped count 1: widht → width
        assertEquals(1, NearestName.distance("widht", "width"), "TC02: a swap must count 1");
        // TC03: the case counts (the callers lower both names): kd → kD is 1
        assertEquals(1, NearestName.distance("kd", "kD"), "TC03: wrong distance");

        // ===== Boundary Values Tests =====
        // TC11: the same name: 0; the empty name: the other's length
        assertEquals(0, NearestName.distance("radius", "radius"), "TC11: the same name must be 0");
        assertEquals(3, NearestName.distance("", "abc"), "TC11: from the empty name: the length");
        assertEquals(3, NearestName.distance("abc", ""), "TC11: to the empty name: the length");
    }
}
