package robotworld.explorer.frames;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutionException;
import javax.swing.SwingWorker;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.FrameworkGenerator;
import robotworld.explorer.generator.GenerationResult;

/** Generates a framework off the Swing thread and reports steps and the outcome to the {@link GenerateFrame}. */
final class GenerateWorker extends SwingWorker<GenerationResult, GenerateWorker.Step> {

    /** One generation step, for the progress bar. */
    record Step(int done, int total, String text) {
    }

    private final GenerateFrame frame;
    private final RobotWorldDocument world;
    private final String viewpoint;
    private final String packageName;
    private final Path destination;
    private final boolean replace;

    GenerateWorker(GenerateFrame frame, RobotWorldDocument world, String viewpoint, String packageName,
                   Path destination, boolean replace) {
        this.frame = frame;
        this.world = world;
        this.viewpoint = viewpoint;
        this.packageName = packageName;
        this.destination = destination;
        this.replace = replace;
    }

    @Override
    protected GenerationResult doInBackground() throws Exception {
        return new FrameworkGenerator().generate(world, viewpoint, packageName, destination, replace,
                (done, total, step) -> publish(new Step(done, total, step)));
    }

    @Override
    protected void process(List<Step> steps) {
        Step last = steps.get(steps.size() - 1);
        frame.stepped(last.done(), last.total(), last.text());
    }

    @Override
    protected void done() {
        try {
            frame.generated(get());
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            frame.failed(cause.getMessage() != null ? cause.getMessage() : cause.toString());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            frame.failed("interrupted");
        }
    }
}
