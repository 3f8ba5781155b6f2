package primitives;

import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.IntConsumer;

import static primitives.Util.requireNonNull;

/**
 * Work shared among threads: the one place the library starts threads, for the render's tiles and
 * the hierarchy's build alike.
 */
public final class Parallel {
    /** The longest the calling thread parks between looks at the threads it waits for. */
    private static final long WAIT_NANOS = 1_000_000;

    /** Not instantiable. */
    private Parallel() {
    }

    /**
     * Runs tasks 0 to count − 1, each once, on up to a number of threads: the calling one and as many
     * more as there are tasks for. Each thread takes the next task left until none is; after a failure
     * no more tasks are handed out, and the first failure (an exception, or an error such as running
     * out of memory) is thrown again on the calling thread once every thread has stopped.
     * <p>
     * Interrupting the calling thread stops the work: no task is started after it (a task under way
     * ends), and once every thread has stopped a {@link CancellationException} says how many tasks were
     * done, the calling thread's interrupt flag still set, as it is whenever the calling thread was
     * interrupted. Work that was complete when the interruption came returns normally (the flag set).
     *
     * @param count   the number of tasks, 0 or more
     * @param threads the number of threads, 1 or more
     * @param name    the name of the threads started, each followed by its number
     * @param task    the task, called with its number
     * @throws IllegalArgumentException when the count is negative, the threads fewer than 1, or the
     *                                  name or task null
     * @throws CancellationException    when the calling thread is interrupted before every task is done
     */
    public static void forEach(int count, int threads, String name, IntConsumer task) {
        if (count < 0)
            throw new IllegalArgumentException("number of tasks must not be negative, got " + count);
        if (threads < 1)
            throw new IllegalArgumentException("number of threads must be 1 or more, got " + threads);
        requireNonNull(name, "thread name");
        requireNonNull(task, "task");
        Thread caller = Thread.currentThread();
        AtomicInteger next = new AtomicInteger();
        AtomicInteger done = new AtomicInteger();
        // set when the wait for the helpers is interrupted, which clears the calling thread's flag
        AtomicBoolean stopped = new AtomicBoolean();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Runnable worker = () -> {
            try {
                for (int t = next.getAndIncrement(); t < count && failure.get() == null; t = next.getAndIncrement()) {
                    if (stopped.get() || caller.isInterrupted())
                        return;
                    task.accept(t);
                    done.incrementAndGet();
                }
            } catch (RuntimeException | Error e) { // thrown again by the calling thread
                failure.compareAndSet(null, e);
            } finally {
                LockSupport.unpark(caller); // a helper's end wakes the caller's wait (joinAll)
            }
        };
        Thread[] helpers = new Thread[Math.max(0, Math.min(threads, count) - 1)];
        for (int h = 0; h < helpers.length; ++h) {
            helpers[h] = new Thread(worker, name + "-" + h);
            helpers[h].start();
        }
        worker.run();
        joinAll(helpers, stopped);
        if (failure.get() instanceof RuntimeException e)
            throw e;
        if (failure.get() instanceof Error e)
            throw e;
        if (done.get() < count)
            throw new CancellationException("interrupted: the " + name + " threads stopped after " + done.get() + " of "
                    + count + " tasks");
    }

    /**
     * Waits for threads to end, whatever interrupts the wait, so that none is left running: an interruption
     * stops them after their tasks under way, and sets the calling thread's flag again at the end. The wait
     * parks rather than joins: a join clears the flag before it throws, and a thread that looked in between
     * would see neither the flag nor the stop. Here the stop is set before the flag is cleared.
     *
     * @param threads the threads
     * @param stopped set once the calling thread is seen interrupted: the threads take no more tasks
     */
    private static void joinAll(Thread[] threads, AtomicBoolean stopped) {
        boolean interrupted = false;
        for (Thread thread : threads)
            while (thread.isAlive()) {
                if (Thread.currentThread().isInterrupted()) {
                    stopped.set(true);
                    Thread.interrupted(); // cleared so that the park waits; set again at the end
                    interrupted = true;
                }
                // woken by each helper's end; the timeout covers one that ends between isAlive and the park
                LockSupport.parkNanos(WAIT_NANOS);
            }
        if (interrupted)
            Thread.currentThread().interrupt();
    }
}
