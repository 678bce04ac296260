package robotworld.explorer.generator;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.xml.namespace.QName;
import org.apache.xmlbeans.XmlCursor;
import org.apache.xmlbeans.XmlObject;
import robotworld.description.DescriptionKind;
import robotworld.description.EnvModuleListType;
import robotworld.description.JavaNames;
import robotworld.description.ModuleClassName;
import robotworld.description.ModuleListType;
import robotworld.description.ModuleType;
import robotworld.description.RobotWorldDocument;
import robotworld.description.RobotWorldType;
import robotworld.description.X10ModuleType;

/**
 * The world as the stylesheets see it: a copy of the validated description into which the generator inserted
 * the viewpoint ({@code <Viewpoint>}), the package ({@code <PackageName>}) and, on every module, its
 * world-unique field name as attribute {@code gen:field}: {@code <Class><n>}, numbered per class in document
 * order across the whole world (so the third motor module anywhere is {@code MotorModule3}).
 */
public final class PreparedWorld {

    static final String EXTERNAL = "external";

    private final RobotWorldDocument document;
    private final String viewpoint;
    private final String packageName;
    /** Participant name to the Java class written for it, in document order. */
    private final Map<String, String> classes = new LinkedHashMap<>();
    private ModulePages pages;

    private PreparedWorld(RobotWorldDocument document, String viewpoint, String packageName) {
        this.document = document;
        this.viewpoint = viewpoint;
        this.packageName = packageName;
    }

    public static PreparedWorld of(RobotWorldDocument loaded, String viewpoint, String requestedPackage)
            throws GenerationException {
        RobotWorldDocument copy = (RobotWorldDocument) loaded.copy();
        RobotWorldType world = copy.getRobotWorld();
        List<String> participants = participantNames(world);
        if (!EXTERNAL.equals(viewpoint) && !participants.contains(viewpoint)) {
            throw new GenerationException("unknown viewpoint '" + viewpoint + "': choose one of " + participants
                    + " or " + EXTERNAL);
        }
        boolean none = "none".equals(world.getCommunicationType().toString());
        if (none && EXTERNAL.equals(viewpoint)) {
            throw new GenerationException("communication type none has no external viewpoint: a program without"
                    + " a space can only drive the hardware of its own participant");
        }
        String packageName = choosePackage(world, requestedPackage);
        PreparedWorld prepared = new PreparedWorld(copy, viewpoint, packageName);
        world.setPackageName(packageName);
        insertViewpoint(world, viewpoint);
        nameFields(world);
        prepared.pages = ModulePages.resolve(world, ModulePages.defaultRoot());
        for (String participant : participants) {
            if (!none || participant.equals(viewpoint)) {
                prepared.classes.put(participant, participant);
            }
        }
        if (EXTERNAL.equals(viewpoint)) {
            prepared.classes.put(EXTERNAL, externalClassName(world.getWorldName(), participants));
        }
        return prepared;
    }

    /** The module pages the project gathers: project path ({@code docs/modules/...}) to the file to copy. */
    public Map<String, java.nio.file.Path> pageCopies() {
        return pages.copies();
    }

    /** The text of {@code docs/index.md}: every module with its field name and page. */
    public String pageIndex() {
        return pages.index(document.getRobotWorld().getWorldName(), viewpoint);
    }

    public RobotWorldDocument document() {
        return document;
    }

    public String communicationType() {
        return document.getRobotWorld().getCommunicationType().toString();
    }

    public String viewpoint() {
        return viewpoint;
    }

    public String packageName() {
        return packageName;
    }

    /** The class holding main: the viewpoint participant's, or the external program's. */
    public String mainClass() {
        return classes.get(viewpoint);
    }

    /** Participant (or {@value #EXTERNAL}) to class name, for every class to write. */
    public Map<String, String> classes() {
        return classes;
    }

    private static List<String> participantNames(RobotWorldType world) {
        List<String> names = new ArrayList<>();
        for (EnvModuleListType environment : world.getEnvironmentArray()) {
            names.add(environment.getEnvironmentName());
        }
        for (ModuleListType robot : world.getRobotDescriptionArray()) {
            names.add(robot.getRobotName());
        }
        return names;
    }

    private static String choosePackage(RobotWorldType world, String requested) throws GenerationException {
        String name = requested != null && !requested.isBlank() ? requested.strip()
                : world.isSetPackageName() ? world.getPackageName() : JavaNames.defaultPackageName(world.getWorldName());
        String problem = JavaNames.problemWithPackageName(name);
        if (problem != null) {
            throw new GenerationException("'" + name + "' is not a valid Java package name: it " + problem);
        }
        return name;
    }

    private static String externalClassName(String worldName, List<String> participants) {
        String name = worldName + "External";
        // class names are file names: on Windows and macOS, DimRoomExternal.java and dimroomexternal.java clash
        while (participants.stream().anyMatch(name::equalsIgnoreCase)) {
            name = name + "Program";
        }
        return name;
    }

    private static void insertViewpoint(RobotWorldType world, String viewpoint) {
        try (XmlCursor cursor = world.xgetPackageName().newCursor()) {
            cursor.toEndToken();
            cursor.toNextToken();
            cursor.insertElementWithText(new QName(DescriptionKind.NAMESPACE, "Viewpoint"), viewpoint);
        }
    }

    private static void nameFields(RobotWorldType world) {
        Map<String, Integer> perClass = new HashMap<>();
        for (EnvModuleListType environment : world.getEnvironmentArray()) {
            for (X10ModuleType module : environment.getX10ModuleArray()) {
                setField(module, ModuleClassName.of(module), perClass);
            }
            for (ModuleType module : environment.getModuleArray()) {
                setField(module, ModuleClassName.of(module), perClass);
            }
        }
        for (ModuleListType robot : world.getRobotDescriptionArray()) {
            for (ModuleType module : robot.getModuleArray()) {
                setField(module, ModuleClassName.of(module), perClass);
            }
        }
    }

    private static void setField(XmlObject module, String moduleClass, Map<String, Integer> perClass) {
        int n = perClass.merge(moduleClass, 1, Integer::sum);
        try (XmlCursor cursor = module.newCursor()) {
            cursor.toNextToken();
            cursor.insertAttributeWithValue(new QName(GeneratorFunctions.NAMESPACE, "field", "gen"), moduleClass + n);
        }
    }
}
