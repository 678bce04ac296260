package robotworld.recording;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.telemetry.TelemetryMessage;
import robotworld.telemetry.Topics;

/** What rwe record --info says about finished and unfinished recordings. */
class RecordingInfoTest {

    @TempDir
    Path temp;

    @Test
    void aRecorderThatDiedLeavesAFileThatIsReadUpToItsLastFlush() throws Exception {
        Path file = temp.resolve("run.mcap");
        Recorder recorder = Recorder.start(file, new Recorder.Start(SimWorld.LAYOUT, "http://space", null),
                Recorder.Options.defaults());
        for (int i = 0; i < 100; i++) {
            recorder.offer(new TelemetryMessage(Topics.LIVENESS, 1_000_000_000L * (i + 1),
                    "{\"participant\":\"SimBot\",\"state\":\"ALIVE\"}".getBytes()));
        }
        recorder.close("test");
        StringWriter finished = new StringWriter();
        RecordingInfo.of(file).print(new PrintWriter(finished, true));
        assertTrue(finished.toString().contains("finished MCAP file"), finished.toString());
        assertTrue(finished.toString().contains("messages     100 in "), finished.toString());
        assertTrue(finished.toString().matches("(?s).*/rwe/liveness\\s+rwe.Liveness\\s+json\\s+100\\n.*"),
                finished.toString());
        assertTrue(finished.toString().contains("(99.000 s)"), finished.toString());

        // the same file without its summary and footer, and cut inside the data end record: as if killed
        byte[] bytes = Files.readAllBytes(file);
        Path cut = temp.resolve("cut.mcap");
        Files.write(cut, Arrays.copyOf(bytes, bytes.length * 3 / 4));
        RecordingInfo info = RecordingInfo.of(cut);
        StringWriter unfinished = new StringWriter();
        info.print(new PrintWriter(unfinished, true));
        assertTrue(unfinished.toString().contains("UNFINISHED"), unfinished.toString());
        assertEquals("SimWorld", info.start().get("world"));
        assertTrue(info.summary().statistics().messageCount() <= 100);
    }
}
