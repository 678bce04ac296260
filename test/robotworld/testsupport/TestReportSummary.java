package robotworld.testsupport;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * Reads the legacy-xml reports that Ant's {@code <junitlauncher>} writes and prints what that task does not:
 * every failed or errored test with its exception type (unless it is an assertion), its message wrapped and cut
 * to a readable length, where a long {@code expected/but was} pair first differs, and the stack frames in project
 * code with each cause, then one closing line {@code tests: N passed, N failed, N skipped}. Exits 1 when a test
 * failed or no test ran at all.
 */
public final class TestReportSummary {

    private static final int STACK_LINES = 12;
    private static final int WIDTH = 150;
    private static final int MESSAGE_LINES = 20;
    /** A single line longer than this (a whole log in one assertion message) keeps only its head and tail. */
    private static final int LINE_CHARS = 1_200;
    private static final int CAUSE_LINES = 2;
    private static final int DIFFERENCE_CONTEXT = 30;
    private static final String EXPECTED = "expected: <";
    private static final String BUT_WAS = "> but was: <";

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

    static String describe(String name, Element problem) {
        StringBuilder text = new StringBuilder("FAILED ").append(name).append('\n');
        String message = message(problem);
        String type = problem.getAttribute("type");
        // an assertion's type says nothing; any other exception's type is half of what went wrong
        boolean assertion = type.isEmpty() || type.endsWith("AssertionFailedError") || type.endsWith("AssertionError");
        String headline = assertion ? message : simpleName(type) + (message.isEmpty() ? "" : ": " + message);
        if (!headline.isEmpty()) {
            text.append(readable(headline, "    "));
        }
        firstDifference(message).ifPresent(difference -> text.append(readable(difference, "    ")));
        // then the frames in project code and each cause: that is where the reader needs to look
        int shown = 0;
        for (String line : stackBelowMessage(problem, message).split("\r?\n")) {
            line = line.strip();
            boolean projectFrame = line.startsWith("at robotworld.");
            boolean cause = line.startsWith("Caused by:");
            if ((projectFrame || cause) && shown < STACK_LINES) {
                String shownLine = readable(line, projectFrame ? "      " : "    ");
                // a cause's message is cut to its first lines: its frames matter more
                text.append(cause ? shownLine.lines().limit(CAUSE_LINES).map(l -> l + "\n")
                        .reduce("", String::concat) : shownLine);
                shown++;
            }
        }
        return text.toString();
    }

    /**
     * The failure's message with its line breaks. The report keeps it in an attribute, where an XML reader turns
     * every line break into a space (a multi-line message would print as one endless line), and at the head of the
     * stack trace, where the breaks survive: that copy is taken when it is the same text.
     */
    static String message(Element problem) {
        String attribute = problem.getAttribute("message");
        String stack = problem.getTextContent().stripLeading();
        String prefix = problem.getAttribute("type") + ": ";
        int end = prefix.length() + attribute.length();
        if (!attribute.isEmpty() && stack.startsWith(prefix) && stack.length() >= end) {
            String original = stack.substring(prefix.length(), end);
            if (original.replaceAll("[\r\n\t]", " ").equals(attribute)) {
                return original;
            }
        }
        return attribute;
    }

    /** The stack trace without its head (type and message): a message may quote frames of its own. */
    private static String stackBelowMessage(Element problem, String message) {
        String stack = problem.getTextContent().strip();
        String head = problem.getAttribute("type") + (message.isEmpty() ? "" : ": " + message);
        return stack.startsWith(head) ? stack.substring(head.length()) : stack;
    }

    private static String simpleName(String type) {
        return type.substring(type.lastIndexOf('.') + 1);
    }

    /**
     * For a long {@code expected: <...> but was: <...>} message, where the two first differ, with a little context:
     * the one thing a reader needs that a cut message may no longer show.
     */
    static Optional<String> firstDifference(String message) {
        int expectedAt = message.indexOf(EXPECTED);
        int actualAt = message.lastIndexOf(BUT_WAS);
        if (expectedAt < 0 || actualAt < expectedAt || !message.endsWith(">")) {
            return Optional.empty();
        }
        String expected = message.substring(expectedAt + EXPECTED.length(), actualAt);
        String actual = message.substring(actualAt + BUT_WAS.length(), message.length() - 1);
        if (expected.length() + actual.length() < WIDTH) {
            return Optional.empty(); // short enough to see at a glance
        }
        int at = 0;
        while (at < expected.length() && at < actual.length() && expected.charAt(at) == actual.charAt(at)) {
            at++;
        }
        return Optional.of("first difference at character " + at + " (of " + expected.length()
                + " expected, " + actual.length() + " actual): expected <" + around(expected, at) + "> but was <"
                + around(actual, at) + ">");
    }

    private static String around(String text, int at) {
        int from = Math.max(0, at - DIFFERENCE_CONTEXT);
        int to = Math.min(text.length(), at + DIFFERENCE_CONTEXT);
        return (from > 0 ? "..." : "") + text.substring(from, to).replace("\n", "\\n")
                + (to < text.length() ? "..." : "");
    }

    /**
     * A message as a reader can take it in: a line longer than {@link #LINE_CHARS} keeps its head and its tail,
     * then lines are wrapped at {@link #WIDTH} columns, at most {@link #MESSAGE_LINES} lines (the full text stays
     * in the XML report), every line indented.
     */
    static String readable(String message, String indent) {
        List<String> lines = new ArrayList<>();
        for (String line : message.strip().split("\r?\n")) {
            if (line.length() > LINE_CHARS) {
                int tail = LINE_CHARS / 4;
                int head = LINE_CHARS - tail;
                line = line.substring(0, head) + " [... " + (line.length() - head - tail) + " characters cut ...] "
                        + line.substring(line.length() - tail);
            }
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
