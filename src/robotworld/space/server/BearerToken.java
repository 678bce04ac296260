package robotworld.space.server;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;

/**
 * The optional shared secret of a server. Requests must carry {@code Authorization: Bearer <token>}; the
 * comparison takes the same time wherever the first difference is, so timing does not leak the token.
 */
final class BearerToken {

    private static final String PREFIX = "Bearer ";

    private final byte[] expected;

    BearerToken(String token) {
        if (token.isBlank() || !token.strip().equals(token) || token.length() > 4096) {
            throw new IllegalArgumentException("a token must be non-blank, without surrounding spaces, at most 4096 chars");
        }
        this.expected = (PREFIX + token).getBytes(StandardCharsets.UTF_8);
    }

    /** Whether {@code token} (sent without the header's "Bearer ", as in a request frame) is the token. */
    boolean acceptsToken(String token) {
        return accepts(PREFIX + token);
    }

    /** Whether an {@code Authorization} header value (possibly null) carries the token. */
    boolean accepts(String authorization) {
        if (authorization == null) {
            return false;
        }
        // MessageDigest.isEqual is constant-time for equal lengths; the length itself is not secret enough to hide
        return MessageDigest.isEqual(expected, authorization.getBytes(StandardCharsets.UTF_8));
    }
}
