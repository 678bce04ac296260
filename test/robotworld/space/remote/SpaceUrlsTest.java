package robotworld.space.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.util.List;

import org.junit.jupiter.api.Test;

/** The text users write for a space's servers: one URL, or several separated by commas, checked one by one. */
class SpaceUrlsTest {

    @Test
    void oneUrlOrSeveralInTheOrderWritten() {
        assertEquals(List.of(URI.create("http://127.0.0.1:9876/space")), SpaceUrls.parse("http://127.0.0.1:9876/space"));
        assertEquals(List.of(URI.create("http://pc-b:9876/space"), URI.create("http://pc-a:9876/space"),
                        URI.create("http://[::1]:9000/space")),
                SpaceUrls.parse(" http://pc-b:9876/space, http://pc-a:9876/space ,http://[::1]:9000/space"));
    }

    @Test
    void eachBadPartIsNamed() {
        assertMessage("ftp://pc-a/space", "http://pc-a:1/space,ftp://pc-a/space");
        assertMessage("empty", "http://pc-a:1/space,,http://pc-b:1/space");
        assertMessage("empty", "http://pc-a:1/space,");
        assertMessage("listed twice", "http://pc-a:1/space,http://pc-a:1/space");
        assertMessage("names no host", "http:///space");
        assertMessage("not a URL", "http://pc a:1/space");
        assertMessage("no space URL", "  ");
        assertMessage("at most 32", "http://a:1/s,".repeat(32) + "http://b:1/s");
    }

    private static void assertMessage(String expected, String text) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SpaceUrls.parse(text));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
    }
}
