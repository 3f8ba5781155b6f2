package scenefile;

import primitives.Point3D;
import primitives.Transform;
import primitives.Vector;
import renderer.Camera;

/**
 * Where a scene file's {@code <transform>} puts a body, and where its {@code <animation>} takes the
 * camera, at a time of an animation's run (0 at its first frame, 1 at the end of its last: the command
 * line's frame k of N is at t = (k − 1) / N, so a turn of 360° loops without a frame shown twice).
 * <p>
 * A transform's steps apply in this order, whatever the order of the attributes in the file: {@code scale}
 * (about the origin), {@code rotate-x}, {@code rotate-y}, {@code rotate-z} (degrees, counter-clockwise
 * looking down the axis toward the origin), {@code spin-x}, {@code spin-y}, {@code spin-z} (degrees over
 * the whole run: the angle at time t is the spin × t), then {@code translate}. So a body is sized and turned
 * about its own origin, spun there like a turntable, and then moved into place.
 */
final class Placement {
    private Placement() {
    }

    /**
     * The transform of a {@code <transform>} element at a time.
     *
     * @param element the {@code <transform>}
     * @param time    the time in the animation's run, 0 for a still picture
     * @return the transform from the body's space to its parent's
     * @throws IllegalArgumentException when a scale factor is 0 (the transform would flatten the body)
     */
    static Transform transform(SceneElement element, double time) {
        Transform transform = Transform.IDENTITY;
        if (element.has("scale")) {
            double[] s = element.numbers("scale");
            transform = s.length == 1 ? Transform.scale(s[0]) : Transform.scale(s[0], s[1], s[2]);
        }
        transform = rotations(transform, element, "rotate-", 1);
        transform = rotations(transform, element, "spin-", time);
        if (element.has("translate")) {
            double[] t = element.numbers("translate");
            transform = then(transform, translation(t[0], t[1], t[2]));
        }
        return transform;
    }

    /** The transform followed by the rotations about x, y and z that the element gives, each times a factor. */
    private static Transform rotations(Transform transform, SceneElement element, String prefix, double factor) {
        for (String axis : new String[] {"x", "y", "z"}) {
            String attribute = prefix + axis;
            double degrees = element.has(attribute) ? element.number(attribute) * factor : 0;
            if (degrees != 0)
                transform = then(transform, switch (axis) {
                    case "x" -> Transform.rotateX(degrees);
                    case "y" -> Transform.rotateY(degrees);
                    default -> Transform.rotateZ(degrees);
                });
        }
        return transform;
    }

    /**
     * Whether a {@code <transform>} moves its body over an animation: it has a spin other than 0.
     *
     * @param element the {@code <transform>}, or null for none
     * @return true when it spins
     */
    static boolean spins(SceneElement element) {
        if (element == null)
            return false;
        for (String axis : new String[] {"spin-x", "spin-y", "spin-z"})
            if (element.has(axis) && element.number(axis) != 0)
                return true;
        return false;
    }

    /**
     * The camera's orbit at a time: a rotation by {@code orbit-degrees} × t about the axis
     * {@code orbit-axis} through {@code orbit-center}.
     *
     * @param animation the {@code <animation>} element, or null for none
     * @param time      the time in the animation's run
     * @return the rotation, or null when the camera stays where it is (no orbit, or an angle of 0)
     * @throws IllegalArgumentException when the axis is the zero vector
     */
    static Transform orbit(SceneElement animation, double time) {
        if (animation == null)
            return null;
        double degrees = animation.number("orbit-degrees") * time;
        if (degrees == 0)
            return null;
        Vector axis = axis(animation);
        Point3D c = animation.point("orbit-center");
        return then(then(translation(-c.getX(), -c.getY(), -c.getZ()), Transform.rotate(axis, degrees)),
                translation(c.getX(), c.getY(), c.getZ()));
    }

    /**
     * Whether the camera moves over an animation.
     *
     * @param animation the {@code <animation>} element, or null for none
     * @return true when its orbit turns by an angle other than 0
     */
    static boolean orbits(SceneElement animation) {
        return animation != null && animation.number("orbit-degrees") != 0;
    }

    private static Vector axis(SceneElement animation) {
        double[] a = animation.numbers("orbit-axis");
        if (a[0] == 0 && a[1] == 0 && a[2] == 0)
            throw new IllegalArgumentException("orbit-axis must not be 0 0 0: the orbit needs an axis to turn about");
        return new Vector(a[0], a[1], a[2]);
    }

    /**
     * A camera moved by a transform: its position, direction and up turned with it (a rotation keeps them
     * orthogonal); its view plane and lens are left to the caller.
     *
     * @param camera the camera
     * @param orbit  the rotation
     * @return the new camera
     */
    static Camera orbited(Camera camera, Transform orbit) {
        return new Camera(orbit.apply(camera.getP0()), orbit.applyToVector(camera.getVTo()),
                orbit.applyToVector(camera.getVUp()));
    }

    /** {@return the translation by (x, y, z), the identity for (0, 0, 0)} */
    private static Transform translation(double x, double y, double z) {
        return x == 0 && y == 0 && z == 0 ? Transform.IDENTITY : Transform.translate(new Vector(x, y, z));
    }

    /** {@return the first transform, then the second; no product with the identity} */
    private static Transform then(Transform first, Transform second) {
        if (first == Transform.IDENTITY)
            return second;
        return second == Transform.IDENTITY ? first : first.then(second);
    }
}
