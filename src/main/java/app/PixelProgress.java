package app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.function.LongConsumer;

import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarConsumer;
import me.tongfei.progressbar.ProgressBarStyle;
import org.jline.terminal.Terminal;
import org.jline.terminal.TerminalBuilder;

/**
 * The command line's progress bar, counting a render's pixels on the error stream: on a terminal as
 * wide as the terminal, redrawn in place; otherwise a line every {@value #LOG_UPDATE_MS} ms, shown once
 * the first tile is done. Closing it ends the bar's line and lets the terminal go.
 */
final class PixelProgress implements AutoCloseable {
    /** The width in characters of the progress bar's line when it is not on a terminal. */
    private static final int BAR_WIDTH = 79;
    /** How often the bar is redrawn on a terminal, in milliseconds. */
    private static final int TERMINAL_UPDATE_MS = 200;
    /** How often a bar line is printed when the error stream is not a terminal, in milliseconds. */
    private static final int LOG_UPDATE_MS = 10_000;

    private final WriterConsumer consumer;
    private final ProgressBar bar;
    private final LongConsumer listener;

    /**
     * Starts a bar.
     *
     * @param writer   the error stream
     * @param terminal true when it is a terminal
     * @param pixels   the pixels of the render
     */
    PixelProgress(PrintWriter writer, boolean terminal, long pixels) {
        this.consumer = new WriterConsumer(writer, terminal);
        this.bar = progressBar(pixels, consumer, terminal);
        this.listener = progress(bar, consumer);
    }

    /** {@return the render's listener, moving the bar forward} */
    LongConsumer listener() {
        return listener;
    }

    /** Stops the bar, and clears its line on a terminal: a failure's line follows, alone. */
    void mute() {
        consumer.mute();
    }

    @Override
    public void close() {
        try {
            bar.close();
            // the library ends the bar (consumer.close) only when its final draw is not also its first:
            // a render done before the first scheduled draw would leave the line open
            consumer.close();
        } finally {
            consumer.closeTerminal();
        }
    }

    /** A progress bar on the error stream, counting pixels. */
    private static ProgressBar progressBar(long pixels, WriterConsumer consumer, boolean terminal) {
        boolean unicode = terminal && StandardCharsets.UTF_8.equals(Charset.defaultCharset());
        return new ProgressBarBuilder().setTaskName("Rendering").setInitialMax(pixels).setUnit(" px", 1)
                .setStyle(unicode ? ProgressBarStyle.UNICODE_BLOCK : ProgressBarStyle.ASCII)
                .setUpdateIntervalMillis(terminal ? TERMINAL_UPDATE_MS : LOG_UPDATE_MS)
                .setConsumer(consumer)
                .build();
    }

    /**
     * A thread-safe listener moving the bar forward (never back, whatever order the threads report in),
     * and letting it show itself once the first tile is done.
     */
    private static LongConsumer progress(ProgressBar bar, WriterConsumer consumer) {
        long[] shown = {0};
        return pixelsDone -> {
            synchronized (shown) {
                if (pixelsDone > shown[0]) {
                    shown[0] = pixelsDone;
                    consumer.start();
                    bar.stepTo(pixelsDone);
                }
            }
        };
    }

    /**
     * Shows the progress bar on a writer: on a terminal the line is redrawn in place, as wide as the
     * terminal is now; otherwise each update is a line of its own, so that a log file stays readable.
     */
    private static final class WriterConsumer implements ProgressBarConsumer {
        /** The narrowest bar line: the task name, the percentage and a few cells of the bar. */
        private static final int MIN_WIDTH = 20;

        private final PrintWriter writer;
        private final boolean terminal;
        /** The terminal, asked for its width at every redraw; null off a terminal or when it cannot be opened. */
        private final Terminal device;
        private String last;
        /** Whether a tile is done: off a terminal, the bar shows nothing before. */
        private boolean started;
        /** Whether the render failed: the bar shows nothing more, the failure's line is alone. */
        private boolean muted;
        /** Whether the bar is done: a redraw still under way on the library's thread then shows nothing. */
        private boolean closed;

        WriterConsumer(PrintWriter writer, boolean terminal) {
            this.writer = writer;
            this.terminal = terminal;
            this.device = terminal ? openTerminal() : null;
        }

        /** The system's terminal, or null when it cannot be opened (the bar is then {@value #BAR_WIDTH} wide). */
        private static Terminal openTerminal() {
            try {
                return TerminalBuilder.builder().system(true).dumb(true).build();
            } catch (IOException | RuntimeException e) {
                return null;
            }
        }

        /** The bar's width: one less than the terminal's (a full line would wrap), or {@value #BAR_WIDTH}. */
        @Override
        public int getMaxRenderedLength() {
            int width = device == null ? 0 : device.getWidth();
            return width > 0 ? Math.max(MIN_WIDTH, width - 1) : BAR_WIDTH;
        }

        /** Lets the terminal go once the bar is done. */
        void closeTerminal() {
            try {
                if (device != null)
                    device.close();
            } catch (IOException e) {
                // the bar is done; a terminal that will not close has nothing left to show
            }
        }

        /** Lets the bar show itself off a terminal too: the render is under way. */
        synchronized void start() {
            started = true;
        }

        /** Stops the bar, and clears its line on a terminal: a failure's line follows, alone. */
        synchronized void mute() {
            muted = true;
            if (terminal)
                writer.print("\r" + " ".repeat(getMaxRenderedLength()) + "\r");
            writer.flush();
        }

        @Override
        public synchronized void accept(String rendered) {
            if (muted || closed || !terminal && !started)
                return;
            if (terminal)
                writer.print('\r' + rendered);
            else if (!rendered.equals(last)) // the library may draw the last state twice
                writer.println(rendered);
            last = rendered;
            writer.flush();
        }

        @Override
        public synchronized void close() {
            if (terminal && !muted && !closed)
                writer.println();
            closed = true;
            writer.flush();
        }
    }
}
