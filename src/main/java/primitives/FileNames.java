package primitives;

import java.nio.charset.Charset;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;

import static primitives.Util.requireNonNull;

/**
 * File names turned into paths, with a message a user can act on when one cannot be a path. The usual
 * cause is the locale: Java encodes file names in the locale's character set, and in the C (POSIX)
 * locale that is ASCII, so a name with any other letter ({@code scène.xml}) cannot be used at all. The
 * message says so and what to set, instead of naming a Java class.
 */
public final class FileNames {
    /** What a user sets so that Java encodes file names in UTF-8. */
    private static final String UTF8_LOCALE = "run with a UTF-8 locale, e.g. LC_ALL=C.UTF-8";

    /** Not instantiable. */
    private FileNames() {
    }

    /**
     * The path of a file name.
     *
     * @param name the file name, relative or absolute
     * @return its path
     * @throws IllegalArgumentException when the name is null or cannot be a path, with a message that
     *                                  names it (made {@link Printable printable}) and why: letters the
     *                                  locale cannot encode (and the locale to set instead), or a
     *                                  character no path may hold (NUL)
     */
    public static Path toPath(String name) {
        requireNonNull(name, "file name");
        try {
            return Path.of(name);
        } catch (InvalidPathException e) {
            throw new IllegalArgumentException(problem(name, fileNameEncoding(), e), e);
        }
    }

    /**
     * The message for a file name that cannot be a path.
     *
     * @param name     the file name
     * @param encoding the character set file names are encoded in, or null when it is not known
     * @param e        the reason the name was refused
     * @return the message, on one line
     */
    static String problem(String name, Charset encoding, InvalidPathException e) {
        String quoted = "the file name '" + Printable.of(name) + "'";
        if (encoding != null && !encoding.newEncoder().canEncode(name))
            return quoted + " has letters that file names cannot hold in this locale (its file names are "
                    + encoding.name() + "); " + UTF8_LOCALE;
        return Printable.of(quoted + " cannot be a path: " + e.getReason());
    }

    /** {@return the character set Java encodes file names in (the locale's), or null when it is not known} */
    private static Charset fileNameEncoding() {
        String name = System.getProperty("sun.jnu.encoding");
        return name != null && Charset.isSupported(name) ? Charset.forName(name) : null;
    }
}
