package robotworld.space.wire;

/**
 * The framed form of the operation requests, on the same port as HTTP: a client turns a connection into a framed
 * one with an HTTP/1.1 upgrade ({@code GET <path>} with {@code Connection: Upgrade}, {@code Upgrade: }{@value
 * #PROTOCOL}; the server answers {@code 101 Switching Protocols}, or answers the {@code GET} as usual if it does not
 * speak frames). From then on the connection carries operation requests and their answers as length-prefixed frames
 * instead of HTTP messages. The bodies are the same JSON as over HTTP; what goes is the HTTP request line and
 * headers, whose parsing was the largest share of the server's time per call. Layout (integers big-endian):
 *
 * <pre>
 * request  = length:u32  nameLength:u8 name  tokenLength:u16 token  acksLength:u16 acks  body
 * answer   = length:u32  status:u16  flags:u8  body
 * </pre>
 *
 * <p>{@code length} counts the bytes after itself. {@code name} is the operation (as in {@code POST
 * <path>/<name>}, printable ASCII), {@code token} the server's access token in UTF-8 or empty, {@code acks} the take
 * confirmations of the {@code Space-Ack} header or empty, {@code status} the HTTP status the same answer would have
 * had, and {@code flags} {@link #RETRY_LATER} (the {@code Retry-After: 1} of a busy or stopping answer) and {@link
 * #CLOSING} (the server closes the connection after this answer). One request at a time per connection: the next
 * one is sent once the answer has arrived, as over HTTP/1.1 without pipelining.
 */
public final class Frames {

    /** The upgrade token. */
    public static final String PROTOCOL = "rwe-frames/1";
    /** Answer flag: the client should wait a second before trying again. */
    public static final int RETRY_LATER = 1;
    /** Answer flag: the server closes the connection after this answer. */
    public static final int CLOSING = 2;
    /** The longest {@code acks} field, as the longest {@code Space-Ack} header. */
    public static final int MAX_ACKS_BYTES = 16 * 1024;
    /** The longest {@code token} field. */
    public static final int MAX_TOKEN_BYTES = 4096 * 4;
    /** Bytes of a request frame besides its body, at most. */
    public static final int MAX_REQUEST_OVERHEAD = 4 + 1 + 255 + 2 + MAX_TOKEN_BYTES + 2 + MAX_ACKS_BYTES;

    private Frames() {
    }
}
