package robotworld.testsupport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The failure printout stays readable whatever a test's message is like. */
class TestReportSummaryTest {

    @Test
    void aLongOneLineMessageIsWrappedAndCut() {
        String message = "expected modules [1, 2] but found [2]: " + "0123456789 ".repeat(1_000);
        List<String> lines = TestReportSummary.readable(message, "    ").lines().toList();
        assertTrue(lines.stream().allMatch(line -> line.length() <= 154), "a line is longer than 150 + indent");
        assertEquals(21, lines.size(), "20 lines of message and one saying where the rest is");
        assertTrue(lines.get(0).startsWith("    expected modules [1, 2]"), lines.get(0));
        assertTrue(lines.get(20).contains("more lines in the test's XML report"), lines.get(20));
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
}
