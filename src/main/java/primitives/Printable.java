package primitives;

import java.util.Locale;

/**
 * Makes text safe to show on a terminal. A message that quotes input — a value from a scene file, a
 * line of an OBJ file, a file name, an argument — may carry control characters (ESC, BEL, the C1
 * controls) that a terminal runs as commands: clear the screen, set the window title. Every message of
 * the library that quotes input passes through {@link #of(Object)}.
 */
public final class Printable {
    /** Not instantiable. */
    private Printable() {
    }

    /**
     * The text with every character a terminal could take for a command written as a visible escape:
     * tab, line feed and carriage return as {@code \t}, {@code \n} and {@code \r}, the other control
     * characters (C0, DEL and C1) as {@code \xHH}, and format characters (such as the bidirectional
     * overrides), line and paragraph separators and unpaired surrogates as {@code \x{HHHH}}. Every other
     * character, backslashes included, is kept, so applying it twice gives the same text.
     *
     * @param text the text (any object stands for its {@code toString()}, null for "null")
     * @return the printable text
     */
    public static String of(Object text) {
        String string = String.valueOf(text);
        StringBuilder printable = null; // made at the first character to escape: most text has none
        for (int k = 0; k < string.length(); k += Character.charCount(string.codePointAt(k))) {
            int c = string.codePointAt(k);
            if (!isPrintable(c) && printable == null)
                printable = new StringBuilder(string.length() + 16).append(string, 0, k);
            if (printable != null)
                printable.append(isPrintable(c) ? Character.toString(c) : escape(c));
        }
        return printable == null ? string : printable.toString();
    }

    /**
     * The refusal of bad input: an {@link IllegalArgumentException} whose message, which quotes the
     * input, is made printable ({@link #of(Object)}).
     *
     * @param message what is wrong, quoting the input
     * @param cause   the exception that revealed it, or null
     * @return the exception to throw
     */
    public static IllegalArgumentException refusal(String message, Throwable cause) {
        return new IllegalArgumentException(of(message), cause);
    }

    /** Whether a character is shown as itself: not a control or format character, not a separator of lines. */
    private static boolean isPrintable(int c) {
        return switch (Character.getType(c)) {
            case Character.CONTROL, Character.FORMAT, Character.LINE_SEPARATOR, Character.PARAGRAPH_SEPARATOR,
                 Character.SURROGATE -> false;
            default -> true;
        };
    }

    /** The visible escape of a character that is not printable. */
    private static String escape(int c) {
        return switch (c) {
            case '\t' -> "\\t";
            case '\n' -> "\\n";
            case '\r' -> "\\r";
            default -> String.format(Locale.ROOT, c <= 0xFF ? "\\x%02X" : "\\x{%04X}", c);
        };
    }
}
