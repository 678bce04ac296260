package robotworld.observe;

import java.util.Objects;
import robotworld.xvsm.XVSMModule;

/**
 * One module of a world: the participant it belongs to, its {@code <Name>} and its {@code <Class>}.
 *
 * @param participant the robot or environment
 * @param name        the module's name, unique within the participant
 * @param moduleClass e.g. {@code MotorModule}, {@code X10LampModule}
 */
public record ModuleRef(String participant, String name, String moduleClass) {

    /** Checks that nothing is null. */
    public ModuleRef {
        Objects.requireNonNull(participant, "participant");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(moduleClass, "moduleClass");
    }

    /** {@code Participant/Module}, for messages. */
    public String label() {
        return participant + "/" + name;
    }

    /** The module's REQUEST container name. */
    public String requestContainer() {
        return XVSMModule.requestContainerName(participant, name);
    }

    /** The module's ANSWER container name. */
    public String answerContainer() {
        return XVSMModule.answerContainerName(participant, name);
    }

    @Override
    public String toString() {
        return label() + " (" + moduleClass + ")";
    }
}
