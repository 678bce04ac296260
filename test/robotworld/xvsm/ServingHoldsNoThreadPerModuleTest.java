package robotworld.xvsm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import robotworld.core.BumperModule;
import robotworld.space.EmbeddedSpace;
import robotworld.space.remote.RemoteSpace;
import robotworld.space.server.SpaceServer;

/**
 * A program serving many modules waits for their requests without a thread per module: its threads are the
 * small serving pool and its space client's, however many modules it serves, and every module answers.
 */
class ServingHoldsNoThreadPerModuleTest {

    private static final int MODULES = 200;

    @Test
    void twoHundredModulesAreServedByAFewThreads() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open();
             SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0));
             XVSMRuntime provider = XVSMRuntime.using(RemoteSpace.open(server.uri()), "robot-pc", true);
             XVSMRuntime caller = XVSMRuntime.using(RemoteSpace.open(server.uri()), "laptop", true)) {
            List<XVSMBumperModuleLocal> locals = new ArrayList<>();
            List<XVSMBumperModuleRemote> remotes = new ArrayList<>();
            for (int m = 0; m < MODULES; m++) {
                int mask = m & 0xFF;
                locals.add(new XVSMBumperModuleLocal(provider, "Robot", "Bumper" + m, new BumperModule() {
                    @Override
                    public int getAllBumper() {
                        return mask;
                    }

                    @Override
                    public boolean getSingleBumper(int bumperNumber) {
                        return (mask >> (bumperNumber - 1) & 1) != 0;
                    }
                }));
                remotes.add(new XVSMBumperModuleRemote(caller, "Robot", "Bumper" + m));
            }
            for (int m = MODULES - 1; m >= 0; m--) {
                assertEquals(m & 0xFF, remotes.get(m).getAllBumper(), "module " + m);
            }
            int serving = threads("xvsm-serve");
            int clients = threads("space-client");
            assertTrue(serving <= 33, MODULES + " modules, " + serving + " serving threads");
            assertTrue(clients <= 8, MODULES + " modules, " + clients + " space client threads");
            assertTrue(locals.stream().allMatch(XVSMLocalModule::isServing));
            locals.forEach(XVSMLocalModule::close);
            assertFalse(locals.stream().anyMatch(XVSMLocalModule::isServing));
            assertEquals(0, caller.space().describeContainer(locals.get(0).requestContainer()).blocked(),
                    "closing withdrew the waiting takes");
        }
    }

    private static int threads(String prefix) {
        return (int) Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().startsWith(prefix)).count();
    }
}
