package robotworld.space.internal;

/** Called per node during a scan; returns whether to go on. */
@FunctionalInterface
interface NodeVisitor {
    boolean visit(Node node);
}
