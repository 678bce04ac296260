package robotworld.xvsm;

import static robotworld.xvsm.X10Tuples.BRIGHTEN;
import static robotworld.xvsm.X10Tuples.DIM;
import static robotworld.xvsm.X10Tuples.NO_LEVEL;
import static robotworld.xvsm.X10Tuples.OFF;
import static robotworld.xvsm.X10Tuples.ON;

import robotworld.core.X10LampModule;

/** An X10 lamp module of another participant, reached through the space; calls return once the command is sent. */
public class XVSMX10LampModuleRemote extends XVSMRemoteModule implements X10LampModule {

    /** Connects to {@code <participant><moduleName>REQUEST}/{@code ANSWER}. */
    public XVSMX10LampModuleRemote(XVSMRuntime runtime, String participant, String moduleName) {
        super(runtime, participant, moduleName);
    }

    @Override
    public void brighten(int level) {
        call(BRIGHTEN, X10Tuples.level(level));
    }

    @Override
    public void dim(int level) {
        call(DIM, X10Tuples.level(level));
    }

    @Override
    public void on() {
        call(ON, NO_LEVEL);
    }

    @Override
    public void off() {
        call(OFF, NO_LEVEL);
    }
}
