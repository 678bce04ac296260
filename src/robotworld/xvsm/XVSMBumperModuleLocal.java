package robotworld.xvsm;

import static robotworld.xvsm.BumperTuples.ALL_BUMPERS;
import static robotworld.xvsm.BumperTuples.GET_ALL_BUMPER;
import static robotworld.xvsm.BumperTuples.GET_SINGLE_BUMPER;

import java.util.List;
import java.util.function.Supplier;
import robotworld.core.BumperModule;
import robotworld.core.ModuleArguments;
import robotworld.space.Entry;

/**
 * A bumper module attached to this computer, shared through the space. Requests {@code <key, bumperNr|0,
 * function>}; answers {@code <key, mask, "getAllBumper">} and {@code <key, <bumperNr, 0|1>, "getSingleBumper">}.
 * With adaptive batching, all waiting requests are answered from one read of all bumpers.
 */
public class XVSMBumperModuleLocal extends XVSMSensorLocalModule<BumperModule> implements BumperModule {

    /** Serves with the runtime's default batching ({@code rwe.sensor.batching}). */
    public XVSMBumperModuleLocal(XVSMRuntime runtime, String participant, String moduleName, BumperModule hardware) {
        this(runtime, participant, moduleName, hardware, runtime.adaptiveBatchingByDefault());
    }

    /** Serves with adaptive batching on or off. */
    public XVSMBumperModuleLocal(XVSMRuntime runtime, String participant, String moduleName, BumperModule hardware,
                                 boolean adaptiveBatching) {
        super(runtime, participant, moduleName, hardware, adaptiveBatching);
        start();
    }

    @Override
    public int getAllBumper() {
        return BumperTuples.mask(callLocally(GET_ALL_BUMPER, ALL_BUMPERS));
    }

    @Override
    public boolean getSingleBumper(int bumperNumber) {
        ModuleArguments.bumperNumber(bumperNumber);
        return BumperTuples.contact(callLocally(GET_SINGLE_BUMPER, bumperNumber), bumperNumber);
    }

    @Override
    protected List<Entry> perform(CallTuple request) {
        request.expectFields(1);
        if (request.is(GET_ALL_BUMPER)) {
            return BumperTuples.maskAnswer(hardware().getAllBumper());
        }
        if (request.is(GET_SINGLE_BUMPER)) {
            int bumper = request.intAt(0);
            return BumperTuples.contactAnswer(bumper, hardware().getSingleBumper(bumper));
        }
        throw request.unknownFunction();
    }

    /** Every answer of a batch from one read of all bumpers. */
    @Override
    protected Performer batchPerformer() {
        Supplier<Integer> mask = readOnce(hardware()::getAllBumper);
        return request -> {
            request.expectFields(1);
            if (request.is(GET_ALL_BUMPER)) {
                return BumperTuples.maskAnswer(mask.get());
            }
            if (request.is(GET_SINGLE_BUMPER)) {
                int bumper = ModuleArguments.bumperNumber(request.intAt(0));
                return BumperTuples.contactAnswer(bumper, (mask.get() & 1 << bumper - 1) != 0);
            }
            throw request.unknownFunction();
        };
    }
}
