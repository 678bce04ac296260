package robotworld.explorer.frames;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutionException;
import javax.swing.SwingWorker;
import robotworld.bus.BusTiming;
import robotworld.bus.RS485Bus;
import robotworld.bus.SerialSettings;
import robotworld.bus.explore.AddressProblem;
import robotworld.bus.explore.ExplorationListener;
import robotworld.bus.explore.ExplorationResult;
import robotworld.bus.explore.FoundModule;
import robotworld.bus.explore.ModuleCatalog;
import robotworld.bus.explore.RobotExplorer;
import robotworld.core.HostNames;
import robotworld.description.DescriptionException;
import robotworld.description.RobotWorldAssembler;

/**
 * Explores a robot's bus off the Swing thread: progress goes to {@link ExploreFrame#progress}, lines to its log,
 * and the outcome (the description written, or what went wrong) to its status. Nothing is thrown at the user.
 */
final class ExploreWorker extends SwingWorker<String, String> {

    private static final int BAUD = 115_200;

    private final ExploreFrame frame;
    private final String port;
    private final String robotName;
    private final Path output;
    private final Path catalogFolder;

    ExploreWorker(ExploreFrame frame, String port, String robotName, Path output, Path catalogFolder) {
        this.frame = frame;
        this.port = port;
        this.robotName = robotName;
        this.output = output;
        this.catalogFolder = catalogFolder;
    }

    @Override
    protected String doInBackground() throws Exception {
        publish("exploring " + port + " for robot '" + robotName + "'");
        try (RS485Bus bus = new RS485Bus(port, SerialSettings.eightNoneOne(BAUD), BusTiming.defaults())) {
            RobotExplorer explorer = new RobotExplorer(bus, new ModuleCatalog(catalogFolder)).host(localHostName());
            ExplorationResult result = explorer.explore(robotName, new Reporter());
            publish(result.summary(explorer.addressCount()));
            result.notes().forEach(note -> publish("note    " + note));
            if (result.description().isEmpty()) {
                throw new IllegalStateException("no module found on " + port + "; nothing written");
            }
            Files.createDirectories(output.toAbsolutePath().getParent());
            RobotWorldAssembler.write(result.description().get(), output);
            return "wrote " + output.toAbsolutePath() + " (" + result.modules().size() + " modules)";
        }
    }

    @Override
    protected void process(List<String> lines) {
        lines.forEach(frame.log()::line);
    }

    @Override
    protected void done() {
        try {
            String outcome = get();
            frame.log().line(outcome);
            frame.finished(outcome, false);
        } catch (ExecutionException e) {
            String message = message(e.getCause());
            frame.log().line("error: " + message);
            frame.finished(message, true);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            frame.finished("interrupted", true);
        }
    }

    private static String message(Throwable failure) {
        if (failure instanceof DescriptionException description) {
            StringBuilder all = new StringBuilder();
            description.errors().forEach(error -> all.append(all.isEmpty() ? "" : "; ").append(error.message()));
            return all.toString();
        }
        return failure.getMessage() != null ? failure.getMessage() : failure.toString();
    }

    private static String localHostName() {
        String name = HostNames.thisComputer();
        return name.matches("[A-Za-z0-9]([A-Za-z0-9.\\-]*[A-Za-z0-9])?") ? name : "localhost";
    }

    /** Feeds progress and log lines from the exploring thread. */
    private final class Reporter implements ExplorationListener {

        @Override
        public void progress(int address, int done, int total) {
            frame.progressLater(address, done, total);
        }

        @Override
        public void moduleFound(FoundModule module) {
            publish("found   " + module);
        }

        @Override
        public void problem(AddressProblem problem) {
            publish("skipped " + problem);
        }
    }
}
