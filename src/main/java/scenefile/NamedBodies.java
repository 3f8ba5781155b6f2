package scenefile;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The bodies of a scene file that have a {@code name}, for {@code <instance of="…">}: every name is
 * declared once in the file (in {@code <library>} or {@code <geometries>}), and an instance names one
 * that is declared. It also knows which elements move over an animation: those with a spinning
 * {@code <transform>}, those holding one, and instances of those.
 */
final class NamedBodies {
    /** The named elements, by name, in the order they are built: the library's first. */
    private final Map<String, SceneElement> declared = new LinkedHashMap<>();
    /** Whether the parts of each element seen so far move. */
    private final Map<SceneElement, Boolean> moving = new IdentityHashMap<>();
    /** The elements whose motion is being found, so that an instance of its own group ends the search. */
    private final Set<SceneElement> open = Collections.newSetFromMap(new IdentityHashMap<>());

    private NamedBodies() {
    }

    /**
     * Gathers the named bodies of a scene file.
     *
     * @param root the file's {@code <scene>}
     * @return its names
     * @throws SceneFileException when a name is declared twice, at the second
     */
    static NamedBodies of(SceneElement root) {
        NamedBodies names = new NamedBodies();
        for (String part : new String[] {"library", "geometries"}) {
            SceneElement element = root.child(part);
            if (element != null)
                names.declare(element);
        }
        return names;
    }

    private void declare(SceneElement element) {
        for (SceneElement child : element.children()) {
            if (child.has("name")) {
                String name = child.text("name");
                SceneElement first = declared.putIfAbsent(name, child);
                if (first != null)
                    throw child.error("the name '" + name + "' is already the name of the <" + first.name()
                            + "> at line " + first.line() + ": names must differ", null);
            }
            declare(child);
        }
    }

    /**
     * The body an instance places.
     *
     * @param instance an {@code <instance>}
     * @return the element its {@code of} names
     * @throws SceneFileException when no body has that name; the message names the nearest one
     */
    SceneElement target(SceneElement instance) {
        String name = instance.text("of");
        SceneElement target = declared.get(name);
        if (target == null)
            throw instance.error(declared.isEmpty() ? "no body is named '" + name + "': give a body name=\"" + name
                    + "\"" : "no body is named '" + name + "'" + NearestName.hint(name, new ArrayList<>(declared.keySet()),
                    "'%s'", "the names are:"), null);
        return target;
    }

    /**
     * Whether an element moves over an animation: its {@code <transform>} spins, a child moves, or it is
     * an instance of a body that moves.
     *
     * @param element a body, group or instance
     * @return true when it is not the same in every frame
     */
    boolean moves(SceneElement element) {
        return Placement.spins(element.child("transform")) || partsMove(element);
    }

    /**
     * Whether what an element holds moves over an animation, its own {@code <transform>} aside: a child
     * moves, or it is an instance of a body that moves. When nothing it holds moves, the body its element
     * describes before its transform is the same in every frame.
     *
     * @param element a body, group or instance
     * @return true when its parts are not the same in every frame
     */
    boolean partsMove(SceneElement element) {
        Boolean known = moving.get(element);
        if (known != null)
            return known;
        if (!open.add(element)) // an instance inside the group it names: refused when it is built
            return false;
        boolean moves = false;
        List<SceneElement> parts = new ArrayList<>(element.children());
        if (element.name().equals("instance") && declared.containsKey(element.text("of")))
            parts.add(declared.get(element.text("of")));
        for (SceneElement part : parts)
            moves |= moves(part);
        open.remove(element);
        moving.put(element, moves);
        return moves;
    }
}
