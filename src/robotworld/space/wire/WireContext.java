package robotworld.space.wire;

import java.io.OutputStream;

import com.fasterxml.jackson.core.JsonFactory;

/**
 * What one side of a connection needs to read and write messages: the JSON factory (thread-safe, with the
 * parser limits), the limits, and the cref translation.
 *
 * @param factory shared JSON factory, see {@link Wire#factory}
 * @param limits  the message limits
 * @param crefs   how crefs are translated on the way in and out
 */
public record WireContext(JsonFactory factory, WireLimits limits, CrefMapping crefs) {

    /** A context with a factory made for {@code limits}. */
    public static WireContext of(WireLimits limits, CrefMapping crefs) {
        return new WireContext(Wire.factory(limits), limits, crefs);
    }

    /** A reader over part of a byte array. */
    public WireReader reader(byte[] data, int offset, int length) {
        return WireReader.of(factory, limits, crefs, data, offset, length);
    }

    /** A writer onto a stream. */
    public WireWriter writer(OutputStream out) {
        return WireWriter.to(factory, crefs, out);
    }
}
