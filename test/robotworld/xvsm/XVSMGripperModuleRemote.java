package robotworld.xvsm;

import robotworld.core.GripperModule;

/** Test-only: a gripper of another participant, reached through the space. */
public class XVSMGripperModuleRemote extends XVSMRemoteModule implements GripperModule {

    public XVSMGripperModuleRemote(XVSMRuntime runtime, String participant, String moduleName) {
        super(runtime, participant, moduleName);
    }

    @Override
    public void grip(int force) {
        call("grip", force);
    }

    @Override
    public int force() {
        return call("force").intAt(0);
    }
}
