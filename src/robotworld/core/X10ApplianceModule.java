package robotworld.core;

/**
 * An X10 appliance module: a switched socket in the environment, addressed by house code and unit code.
 * X10 modules report nothing back, so a call returns once the command has gone out on the power line.
 * Implementations signal a failed command with an unchecked exception.
 */
public interface X10ApplianceModule {

    /** Switches the appliance on. */
    void on();

    /** Switches the appliance off. */
    void off();
}
