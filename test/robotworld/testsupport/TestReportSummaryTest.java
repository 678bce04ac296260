package robotworld.testsupport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;

/** The failure printout stays readable whatever a test's message is like. */
class TestReportSummaryTest {

    @Test
    void aLongOneLineMessageKeepsItsHeadAndTailWrapped() {
        // like a whole demo log in one assertion message
        String message = "expected modules [1, 2] but found [2]: " + "0123456789 ".repeat(1_000) + "the end";
        List<String> lines = TestReportSummary.readable(message, "    ").lines().toList();
        assertTrue(lines.stream().allMatch(line -> line.length() <= 154), "a line is longer than 150 + indent");
        assertTrue(lines.size() <= 10, lines.size() + " lines");
        assertTrue(lines.get(0).startsWith("    expected modules [1, 2]"), lines.get(0));
        assertTrue(String.join(" ", lines).contains("characters cut"), lines.toString());
        assertTrue(lines.get(lines.size() - 1).endsWith("the end"), lines.get(lines.size() - 1));
    }

    @Test
    void aMessageOfManyLinesIsCutAndSaysWhereTheRestIs() {
        List<String> lines = TestReportSummary.readable("line\n".repeat(500), "  ").lines().toList();
        assertEquals(21, lines.size(), "20 lines of message and one saying where the rest is");
        assertEquals("  ... 480 more lines in the test's XML report", lines.get(20));
    }

    @Test
    void aWordLongerThanTheWidthIsCutHard() {
        List<String> lines = TestReportSummary.readable("x".repeat(400), "").lines().toList();
        assertEquals(List.of(150, 150, 100), lines.stream().map(String::length).toList());
    }

    @Test
    void aShortMessageIsKeptAsItIs() {
        assertEquals("  one\n  two\n", TestReportSummary.readable("one\ntwo", "  "));
    }

    @Test
    void aLongExpectedButWasSaysWhereTheyFirstDiffer() {
        String expected = "a ".repeat(3_000);
        String actual = "a ".repeat(2_000) + "b" + " a".repeat(999);
        Optional<String> difference = TestReportSummary.firstDifference("modules ==> expected: <" + expected
                + "> but was: <" + actual + ">");
        assertEquals("first difference at character 4000 (of 6000 expected, 5999 actual): expected <..."
                + "a ".repeat(30) + "...> but was <..." + "a ".repeat(15) + "b" + " a".repeat(14) + " ...>",
                difference.orElseThrow());
        assertEquals(Optional.empty(), TestReportSummary.firstDifference("expected: <1> but was: <2>"),
                "a short pair is seen at a glance");
    }

    @Test
    void aMultiLineMessageKeepsItsLinesThoughTheReportsAttributeLostThem() throws Exception {
        // as the legacy XML report writes it: raw line breaks in the attribute, which a reader turns into spaces;
        // the message quotes a child program's log, frames included, which are not this test's frames
        String message = "step 7 failed; its log:\nException in thread main\n"
                + "\tat robotworld.bus.RS485Bus.decode(X.java:1)";
        String report = "<testcase><failure message=\"" + message + "\" type=\"org.opentest4j.AssertionFailedError\">"
                + "<![CDATA[org.opentest4j.AssertionFailedError: " + message + "\n"
                + "\tat robotworld.explorer.demo.DemoTest.run(DemoTest.java:7)\n"
                + "\tat org.junit.Runner.run(Runner.java:1)\n"
                + "]]></failure></testcase>";
        Element failure = (Element) DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new java.io.ByteArrayInputStream(report.getBytes(java.nio.charset.StandardCharsets.UTF_8)))
                .getElementsByTagName("failure").item(0);
        assertEquals(message.replaceAll("[\n\t]", " "), failure.getAttribute("message"), "what the attribute gives");
        assertEquals("""
                FAILED DemoTest > run()
                    step 7 failed; its log:
                    Exception in thread main
                    \tat robotworld.bus.RS485Bus.decode(X.java:1)
                      at robotworld.explorer.demo.DemoTest.run(DemoTest.java:7)
                """, TestReportSummary.describe("DemoTest > run()", failure));
    }

    @Test
    void anExceptionShowsItsTypeProjectFramesAndCauseNotTheLibraryFrames() throws Exception {
        Document document = DocumentBuilderFactory.newInstance().newDocumentBuilder().newDocument();
        Element failure = document.createElement("failure");
        failure.setAttribute("type", "java.lang.IllegalStateException");
        failure.setAttribute("message", "the space is gone");
        failure.setTextContent("""
                java.lang.IllegalStateException: the space is gone
                \tat robotworld.space.Remote.take(Remote.java:10)
                \tat java.base/java.lang.reflect.Method.invoke(Method.java:569)
                \tat org.junit.platform.Launcher.run(Launcher.java:5)
                Caused by: java.net.ConnectException: Connection refused
                \tat java.base/sun.nio.ch.Net.connect(Net.java:1)
                \tat robotworld.space.Remote.connect(Remote.java:20)
                \t... 12 more
                """);
        String text = TestReportSummary.describe("robotworld.space.RemoteTest > take()", failure);
        assertEquals("""
                FAILED robotworld.space.RemoteTest > take()
                    IllegalStateException: the space is gone
                      at robotworld.space.Remote.take(Remote.java:10)
                    Caused by: java.net.ConnectException: Connection refused
                      at robotworld.space.Remote.connect(Remote.java:20)
                """, text);
        failure.setAttribute("type", "org.opentest4j.AssertionFailedError");
        assertFalse(TestReportSummary.describe("t", failure).contains("AssertionFailedError"),
                "an assertion's type is noise");
    }
}
