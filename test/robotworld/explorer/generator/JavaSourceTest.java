package robotworld.explorer.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

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

    /** "Trojan source": no bidirectional control or other invisible character reaches a generated comment. */
    @Test
    void commentTextWritesInvisibleCharactersOut() {
        String hostile = "lamp \u202E } if (admin) { \u2066 \u2069 \u200B \u00AD \u2028 \u0085 \uFEFF \uE000 end";
        String safe = JavaSource.commentText(hostile);
        assertEquals("lamp [U+202E] } if (admin) { [U+2066] [U+2069] [U+200B] [U+00AD] [U+2028]   [U+FEFF] [U+E000] end",
                safe);
        safe.codePoints().forEach(c -> assertTrue(c >= 0x20 && c < 0x7f, "left in: U+" + Integer.toHexString(c)));
        assertEquals("Stoßstange vorn, مصباح", JavaSource.commentText("Stoßstange vorn, مصباح"), "visible text stays");
        assertEquals("a- -b", JavaSource.commentText("a--b"), "no XML comment end");
    }

    @Test
    void houseCodesAreAToP() {
        assertEquals("P", JavaSource.houseCode("P"));
        assertThrows(IllegalArgumentException.class, () -> JavaSource.houseCode("Q"));
        assertThrows(IllegalArgumentException.class, () -> JavaSource.houseCode("'"));
    }
}
