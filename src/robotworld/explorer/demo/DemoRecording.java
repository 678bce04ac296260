package robotworld.explorer.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import robotworld.explorer.monitor.MonitorSpace;
import robotworld.explorer.monitor.MonitoredWorld;
import robotworld.explorer.monitor.WorldLayouts;
import robotworld.observe.WorldLayout;
import robotworld.observe.WorldTap;
import robotworld.recording.Recorder;
import robotworld.space.Capi;
import robotworld.telemetry.SafetyTelemetry;

/**
 * The demo's optional recording ({@code rwe demo --record FILE}): a recorder of the world's traffic, including the
 * robot's ground truth, which the demo always publishes.
 */
final class DemoRecording {

    private final Capi space;
    private final WorldTap tap;
    private final SafetyTelemetry safety;
    private final Recorder recorder;

    private DemoRecording(Capi space, WorldTap tap, SafetyTelemetry safety, Recorder recorder) {
        this.space = space;
        this.tap = tap;
        this.safety = safety;
        this.recorder = recorder;
    }

    static DemoRecording start(Path file, MonitoredWorld world, Path description, String spaceUrl)
            throws IOException {
        WorldLayout layout = WorldLayouts.of(world);
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        Recorder recorder = Recorder.start(file, new Recorder.Start(layout, spaceUrl, Files.readAllBytes(description)),
                Recorder.Options.defaults());
        Capi space = MonitorSpace.open(spaceUrl);
        WorldTap tap = new WorldTap(space, layout).add(recorder.observer());
        SafetyTelemetry safety;
        try {
            tap.start();
            safety = SafetyTelemetry.start(space, recorder::offer);
        } catch (RuntimeException e) {
            tap.close();
            recorder.close("the space could not be watched");
            space.close();
            throw e;
        }
        return new DemoRecording(space, tap, safety, recorder);
    }

    /** Stops and finishes the file; says what was recorded. */
    String close() throws IOException {
        tap.close();
        safety.close();
        recorder.close("the demo ended");
        space.close();
        Recorder.Status status = recorder.status();
        return "recorded " + status.messages() + " messages into " + recorder.file() + " (" + status.dropped()
                + " dropped); replay it with: rwe replay " + recorder.file() + " --console";
    }
}
