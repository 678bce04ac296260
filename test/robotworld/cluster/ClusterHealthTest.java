package robotworld.cluster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.net.URI;
import java.time.Duration;
import java.util.function.Predicate;

import com.fasterxml.jackson.databind.JsonNode;

import org.junit.jupiter.api.Test;

import robotworld.space.EmbeddedSpace;
import robotworld.space.server.SpaceServer;

/**
 * {@code GET <path>/health} of a clustered space server tells an operator how many members its member sees and whether every
 * partition has its backups in place, i.e. whether taking down another member is safe now.
 */
class ClusterHealthTest {

    @Test
    void aClusteredServerSaysHowManyMembersItSeesAndWhetherTheirBackupsAreInPlace() throws Exception {
        try (LocalCluster cluster = LocalCluster.start(3)) {
            ClusterSpace handle = cluster.member(0).openSpace("health");
            SpaceServer server = SpaceServer.start(handle, SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
            try {
                JsonNode whole = describe(server.uri(), answer -> answer.path("cluster").path("backupsInPlace")
                        .asBoolean());
                assertEquals(3, whole.path("cluster").path("members").asInt(), whole.toString());

                cluster.member(2).crash();
                // one member fewer, and once the survivors have copied the lost backups again, safe again
                JsonNode after = describe(server.uri(), answer -> answer.path("cluster").path("members").asInt() == 2
                        && answer.path("cluster").path("backupsInPlace").asBoolean());
                assertEquals(2, after.path("cluster").path("members").asInt(), after.toString());
            } finally {
                server.stop();
                handle.close();
            }
        }
    }

    @Test
    void aServerOfOneProcessHasNoClusterToDescribe() throws Exception {
        try (EmbeddedSpace space = EmbeddedSpace.open()) {
            SpaceServer server = SpaceServer.start(space, SpaceServer.Options.defaults().port(0).stopGraceMillis(100));
            try {
                JsonNode answer = get(server.uri());
                assertFalse(answer.has("cluster"), answer.toString());
                assertTrue(answer.has("space"), "it names its space: " + answer);
            } finally {
                server.stop();
            }
        }
    }

    private static JsonNode describe(URI server, Predicate<JsonNode> until) throws Exception {
        long deadline = System.nanoTime() + Duration.ofSeconds(30).toNanos();
        JsonNode answer;
        while (!until.test(answer = get(server))) {
            if (System.nanoTime() > deadline) {
                fail("the server never said so within 30 s; its last answer: " + answer);
            }
            Thread.sleep(100);
        }
        return answer;
    }

    private static JsonNode get(URI server) throws Exception {
        return HealthProbe.read(server, Duration.ofSeconds(10));
    }
}
