package primitives;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.IntConsumer;

import static primitives.Util.requireNonNull;

/**
 * Work shared among threads: the one place the library starts threads, for the render's tiles and
 * the hierarchy's build alike.
 */
public final class Parallel {
    /** Not instantiable. */
    private Parallel() {
    }

    /**
     * Runs tasks 0 to count − 1, each once, on up to a number of threads: the calling one and as many
     * more as there are tasks for. Each thread takes the next task left until none is; after a failure
     * no more tasks are handed out, and the first failure (an exception, or an error such as running
     * out of memory) is thrown again on the calling thread once every thread has stopped.
     *
     * @param count   the number of tasks, 0 or more
     * @param threads the number of threads, 1 or more
     * @param name    the name of the threads started, each followed by its number
     * @param task    the task, called with its number
     * @throws IllegalArgumentException when the count is negative, the threads fewer than 1, or the
     *                                  name or task null
     * @throws IllegalStateException    when the calling thread is interrupted while it waits for the others
     */
    public static void forEach(int count, int threads, String name, IntConsumer task) {
        if (count < 0)
            throw new IllegalArgumentException("number of tasks must not be negative, got " + count);
        if (threads < 1)
            throw new IllegalArgumentException("number of threads must be 1 or more, got " + threads);
        requireNonNull(name, "thread name");
        requireNonNull(task, "task");
        AtomicInteger next = new AtomicInteger();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Runnable worker = () -> {
            try {
                for (int t = next.getAndIncrement(); t < count && failure.get() == null; t = next.getAndIncrement())
                    task.accept(t);
            } catch (RuntimeException | Error e) { // thrown again by the calling thread
                failure.compareAndSet(null, e);
            }
        };
        Thread[] helpers = new Thread[Math.max(0, Math.min(threads, count) - 1)];
        for (int h = 0; h < helpers.length; ++h) {
            helpers[h] = new Thread(worker, name + "-" + h);
            helpers[h].start();
        }
        worker.run();
        try {
            for (Thread helper : helpers)
                helper.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the " + name + " threads", e);
        }
        if (failure.get() instanceof RuntimeException e)
            throw e;
        if (failure.get() instanceof Error e)
            throw e;
    }
}
