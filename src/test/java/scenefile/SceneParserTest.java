package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static testutil.TestAssertions.assertMessage;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertPrintable;

import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import org.junit.jupiter.api.Test;
import org.xml.sax.SAXParseException;

import testutil.TestFiles;

import primitives.Point3D;

/**
 * Unit tests for {@link SceneParser}: the validator's messages in the scene file's terms, and the tree
 * read from a small scene file.
 */
class SceneParserTest {
    private static final Path FOLDER = Path.of("target", "test-scenes", "parser");
    /** Where the named pipes go: apart from the files, whose names they would take. */
    private static final Path PIPES = FOLDER.resolve("pipes");

    /** The lines of a small valid scene file. */
    private static final List<String> TINY = List.of(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>",
            "<scene name=\"tiny\" background-color=\"75 127 90\">",
            "  <ambient-light color=\"255 191 191\"/>",
            "  <geometries>",
            "    <sphere center=\"0 0 -100\" radius=\"50\"/>",
            "    <triangle p0=\"-100 0 -100\" p1=\"0 100 -100\" p2=\"-100 100 -100\" kD=\"0.5\" nShininess=\"20\"/>",
            "    <sphere center=\" 1  2   3 \" radius=\"2.5e1\" emission=\"10 20 30\"/>",
            "  </geometries>",
            "  <lights><point-light color=\"100 100 100\" position=\"0 0 100\"/></lights>",
            "  <image width=\"40\" height=\"30\"/>",
            "</scene>");

    /** Writes a scene file under target/ and returns its path. */
    private static Path file(String name, String xml) {
        return TestFiles.write(FOLDER, name, xml);
    }

    /** The line of an element, as its errors report it. */
    private static int line(SceneElement e) {
        return e.error("where", null).getLine();
    }

    /** The column of an element, as its errors report it. */
    private static int column(SceneElement e) {
        return e.error("where", null).getColumn();
    }

    /** The column just after the first start tag of a line that ends with "/&gt;" or "&gt;". */
    private static int columnAfter(String text, String tagEnd) {
        return text.indexOf(tagEnd) + tagEnd.length() + 1;
    }

    /**
     * The validator's message for an attribute value not of its type: "cvc-attribute.3: The value 'V' of
     * attribute 'A' on element 'E' is not valid with respect to its type, 'T'."
     *
     * @param value     the value, as in the file
     * @param attribute the attribute's name
     * @param element   the element's name
     * @param type      the schema type's name
     * @return the message
     */
    private static String badValue(String value, String attribute, String element, String type) {
        return "cvc-attribute.3: The value '" + value + "' of attribute '" + attribute + "' on element '" + element
                + "' is not valid with respect to its type, '" + type + "'.";
    }

    /** Test method for {@link SceneParser#plain(String)}: attribute messages. */
    @Test
    void testPlainAttributes() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a bad number → "attribute 'radius' of <sphere> must be a number, got '5x0'"
        assertEquals("attribute 'radius' of <sphere> must be a number, got '5x0'",
                SceneParser.plain(badValue("5x0", "radius", "sphere", "number")), "TC01: wrong bad-number message");
        // TC02: each schema type in words: triple, count, whole, seed, flag, path, vertices
        assertEquals("attribute 'center' of <sphere> must be three numbers, got '0 0'",
                SceneParser.plain(badValue("0 0", "center", "sphere", "triple")), "TC02: wrong triple message");
        assertEquals("attribute 'width' of <image> must be a whole number, 1 or more, got '0'",
                SceneParser.plain(badValue("0", "width", "image", "count")), "TC02: wrong count message");
        assertEquals("attribute 'grid' of <image> must be a whole number, 0 or more, got '-1'",
                SceneParser.plain(badValue("-1", "grid", "image", "whole")), "TC02: wrong whole message");
        assertEquals("attribute 'seed' of <render> must be a whole number, got '1.5'",
                SceneParser.plain(badValue("1.5", "seed", "render", "seed")), "TC02: wrong seed message");
        assertEquals("attribute 'soft-shadows' of <render> must be true or false, got 'yes'",
                SceneParser.plain(badValue("yes", "soft-shadows", "render", "flag")), "TC02: wrong flag message");
        assertEquals("attribute 'file' of <mesh> must be a file name, got ''",
                SceneParser.plain(badValue("", "file", "mesh", "path")), "TC02: wrong path message");
        assertEquals("attribute 'vertices' of <polygon> must be a list of numbers, x y z for each of 3 or more "
                + "vertices, got '0 0 0'",
                SceneParser.plain(badValue("0 0 0", "vertices", "polygon", "vertices")),
                "TC02: wrong vertices message");
        // TC03: an attribute the element does not have → "unknown attribute 'foo' on <sphere>"
        assertEquals("unknown attribute 'foo' on <sphere>", SceneParser.plain(
                "cvc-complex-type.3.2.2: Attribute 'foo' is not allowed to appear in element 'sphere'."),
                "TC03: wrong unknown-attribute message");
        // TC04: a required attribute missing → "<sphere> needs the attribute 'radius'"
        assertEquals("<sphere> needs the attribute 'radius'", SceneParser.plain(
                "cvc-complex-type.4: Attribute 'radius' must appear on element 'sphere'."),
                "TC04: wrong missing-attribute message");

