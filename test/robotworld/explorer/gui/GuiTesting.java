package robotworld.explorer.gui;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.Component;
import java.awt.GraphicsEnvironment;
import java.awt.Window;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;

/**
 * Helpers for tests that drive Swing: skip without a display, run on the event thread, wait for a condition
 * (checked on the event thread) instead of sleeping, and save screenshots under {@code <build>/screenshots/}.
 */
public final class GuiTesting {

    private GuiTesting() {
    }

    /**
     * Skips the test when there is no display. {@code ./antw test} gives the tests a virtual one (xvfb-run) when
     * the machine has none and Xvfb is installed, or can be.
     */
    public static void assumeDisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), "no display for the Swing tests: install Xvfb with 'sudo apt-get"
                + " install xvfb xauth' and ./antw test runs them on a virtual display");
        assumeTrue(DISPLAY_WORKS, "the display cannot be opened (a headless JRE without libawt_xawt?): install the"
                + " full JRE, e.g. 'sudo apt-get install openjdk-17-jre'");
    }

    /** Whether windows can really be opened: a display may be set while the JRE lacks its X11 toolkit. */
    private static final boolean DISPLAY_WORKS = probeDisplay();

    private static boolean probeDisplay() {
        if (GraphicsEnvironment.isHeadless()) {
            return false;
        }
        try {
            return GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices().length > 0;
        } catch (Throwable e) { // AWTError, UnsatisfiedLinkError: no usable toolkit
            return false;
        }
    }

    /** Runs {@code work} on the event thread and returns its result; exceptions are rethrown here. */
    public static <T> T onEdt(Callable<T> work) {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> {
                try {
                    result.set(work.call());
                } catch (Exception e) {
                    failure.set(e);
                }
            });
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        } catch (InvocationTargetException e) {
            throw e.getCause() instanceof RuntimeException r ? r : new IllegalStateException(e.getCause());
        }
        if (failure.get() != null) {
            throw failure.get() instanceof RuntimeException r ? r : new IllegalStateException(failure.get());
        }
        return result.get();
    }

    /** Runs {@code work} on the event thread. */
    public static void onEdt(Runnable work) {
        onEdt(() -> {
            work.run();
            return null;
        });
    }

    /** Waits until {@code condition}, evaluated on the event thread, holds; fails after {@code limit}. */
    public static void eventually(String what, Duration limit, Callable<Boolean> condition) {
        long deadline = System.nanoTime() + limit.toNanos();
        while (!onEdt(condition)) {
            if (System.nanoTime() - deadline > 0) {
                fail("not within " + limit.toMillis() + " ms: " + what);
            }
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("interrupted while waiting for: " + what);
            }
        }
    }

    /**
     * {@link #eventually(String, Duration, Callable)} with twenty seconds: only a failure waits that long, and a
     * busy machine may take seconds to get a window on the screen.
     */
    public static void eventually(String what, Callable<Boolean> condition) {
        eventually(what, Duration.ofSeconds(20), condition);
    }

    /** Where screenshots go: {@code <rwe.build.dir or build>/screenshots}. */
    public static Path screenshotDirectory() {
        return Path.of(System.getProperty("rwe.build.dir", "build")).resolve("screenshots");
    }

    /**
     * Paints {@code component} (a window, or a panel laid out at its preferred size) into
     * {@code screenshots/<name>.png} and returns the file.
     */
    public static Path screenshot(Component component, String name) {
        return onEdt(() -> {
            if (!(component instanceof Window) && component.getParent() == null) {
                component.setSize(component.getPreferredSize());
                layOut(component);
            }
            Component painted = component instanceof javax.swing.RootPaneContainer container
                    ? container.getRootPane() : component;
            BufferedImage image = new BufferedImage(Math.max(1, painted.getWidth()), Math.max(1, painted.getHeight()),
                    BufferedImage.TYPE_INT_RGB);
            java.awt.Graphics2D graphics = image.createGraphics();
            try {
                painted.paintAll(graphics);
            } finally {
                graphics.dispose();
            }
            Path file = screenshotDirectory().resolve(name + ".png");
            try {
                Files.createDirectories(file.getParent());
                ImageIO.write(image, "png", file.toFile());
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            return file;
        });
    }

    private static void layOut(Component component) {
        component.doLayout();
        if (component instanceof java.awt.Container container) {
            for (Component child : container.getComponents()) {
                layOut(child);
            }
        }
    }
}
