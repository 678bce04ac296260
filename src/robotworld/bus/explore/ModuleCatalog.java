package robotworld.bus.explore;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.regex.Pattern;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.ModuleDescriptionType;

/**
 * The module descriptions in a folder ({@code ModuleDescriptions/<NodeID>.xml}), looked up by the NodeID a
 * module reports. A NodeID comes from the bus, so it is checked against the schema's pattern before it becomes
 * part of a file name.
 */
public final class ModuleCatalog {

    /** The NodeID pattern of the schema (Types.xsd, NodeIdType). */
    private static final Pattern NODE_ID = Pattern.compile("[A-Za-z0-9][A-Za-z0-9_\\-]{0,31}");

    private final Path folder;
    private final Map<String, ModuleDescriptionType> loaded = new ConcurrentHashMap<>();

    public ModuleCatalog(Path folder) {
        this.folder = folder;
    }

    /** The folder searched. */
    public Path folder() {
        return folder;
    }

    /**
     * The description of a NodeID.
     *
     * @return empty when there is no such file (an unknown module model)
     * @throws DescriptionException when the file exists but is invalid, or names another NodeID
     * @throws IllegalArgumentException when {@code nodeId} is not a valid NodeID
     */
    public Optional<ModuleDescriptionType> lookUp(String nodeId) throws DescriptionException {
        if (!NODE_ID.matcher(nodeId).matches()) {
            throw new IllegalArgumentException("'" + nodeId + "' is not a valid NodeID");
        }
        ModuleDescriptionType cached = loaded.get(nodeId);
        if (cached != null) {
            return Optional.of(cached);
        }
        Path file = fileOf(nodeId);
        if (!Files.isRegularFile(file)) {
            return Optional.empty();
        }
        ModuleDescriptionType description = DescriptionLoader.loadModuleDescription(file).getModuleDescription();
        if (!description.getNodeID().equals(nodeId)) {
            throw new DescriptionException(new robotworld.description.DescriptionError(file.toString(), 0, 0,
                    "describes NodeID '" + description.getNodeID() + "', but the file is named for '" + nodeId + "'"));
        }
        loaded.put(nodeId, description);
        return Optional.of(description);
    }

    /** Where the description of {@code nodeId} would be. */
    public Path fileOf(String nodeId) {
        return folder.resolve(nodeId + ".xml");
    }
}
