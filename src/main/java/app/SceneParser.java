package app;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParser;
import javax.xml.parsers.SAXParserFactory;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;

import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * Reads a scene file into a tree of {@link SceneElement}s, checking it against the scene schema
 * ({@code app/scene.xsd}, shipped in the jar). The first problem stops the reading with a
 * {@link SceneFileException} whose message is one plain line: the schema validator's wording is
 * turned into the scene file's terms ("attribute 'radius' of &lt;sphere&gt; must be a number").
 */
final class SceneParser {
    /** The schema's resource, beside this class. */
    private static final String SCHEMA = "scene.xsd";

    private static final Schema SCENE_SCHEMA = loadSchema();

    private static final Pattern CODE = Pattern.compile("^cvc-[\\w.-]+: ");
    private static final Pattern BAD_VALUE = Pattern.compile(
            "The value '(.*)' of attribute '(.*)' on element '(.*)' is not valid with respect to its type, '(.*)'\\.");
    private static final Pattern UNKNOWN_ATTRIBUTE = Pattern.compile(
            "Attribute '(.*)' is not allowed to appear in element '(.*)'\\.");
    private static final Pattern MISSING_ATTRIBUTE = Pattern.compile("Attribute '(.*)' must appear on element '(.*)'\\.");
    private static final Pattern MISPLACED_ELEMENT = Pattern.compile(
            "Invalid content was found starting with element '(.*?)'\\. (?:One of '\\{(.*)\\}' is expected|No child element is expected at this point)\\.");
    private static final Pattern UNKNOWN_ROOT = Pattern.compile("Cannot find the declaration of element '(.*)'\\.");
    private static final Pattern TEXT_CONTENT = Pattern.compile(
            "Element '(.*)' (?:cannot have character|must have no character or element information item) .*");
    private static final Map<String, String> TYPES = Map.of(
            "number", "a number",
            "triple", "three numbers",
            "vertices", "a list of numbers, x y z for each of 3 or more vertices",
            "count", "a whole number, 1 or more",
            "whole", "a whole number, 0 or more",
            "seed", "a whole number",
            "flag", "true or false",
            "path", "a file name");

    private SceneParser() {
    }

    private static Schema loadSchema() {
        URL schema = SceneParser.class.getResource(SCHEMA);
        if (schema == null)
            throw new IllegalStateException("the scene schema " + SCHEMA + " is missing from the class path");
        try {
            return SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI).newSchema(schema);
        } catch (SAXException e) {
            throw new IllegalStateException("the scene schema " + SCHEMA + " is broken: " + e.getMessage(), e);
        }
    }

    /**
     * Reads and checks a scene file.
     *
     * @param file the scene file
     * @return its root element
     * @throws SceneFileException when the file is missing, unreadable, not well-formed XML or not a scene
     */
    static SceneElement parse(Path file) {
        if (Files.isDirectory(file))
            throw new SceneFileException(file, "is a folder, not a scene file", null);
        try (InputStream in = Files.newInputStream(file)) {
            InputSource source = new InputSource(in);
            source.setSystemId(file.toUri().toString());
            TreeBuilder builder = new TreeBuilder(file);
            newParser().parse(source, builder);
            return builder.root;
        } catch (NoSuchFileException e) {
            throw new SceneFileException(file, "no such scene file", e);
        } catch (SAXParseException e) {
            throw new SceneFileException(file, e.getLineNumber(), e.getColumnNumber(), plain(e.getMessage()), e);
        } catch (SAXException e) {
            throw new SceneFileException(file, "not a scene file: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new SceneFileException(file, "cannot read the scene file: " + e, e);
        }
    }

    private static SAXParser newParser() throws SAXException {
        SAXParserFactory factory = SAXParserFactory.newInstance();
        factory.setNamespaceAware(true);
        factory.setSchema(SCENE_SCHEMA);
        try {
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            SAXParser parser = factory.newSAXParser();
            parser.setProperty("http://apache.org/xml/properties/locale", Locale.ENGLISH);
            return parser;
        } catch (ParserConfigurationException e) {
            throw new IllegalStateException("no suitable XML parser: " + e.getMessage(), e);
        }
    }

    /**
     * Turns a parser's message into the scene file's terms.
     *
     * @param message the parser's message
     * @return the message, without validator codes
     */
    static String plain(String message) {
        String text = CODE.matcher(message).replaceFirst("");
        Matcher m;
        if ((m = BAD_VALUE.matcher(text)).matches())
            return "attribute '" + m.group(2) + "' of <" + m.group(3) + "> must be "
                    + TYPES.getOrDefault(m.group(4), "a " + m.group(4)) + ", got '" + m.group(1) + "'";
        if ((m = UNKNOWN_ATTRIBUTE.matcher(text)).matches())
            return "unknown attribute '" + m.group(1) + "' on <" + m.group(2) + ">";
        if ((m = MISSING_ATTRIBUTE.matcher(text)).matches())
            return "<" + m.group(2) + "> needs the attribute '" + m.group(1) + "'";
        if ((m = MISPLACED_ELEMENT.matcher(text)).matches())
            return "element <" + m.group(1) + "> is unknown or not allowed here"
                    + (m.group(2) == null ? "" : "; expected one of: " + m.group(2).replace(",", ", ").replace("  ", " "));
        if ((m = UNKNOWN_ROOT.matcher(text)).matches())
            return m.group(1).equals("scene") ? "<scene> must not have a namespace"
                    : "the root element must be <scene>, not <" + m.group(1) + ">";
        if ((m = TEXT_CONTENT.matcher(text)).matches())
            return "<" + m.group(1) + "> must not contain text";
        if (text.startsWith("DOCTYPE is disallowed"))
            return "a scene file must not have a DOCTYPE";
        return text;
    }

    /** Builds the tree of elements; stops at the first problem the validator reports. */
    private static final class TreeBuilder extends DefaultHandler {
        private final Path file;
        private final Deque<SceneElement> open = new ArrayDeque<>();
        private Locator locator;
        private SceneElement root;
        /** A value's facet problem, reported again by the next message with the attribute's name. */
        private SAXParseException pendingValueProblem;

        TreeBuilder(Path file) {
            this.file = file;
        }

        @Override
        public void setDocumentLocator(Locator locator) {
            this.locator = locator;
        }

        @Override
        public void startElement(String uri, String localName, String qName, Attributes attributes)
                throws SAXException {
            throwPending();
            Map<String, String> values = new LinkedHashMap<>();
            for (int k = 0; k < attributes.getLength(); ++k)
                values.put(attributes.getLocalName(k), attributes.getValue(k));
            SceneElement element = new SceneElement(file, localName, values, locator.getLineNumber(),
                    locator.getColumnNumber());
            if (open.isEmpty())
                root = element;
            else
                open.peek().addChild(element);
            open.push(element);
        }

        @Override
        public void endElement(String uri, String localName, String qName) throws SAXException {
            throwPending();
            open.pop();
        }

        @Override
        public void endDocument() throws SAXException {
            throwPending();
        }

        @Override
        public void error(SAXParseException e) throws SAXException {
            if (pendingValueProblem == null && e.getMessage().matches("cvc-[\\w-]+-valid(\\.[\\w.]+)?: .*")) {
                pendingValueProblem = e;
                return;
            }
            throw e;
        }

        @Override
        public void fatalError(SAXParseException e) throws SAXException {
            throw e;
        }

        private void throwPending() throws SAXParseException {
            if (pendingValueProblem != null)
                throw pendingValueProblem;
        }
    }
}
