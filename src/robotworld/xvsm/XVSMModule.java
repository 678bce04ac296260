package robotworld.xvsm;

import java.util.Objects;
import robotworld.space.ContainerRef;

/**
 * What every module proxy that shares a module through the space has (thesis table 2): the runtime with its
 * space connection, the host name of this computer, the module's participant and name, and the module's two
 * containers {@code <Participant><Module>REQUEST} and {@code <Participant><Module>ANSWER}, looked up or created
 * on construction. {@link XVSMLocalModule} serves the module on the computer that has the hardware (waiting for
 * requests without a thread); {@link XVSMRemoteModule} calls it from anywhere else.
 *
 * <p>A proxy registers itself with its runtime, so closing the runtime closes it.
 */
public abstract class XVSMModule implements AutoCloseable {

    /** Suffix of the request container's name. */
    public static final String REQUEST_SUFFIX = "REQUEST";
    /** Suffix of the answer container's name. */
    public static final String ANSWER_SUFFIX = "ANSWER";

    private final XVSMRuntime runtime;
    private final String participant;
    private final String moduleName;
    private final String requestName;
    private final String answerName;
    final ModuleContainers containers;

    /**
     * Looks up or creates the module's containers and registers with the runtime.
     *
     * @param participant the robot or environment the module belongs to, as named in the RobotWorld
     * @param moduleName  the module's name in the description
     * @throws robotworld.space.SpaceException when the space cannot be reached
     */
    protected XVSMModule(XVSMRuntime runtime, String participant, String moduleName) {
        this.runtime = Objects.requireNonNull(runtime, "runtime");
        this.participant = requireName(participant, "participant");
        this.moduleName = requireName(moduleName, "module name");
        this.requestName = requestContainerName(participant, moduleName);
        this.answerName = answerContainerName(participant, moduleName);
        this.containers = new ModuleContainers(runtime.moduleSpace(), requestName, answerName);
        runtime.register(this);
    }

    /** {@code <participant><moduleName>REQUEST}. */
    public static String requestContainerName(String participant, String moduleName) {
        return participant + moduleName + REQUEST_SUFFIX;
    }

    /** {@code <participant><moduleName>ANSWER}: the container monitors subscribe to. */
    public static String answerContainerName(String participant, String moduleName) {
        return participant + moduleName + ANSWER_SUFFIX;
    }

    /** The runtime this proxy runs in. */
    public XVSMRuntime runtime() {
        return runtime;
    }

    /** The participant the module belongs to. */
    public String participant() {
        return participant;
    }

    /** The module's name in the description. */
    public String moduleName() {
        return moduleName;
    }

    /** This computer's host name (the key of its requests and of its published local calls). */
    public String hostName() {
        return runtime.hostName();
    }

    /** The name of the REQUEST container. */
    public String requestName() {
        return requestName;
    }

    /** The name of the ANSWER container. */
    public String answerName() {
        return answerName;
    }

    /** The REQUEST container as last looked up. */
    public ContainerRef requestContainer() {
        return containers.requests();
    }

    /** The ANSWER container as last looked up. */
    public ContainerRef answerContainer() {
        return containers.answers();
    }

    /** Stops using the space for this module; idempotent. Never closes the hardware. */
    @Override
    public abstract void close();

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[" + participant + "/" + moduleName + " on host " + hostName() + "]";
    }

    private static String requireName(String name, String what) {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("the " + what + " must not be blank");
        }
        return name;
    }
}
