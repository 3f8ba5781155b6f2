package accel;

import geometries.TriangleMesh;
import java.util.Arrays;

/**
 * The rays of a packet of shadow rays, traced together through a subtree ({@link PacketWalk}), and
 * the packet walk's scratch space.
 */
final class Packet {
    /** The rays, each with its answer: rays [0, {@link #size}) are the packet's. */
    RayState[] rays = new RayState[0];
    int size;
    /** The first and the last ray of the packet that may meet each node on the stack of a packet walk. */
    final int[] firstRays;
    final int[] lastRays;
    /** The rays of the packet that meet the leaf a packet walk is at, in order. */
    int[] leafRays = new int[0];
    /** A mesh's triangle's data (p1, its edges, the parallel limit), read once per leaf of a packet walk. */
    final double[] triangle = new double[TriangleMesh.TRIANGLE_DATA];

    /** Creates an empty packet for walks of a tree no deeper than stackSize − 2. */
    Packet(int stackSize) {
        this.firstRays = new int[stackSize];
        this.lastRays = new int[stackSize];
    }

    /** {@return room for one more ray, now the last of the packet} */
    RayState add() {
        if (size == rays.length) {
            int capacity = Math.max(16, 2 * size);
            rays = Arrays.copyOf(rays, capacity);
            for (int r = size; r < capacity; ++r)
                rays[r] = new RayState();
            leafRays = Arrays.copyOf(leafRays, capacity);
        }
        return rays[size++];
    }
}
