package robotworld.space.wire;

import java.net.URI;

import robotworld.space.ContainerRef;

/**
 * Translates crefs between the URI a space has in-process and the public URI a server gives it on the wire, so
 * that crefs received by remote clients name the server, and crefs sent by them reach the space.
 */
public final class CrefMapping {

    /** No translation (a client, or a space whose own URI is the public one). */
    public static final CrefMapping IDENTITY = new CrefMapping(null, null);

    private final URI internal;
    private final URI external;

    private CrefMapping(URI internal, URI external) {
        this.internal = internal;
        this.external = external;
    }

    /** Maps {@code internal} (the space's own URI) to {@code external} (its public URI) and back. */
    public static CrefMapping between(URI internal, URI external) {
        return internal.equals(external) ? IDENTITY : new CrefMapping(internal, external);
    }

    /** The form to send. */
    public ContainerRef outgoing(ContainerRef ref) {
        return internal != null && ref.space().equals(internal) ? new ContainerRef(external, ref.id()) : ref;
    }

    /** The form to use after receiving. */
    public ContainerRef incoming(ContainerRef ref) {
        return external != null && ref.space().equals(external) ? new ContainerRef(internal, ref.id()) : ref;
    }
}
