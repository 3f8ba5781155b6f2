package app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The frames of an animation a run renders: N frames in all, numbered from 1, of which this run
 * renders those from {@code first} to {@code last} (all of them unless {@code --frame-range} says
 * otherwise). Frame k is the scene at time t = (k − 1) / N of the run, so the times go 0, 1/N, …,
 * (N − 1)/N: a turn of 360° over the run loops without showing its first picture twice. Frame k goes
 * to the file {@code NAME-000k.png} beside the output {@code NAME.png} or {@code NAME.gif} (the
 * number has 4 digits, more when N needs them; an output {@code NAME.jpg} or {@code NAME.bmp} gives
 * frames of its own format).
 *
 * @param frames the number of frames of the whole animation
 * @param first  the first frame this run renders, from 1
 * @param last   the last frame this run renders, at most {@code frames}
 */
record Animation(int frames, int first, int last) {
    /** The most frames an animation has. */
    static final int MAX_FRAMES = 100_000;
    /** The fewest digits of a frame's number in its file name. */
    static final int MIN_DIGITS = 4;
    /** The extension of an animated GIF output. */
    static final String GIF = ".gif";

    private static final Pattern RANGE = Pattern.compile("(\\d{1,9})-(\\d{1,9})");

    /**
     * Checks the frames.
     *
     * @param frames the number of frames, 1 to {@link #MAX_FRAMES}
     * @param first  the first frame rendered, 1 to {@code last}
     * @param last   the last frame rendered, {@code first} to {@code frames}
     * @throws IllegalArgumentException when a number is out of its bounds; the message says which
     */
    Animation {
        if (frames < 1 || frames > MAX_FRAMES)
            throw new IllegalArgumentException("--frames must be 1 to " + MAX_FRAMES + ", got " + frames);
        if (first < 1)
            throw new IllegalArgumentException("--frame-range " + first + "-" + last + ": frame " + first
                    + " does not exist: frames are numbered from 1");
        if (last > frames)
            throw new IllegalArgumentException("--frame-range " + first + "-" + last + ": frame " + last
                    + " is beyond the last frame, " + frames + " (--frames " + frames + ")");
        if (first > last)
            throw new IllegalArgumentException("--frame-range " + first + "-" + last + " is empty: its first frame "
                    + first + " comes after its last, " + last);
    }

    /**
     * The frames of a run.
     *
     * @param frames the number of frames of the animation
     * @param range  the frames this run renders, {@code A-B} (1-based, both included), or null for all
     * @return the animation
     * @throws IllegalArgumentException when the range is not two frame numbers {@code A-B} of the
     *                                  animation, the first no later than the second
     */
    static Animation of(int frames, String range) {
        if (range == null)
            return new Animation(frames, 1, frames);
        Matcher m = RANGE.matcher(range.strip());
        if (!m.matches())
            throw new IllegalArgumentException("--frame-range must be two frame numbers A-B, such as 1-"
                    + Math.min(frames, 10) + ", got '" + range + "'");
        return new Animation(frames, Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)));
    }

    /** {@return the number of frames this run renders} */
    int count() {
        return last - first + 1;
    }

    /** {@return whether this run renders every frame} */
    boolean whole() {
        return first == 1 && last == frames;
    }

    /**
     * The time of a frame in the run.
     *
     * @param k the frame, 1 to {@link #frames}
     * @return (k − 1) / N
     * @throws IllegalArgumentException when there is no such frame
     */
    double time(int k) {
        requireFrame(k);
        return (k - 1) / (double) frames;
    }

    /**
     * The file of a frame: {@code NAME-000k.png} beside {@code NAME.png} or {@code NAME.gif}.
     *
     * @param output the run's output file
     * @param k      the frame, 1 to {@link #frames}
     * @return the frame's image file, in the output's format (PNG for a GIF)
     * @throws IllegalArgumentException when there is no such frame
     */
    Path frameFile(Path output, int k) {
        requireFrame(k);
        String name = output.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = dot > 0 ? name.substring(0, dot) : name;
        String extension = isGif(output) ? ".png" : dot > 0 ? name.substring(dot) : ".png";
        int digits = Math.max(MIN_DIGITS, Integer.toString(frames).length());
        return output.resolveSibling(String.format(Locale.ROOT, "%s-%0" + digits + "d%s", base, k, extension));
    }

    /**
     * The files of every frame of the animation, in order.
     *
     * @param output the run's output file
     * @return the files of frames 1 to N
     */
    List<Path> frameFiles(Path output) {
        List<Path> files = new ArrayList<>(frames);
        for (int k = 1; k <= frames; ++k)
            files.add(frameFile(output, k));
        return files;
    }

    /**
     * Whether an output is an animated GIF.
     *
     * @param output the output file
     * @return true when its name ends with {@code .gif}, in any case
     */
    static boolean isGif(Path output) {
        Path name = output.getFileName();
        return name != null && name.toString().toLowerCase(Locale.ROOT).endsWith(GIF);
    }

    private void requireFrame(int k) {
        if (k < 1 || k > frames)
            throw new IllegalArgumentException("frame " + k + " is not one of the animation's frames 1 to " + frames);
    }
}
