package scenefile;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UnsupportedEncodingException;
import java.net.URL;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
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
 * ({@code scenefile/scene.xsd}, shipped in the jar). The first problem stops the reading with a
 * {@link SceneFileException} whose message is one plain line: the schema validator's wording is
 * turned into the scene file's terms ("attribute 'radius' of &lt;sphere&gt; must be a number").
 * A file may name a schema for editors ({@code xsi:noNamespaceSchemaLocation}, as the example scenes
 * do); the file it names is never read, and such attributes are not among an element's attributes.
 */
final class SceneParser {
    /** The schema's resource, beside this class. */
    static final String SCHEMA = "scene.xsd";

    private static final Schema SCENE_SCHEMA = loadSchema();

    /** The deepest nesting of elements in a scene file. */
    static final int MAX_DEPTH = 64;
    /** The longest value (a number, a name) in an attribute, in characters. */
    static final int MAX_VALUE_LENGTH = 1000;

    private static final Pattern CODE = Pattern.compile("^cvc-[\\w.-]+: ");
    private static final Pattern BAD_VALUE = Pattern.compile(
            "The value '(.*)' of attribute '(.*)' on element '(.*)' is not valid with respect to its type, '(.*)'\\.");
    private static final Pattern UNKNOWN_ATTRIBUTE = Pattern.compile(
            "Attribute '(.*)' is not allowed to appear in element '(.*)'\\.");
    private static final Pattern MISSING_ATTRIBUTE = Pattern.compile("Attribute '(.*)' must appear on element '(.*)'\\.");
    private static final Pattern MISPLACED_ELEMENT = Pattern.compile(
            "Invalid content was found starting with element '(.*?)'\\. (?:One of '\\{(.*)\\}' is expected|No child element is expected at this point)\\.");
    private static final Pattern UNKNOWN_ROOT = Pattern.compile("Cannot find the declaration of element '(.*)'\\.");
    private static final Pattern TEXT_CONTENT = Pattern.compile("Element '(.*)' cannot have character .*");
    private static final Pattern ANY_CONTENT = Pattern.compile(
            "Element '(.*)' must have no character or element information item .*");
    private static final Map<String, String> TYPES = Map.ofEntries(
            Map.entry("number", "a number"),
            Map.entry("triple", "three numbers"),
            Map.entry("vertices", "a list of numbers, x y z for each of 3 or more vertices"),
            Map.entry("numbers", "a list of numbers"),
            Map.entry("indices", "a list of whole numbers, 0 or more"),
            Map.entry("count", "a whole number, 1 or more"),
            Map.entry("whole", "a whole number, 0 or more"),
            Map.entry("seed", "a whole number"),
            Map.entry("flag", "true or false"),
            Map.entry("path", "a file name"),
            Map.entry("name", "a name: a letter or '_', then letters, digits, '_', '-' or '.'"),
            Map.entry("scale", "one number, or three (x y z)"));

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
     * Reads and checks a scene file. A first pass checks the nesting depth and the length of the
     * attributes' values, so that the schema never sees a file that would take it long to check; the
     * second, with the schema, reads the bytes the first one read. The file is read once, so it may be a
     * pipe ({@code /dev/stdin}, a shell's {@code <(…)}).
     *
     * @param file the scene file
     * @return its root element
     * @throws SceneFileException when the file is missing, unreadable, not well-formed XML or not a scene
     */
    static SceneElement parse(Path file) {
        if (Files.isDirectory(file))
            throw new SceneFileException(file, "is a folder, not a scene file", null);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        TreeBuilder builder = new TreeBuilder(file);
        try {
            try (InputStream in = new CopyingStream(Files.newInputStream(file), bytes)) {
                read(in, file, newParser(null), new LimitsChecker());
            }
            read(new ByteArrayInputStream(bytes.toByteArray()), file, newParser(SCENE_SCHEMA), builder);
            return builder.root;
        } catch (NoSuchFileException e) {
            throw new SceneFileException(file, "no such scene file", e);
        } catch (AccessDeniedException e) {
            throw new SceneFileException(file, "cannot read the scene file: permission denied", e);
        } catch (SAXParseException e) {
            int[] place = e.getLineNumber() > 0 ? new int[] {e.getLineNumber(), e.getColumnNumber()}
                    : end(bytes.toByteArray());
            throw new SceneFileException(file, place[0], place[1], plain(e.getMessage(), builder.openElement()), e);
        } catch (SAXException e) {
            throw new SceneFileException(file, "not a scene file: " + e.getMessage(), e);
        } catch (UnsupportedEncodingException e) {
            throw new SceneFileException(file, 1, 1, "unknown character encoding '" + e.getMessage()
                    + "' in the XML declaration", e);
        } catch (IOException e) {
            throw new SceneFileException(file, "cannot read the scene file: " + e.getMessage(), e);
        }
    }

    private static void read(InputStream in, Path file, SAXParser parser, DefaultHandler handler)
            throws IOException, SAXException {
        InputSource source = new InputSource(in);
        source.setSystemId(file.toUri().toString());
        parser.parse(source, handler);
    }

    /** The line and column just after the last of the bytes read, where a file cut short ends. */
    private static int[] end(byte[] bytes) {
        int line = 1;
        int column = 1;
        for (byte b : bytes) {
            column = b == '\n' ? 1 : column + 1;
            line += b == '\n' ? 1 : 0;
        }
        return new int[] {line, column};
    }

    /**
     * A stream that keeps a copy of every byte read through it (skipped bytes too: the stream's own
     * {@code skip} reads them).
     */
    private static final class CopyingStream extends InputStream {
        private final InputStream in;
        private final ByteArrayOutputStream copy;

        CopyingStream(InputStream in, ByteArrayOutputStream copy) {
            this.in = in;
            this.copy = copy;
        }

        @Override
        public int read() throws IOException {
            int b = in.read();
            if (b >= 0)
                copy.write(b);
            return b;
        }

        @Override
        public int read(byte[] buffer, int offset, int length) throws IOException {
            int n = in.read(buffer, offset, length);
            if (n > 0)
                copy.write(buffer, offset, n);
            return n;
        }

        @Override
        public void close() throws IOException {
            in.close();
        }
    }

    /**
     * A parser of the scene files: secure (no DOCTYPE, no external entities), with English messages
     * whatever the default locale.
     *
     * @param schema the schema it checks the file against, or null for none
     */
    private static SAXParser newParser(Schema schema) throws SAXException {
        SAXParserFactory factory = SAXParserFactory.newInstance();
        factory.setNamespaceAware(true);
        factory.setSchema(schema);
        try {
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            SAXParser parser = factory.newSAXParser();
            // the root locale: the messages' base bundle, English (any other locale falls back to the default one)
            parser.setProperty("http://apache.org/xml/properties/locale", Locale.ROOT);
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
        return plain(message, null);
    }

    /**
     * Turns a parser's message into the scene file's terms. An unknown attribute or element names the
     * nearest valid one ("did you mean 'kD'?") and, when there are at most {@value NearestName#MAX_LISTED},
     * lists them.
     *
     * @param message the parser's message
     * @param parent  the element the parser was in (the parent of an element it refuses), or null
     * @return the message, without validator codes
     */
    static String plain(String message, String parent) {
        String text = CODE.matcher(message).replaceFirst("");
        Matcher m;
        if ((m = BAD_VALUE.matcher(text)).matches())
            return "attribute '" + m.group(2) + "' of <" + m.group(3) + "> must be "
                    + TYPES.getOrDefault(m.group(4), "a " + m.group(4)) + ", got '" + m.group(1) + "'";
        if ((m = UNKNOWN_ATTRIBUTE.matcher(text)).matches())
            return "unknown attribute '" + m.group(1) + "' on <" + m.group(2) + ">" + NearestName.hint(m.group(1),
                    SchemaNames.scene().attributes(m.group(2)), "'%s'", "<" + m.group(2) + "> has:");
        if ((m = MISSING_ATTRIBUTE.matcher(text)).matches())
            return "<" + m.group(2) + "> needs the attribute '" + m.group(1) + "'";
        if ((m = MISPLACED_ELEMENT.matcher(text)).matches())
            return misplaced(m.group(1), m.group(2) == null ? List.of() : List.of(m.group(2).split(",\\s*")), parent);
        if ((m = UNKNOWN_ROOT.matcher(text)).matches())
            return m.group(1).equals("scene") ? "<scene> must not have a namespace"
                    : "the root element must be <scene>, not <" + m.group(1) + ">";
        if ((m = TEXT_CONTENT.matcher(text)).matches())
            return "<" + m.group(1) + "> must not contain text";
        if ((m = ANY_CONTENT.matcher(text)).matches())
            return "<" + m.group(1) + "> must not contain text or elements";
        if (text.startsWith("DOCTYPE is disallowed"))
            return "a scene file must not have a DOCTYPE";
        return text;
    }

    /**
     * The message for an element the schema does not allow where it is.
     *
     * @param element  the element's name
     * @param expected the elements the validator expected there, perhaps none
     * @param parent   the element it is in, or null when not known
     * @return the message, naming the nearest valid element and the valid ones
     */
    private static String misplaced(String element, List<String> expected, String parent) {
        List<String> allowed = parent == null ? List.of() : SchemaNames.scene().children(parent);
        if (allowed.contains(element) && !expected.contains(element)) // a second one where one is allowed
            return "<" + parent + "> may have only one <" + element + ">";
        String problem = "element <" + element + "> is unknown or not allowed here";
        if (!expected.isEmpty())
            return problem + NearestName.hint(element, expected, "<%s>", "expected one of:");
        return problem + NearestName.hint(element, allowed, "<%s>", "<" + parent + "> has:");
    }

    /** A handler that knows where the parser is in the file. */
    private abstract static class LocatedHandler extends DefaultHandler {
        /** The parser's place in the file. */
        protected Locator locator;

        @Override
        public void setDocumentLocator(Locator locator) {
            this.locator = locator;
        }
    }

    /**
     * Checks the sizes the schema is slow or deep on: the nesting of elements (at most
     * {@link #MAX_DEPTH}) and the length of each value in an attribute (at most {@link #MAX_VALUE_LENGTH}
     * characters between blanks).
     */
    private static final class LimitsChecker extends LocatedHandler {
        private int depth;

        @Override
        public void startElement(String uri, String localName, String qName, Attributes attributes)
                throws SAXException {
            if (++depth > MAX_DEPTH)
                throw new SAXParseException("<" + localName + "> is nested too deeply: a scene file nests at most "
                        + MAX_DEPTH + " elements (fewer <geometries> groups inside each other)", locator);
            for (int k = 0; k < attributes.getLength(); ++k)
                for (String value : attributes.getValue(k).split("\\s+"))
                    if (value.length() > MAX_VALUE_LENGTH)
                        throw new SAXParseException("a value of attribute '" + attributes.getLocalName(k) + "' of <"
                                + localName + "> is " + value.length() + " characters long; a number or name in a "
                                + "scene file has at most " + MAX_VALUE_LENGTH, locator);
        }

        @Override
        public void endElement(String uri, String localName, String qName) {
            --depth;
        }
    }

    /** Builds the tree of elements; stops at the first problem the validator reports. */
    private static final class TreeBuilder extends LocatedHandler {
        private final Path file;
        private final Deque<SceneElement> open = new ArrayDeque<>();
        private SceneElement root;
        /** A value's facet problem, reported again by the next message with the attribute's name. */
        private SAXParseException pendingValueProblem;

        TreeBuilder(Path file) {
            this.file = file;
        }

        /** {@return the name of the element the parser is in, or null before the root and after it} */
        String openElement() {
            return open.isEmpty() ? null : open.peek().name();
        }

        @Override
        public void startElement(String uri, String localName, String qName, Attributes attributes)
                throws SAXException {
            throwPending();
            Map<String, String> values = new LinkedHashMap<>();
            for (int k = 0; k < attributes.getLength(); ++k)
                if (!XMLConstants.W3C_XML_SCHEMA_INSTANCE_NS_URI.equals(attributes.getURI(k))) // the editors' hints
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
