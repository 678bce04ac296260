package robotworld.testsupport;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * Reads the legacy-xml reports that Ant's {@code <junitlauncher>} writes and prints what that task does not:
 * every failed or errored test with its assertion message and the top of its stack trace, then one closing
 * line {@code tests: N passed, N failed, N skipped}. Exits 1 when a test failed or no test ran at all.
 */
public final class TestReportSummary {

    private static final int STACK_LINES = 12;
    private static final int WIDTH = 150;
    private static final int MESSAGE_LINES = 20;

    private int passed;
    private int failed;
    private int skipped;
    private final java.util.Map<String, Integer> skipReasons = new java.util.TreeMap<>();
    private final List<String> failures = new ArrayList<>();

    public static void main(String[] args) throws Exception {
        if (args.length != 1) {
            System.err.println("usage: TestReportSummary REPORT_DIR");
            System.exit(2);
        }
        TestReportSummary summary = new TestReportSummary();
        summary.readAll(Path.of(args[0]));
        summary.print();
        System.exit(summary.failed > 0 || summary.passed + summary.failed == 0 ? 1 : 0);
    }

    private void readAll(Path reportDir) throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        try (DirectoryStream<Path> reports = Files.newDirectoryStream(reportDir, "TEST-*.xml")) {
            for (Path report : reports) {
                read(factory.newDocumentBuilder().parse(report.toFile()));
            }
        } catch (IOException e) {
            System.err.println("cannot read test reports in " + reportDir + ": " + e.getMessage());
        }
    }

    private void read(Document report) {
        NodeList cases = report.getElementsByTagName("testcase");
        for (int i = 0; i < cases.getLength(); i++) {
            Element testCase = (Element) cases.item(i);
            String name = testCase.getAttribute("classname") + " > " + testCase.getAttribute("name");
            Element problem = firstChild(testCase, "failure");
            if (problem == null) {
                problem = firstChild(testCase, "error");
            }
            if (problem != null) {
                failed++;
                failures.add(describe(name, problem));
            } else if (firstChild(testCase, "skipped") != null || firstChild(testCase, "aborted") != null) {
                // "aborted" is how the legacy XML reports a failed assumption (e.g. GUI tests without a display)
                skipped++;
                Element aborted = firstChild(testCase, "aborted");
                if (aborted != null && !aborted.getAttribute("message").isEmpty()) {
                    skipReasons.merge(aborted.getAttribute("message"), 1, Integer::sum);
                }
            } else {
                passed++;
            }
        }
    }

    private static String describe(String name, Element problem) {
        StringBuilder text = new StringBuilder("FAILED ").append(name).append('\n');
        String message = problem.getAttribute("message");
        if (!message.isEmpty()) {
            text.append(readable(message, "    "));
        }
        // the exception line, then the frames in project code: that is where the reader needs to look
        String[] stack = problem.getTextContent().strip().split("\n");
        int shown = 0;
        for (int i = 0; i < stack.length && shown < STACK_LINES; i++) {
            String line = stack[i].strip();
            boolean exceptionLine = i == 0 || line.startsWith("Caused by:");
            if (exceptionLine && message.isEmpty() || line.startsWith("at robotworld.")) {
                text.append(readable(line, "      "));
                shown++;
            }
        }
        return text.toString();
    }

    /**
     * A message as a reader can take it in: wrapped at {@link #WIDTH} columns, at most {@link #MESSAGE_LINES}
     * lines (the full text stays in the XML report), every line indented.
     */
    static String readable(String message, String indent) {
        List<String> lines = new ArrayList<>();
        for (String line : message.strip().split("\r?\n")) {
            while (line.length() > WIDTH) {
                int cut = line.lastIndexOf(' ', WIDTH);
                cut = cut < WIDTH / 2 ? WIDTH : cut;
                lines.add(line.substring(0, cut));
                line = line.substring(cut).stripLeading();
            }
            lines.add(line);
        }
        StringBuilder text = new StringBuilder();
        lines.stream().limit(MESSAGE_LINES).forEach(line -> text.append(indent).append(line).append('\n'));
        if (lines.size() > MESSAGE_LINES) {
            text.append(indent).append("... ").append(lines.size() - MESSAGE_LINES)
                    .append(" more lines in the test's XML report\n");
        }
        return text.toString();
    }

    private static Element firstChild(Element parent, String tag) {
        NodeList list = parent.getElementsByTagName(tag);
        return list.getLength() == 0 ? null : (Element) list.item(0);
    }

    private void print() {
        failures.forEach(System.out::print);
        skipReasons.forEach((reason, count) -> System.out.print(readable("skipped " + count + ": " + reason, "")));
        if (passed + failed == 0) {
            System.out.println("no test ran");
        }
        System.out.println("tests: " + passed + " passed, " + failed + " failed, " + skipped + " skipped");
    }
}
