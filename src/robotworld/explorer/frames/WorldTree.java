package robotworld.explorer.frames;

import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import robotworld.explorer.monitor.MonitoredModule;
import robotworld.explorer.monitor.MonitoredParticipant;
import robotworld.explorer.monitor.MonitoredWorld;

/** The tree of a world as the generate frame shows it (thesis figure 4.4): participants, then their modules. */
final class WorldTree {

    private WorldTree() {
    }

    static DefaultTreeModel of(MonitoredWorld world) {
        DefaultMutableTreeNode root = new DefaultMutableTreeNode(world.name() + " (" + world.communicationType() + ")");
        for (MonitoredParticipant participant : world.participants()) {
            DefaultMutableTreeNode node = new DefaultMutableTreeNode(participant.name() + " - "
                    + (participant.kind().equals("robot") ? "Robot" : "Environment"));
            for (MonitoredModule module : participant.modules()) {
                node.add(new DefaultMutableTreeNode(module.moduleName() + " (" + module.moduleClass() + ")"));
            }
            root.add(node);
        }
        return new DefaultTreeModel(root);
    }

    static DefaultTreeModel empty() {
        return new DefaultTreeModel(new DefaultMutableTreeNode("no world loaded"));
    }
}
