package robotworld.cluster;

import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentMap;

import com.hazelcast.config.Config;
import com.hazelcast.config.InMemoryFormat;
import com.hazelcast.config.JavaSerializationFilterConfig;
import com.hazelcast.config.JoinConfig;
import com.hazelcast.config.ListenerConfig;
import com.hazelcast.config.MapConfig;
import com.hazelcast.config.MergePolicyConfig;
import com.hazelcast.config.NetworkConfig;
import com.hazelcast.config.SplitBrainProtectionConfig;
import com.hazelcast.config.TopicConfig;
import com.hazelcast.spi.merge.PutIfAbsentMergePolicy;
import com.hazelcast.splitbrainprotection.SplitBrainProtectionOn;

/**
 * The Hazelcast configuration of a space member, built in code from {@link ClusterOptions} (no XML, nothing read
 * from the environment): an explicit member list, no multicast or discovery, no phoning home, our own binary
 * serialization, containers stored as objects with synchronous backups and majority split-brain protection.
 */
final class HazelcastSetup {

    /** Map of one space's containers: {@code rwe.containers.<space>}. */
    static final String CONTAINERS = "rwe.containers.";
    /** Map of one space's names: {@code rwe.names.<space>}. */
    static final String NAMES = "rwe.names.";
    /** Topic of one member, {@code rwe.member.<uuid>}: carries {@link MemberMessage}s to that member only. */
    static final String MEMBER_TOPIC = "rwe.member.";
    static final String SPLIT_BRAIN_PROTECTION = "rwe.majority";
    /** How long a change waits for its backups to confirm it (Hazelcast checks once a second). */
    static final long BACKUP_ANSWER_MILLIS = 500;

    private HazelcastSetup() {
    }

    static Config config(ClusterOptions options) {
        Config config = new Config();
        config.setClusterName(options.clusterName());
        ConcurrentMap<String, Object> userContext = new ConcurrentHashMap<>();
        config.setUserContext(userContext);

        // quiet, private, and quick to notice a departed member
        config.setProperty("hazelcast.phone.home.enabled", "false");
        config.setProperty("hazelcast.logging.type", "slf4j");
        config.setProperty("hazelcast.shutdownhook.enabled", "false");
        config.setProperty("hazelcast.health.monitoring.level", "OFF");
        config.setProperty("hazelcast.wait.seconds.before.join", "1");
        config.setProperty("hazelcast.socket.bind.any", "false");
        if (PartitionMovesLog.wanted()) {
            config.addListenerConfig(new ListenerConfig(new PartitionMovesLog()));
        }
        config.setProperty("hazelcast.heartbeat.interval.seconds", "1");
        config.setProperty("hazelcast.max.no.heartbeat.seconds",
                Long.toString(options.failureDetection().toSeconds()));
        config.setProperty("hazelcast.invocation.retry.pause.millis", "100");
        // a member whose connection broke and that refuses a new one twice (100 ms apart) is suspected dead at once:
        // a crashed process, not a slow one (a slow member keeps its connections); Hazelcast waits for three
        config.setProperty("hazelcast.connection.monitor.max.faults", "2");
        // a call whose owner stays silent this long fails (and is repeated, at most once in effect)
        config.setProperty("hazelcast.operation.call.timeout.millis",
                Long.toString(Math.max(1_000, options.callAllowance().toMillis())));
        // a change whose backup went to a member that had just died waits this long for the backup's answer, then
        // stands (Hazelcast repairs the backup from the owner): the default 5 s held such calls, and so whole modules,
        // for 5 s after a member's crash, in the short window before the survivors have a new partition table
        config.setProperty("hazelcast.operation.backup.timeout.millis", Long.toString(BACKUP_ANSWER_MILLIS));
        config.setProperty("hazelcast.merge.first.run.delay.seconds", "5");
        config.setProperty("hazelcast.merge.next.run.delay.seconds", "5");

        NetworkConfig network = config.getNetworkConfig();
        network.setPort(options.port()).setPortAutoIncrement(false);
        network.getInterfaces().setEnabled(true).addInterface(options.bindAddress());
        JoinConfig join = network.getJoin();
        join.getMulticastConfig().setEnabled(false);
        join.getAutoDetectionConfig().setEnabled(false);
        join.getTcpIpConfig().setEnabled(true).setMembers(options.members());

        config.getSerializationConfig()
                .addDataSerializableFactory(ClusterSerialization.FACTORY_ID, new ClusterSerialization())
                // Java serialization only for Hazelcast's own and the JDK's classes (e.g. exceptions in answers)
                .setJavaSerializationFilterConfig(new JavaSerializationFilterConfig());

        config.addSplitBrainProtectionConfig(new SplitBrainProtectionConfig(SPLIT_BRAIN_PROTECTION, true,
                options.effectiveMinimumMembers()).setProtectOn(SplitBrainProtectionOn.READ_WRITE));
        // after a split heals, the side that merges in (the smaller one) keeps only what the other side lacks
        MergePolicyConfig merge = new MergePolicyConfig(PutIfAbsentMergePolicy.class.getName(),
                MergePolicyConfig.DEFAULT_BATCH_SIZE);
        config.addMapConfig(new MapConfig(CONTAINERS + "*")
                .setInMemoryFormat(InMemoryFormat.OBJECT)
                .setBackupCount(options.backups())
                .setAsyncBackupCount(0)
                .setStatisticsEnabled(false)
                .setPerEntryStatsEnabled(false)
                .setSplitBrainProtectionName(SPLIT_BRAIN_PROTECTION)
                .setMergePolicyConfig(merge));
        config.addMapConfig(new MapConfig(NAMES + "*")
                .setBackupCount(options.backups())
                .setAsyncBackupCount(0)
                .setStatisticsEnabled(false)
                .setSplitBrainProtectionName(SPLIT_BRAIN_PROTECTION)
                .setMergePolicyConfig(merge));
        config.addTopicConfig(new TopicConfig(MEMBER_TOPIC + "*").setStatisticsEnabled(false));
        return config;
    }
}
