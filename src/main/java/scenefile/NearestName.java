package scenefile;

import java.util.List;
import java.util.Locale;

/**
 * The valid name a misspelt one most likely meant, for the messages about unknown attributes and
 * elements: the one that differs only in case ({@code kd} → {@code kD}), or else the one fewest edits
 * away ({@link #distance edit distance}, ignoring case), when that is close enough to be a slip of the
 * keyboard.
 */
final class NearestName {
    /** The longest name that gets a suggestion: longer ones are no slip of the keyboard. */
    static final int MAX_LENGTH = 64;
    /** The most valid names listed in a message; a longer list is left out. */
    static final int MAX_LISTED = 11;

    private NearestName() {
    }

    /**
     * The valid name nearest a given one: the first that equals it ignoring case, or else the first of
     * those fewest {@link #distance edits} away, ignoring case, when they are at most a third of the given
     * name's length (at least 1) and the two start alike (the same first letter, or one a letter longer in
     * front).
     *
     * @param given the name in the file
     * @param valid the valid names, in the order ties are broken
     * @return the nearest valid name, or null when none is close enough, or the given name is longer than
     * {@value #MAX_LENGTH} characters
     */
    static String of(String given, List<String> valid) {
        if (given.length() > MAX_LENGTH)
            return null;
        for (String name : valid)
            if (name.equalsIgnoreCase(given))
                return name;
        String lower = given.toLowerCase(Locale.ROOT);
        String nearest = null;
        int least = Math.max(1, given.length() / 3) + 1;
        for (String name : valid) {
            String candidate = name.toLowerCase(Locale.ROOT);
            int distance = distance(lower, candidate);
            if (distance < least && sameStart(lower, candidate)) {
                least = distance;
                nearest = name;
            }
        }
        return nearest;
    }

    /**
     * What a message adds about a name the file got wrong: the nearest valid name, as {@code did you
     * mean 'kD'?}, and, when there are at most {@value #MAX_LISTED} valid names, all of them.
     *
     * @param given  the name in the file
     * @param valid  the valid names, in the schema's order
     * @param quote  how a name is written: {@code "'%s'"} for an attribute, {@code "<%s>"} for an element
     * @param listed the words before the list, such as {@code "<image> has:"}
     * @return the text to append to the message, starting with "; ", or "" when there is nothing to add
     */
    static String hint(String given, List<String> valid, String quote, String listed) {
        String nearest = of(given, valid);
        String list = valid.isEmpty() || valid.size() > MAX_LISTED ? null : String.join(", ", valid);
        if (nearest == null)
            return list == null ? "" : "; " + listed + " " + list;
        String mean = "; did you mean " + quote.formatted(nearest) + "?";
        return list == null ? mean : mean + " " + Character.toUpperCase(listed.charAt(0)) + listed.substring(1)
                + " " + list;
    }

    /**
     * Whether two names start alike: with the same letter, or one is the other with a letter more in
     * front ({@code shininess} and {@code nshininess}). A slip of the keyboard seldom changes the first
     * letter: {@code cube} is not a misspelt {@code tube}.
     */
    private static boolean sameStart(String a, String b) {
        return a.isEmpty() || b.isEmpty() || a.charAt(0) == b.charAt(0) || a.equals(b.substring(1))
                || b.equals(a.substring(1));
    }

    /**
     * The edit distance between two names: the fewest insertions, deletions and substitutions of one
     * character, and swaps of two neighbouring ones, that turn one into the other (the optimal string
     * alignment distance: {@code widht} is 1 from {@code width}).
     *
     * @param a one name
     * @param b the other
     * @return the distance
     */
    static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); ++i)
            d[i][0] = i;
        for (int j = 0; j <= b.length(); ++j)
            d[0][j] = j;
        for (int i = 1; i <= a.length(); ++i)
            for (int j = 1; j <= b.length(); ++j) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(d[i - 1][j - 1] + cost, Math.min(d[i - 1][j], d[i][j - 1]) + 1);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1))
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
            }
        return d[a.length()][b.length()];
    }
}
