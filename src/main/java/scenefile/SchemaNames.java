package scenefile;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;

import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.SAXException;

/**
 * The names the scene schema ({@code scenefile/scene.xsd}) allows: each element's attributes and child
 * elements, in the schema's order, read from the schema itself so that they never drift from it. The
 * parser's messages use them to name what a misspelt name may have meant.
 */
final class SchemaNames {
    /** The schema's namespace, whose elements ({@code xs:element}, {@code xs:attribute}…) are read. */
    private static final String XS = XMLConstants.W3C_XML_SCHEMA_NS_URI;

    /** The names of the shipped schema, read once. */
    private static final SchemaNames SCENE = read(SceneParser.SCHEMA);

    /** Each named complex type's element of the schema, by name. */
    private final Map<String, Element> types = new HashMap<>();
    /** Each named attribute group's element of the schema, by name. */
    private final Map<String, Element> groups = new HashMap<>();
    /** Each named model group's element of the schema (a choice of elements), by name. */
    private final Map<String, Element> modelGroups = new HashMap<>();
    /** Each element's attributes, by the element's name. */
    private final Map<String, List<String>> attributes = new HashMap<>();
    /** Each element's child elements, by the element's name. */
    private final Map<String, List<String>> children = new HashMap<>();

    private SchemaNames(Element schema) {
        for (Element child : children(schema))
            if (child.getLocalName().equals("complexType"))
                types.put(child.getAttribute("name"), child);
            else if (child.getLocalName().equals("attributeGroup"))
                groups.put(child.getAttribute("name"), child);
            else if (child.getLocalName().equals("group"))
                modelGroups.put(child.getAttribute("name"), child);
        declare(schema);
    }

    /** {@return the names of the shipped scene schema} */
    static SchemaNames scene() {
        return SCENE;
    }

    /**
     * Reads a schema beside this class.
     *
     * @param resource the schema's resource name
     * @return its names
     * @throws IllegalStateException when the schema is missing or cannot be read
     */
    static SchemaNames read(String resource) {
        try (InputStream in = SchemaNames.class.getResourceAsStream(resource)) {
            if (in == null)
                throw new IllegalStateException("the scene schema " + resource + " is missing from the class path");
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setNamespaceAware(true);
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            return new SchemaNames(factory.newDocumentBuilder().parse(in).getDocumentElement());
        } catch (IOException | SAXException | ParserConfigurationException e) {
            throw new IllegalStateException("the scene schema " + resource + " cannot be read: " + e.getMessage(), e);
        }
    }

    /**
     * The attributes an element may have.
     *
     * @param element the element's name
     * @return its attributes in the schema's order, none for an element the schema does not declare
     */
    List<String> attributes(String element) {
        return attributes.getOrDefault(element, List.of());
    }

    /**
     * The child elements an element may have.
     *
     * @param element the element's name
     * @return its children's names in the schema's order, none for an element the schema does not declare
     */
    List<String> children(String element) {
        return children.getOrDefault(element, List.of());
    }

    /** Records every element the schema declares, with the attributes and children of its type. */
    private void declare(Element schema) {
        NodeList declarations = schema.getElementsByTagNameNS(XS, "element");
        for (int k = 0; k < declarations.getLength(); ++k) {
            Element declaration = (Element) declarations.item(k);
            String name = declaration.getAttribute("name");
            if (name.isEmpty() || attributes.containsKey(name)) // a reference, or declared already (geometries)
                continue;
            Element type = declaration.hasAttribute("type") ? types.get(declaration.getAttribute("type"))
                    : first(declaration, "complexType");
            Set<String> names = new LinkedHashSet<>();
            Set<String> elements = new LinkedHashSet<>();
            if (type != null)
                collect(type, names, elements);
            attributes.put(name, List.copyOf(names));
            children.put(name, List.copyOf(elements));
        }
    }

    /**
     * Gathers the attributes and child elements of a type: its own, its attribute groups' and its base
     * type's (an extension's base first, as the schema's order has it).
     */
    private void collect(Element node, Set<String> names, Set<String> elements) {
        for (Element child : children(node))
            switch (child.getLocalName()) {
                case "attribute" -> names.add(child.getAttribute("name"));
                case "attributeGroup" -> {
                    Element group = groups.get(child.getAttribute("ref"));
                    if (group != null)
                        collect(group, names, elements);
                }
                case "element" -> elements.add(child.getAttribute("name"));
                case "group" -> {
                    Element group = modelGroups.get(child.getAttribute("ref"));
                    if (group != null)
                        collect(group, names, elements);
                }
                case "extension" -> {
                    Element base = types.get(child.getAttribute("base"));
                    if (base != null)
                        collect(base, names, elements);
                    collect(child, names, elements);
                }
                case "annotation" -> { } // documentation only
                default -> collect(child, names, elements); // all, choice, sequence, complexContent
            }
    }

    /** {@return the first child of a node in the schema's namespace with this local name, or null} */
    private static Element first(Element node, String localName) {
        for (Element child : children(node))
            if (child.getLocalName().equals(localName))
                return child;
        return null;
    }

    /** {@return the child elements of a node that are in the schema's namespace} */
    private static List<Element> children(Element node) {
        List<Element> list = new ArrayList<>();
        for (Node child = node.getFirstChild(); child != null; child = child.getNextSibling())
            if (child instanceof Element element && XS.equals(element.getNamespaceURI()))
                list.add(element);
        return Collections.unmodifiableList(list);
    }
}
