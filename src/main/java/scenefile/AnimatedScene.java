package scenefile;

import java.nio.file.Path;
import java.util.IdentityHashMap;
import java.util.Map;

import geometries.Intersectable;

import static primitives.Util.requireFinite;

/**
 * A scene file as an animation: its picture at any time of the run, from 0 (the first frame, and the
 * still picture {@link SceneLoader#load} gives) toward 1 (the end of the last frame). What moves is
 * what the file says: the camera's orbit ({@code <animation>}) and the spins of {@code <transform>}s.
 * A body whose parts do not move is built once, for the first picture asked for, and shared by all
 * the others — a mesh is read from its file once, even when it spins; only its placement is made for
 * each time. Every picture of a time is the same, whichever pictures were asked for before it.
 *
 * <pre>{@code
 * AnimatedScene turntable = SceneLoader.loadAnimation(Path.of("scenes/turntable.xml"));
 * Picture quarter = turntable.at(0.25);
 * }</pre>
 */
public final class AnimatedScene {
    private final SceneElement root;
    private final Path file;
    private final NamedBodies names;
    private final Map<SceneElement, Intersectable> still = new IdentityHashMap<>();
    private final boolean moves;

    /**
     * Reads the names and motions of a checked scene file.
     *
     * @param root the file's root element
     * @param file the file
     * @throws SceneFileException when a name is given twice, or an orbit's axis is zero
     */
    AnimatedScene(SceneElement root, Path file) {
        this.root = root;
        this.file = file;
        this.names = NamedBodies.of(root);
        SceneElement animation = root.child("animation");
        SceneElement geometries = root.child("geometries");
        this.moves = Placement.orbits(animation) || geometries != null && names.moves(geometries);
    }

    /**
     * The picture at a time of the run.
     *
     * @param time the time: 0 for the first frame; the command line's frame k of N is at (k − 1) / N
     * @return the picture, with a camera and bodies of its own where they move
     * @throws IllegalArgumentException when the time is NaN or infinite
     * @throws SceneFileException       when the file does not describe a valid scene
     */
    public Picture at(double time) {
        requireFinite(time, "animation time");
        return SceneLoader.picture(root, file, time, names, still);
    }

    /** {@return whether anything moves: the camera orbits, or a body spins} */
    public boolean moves() {
        return moves;
    }
}
