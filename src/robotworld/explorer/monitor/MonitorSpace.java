package robotworld.explorer.monitor;

import robotworld.core.RuntimeSettings;
import robotworld.space.Capi;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.remote.SpaceUrls;

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
     * Connects to the space server at {@code url} (or to the servers of a clustered space, their URLs separated by
     * commas: calls fail over between them), with the token of {@code rwe.space.token} if any.
     *
     * @throws IllegalArgumentException for a URL that is not http(s), naming it
     * @throws robotworld.space.SpaceException when no server can be reached
     */
    public static Capi open(String url) {
        return RemoteSpace.open(SpaceUrls.parse(url),
                RemoteSpace.Options.defaults().token(RuntimeSettings.fromSystem().spaceToken()));
    }
}
