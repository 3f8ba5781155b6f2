package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.Set;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
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

    /**
     * Test method for {@link Parallel#forEach(int, int, String, java.util.function.IntConsumer)}: interrupting
     * the calling thread stops the work and says so, its flag kept; complete work returns normally.
     */
    @Test
    void testInterruption() {
        Thread caller = Thread.currentThread();
        try {
            // ===== Equivalence Partitions Tests =====
            // TC01: one thread, interrupted in task 3 of 100: tasks 0 to 3 ran, then a CancellationException
            // saying "4 of 100", the flag still set
            AtomicIntegerArray runs = new AtomicIntegerArray(100);
            CancellationException e = assertThrows(CancellationException.class, () -> Parallel.forEach(100, 1, "one",
                    t -> {
                        runs.incrementAndGet(t);
                        if (t == 3)
                            caller.interrupt();
                    }), "TC01: the interruption must be reported");
            assertMessage(e, "interrupted: the one threads stopped after 4 of 100 tasks", "TC01");
            for (int t = 0; t < 100; ++t)
                assertEquals(t <= 3 ? 1 : 0, runs.get(t), "TC01: task " + t);
            assertTrue(Thread.interrupted(), "TC01: the interrupt flag must stay set");
            // TC02: three threads, a helper interrupting the caller in task 10 of 100,000: each thread ends its
            // task under way and takes no more, far fewer than all run, every thread has stopped at the return
            AtomicInteger ran = new AtomicInteger();
            Set<Thread> workers = ConcurrentHashMap.newKeySet();
            assertThrows(CancellationException.class, () -> Parallel.forEach(100_000, 3, "three", t -> {
                workers.add(Thread.currentThread());
                ran.incrementAndGet();
                if (t == 10)
                    caller.interrupt();
            }), "TC02: the interruption must be reported");
            assertTrue(ran.get() < 100_000, "TC02: the work must stop, " + ran.get() + " tasks ran");
            assertTrue(workers.stream().noneMatch(w -> w != caller && w.isAlive()), "TC02: a helper is still running");
            assertTrue(Thread.interrupted(), "TC02: the interrupt flag must stay set");
            // TC03: the IllegalStateException it is: a caller catching the old contract still catches it
            caller.interrupt();
            assertThrows(IllegalStateException.class, () -> Parallel.forEach(5, 2, "old", t -> { }),
                    "TC03: an interrupted call must throw an IllegalStateException");
            assertTrue(Thread.interrupted(), "TC03: the interrupt flag must stay set");

            // ===== Boundary Values Tests =====
            // TC11: interrupted in the last task: the work is complete, so it returns normally, the flag set
            AtomicInteger done = new AtomicInteger();
            Parallel.forEach(10, 1, "last", t -> {
                done.incrementAndGet();
                if (t == 9)
                    caller.interrupt();
            });
            assertEquals(10, done.get(), "TC11: every task must run");
            assertTrue(Thread.interrupted(), "TC11: the interrupt flag must stay set");
            // TC12: interrupted before the call: no task runs, "0 of 5"
            caller.interrupt();
            assertMessage(assertThrows(CancellationException.class, () -> Parallel.forEach(5, 1, "before",
                    t -> { throw new AssertionError("TC12: no task may run"); }), "TC12: the interruption must be "
                    + "reported"), "after 0 of 5 tasks", "TC12");
            assertTrue(Thread.interrupted(), "TC12: the interrupt flag must stay set");
            // TC13 (own): interrupted before a call of no task: nothing to stop, it returns normally, the flag set
            caller.interrupt();
            Parallel.forEach(0, 2, "nothing", t -> { });
            assertTrue(Thread.interrupted(), "TC13: the interrupt flag must stay set");
        } finally {
            Thread.interrupted(); // the test thread goes on uninterrupted whatever failed
        }
    }
}
