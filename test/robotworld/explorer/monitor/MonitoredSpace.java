package robotworld.explorer.monitor;

import java.util.ArrayList;
import java.util.List;
import robotworld.space.Capi;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;
import robotworld.xvsm.XVSMRuntime;

/**
 * A loopback space server with separate connections per "computer": the module's host, a caller, and the
 * monitor, as on a real network.
 */
final class MonitoredSpace implements AutoCloseable {

    private final EmbeddedSpace data = EmbeddedSpace.open();
    final SpaceServer server = SpaceServer.start(data, SpaceServer.Options.defaults().port(0).stopGraceMillis(200));
    private final List<AutoCloseable> opened = new ArrayList<>();

    /** A computer with its own connection and host name. */
    XVSMRuntime host(String name) {
        XVSMRuntime runtime = XVSMRuntime.using(RemoteSpace.open(server.uri()), name, true);
        opened.add(runtime);
        return runtime;
    }

    /** Another connection, for a monitor. */
    Capi connection() {
        Capi space = RemoteSpace.open(server.uri());
        opened.add(space);
        return space;
    }

    String url() {
        return server.uri().toString();
    }

    @Override
    public void close() throws Exception {
        for (int i = opened.size() - 1; i >= 0; i--) {
            opened.get(i).close();
        }
        server.stop();
        data.close();
    }
}
