package robotworld.cluster;

import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentMap;

import com.hazelcast.config.Config;
import com.hazelcast.config.ExecutorConfig;
import com.hazelcast.config.InMemoryFormat;
import com.hazelcast.config.JavaSerializationFilterConfig;
import com.hazelcast.config.JoinConfig;
import com.hazelcast.config.MapConfig;
import com.hazelcast.config.MergePolicyConfig;
import com.hazelcast.config.NetworkConfig;
import com.hazelcast.config.SplitBrainProtectionConfig;
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
    /** Executor that carries {@link MemberMessage}s. */
    static final String MESSAGES = "rwe.messages";
    static final String SPLIT_BRAIN_PROTECTION = "rwe.majority";

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
        config.setProperty("hazelcast.heartbeat.interval.seconds", "1");
        config.setProperty("hazelcast.max.no.heartbeat.seconds",
                Long.toString(options.failureDetection().toSeconds()));
        config.setProperty("hazelcast.invocation.retry.pause.millis", "100");
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
        config.addExecutorConfig(new ExecutorConfig(MESSAGES).setPoolSize(4).setStatisticsEnabled(false));
        return config;
    }
}
