package robotworld.explorer.generator;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The marked place of a generated main class where the control program goes: the lines between
 * {@value #BEGIN} and {@value #END} in {@code control()}.
 */
public final class ControlRegion {

    public static final String BEGIN = "// >>> control logic begins here";
    public static final String END = "// <<< control logic ends here";

    private ControlRegion() {
    }

    /** Replaces what is between the markers of {@code mainSource} with {@code program}, indented as the method body. */
    public static void replace(Path mainSource, String program) throws IOException {
        String source = Files.readString(mainSource, StandardCharsets.UTF_8);
        int begin = source.indexOf(BEGIN);
        int end = source.indexOf(END);
        if (begin < 0 || end < begin) {
            throw new IOException(mainSource + " has no control markers (" + BEGIN + ")");
        }
        int afterBegin = source.indexOf('\n', begin) + 1;
        int endLine = source.lastIndexOf('\n', end) + 1;
        String indent = source.substring(source.lastIndexOf('\n', begin) + 1, begin);
        StringBuilder body = new StringBuilder();
        for (String line : program.replace("\r\n", "\n").split("\n", -1)) {
            body.append(line.isBlank() ? "" : indent + line).append('\n');
        }
        while (body.length() > 1 && body.charAt(body.length() - 1) == '\n' && body.charAt(body.length() - 2) == '\n') {
            body.setLength(body.length() - 1);
        }
        Files.writeString(mainSource, source.substring(0, afterBegin) + body + source.substring(endLine),
                StandardCharsets.UTF_8);
    }
}
