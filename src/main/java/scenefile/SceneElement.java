package scenefile;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

/**
 * An element of a scene file, already checked against the schema (so its numbers parse), with its
 * attributes (defaults filled in by the schema), its children and its place in the file.
 */
final class SceneElement {
    /**
     * The largest magnitude of a number in a scene file, 1e100 (the messages say so): products of a
     * few such numbers (a squared distance times kQ, a colour times kS) stay finite, so no computation
     * of the render overflows.
     */
    static final double MAX_MAGNITUDE = 1e100;

    private final Path file;
    private final String name;
    private final Map<String, String> attributes;
    private final int line;
    private final int column;
    private final List<SceneElement> children = new ArrayList<>();

    /**
     * @param file       the scene file
     * @param name       the element's name
     * @param attributes the attributes, by name
     * @param line       the line where the element's start tag ends (the parser's position after its '>')
     * @param column     the column just after the element's start tag
     */
    SceneElement(Path file, String name, Map<String, String> attributes, int line, int column) {
        this.file = file;
        this.name = name;
        this.attributes = attributes;
        this.line = line;
        this.column = column;
    }

    /** {@return the element's name} */
    String name() {
        return name;
    }

    /** {@return the line where the element's start tag ends} */
    int line() {
        return line;
    }

    /** {@return the child elements, in file order} */
    List<SceneElement> children() {
        return Collections.unmodifiableList(children);
    }

    /** Adds a child element. */
    void addChild(SceneElement child) {
        children.add(child);
    }

    /** {@return the first child of this name, or null} */
    SceneElement child(String childName) {
        for (SceneElement child : children)
            if (child.name.equals(childName))
                return child;
        return null;
    }

    /** {@return whether the attribute is given (or has a default)} */
    boolean has(String attribute) {
        return attributes.containsKey(attribute);
    }

    /** {@return the attribute's text, or null when absent} */
    String text(String attribute) {
        return attributes.get(attribute);
    }

    /** {@return the attribute as a number, at most {@link #MAX_MAGNITUDE} in magnitude} */
    double number(String attribute) {
        return bounded(Double.parseDouble(require(attribute)), "attribute '" + attribute + "'");
    }

    /** {@return the attribute as an int} */
    int integer(String attribute) {
        return Integer.parseInt(require(attribute));
    }

    /** {@return the attribute as a long} */
    long longInteger(String attribute) {
        return Long.parseLong(require(attribute));
    }

    /** {@return the attribute as a boolean (schema booleans: true, false, 1, 0)} */
    boolean flag(String attribute) {
        String value = require(attribute);
        return "true".equals(value) || "1".equals(value);
    }

    /** {@return the attribute as a list of numbers, each at most {@link #MAX_MAGNITUDE} in magnitude} */
    double[] numbers(String attribute) {
        String[] items = require(attribute).trim().split("\\s+");
        double[] values = new double[items.length];
        String what = "attribute '" + attribute + "'";
        for (int k = 0; k < items.length; ++k)
            values[k] = bounded(Double.parseDouble(items[k]), what);
        return values;
    }

    /**
     * Checks that a number of this element is at most {@link #MAX_MAGNITUDE} in magnitude.
     *
     * @param value the number
     * @param what  what it is, for the message
     * @return the number
     * @throws SceneFileException when it is larger
     */
    double bounded(double value, String what) {
        if (!(Math.abs(value) <= MAX_MAGNITUDE))
            throw error(what + " is too large (" + value + "): numbers in a scene file must lie within ±1e100,"
                    + " or the render overflows", null);
        return value;
    }

    /** {@return the attribute (three numbers) as a point} */
    Point3D point(String attribute) {
        double[] xyz = numbers(attribute);
        return new Point3D(xyz[0], xyz[1], xyz[2]);
    }

    /** {@return the attribute (three numbers) as a vector} */
    Vector vector(String attribute) {
        return new Vector(point(attribute));
    }

    /** {@return the attribute (three numbers) as a colour} */
    Color color(String attribute) {
        double[] rgb = numbers(attribute);
        return new Color(rgb[0], rgb[1], rgb[2]);
    }

    /**
     * A problem with this element.
     *
     * @param problem what is wrong
     * @param cause   the exception that revealed it, or null
     * @return the exception naming the file and this element's place
     */
    SceneFileException error(String problem, Throwable cause) {
        return new SceneFileException(file, line, column, "<" + name + ">: " + problem, cause);
    }

    private String require(String attribute) {
        String value = attributes.get(attribute);
        if (value == null)
            throw error("attribute '" + attribute + "' is missing", null);
        return value;
    }
}
