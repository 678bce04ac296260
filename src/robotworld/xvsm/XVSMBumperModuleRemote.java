package robotworld.xvsm;

import static robotworld.xvsm.BumperTuples.ALL_BUMPERS;
import static robotworld.xvsm.BumperTuples.GET_ALL_BUMPER;
import static robotworld.xvsm.BumperTuples.GET_SINGLE_BUMPER;

import robotworld.core.BumperModule;
import robotworld.core.ModuleArguments;

/** A bumper module of another participant, reached through the space. */
public class XVSMBumperModuleRemote extends XVSMRemoteModule implements BumperModule {

    /** Connects to {@code <participant><moduleName>REQUEST}/{@code ANSWER}. */
    public XVSMBumperModuleRemote(XVSMRuntime runtime, String participant, String moduleName) {
        super(runtime, participant, moduleName);
    }

    @Override
    public int getAllBumper() {
        return BumperTuples.mask(call(GET_ALL_BUMPER, ALL_BUMPERS));
    }

    @Override
    public boolean getSingleBumper(int bumperNumber) {
        ModuleArguments.bumperNumber(bumperNumber);
        return BumperTuples.contact(call(GET_SINGLE_BUMPER, bumperNumber), bumperNumber);
    }
}