        // ===== Boundary Values Tests =====
        // TC11: a type without words (a built-in 'double') → "a double"
        assertEquals("attribute 'kD' of <sphere> must be a double, got 'x'",
                SceneParser.plain(badValue("x", "kD", "sphere", "double")),
                "TC11: an unnamed type must read 'a <type>'");
        // TC12: a value with spaces and a quote in it is kept whole: got '5' x'
        assertEquals("attribute 'radius' of <sphere> must be a number, got '5' x'",
                SceneParser.plain(badValue("5' x", "radius", "sphere", "number")),
                "TC12: the whole value must be kept");
    }

    /** Test method for {@link SceneParser#plain(String)}: element and document messages. */
    @Test
    void testPlainElements() {
        // ===== Equivalence Partitions Tests =====
        // TC01: an unknown element where others are expected (2.4.a) → the expected ones listed
        assertEquals("element <cube> is unknown or not allowed here; expected one of: sphere, triangle, polygon",
                SceneParser.plain("cvc-complex-type.2.4.a: Invalid content was found starting with element 'cube'. "
                        + "One of '{sphere, triangle, polygon}' is expected."), "TC01: wrong 2.4.a message");
        // TC02: an element where no more are allowed (2.4.d) → no list
        assertEquals("element <geometries> is unknown or not allowed here", SceneParser.plain(
                "cvc-complex-type.2.4.d: Invalid content was found starting with element 'geometries'. "
                        + "No child element is expected at this point."), "TC02: wrong 2.4.d message");
        // TC03: a wrong root element → "the root element must be <scene>, not <scena>"
        assertEquals("the root element must be <scene>, not <scena>", SceneParser.plain(
                "cvc-elt.1.a: Cannot find the declaration of element 'scena'."), "TC03: wrong root message");
        // TC04: <scene> in a namespace (the only way 'scene' is not declared) → "<scene> must not have a namespace"
        assertEquals("<scene> must not have a namespace", SceneParser.plain(
                "cvc-elt.1.a: Cannot find the declaration of element 'scene'."), "TC04: wrong namespace message");
        // TC05: text in an element-only element (2.3) → "<geometries> must not contain text"
        assertEquals("<geometries> must not contain text", SceneParser.plain(
                "cvc-complex-type.2.3: Element 'geometries' cannot have character [children], because the type's "
                        + "content type is element-only."), "TC05: wrong element-only message");
        // TC06: text or children in an empty element (2.1) → "<tube> must not contain text or elements"
        assertEquals("<tube> must not contain text or elements", SceneParser.plain(
                "cvc-complex-type.2.1: Element 'tube' must have no character or element information item "
                        + "[children], because the type's content type is empty."), "TC06: wrong empty-type message");
        // TC07: a DOCTYPE → "a scene file must not have a DOCTYPE"
        assertEquals("a scene file must not have a DOCTYPE", SceneParser.plain(
                "DOCTYPE is disallowed when the feature \"http://apache.org/xml/features/disallow-doctype-decl\" "
                        + "set to true."), "TC07: wrong DOCTYPE message");
        // TC08: an unknown validator message loses only its code
        assertEquals("There are multiple occurrences of ID value 'a'.", SceneParser.plain(
                "cvc-id.2: There are multiple occurrences of ID value 'a'."), "TC08: the code must be removed");
        // TC09: a plain parser message (no code) is unchanged
        assertEquals("XML document structures must start and end within the same entity.", SceneParser.plain(
                "XML document structures must start and end within the same entity."),
                "TC09: a plain message must be unchanged");
        assertEquals("Attribute \"radius\" was already specified for element \"sphere\".", SceneParser.plain(
                "Attribute \"radius\" was already specified for element \"sphere\"."),
                "TC09: a plain message must be unchanged");

        // ===== Boundary Values Tests =====
        // TC11: one expected element → "expected one of: geometries"
        assertEquals("element <foo> is unknown or not allowed here; expected one of: geometries",
                SceneParser.plain("cvc-complex-type.2.4.a: Invalid content was found starting with element 'foo'. "
                        + "One of '{geometries}' is expected."), "TC11: wrong single-item list");
        // TC12: a list without spaces after the commas gets them
        assertEquals("element <foo> is unknown or not allowed here; expected one of: camera, image",
                SceneParser.plain("cvc-complex-type.2.4.a: Invalid content was found starting with element 'foo'. "
                        + "One of '{camera,image}' is expected."), "TC12: the list must be ', '-separated");
        // TC13: a code in the middle of a message is not removed
        assertEquals("see cvc-elt.1.a: x", SceneParser.plain("see cvc-elt.1.a: x"),
                "TC13: only a leading code must be removed");
        // TC14: the empty message stays empty
        assertEquals("", SceneParser.plain(""), "TC14: the empty message must stay empty");
    }

    /**
     * Test method for {@link SceneParser#plain(String, String)}: an unknown attribute or element names the
     * nearest valid one and, when there are few, all of them.
     */
    @Test
    void testPlainSuggestions() {
        String camra = "cvc-complex-type.2.4.a: Invalid content was found starting with element 'camra'. "
                + "One of '{camera, image}' is expected.";
        String secondCamera = "cvc-complex-type.2.4.a: Invalid content was found starting with element 'camera'. "
                + "One of '{image, render, ambient-light, lights, geometries}' is expected.";
        String noneExpected = "cvc-complex-type.2.4.d: Invalid content was found starting with element 'foo'. "
                + "No child element is expected at this point.";
        // ===== Equivalence Partitions Tests =====
        // TC01: an attribute that differs in case: "did you mean 'kD'?" (<plane> has 10 attributes: no list)
        assertEquals("unknown attribute 'kd' on <plane>; did you mean 'kD'?",
                SceneParser.plain(unknownAttribute("kd", "plane"), "geometries"), "TC01: wrong message");
        // TC02: two letters swapped on an element of 3 attributes: the nearest and the list
        assertEquals("unknown attribute 'widht' on <image>; did you mean 'width'? <image> has: width, height, grid",
                SceneParser.plain(unknownAttribute("widht", "image"), "scene"), "TC02: wrong message");
        // TC03: nothing near, few attributes: the list alone
        assertEquals("unknown attribute 'size' on <image>; <image> has: width, height, grid",
                SceneParser.plain(unknownAttribute("size", "image"), "scene"), "TC03: wrong message");
        // TC04: a misspelt element: the nearest of the expected ones, then the list
        assertEquals("element <camra> is unknown or not allowed here; did you mean <camera>? Expected one of: camera,"
                + " image", SceneParser.plain(camra, "scene"), "TC04: wrong message");
        // TC05: a second element where one is allowed: said so
        assertEquals("<scene> may have only one <camera>", SceneParser.plain(secondCamera, "scene"),
                "TC05: wrong message");

        // ===== Boundary Values Tests =====
        // TC11: nothing near on <sphere> (10 attributes): the message alone
        assertEquals("unknown attribute 'foo' on <sphere>", SceneParser.plain(unknownAttribute("foo", "sphere"),
                "geometries"), "TC11: wrong message");
        // TC12: no element expected, in <scene>: its children listed; with no parent known, nothing added
        assertEquals("element <foo> is unknown or not allowed here; <scene> has: camera, image, render, ambient-light,"
                + " lights, geometries, library, animation", SceneParser.plain(noneExpected, "scene"),
                "TC12: wrong message");
        assertEquals("element <foo> is unknown or not allowed here", SceneParser.plain(noneExpected, null),
                "TC12: wrong message without a parent");
        // TC13: the second-element message needs the parent: without it, the expected list as before
        assertEquals("element <camera> is unknown or not allowed here; expected one of: image, render,"
                + " ambient-light, lights, geometries", SceneParser.plain(secondCamera), "TC13: wrong message");
        // TC14: an unknown element that is no slip of the keyboard (<cube>, <tube> one letter away): no guess
        assertEquals("element <cube> is unknown or not allowed here; expected one of: sphere, tube",
                SceneParser.plain("cvc-complex-type.2.4.a: Invalid content was found starting with element 'cube'. "
                        + "One of '{sphere, tube}' is expected.", "geometries"), "TC14: wrong message");
        // TC15: a file with a misspelt attribute: the message with its place
        String plane = "<geometries><plane q0=\"0 0 0\" normal=\"0 1 0\" kd=\"1\"/></geometries>";
        Path kd = file("kd.xml", "<scene>\n" + plane + "\n</scene>\n");
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneParser.parse(kd), "TC15: kd");
        assertEquals(kd + ":2:" + columnAfter(plane, "/>") + ": unknown attribute 'kd' on <plane>; did you mean 'kD'?",
                e.getMessage(), "TC15: wrong message");
        Path twice = file("twice.xml", "<scene>\n<image/>\n<image/>\n</scene>\n");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(twice), "TC15: two images");
        assertEquals(twice + ":3:9: <scene> may have only one <image>", e.getMessage(), "TC15: wrong message");
    }

    /** The validator's message for an attribute an element does not have. */
    private static String unknownAttribute(String attribute, String element) {
        return "cvc-complex-type.3.2.2: Attribute '" + attribute + "' is not allowed to appear in element '" + element
                + "'.";
    }

    /** Test method for {@link SceneParser#parse(Path)}: the tree of a small valid file. */
    @Test
    void testParseTree() {
        Path path = file("tiny.xml", String.join("\n", TINY) + "\n");
        SceneElement scene = SceneParser.parse(path);

        // ===== Equivalence Partitions Tests =====
        // TC01: the root <scene> with its attributes, at line 2
        assertEquals("scene", scene.name(), "TC01: the root must be <scene>");
        assertEquals("tiny", scene.text("name"), "TC01: wrong scene name");
        assertColor(75, 127, 90, scene.color("background-color"), "TC01: wrong background");
        assertEquals(2, line(scene), "TC01: <scene> must be at line 2");
        assertEquals(TINY.get(1).length() + 1, column(scene), "TC01: <scene> column must be just after its tag");
        // TC02: the children of <scene> in file order: ambient-light, geometries, lights, image
        assertEquals(List.of("ambient-light", "geometries", "lights", "image"),
                scene.children().stream().map(SceneElement::name).toList(), "TC02: wrong children of <scene>");
        assertEquals(List.of(3, 4, 9, 10), scene.children().stream().map(SceneParserTest::line).toList(),
                "TC02: wrong lines of the children of <scene>");
        // TC03: the bodies in file order: sphere (line 5), triangle (line 6), sphere (line 7)
        SceneElement geometries = scene.child("geometries");
        List<SceneElement> bodies = geometries.children();
        assertEquals(List.of("sphere", "triangle", "sphere"), bodies.stream().map(SceneElement::name).toList(),
                "TC03: wrong bodies");
        assertEquals(List.of(5, 6, 7), bodies.stream().map(SceneParserTest::line).toList(), "TC03: wrong body lines");
        assertEquals(TINY.get(4).length() + 1, column(bodies.get(0)), "TC03: wrong column of the first sphere");
        assertSame(bodies.get(0), geometries.child("sphere"), "TC03: child must give the first sphere");
        // TC04: attribute values given in the file
        assertEquals(new Point3D(0, 0, -100), bodies.get(0).point("center"), "TC04: wrong sphere centre");
        assertEquals(50, bodies.get(0).number("radius"), 1e-12, "TC04: wrong sphere radius");
        assertEquals(0.5, bodies.get(1).number("kD"), 1e-12, "TC04: wrong triangle kD");
        assertEquals(20, bodies.get(1).integer("nShininess"), "TC04: wrong triangle nShininess");
        assertEquals(new Point3D(-100, 100, -100), bodies.get(1).point("p2"), "TC04: wrong triangle p2");
        assertEquals(25, bodies.get(2).number("radius"), 1e-12, "TC04: 2.5e1 must be 25");
        assertColor(10, 20, 30, bodies.get(2).color("emission"), "TC04: wrong emission");
        assertEquals(40, scene.child("image").integer("width"), "TC04: wrong width");
        assertEquals(30, scene.child("image").integer("height"), "TC04: wrong height");
        // TC05: schema defaults filled in where the file has none
        SceneElement sphere = bodies.get(0);
        assertTrue(sphere.has("kD"), "TC05: kD must get its default");
        assertEquals(0, sphere.number("kD"), 0, "TC05: the default kD must read as 0");
        assertEquals(0, sphere.number("kT"), 0, "TC05: the default kT must read as 0");
        assertEquals(0, sphere.integer("nShininess"), "TC05: the default nShininess must be 0");
        assertColor(0, 0, 0, sphere.color("emission"), "TC05: the default emission must be black");
        assertEquals(1, scene.child("ambient-light").number("kA"), 1e-12, "TC05: the default kA must be 1");
        assertEquals(0, scene.child("image").integer("grid"), "TC05: the default grid must be 0");
        SceneElement light = scene.child("lights").children().get(0);
        assertEquals("point-light", light.name(), "TC05: wrong light");
        assertEquals(1, light.number("kC"), 1e-12, "TC05: the default kC must be 1");
        assertEquals(0, light.number("edge"), 0, "TC05: the default edge must be 0");
        // TC06: attributes with no default stay absent
        assertFalse(light.has("u"), "TC06: u has no default");
        assertNull(light.text("v"), "TC06: v has no default");
        assertNull(scene.child("camera"), "TC06: there is no camera");

        // ===== Boundary Values Tests =====
        // TC11: a list with extra spaces " 1  2   3 " is read as (1, 2, 3)
        assertEquals(new Point3D(1, 2, 3), bodies.get(2).point("center"), "TC11: extra spaces must be ignored");
        // TC12: the smallest scene file "<scene/>": no children, the default background black
        SceneElement empty = SceneParser.parse(file("empty.xml", "<scene/>"));
        assertEquals("scene", empty.name(), "TC12: the root must be <scene>");
        assertTrue(empty.children().isEmpty(), "TC12: an empty scene must have no children");
        assertColor(0, 0, 0, empty.color("background-color"), "TC12: the default background must be black");
        assertFalse(empty.has("name"), "TC12: the name has no default");
        assertEquals(1, line(empty), "TC12: <scene/> must be at line 1");
        assertEquals(columnAfter("<scene/>", "/>"), column(empty), "TC12: <scene/> column must be 9");
    }

    /**
     * Test method for {@link SceneParser#parse(Path)}: a file that names a schema for editors
     * ({@code xsi:noNamespaceSchemaLocation}) is checked against the shipped schema, whatever it names.
     */
    @Test
    void testSchemaLocation() {
        String xsi = "<scene xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xsi:noNamespaceSchemaLocation=\"";
        String body = "\" name=\"hinted\"><geometries><sphere center=\"0 0 0\" radius=\"5\"/></geometries></scene>";
        Path schema = Path.of("src", "main", "resources", "scenefile", "scene.xsd").toAbsolutePath();
        // ===== Equivalence Partitions Tests =====
        // TC01: the project's own schema named: read, the hint not among the scene's attributes
        SceneElement scene = SceneParser.parse(file("hinted.xml", xsi + schema.toUri() + body));
        assertEquals("hinted", scene.text("name"), "TC01: wrong scene name");
        assertFalse(scene.has("noNamespaceSchemaLocation"), "TC01: the hint must not be an attribute of <scene>");
        assertEquals(5, scene.child("geometries").child("sphere").number("radius"), 0, "TC01: wrong radius");
        // TC02: a schema named that allows <scene> no attribute and no child: the shipped one is checked
        Path other = file("other.xsd", "<xs:schema xmlns:xs=\"http://www.w3.org/2001/XMLSchema\">"
                + "<xs:element name=\"scene\"><xs:complexType/></xs:element></xs:schema>");
        file("bad-by-other.xml", xsi + other.toAbsolutePath().toUri() + body);
        assertEquals("hinted", SceneParser.parse(FOLDER.resolve("bad-by-other.xml")).text("name"),
                "TC02: the named schema must not replace the shipped one");
        // ===== Boundary Values Tests =====
        // TC11: a schema that is not there, or on the web: never read, the file loads
        assertEquals("hinted", SceneParser.parse(file("missing-xsd.xml", xsi + "no/such/scene.xsd" + body))
                .text("name"), "TC11: a missing schema file must not matter");
        assertEquals("hinted", SceneParser.parse(file("web-xsd.xml", xsi + "http://localhost:9/scene.xsd" + body))
                .text("name"), "TC11: a schema on the web must not be fetched");
    }

    /** Test method for {@link SceneParser#parse(Path)}: bad files give one plain line with the place. */
    @Test
    void testParseErrors() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a bad number: the attribute's name, not the datatype's message, at line 2 just after the tag
        String sphereLine = "  <geometries><sphere center=\"0 0 0\" radius=\"5x0\"/></geometries>";
        Path bad = file("badNumber.xml", "<scene>\n" + sphereLine + "\n</scene>\n");
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneParser.parse(bad),
                "TC01: a bad number must be reported");
        assertEquals(bad + ":2:" + columnAfter(sphereLine, "/>") + ": attribute 'radius' of <sphere> must be a number, "
                + "got '5x0'", e.getMessage(), "TC01: wrong message");
        assertEquals(2, e.getLine(), "TC01: wrong line");
        assertInstanceOf(SAXParseException.class, e.getCause(), "TC01: the cause must be the parser's exception");
        // TC02: an unknown element, in plain words
        Path cube = file("cube.xml", "<scene><geometries><cube/></geometries></scene>");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(cube), "TC02: <cube> must be reported");
        assertEquals("element <cube> is unknown or not allowed here; expected one of: sphere, triangle, polygon, "
                + "plane, tube, cylinder, mesh, triangle-mesh, geometries, instance, transform", e.getProblem(),
                "TC02: wrong problem");
        assertEquals(1, e.getLine(), "TC02: wrong line");
        assertEquals(27, e.getColumn(), "TC02: wrong column");
        // TC03: XML that is not well-formed: the parser's own message, with its place
        Path broken = file("broken.xml", "<scene>\n");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(broken), "TC03: broken XML");
        assertFalse(e.getProblem().startsWith("cvc-"), "TC03: no validator code");
        assertTrue(e.getLine() >= 1, "TC03: the line must be known, got " + e.getLine());
        // TC04: a missing file: "no such scene file", no place
        Path missing = FOLDER.resolve("missing.xml");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(missing), "TC04: a missing file");
        assertEquals(missing + ": no such scene file", e.getMessage(), "TC04: wrong message");
        assertEquals(SceneFileException.UNKNOWN, e.getLine(), "TC04: the line must be unknown");
        assertInstanceOf(NoSuchFileException.class, e.getCause(), "TC04: wrong cause");

        // ===== Boundary Values Tests =====
        // TC11: a folder instead of a file: "is a folder, not a scene file"
        file("any.xml", "<scene/>");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(FOLDER), "TC11: a folder");
        assertEquals(FOLDER + ": is a folder, not a scene file", e.getMessage(), "TC11: wrong message");
        // TC12: an empty file: reported with no validator code
        Path emptyFile = file("emptyFile.xml", "");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(emptyFile), "TC12: an empty file");
        assertFalse(e.getProblem().startsWith("cvc-"), "TC12: no validator code");
        // TC13: a count of 0 (just below the allowed 1)
        Path zero = file("zeroWidth.xml", "<scene><image width=\"0\"/></scene>");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(zero), "TC13: width 0");
        assertEquals("attribute 'width' of <image> must be a whole number, 1 or more, got '0'", e.getProblem(),
                "TC13: wrong problem");
    }

    /**
     * Test method for {@link SceneParser#parse(Path)}: the file is read once, so a named pipe (as a shell's
     * {@code <(cat scene.xml)} or {@code /dev/stdin} gives) is read like a file.
     */
    @Test
    void testReadOnce() {
        String tiny = String.join("\n", TINY);
        // ===== Equivalence Partitions Tests =====
        // TC01: the tiny scene through a pipe: the same tree as from a file, its 3 bodies and 1 light
        Path pipe = TestFiles.fifo(PIPES, "pipe.xml");
        TestFiles.feed(pipe, tiny);
        SceneElement root = SceneParser.parse(pipe);
        assertEquals("tiny", root.text("name"), "TC01: wrong scene name");
        assertEquals(3, root.child("geometries").children().size(), "TC01: the bodies must be read");
        assertEquals(1, root.child("lights").children().size(), "TC01: the light must be read");
        // TC02: a scene the schema refuses, through a pipe: the schema's message with its place, not an end of file
        Path refused = TestFiles.fifo(PIPES, "refused.xml");
        TestFiles.feed(refused, "<scene>\n<image width=\"0\"/>\n</scene>\n");
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneParser.parse(refused),
                "TC02: width 0 must be refused");
        assertEquals("attribute 'width' of <image> must be a whole number, 1 or more, got '0'", e.getProblem(),
                "TC02: wrong problem");
        assertEquals(2, e.getLine(), "TC02: wrong line");

        // ===== Boundary Values Tests =====
        // TC11: a pipe cut inside the XML declaration: the place is the end of what it gave (line 1, column 6)
        Path cut = TestFiles.fifo(PIPES, "cut.xml");
        TestFiles.feed(cut, "<?xml");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(cut), "TC11: a cut pipe");
        assertEquals(cut + ":1:6: Premature end of file.", e.getMessage(), "TC11: wrong message");
        // TC12 (own): an empty pipe: a premature end at line 1, column 1
        Path empty = TestFiles.fifo(PIPES, "empty.xml");
        TestFiles.feed(empty, "");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(empty), "TC12: an empty pipe");
        assertEquals(empty + ":1:1: Premature end of file.", e.getMessage(), "TC12: wrong message");
        // TC13 (own): the last line of a file cut after two lines: the place is line 3, column 1
        Path twoLines = file("twoLines.xml", "<scene>\n<geometries>\n");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(twoLines), "TC13: a cut file");
        assertEquals(3, e.getLine(), "TC13: wrong line");
        assertEquals(1, e.getColumn(), "TC13: wrong column");
    }

    /**
     * Test method for {@link SceneParser#parse(Path)}: text the messages quote from a file (and the file's
     * name) reaches no terminal as commands: control characters are visible escapes.
     */
    @Test
    void testControlCharactersQuoted() {
        String sphere = "<scene><geometries><sphere center=\"0 0 0\" radius=\"%s\"/></geometries></scene>";
        // ===== Equivalence Partitions Tests =====
        // TC01: an XML 1.1 attribute holding ESC ] 0 ; pwned BEL (sets an xterm's title): "got '\x1B]0;pwned\x07'"
        Path title = file("title.xml", "<?xml version=\"1.1\"?>\n" + sphere.formatted("&#x1B;]0;pwned&#x7;"));
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneParser.parse(title),
                "TC01: a bad number must be reported");
        assertEquals("attribute 'radius' of <sphere> must be a number, got '\\x1B]0;pwned\\x07'", e.getProblem(),
                "TC01: wrong problem");
        assertPrintable(e.getMessage(), "\\x1B]0;pwned\\x07", "TC01");
        // TC02: a C1 control, CSI (U+009B), clears the screen on some terminals: "\x9B2J"
        Path csi = file("csi.xml", "<?xml version=\"1.1\"?>\n" + sphere.formatted("&#x9B;2J"));
        assertPrintable(assertThrows(SceneFileException.class, () -> SceneParser.parse(csi), "TC02: a bad number")
                .getMessage(), "got '\\x9B2J'", "TC02");
        // TC03 (own): a file whose name holds ESC [ 2 J: the message names it printably
        Path named = file("clear\u001b[2J.xml", "<scene>\n");
        assertPrintable(assertThrows(SceneFileException.class, () -> SceneParser.parse(named), "TC03: broken XML")
                .getMessage(), "clear\\x1B[2J.xml:", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: the first control character, NUL, cannot be in XML at all, and BEL (U+0007), the last one a title
        // needs, can only in XML 1.1: in 1.0 it is refused as the parser's message, which quotes no input
        Path bell = file("bell.xml", sphere.formatted("&#x7;"));
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(bell), "TC11: BEL in XML 1.0");
        assertPrintable(e.getMessage(), "invalid XML character", "TC11");
        // TC12 (own): a tab and a line feed as character references stay on the one line: "\t" and "\n"
        Path blanks = file("blanks.xml", sphere.formatted("x&#9;y&#10;z"));
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(blanks), "TC12: a bad number");
        assertPrintable(e.getMessage(), "'x\\ty\\nz'", "TC12");
    }

    /**
     * Test method for {@link SceneParser#parse(Path)}: sizes checked before the schema, the XML
     * declaration's problems with a place, and English messages whatever the default locale.
     */
    @Test
    void testLimitsAndDeclaration() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 100,000 nested <geometries>: refused at the 65th level, naming the limit
        Path deep = file("deep.xml", "<scene>" + "<geometries>".repeat(100_000) + "</geometries>".repeat(100_000)
                + "</scene>");
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneParser.parse(deep),
                "TC01: deep nesting must be refused");
        assertMessage(e, "nested too deeply: a scene file nests at most " + SceneParser.MAX_DEPTH, "TC01");
        assertEquals(1, e.getLine(), "TC01: wrong line");
        // TC02: a number of 1,000,000 digits: refused before the schema's pattern sees it, naming the limit
        Path digits = file("digits.xml", "<scene><geometries><sphere center=\"0 0 0\" radius=\"" + "1".repeat(1_000_000)
                + "\"/></geometries></scene>");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(digits), "TC02: a huge number must be refused");
        assertMessage(e, "attribute 'radius' of <sphere> is 1000000 characters long", "TC02");
        assertMessage(e, "at most " + SceneParser.MAX_VALUE_LENGTH, "TC02");
        // TC03: an unknown encoding: named with a place, not the Java exception
        Path encoding = file("encoding.xml", "<?xml version=\"1.0\" encoding=\"UTF-9\"?>\n<scene/>\n");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(encoding), "TC03: UTF-9 must be refused");
        assertEquals(encoding + ":1:1: unknown character encoding 'UTF-9' in the XML declaration", e.getMessage(),
                "TC03: wrong message");
        // TC04: with a German default locale, the parser's and the validator's messages are in English
        Locale locale = Locale.getDefault();
        Path german = file("german.xml", "<scene>\n<geometries>\n<sphere center=\"0 0 0\" radius=\"x\"/>\n</geometries>"
                + "\n</scene>\n");
        Path unclosed = file("unclosed.xml", "<scene>\n</scenex>\n");
        try {
            Locale.setDefault(Locale.GERMAN);
            e = assertThrows(SceneFileException.class, () -> SceneParser.parse(german), "TC04: a bad number");
            assertEquals("attribute 'radius' of <sphere> must be a number, got 'x'", e.getProblem(),
                    "TC04: the validator's message must be English");
            e = assertThrows(SceneFileException.class, () -> SceneParser.parse(unclosed), "TC04: a bad end tag");
            assertMessage(e, "The end-tag for element type \"scene\" must end with a", "TC04");
        } finally {
            Locale.setDefault(locale);
        }

        // ===== Boundary Values Tests =====
        // TC11: 64 nested elements (the limit) are read
        Path limit = file("limit.xml", "<scene>" + "<geometries>".repeat(SceneParser.MAX_DEPTH - 1)
                + "</geometries>".repeat(SceneParser.MAX_DEPTH - 1) + "</scene>");
        assertEquals("scene", SceneParser.parse(limit).name(), "TC11: 64 levels must be read");
        // TC12: a number of 1000 characters (the limit) is read
        Path longest = file("longest.xml", "<scene><geometries><sphere center=\"0 0 0\" radius=\"1"
                + "0".repeat(SceneParser.MAX_VALUE_LENGTH - 1) + "\"/></geometries></scene>");
        assertEquals("scene", SceneParser.parse(longest).name(), "TC12: a 1000-character number must be read");
        // TC13: a file cut inside the XML declaration: the place is the end of the file (line 1, column 6)
        Path cut = file("cut.xml", "<?xml");
        e = assertThrows(SceneFileException.class, () -> SceneParser.parse(cut), "TC13: a cut file");
        assertEquals(cut + ":1:6: Premature end of file.", e.getMessage(), "TC13: wrong message");
    }
}
