package robotworld.description;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import robotworld.testsupport.ProjectFiles;

/**
 * The corpus of broken descriptions in {@code invalid/}: each must be rejected with a
 * {@link DescriptionException} whose first error is at the expected line and column with the expected message
 * (listed in {@code invalid/expected.tsv}), and never with any other exception.
 */
class InvalidDescriptionCorpusTest {

    private static final Path CORPUS = ProjectFiles.resolve("test/robotworld/description/invalid");

    record Expectation(String file, int line, int column, String message) {
        @Override
        public String toString() {
            return file;
        }
    }

    static List<Expectation> expectations() throws IOException {
        return Files.readAllLines(CORPUS.resolve("expected.tsv")).stream()
                .filter(line -> !line.isBlank() && !line.startsWith("#"))
                .map(line -> {
                    String[] fields = line.split("\t", 3);
                    String[] position = fields[1].split(":");
                    return new Expectation(fields[0], Integer.parseInt(position[0]), Integer.parseInt(position[1]),
                            fields[2]);
                })
                .collect(Collectors.toList());
    }

    @ParameterizedTest
    @MethodSource("expectations")
    void rejectedWithPositionAndMessage(Expectation expected) {
        Path file = CORPUS.resolve(expected.file());
        DescriptionException thrown = assertThrows(DescriptionException.class, () -> DescriptionLoader.loadWorld(file));
        DescriptionError first = thrown.errors().get(0);
        assertEquals(file.toString(), first.source());
        assertEquals(expected.line() + ":" + expected.column(), first.line() + ":" + first.column(),
                "position of: " + first);
        assertTrue(first.message().contains(expected.message()), "message was: " + first.message());
        assertTrue(first.toString().startsWith(file + ":" + expected.line() + ":" + expected.column() + ": "));
        assertFalse(thrown.getMessage().contains("Exception"), "leaks an exception name: " + thrown.getMessage());
    }

    @Test
    void corpusIsLargeAndEveryFileHasAnExpectation() throws IOException {
        Set<String> files;
        try (Stream<Path> listing = Files.list(CORPUS)) {
            files = listing.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".xml"))
                    .collect(Collectors.toCollection(TreeSet::new));
        }
        Set<String> expected = expectations().stream().map(Expectation::file)
                .collect(Collectors.toCollection(TreeSet::new));
        assertEquals(files, expected);
        assertTrue(files.size() >= 30, "only " + files.size() + " invalid descriptions");
    }

    @Test
    void everyErrorIsReportedNotOnlyTheFirst() {
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorld(CORPUS.resolve("many-errors.xml")));
        assertEquals(2, thrown.errors().size(), thrown.getMessage());
        assertTrue(thrown.errors().get(1).message().contains("'ZERO'"));
    }

    @Test
    void cascadingSchemaErrorsAreReportedOnce() {
        DescriptionException thrown = assertThrows(DescriptionException.class,
                () -> DescriptionLoader.loadWorld(CORPUS.resolve("missing-world-name.xml")));
        assertEquals(1, thrown.errors().size(), thrown.getMessage());
    }
}
