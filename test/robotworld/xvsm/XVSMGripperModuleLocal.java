package robotworld.xvsm;

import java.util.List;
import robotworld.core.GripperModule;
import robotworld.space.Entry;

/** Test-only: a gripper attached to this computer, shared through the space as {@code <key, [force], fn>}. */
public class XVSMGripperModuleLocal extends XVSMLocalModule<GripperModule> implements GripperModule {

    public XVSMGripperModuleLocal(XVSMRuntime runtime, String participant, String moduleName, GripperModule hardware) {
        super(runtime, participant, moduleName, hardware);
        start();
    }

    @Override
    public void grip(int force) {
        callLocally("grip", force);
    }

    @Override
    public int force() {
        return callLocally("force").intAt(0);
    }

    @Override
    protected List<Entry> perform(CallTuple request) {
        if (request.is("grip")) {
            hardware().grip(request.expectFields(1).intAt(0));
            return request.fields();
        }
        if (request.is("force")) {
            return List.of(Entry.of(hardware().force()));
        }
        throw request.unknownFunction();
    }
}
