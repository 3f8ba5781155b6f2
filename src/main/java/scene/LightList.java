package scene;

import java.util.AbstractList;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.RandomAccess;

import lighting.LightSource;

/**
 * A scene's own list of lights, {@link Scene#lights} until a list is set: a growable list, as the course's
 * {@code scene.lights.add(light)} expects, that refuses null wherever a light is put in (add, set, addAll),
 * so that a missing light is reported at the call that made it rather than when the picture renders.
 */
final class LightList extends AbstractList<LightSource> implements RandomAccess {
    private final List<LightSource> lights = new ArrayList<>();

    @Override
    public LightSource get(int index) {
        return lights.get(index);
    }

    @Override
    public int size() {
        return lights.size();
    }

    @Override
    public LightSource set(int index, LightSource light) {
        return lights.set(index, Scene.requireLight(light, index));
    }

    @Override
    public void add(int index, LightSource light) {
        lights.add(index, Scene.requireLight(light, index));
        ++modCount;
    }

    /** Adds every light at the end or, when one of them is null, none. */
    @Override
    public boolean addAll(Collection<? extends LightSource> added) {
        return addAll(size(), added);
    }

    /** Adds every light or, when one of them is null, none. */
    @Override
    public boolean addAll(int index, Collection<? extends LightSource> added) {
        int k = index;
        for (LightSource light : added)
            Scene.requireLight(light, k++);
        ++modCount;
        return lights.addAll(index, added);
    }

    @Override
    public LightSource remove(int index) {
        LightSource removed = lights.remove(index);
        ++modCount;
        return removed;
    }
}
