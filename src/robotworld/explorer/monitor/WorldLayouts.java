package robotworld.explorer.monitor;

import java.util.List;
import robotworld.observe.ModuleRef;
import robotworld.observe.WorldLayout;

/** A loaded world as the {@link WorldLayout} that taps, recorders and the Foxglove endpoint watch. */
public final class WorldLayouts {

    private WorldLayouts() {
    }

    /** Participants and modules of {@code world}, in description order. */
    public static WorldLayout of(MonitoredWorld world) {
        List<WorldLayout.Participant> participants = world.participants().stream()
                .map(p -> new WorldLayout.Participant(p.name(), p.kind(), p.modules().stream()
                        .map(m -> new ModuleRef(m.participant(), m.moduleName(), m.moduleClass())).toList()))
                .toList();
        return new WorldLayout(world.name(), participants);
    }
}
