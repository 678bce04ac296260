package robotworld.explorer.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class JavaSourceTest {

    @Test
    void identifiersAreCheckedNotRepaired() {
        assertEquals("MotorModule1", JavaSource.identifier("MotorModule1"));
        for (String bad : new String[] {"class", "1abc", "a b", "a;b", "a\"b", "", "Motor-Controller", "x.y"}) {
            assertThrows(IllegalArgumentException.class, () -> JavaSource.identifier(bad), bad);
        }
        assertEquals("my.pkg", JavaSource.qualifiedName("my.pkg"));
        assertThrows(IllegalArgumentException.class, () -> JavaSource.qualifiedName("my..pkg"));
        assertThrows(IllegalArgumentException.class, () -> JavaSource.qualifiedName("my.int"));
    }

    @Test
    void stringLiteralsEscapeEverythingThatCouldEndThem() {
        assertEquals("\"Motor-Controller\"", JavaSource.stringLiteral("Motor-Controller"));
        assertEquals("\"a\\\"b\\\\c\"", JavaSource.stringLiteral("a\"b\\c"));
        assertEquals("\"line\\u000abreak\"", JavaSource.stringLiteral("line\nbreak"));
        assertEquals("\"caf\\u00e9\"", JavaSource.stringLiteral("café"));
    }

    @Test
    void commentTextCannotCloseTheCommentOrSmuggleUnicodeEscapes() {
        String hostile = "x */ System.exit(1); /* \\u000a new line\r\nand more";
        String safe = JavaSource.commentText(hostile);
        assertFalse(safe.contains("*/"), safe);
        assertFalse(safe.contains("\\"), safe);
        assertFalse(safe.contains("\n") || safe.contains("\r"), safe);
    }

    @Test
    void houseCodesAreAToP() {
        assertEquals("P", JavaSource.houseCode("P"));
        assertThrows(IllegalArgumentException.class, () -> JavaSource.houseCode("Q"));
        assertThrows(IllegalArgumentException.class, () -> JavaSource.houseCode("'"));
    }
}
