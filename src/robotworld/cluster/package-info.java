/**
 * The space kept by a cluster of members, so that no single process is a point of failure: each member is an
 * embedded Hazelcast member (community edition) holding a share of the containers and backups of others, and a
 * {@link robotworld.cluster.ClusterSpace} opened on any member is a {@link robotworld.space.Capi} with the
 * semantics of the embedded space. Start one with {@link robotworld.cluster.ClusterMember#start}. User guide:
 * {@code docs/cluster.md}.
 *
 * <h2>Contract</h2>
 * <ul>
 * <li><b>Same semantics.</b> Containers, entries, orders, views, templates, naming, blocking, fairness and
 * notifications behave as {@link robotworld.space.EmbeddedSpace} documents (the same contract test suite runs
 * against a 3-member cluster, each call of a test on the next member). Handles on different members see one space;
 * crefs name it ({@code cluster:<cluster>/<space>}) and work on every member.</li>
 * <li><b>Linearizable per container</b> while the space serves: every call on a container runs on the member that
 * owns the container's partition, on that partition's thread, one call at a time, and is answered only after every
 * synchronous backup ({@link robotworld.cluster.ClusterOptions#backups()}, 1 by default) applied it. Calls on
 * different containers are independent, as in the embedded space.</li>
 * <li><b>Bounded calls.</b> A call returns within its timeout plus {@link
 * robotworld.cluster.ClusterOptions#callAllowance()} (3 s); when the cluster cannot answer in that time it fails
 * with {@link robotworld.space.SpaceUnavailableException}. A call the cluster repeats after a member's failure takes
 * effect at most once.</li>
 * <li><b>One member failing</b> (crash, kill, cable pulled) loses nothing that was acknowledged: the backups take
 * over the failed member's containers, with their entries, orders, keys, positions, blocked operations and
 * subscriptions. Operations blocked by threads on surviving members go on waiting and are served; the failed
 * member's own blocked operations and subscriptions are dropped, and whatever the container had already handed to
 * its threads but they had not yet collected is put back (a take's entries return to where they were).</li>
 * <li><b>Notifications never stop silently.</b> A subscription on a surviving member either goes on with every
 * notification, in order (events a failed member did not pass on are read from the container's journal), or ends
 * with {@link robotworld.space.SubscriptionEnd#OVERFLOWED}, after an unbroken prefix, when the journal
 * ({@link robotworld.cluster.ClusterOptions#journalCapacity()} events per container) no longer holds what is
 * missing.</li>
 * <li><b>Too few members refuse.</b> With fewer members in sight than {@link
 * robotworld.cluster.ClusterOptions#effectiveMinimumMembers()} (a majority by default), calls fail with
 * {@link robotworld.space.SpaceUnavailableException} instead of going on alone.</li>
 * </ul>
 *
 * <h2>What it does not promise</h2>
 * <ul>
 * <li>Hazelcast's community edition is an AP system. During a network split, the side that has too few members
 * refuses once it notices the split (within {@link robotworld.cluster.ClusterOptions#failureDetection()}); calls it
 * acknowledged before noticing are discarded when the split heals, because the larger side's containers win the
 * merge. A split into equal halves leaves no side serving.</li>
 * <li>Two members failing at once lose the containers whose owner and only backup they were (raise
 * {@code backups} to survive more).</li>
 * <li>A restart of the whole cluster keeps nothing: the space lives in the members' memory only.</li>
 * <li>A thread on a member that fails, fails with it: an entry it had already received is gone with it, as with an
 * embedded space in a process that dies.</li>
 * <li>Subscription timeouts and the order between a notification and a later call are judged on the member where
 * the subscription was made, when the notification arrives there.</li>
 * </ul>
 *
 * <h2>Design</h2>
 * <ul>
 * <li><b>One map entry per container</b> ({@link robotworld.cluster.ContainerRecord} in the map
 * {@code rwe.containers.<space>}, stored as objects): the entries with every index (shared with the embedded engine
 * through {@link robotworld.space.internal.ContainerContents}), the queue of blocked operations, results served but
 * not yet collected, the subscriptions, a journal of recent events and the outcomes of recent calls. Names live in
 * {@code rwe.names.<space>}.</li>
 * <li><b>Every call is an entry processor</b> ({@link robotworld.cluster.ContainerCall}) on the owner. It logs each
 * change it makes ({@link robotworld.cluster.Change}); the backups replay exactly those changes, so no decision (a
 * random choice, the clock) is taken twice and the container is never copied whole on a call. It remembers its
 * outcome under its call id, so a call Hazelcast repeats on the new owner after the old one died returns the first
 * outcome instead of applying twice.</li>
 * <li><b>Blocked operations</b> are queued in the container and retried, oldest first, by every call that changes
 * it (the embedded engine's rule). The waiting thread sleeps on its own member. The call that serves it reports a
 * wake-up, which the serving call's member passes on ({@link robotworld.cluster.MemberMessage}); the woken thread
 * collects its result from the container. A timed-out, interrupted or closed wait withdraws its operation, unless
 * it was served meanwhile: then it gets the result. Threads also look by themselves every 1 to 5 s, and at once
 * when a member leaves, so a lost wake-up delays an operation but never loses it. The timers of waits (deadlines,
 * looks) have threads of their own that never call the cluster: a member's background work (clearing a departed
 * member, sweeps, reading journals) can block for seconds while the cluster recovers, and runs on other threads.</li>
 * <li><b>Notifications</b>: while a container has subscriptions, each operation that affected entries is journaled
 * as an event naming its predecessor and passed on to the members with subscriptions. Each member's
 * {@link robotworld.cluster.EventInbox} puts events back in order, reads missing ones from the journal, and hands
 * them to the subscriptions, which deliver them like the embedded space (modes, timeouts, bounded queue).</li>
 * <li><b>Members leaving</b>: the oldest member clears the departed member's queued operations, uncollected results
 * (put back) and subscriptions from every container.</li>
 * <li><b>Configuration</b> ({@link robotworld.cluster.HazelcastSetup}): an explicit member list over TCP (no
 * multicast, no discovery), bound to one address, no phoning home, split-brain protection by member count,
 * {@code PutIfAbsent} merges, and every value in its own binary encoding ({@link robotworld.cluster.Codec}); Java
 * deserialization only for Hazelcast's and the JDK's own classes.</li>
 * </ul>
 */
package robotworld.cluster;
