package robotworld.core;

/**
 * A module type that exists only in the test sources. With its hardware proxy, XVSM proxies and a schema
 * value it proves that adding a module type needs no change to existing code.
 */
public interface GripperModule {

    /** Closes the gripper with {@code force} (0 = open .. 100). */
    void grip(int force);

    /** The force currently applied. */
    int force();
}
