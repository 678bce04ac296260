package robotworld.space;

/**
 * What a clustered space engine says about itself, for operators and tools that must know whether the loss of one
 * more member is safe (e.g. before restarting the next computer of a rolling update).
 *
 * @param members        how many members the answering member sees, itself included
 * @param backupsInPlace whether every part of the space has its backups in place, with no migration under way: until
 *                       then a crash of the member owning a part that is still moving can lose that part
 */
public record ClusterHealth(int members, boolean backupsInPlace) {
}
