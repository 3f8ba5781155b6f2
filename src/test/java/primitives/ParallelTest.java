package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicIntegerArray;

import org.junit.jupiter.api.Test;

/** Unit tests for {@link Parallel}. */
class ParallelTest {

    /** Test method for {@link Parallel#forEach(int, int, String, java.util.function.IntConsumer)}. */
    @Test
    void testForEach() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 1000 tasks on 3 threads: each task runs exactly once
        AtomicIntegerArray runs = new AtomicIntegerArray(1000);
        Parallel.forEach(1000, 3, "test", runs::incrementAndGet);
        for (int t = 0; t < runs.length(); ++t)
            assertEquals(1, runs.get(t), "TC01: task " + t + " must run once");
        // TC02: the calling thread works too, and the others carry the given name
        Set<String> names = ConcurrentHashMap.newKeySet();
        Parallel.forEach(200, 2, "named", t -> names.add(Thread.currentThread().getName()));
        assertTrue(names.stream().allMatch(n -> n.equals(Thread.currentThread().getName()) || n.equals("named-0")),
                "TC02: unexpected thread names " + names);
        // TC03: a task's exception is thrown again on the calling thread, the same object
        IllegalStateException thrown = new IllegalStateException("task 7 failed");
        assertSame(thrown, assertThrows(IllegalStateException.class, () -> Parallel.forEach(50, 3, "failing",
                t -> { if (t == 7) throw thrown; }), "TC03: the failure must reach the caller"), "TC03: same object");
        // TC04: an error (not an exception) is thrown again too
        StackOverflowError error = new StackOverflowError();
        assertSame(error, assertThrows(StackOverflowError.class, () -> Parallel.forEach(50, 2, "erring",
                t -> { if (t == 3) throw error; }), "TC04: the error must reach the caller"), "TC04: same object");

        // ===== Boundary Values Tests =====
        // TC11: no task: nothing runs
        Parallel.forEach(0, 4, "none", t -> { throw new AssertionError("TC11: no task may run"); });
        // TC12: one thread runs the tasks in order on the calling thread, and stops handing them out
        // after a failure
        AtomicIntegerArray order = new AtomicIntegerArray(10);
        assertThrows(IllegalArgumentException.class, () -> Parallel.forEach(10, 1, "one", t -> {
            order.set(t, 1);
            if (t == 4)
                throw new IllegalArgumentException("stop");
        }), "TC12: the failure must reach the caller");
        for (int t = 0; t < 10; ++t)
            assertEquals(t <= 4 ? 1 : 0, order.get(t), "TC12: task " + t);
        // TC13: more threads than tasks: each task still runs once
        AtomicIntegerArray few = new AtomicIntegerArray(2);
        Parallel.forEach(2, 8, "few", few::incrementAndGet);
        assertEquals(1, few.get(0), "TC13: task 0 must run once");
        assertEquals(1, few.get(1), "TC13: task 1 must run once");
        // TC14: bad arguments are refused, naming them
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Parallel.forEach(-1, 1, "n", t -> { })),
                "number of tasks must not be negative", "TC14");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Parallel.forEach(1, 0, "n", t -> { })),
                "number of threads must be 1 or more", "TC14");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Parallel.forEach(1, 1, null, t -> { })),
                "thread name", "TC14");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Parallel.forEach(1, 1, "n", null)),
                "task", "TC14");
    }
}
