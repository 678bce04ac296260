package robotworld.explorer.monitor;

import java.net.URI;
import robotworld.core.RuntimeSettings;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;

/** Opens the space a monitor watches: an explicit URL, else the override or the world's {@code <SpaceURL>}. */
public final class MonitorSpace {

    private MonitorSpace() {
    }

    /**
     * The URL to watch: {@code explicit} if given, else {@code rwe.space.url} / {@code RWE_SPACE_URL}, else the
     * world's.
     *
     * @throws IllegalStateException when none is set
     */
    public static String url(String explicit, MonitoredWorld world) {
        if (explicit != null && !explicit.isBlank()) {
            return explicit.strip();
        }
        return RuntimeSettings.fromSystem().spaceUrl(world.spaceUrl());
    }

    /**
     * Connects to the space server at {@code url}, with the token of {@code rwe.space.token} if any.
     *
     * @throws IllegalArgumentException for a URL that is not http(s)
     * @throws robotworld.space.SpaceException when the server cannot be reached
     */
    public static Capi open(String url) {
        URI uri = URI.create(url);
        if (!"http".equals(uri.getScheme()) && !"https".equals(uri.getScheme())) {
            throw new IllegalArgumentException("a space URL is http:// or https://, not " + url);
        }
        return RemoteSpace.open(uri, RemoteSpace.Options.defaults().token(RuntimeSettings.fromSystem().spaceToken()));
    }
}
