package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

/** Unit tests for {@link Printable}: input quoted in messages cannot reach a terminal as commands. */
class PrintableTest {

    /** Test method for {@link Printable#of(Object)}. */
    @Test
    void testOf() {
        // ===== Equivalence Partitions Tests =====
        // TC01: printable text, non-ASCII letters included, is the same string object
        String plain = "scène: radius must be positive, got 'abc'";
        assertSame(plain, Printable.of(plain), "TC01: printable text must be kept as it is");
        // TC02: an xterm title sequence, ESC ] 0 ; … BEL: "\x1B]0;pwned\x07"
        assertEquals("got '\\x1B]0;pwned\\x07'", Printable.of("got '\u001b]0;pwned\u0007'"),
                "TC02: ESC and BEL must become visible escapes");
        // TC03: the C1 control CSI (U+009B) and DEL: "\x9B2J\x7F"
        assertEquals("\\x9B2J\\x7F", Printable.of("\u009b2J\u007f"), "TC03: C1 controls and DEL must be escaped");
        // TC04: tab, line feed and carriage return by name: "a\tb\nc\rd"
        assertEquals("a\\tb\\nc\\rd", Printable.of("a\tb\nc\rd"), "TC04: \\t, \\n and \\r must be named");
        // TC05: a bidirectional override (U+202E) and a line separator (U+2028): "\x{202E}x\x{2028}"
        assertEquals("\\x{202E}x\\x{2028}", Printable.of("\u202ex\u2028"),
                "TC05: format characters and separators of lines must be escaped");
        // TC06: any object stands for its text: a path holding ESC
        assertEquals("target/\\x1B[2J.png", Printable.of(Path.of("target", "\u001b[2J.png")),
                "TC06: a path's text must be made printable");
        // TC07 (own): a letter outside the BMP (a surrogate pair) is kept, an unpaired surrogate is escaped
        assertEquals("\ud83d\ude00 \\x{D83D}", Printable.of("\ud83d\ude00 \ud83d"),
                "TC07: a pair must be kept, a lone surrogate escaped");

        // ===== Boundary Values Tests =====
        // TC11: the empty text and null
        assertEquals("", Printable.of(""), "TC11: the empty text must stay empty");
        assertEquals("null", Printable.of(null), "TC11: null must be \"null\"");
        // TC12: the ends of the control ranges: NUL, U+001F, U+0080 and U+009F escaped, space and U+00A0 kept
        assertEquals("\\x00\\x1F \\x80\\x9F\u00a0", Printable.of("\u0000\u001f \u0080\u009f\u00a0"),
                "TC12: the first and last control characters must be escaped, their neighbours kept");
        // TC13: a control character first and last
        assertEquals("\\x1Bx\\x1B", Printable.of("\u001bx\u001b"), "TC13: the first and last characters");
        // TC14 (own): applying it twice gives the same text; a backslash of the input is kept
        String once = Printable.of("C:\\scenes\\a\u001b.xml");
        assertEquals("C:\\scenes\\a\\x1B.xml", once, "TC14: backslashes must be kept");
        assertEquals(once, Printable.of(once), "TC14: printable text must not change again");
    }

    /** Test method for {@link Printable#refusal(String, Throwable)}. */
    @Test
    void testRefusal() {
        IllegalStateException cause = new IllegalStateException("cause");
        // ===== Equivalence Partitions Tests =====
        // TC01: a message quoting ESC: an IllegalArgumentException, its message printable, its cause kept
        IllegalArgumentException e = Printable.refusal("bad file \u001B]0;title\u0007.obj", cause);
        assertEquals("bad file \\x1B]0;title\\x07.obj", e.getMessage(), "TC01: wrong message");
        assertSame(cause, e.getCause(), "TC01: the cause must be kept");
        // ===== Boundary Values Tests =====
        // TC11: a printable message is kept as it is, and no cause is none
        IllegalArgumentException plain = Printable.refusal("plain", null);
        assertEquals("plain", plain.getMessage(), "TC11: a printable message must be kept");
        assertNull(plain.getCause(), "TC11: no cause");
    }
}
