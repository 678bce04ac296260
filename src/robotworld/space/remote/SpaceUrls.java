package robotworld.space.remote;

import java.net.URI;
import java.net.URISyntaxException;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * The servers of one space as written by users: one URL, or the URLs of several servers of the same space (the
 * members of a cluster) separated by commas, e.g. {@code http://a:9876/space,http://b:9876/space}. The same text
 * goes in a world's {@code <SpaceURL>}, {@code -Drwe.space.url}, {@code RWE_SPACE_URL} and {@code --space}.
 */
public final class SpaceUrls {

    /** More servers than any cluster a client should list; stops a runaway value early. */
    public static final int MAX_URLS = 32;

    private SpaceUrls() {
    }

    /**
     * The URLs in {@code text}, in the order written (a client tries them in that order), each checked.
     *
     * @throws IllegalArgumentException naming the bad URL: not http(s), no host, empty between commas, written
     *                                  twice, or more than {@link #MAX_URLS}
     */
    public static List<URI> parse(String text) {
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("no space URL given (e.g. http://127.0.0.1:9876/space)");
        }
        String[] parts = text.split(",", -1);
        if (parts.length > MAX_URLS) {
            throw new IllegalArgumentException("at most " + MAX_URLS + " space URLs, not " + parts.length);
        }
        Set<URI> urls = new LinkedHashSet<>();
        for (String part : parts) {
            URI url = one(part.strip(), text);
            if (!urls.add(url)) {
                throw new IllegalArgumentException("the space URL " + url + " is listed twice in '" + text + "'");
            }
        }
        return new ArrayList<>(urls);
    }

    private static URI one(String text, String whole) {
        if (text.isEmpty()) {
            throw new IllegalArgumentException("an empty space URL in '" + whole
                    + "': separate several servers' URLs with single commas");
        }
        URI url;
        try {
            url = new URI(text);
        } catch (URISyntaxException e) {
            throw new IllegalArgumentException("the space URL '" + text + "' is not a URL: " + e.getReason(), e);
        }
        String scheme = url.getScheme() == null ? "" : url.getScheme().toLowerCase(Locale.ROOT);
        if (!scheme.equals("http") && !scheme.equals("https")) {
            throw new IllegalArgumentException("a space URL is http:// or https:// (e.g. "
                    + "http://127.0.0.1:9876/space), was '" + text + "'");
        }
        if (url.getHost() == null) {
            throw new IllegalArgumentException("the space URL '" + text + "' names no host (e.g. "
                    + "http://127.0.0.1:9876/space)");
        }
        return url;
    }
}
