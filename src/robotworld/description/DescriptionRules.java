package robotworld.description;

import java.lang.reflect.Constructor;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.apache.xmlbeans.XmlCursor;
import org.apache.xmlbeans.XmlObject;

/**
 * The rules a schema cannot express, checked after schema validation. Together with the schema they promise
 * that a world that validates generates a project that compiles, for every viewpoint:
 * <ul>
 *   <li>names that become Java classes, fields or packages are neither keywords nor hide a class or variable the
 *       generated code uses ({@link JavaNames});</li>
 *   <li>participant names are unique in a world (also ignoring case: they are file names), module names unique in
 *       a participant, and the space container names built from them ({@code <Participant><Module>REQUEST}) are
 *       unique;</li>
 *   <li>bus addresses (NodeNumber) are unique on each bus;</li>
 *   <li>an environment with robot-bus modules names the bus port and the bus class, and a {@code TalkToBusClass}
 *       is a bus class on the class path that the module proxies accept;</li>
 *   <li>no text carries invisible control characters (bidirectional overrides and the like), which could make
 *       generated code read differently from how it compiles.</li>
 * </ul>
 */
final class DescriptionRules {

    private static final String DEFAULT_BUS_PACKAGE = "robotworld.bus.";

    private final String source;
    private final List<DescriptionError> errors = new ArrayList<>();

    private DescriptionRules(String source) {
        this.source = source;
    }

    static List<DescriptionError> check(XmlObject document, String source) {
        DescriptionRules rules = new DescriptionRules(source);
        if (document instanceof RobotWorldDocument world) {
            rules.checkWorld(world.getRobotWorld());
        } else if (document instanceof RobotDescriptionDocument robot) {
            rules.checkRobot(robot.getRobotDescription());
        } else if (document instanceof EnvironmentDocument environment) {
            rules.checkEnvironment(environment.getEnvironment());
        }
        rules.invisibleCharacters(document);
        return rules.errors;
    }

    private void checkWorld(RobotWorldType world) {
        String worldName = world.getWorldName();
        if (JavaNames.isReserved(worldName)) {
            error(world.xgetWorldName(), "world name '" + worldName + "' is a Java keyword; choose another name");
        }
        if (world.isSetPackageName()) {
            String problem = JavaNames.problemWithPackageName(world.getPackageName());
            if (problem != null) {
                error(world.xgetPackageName(), "package name '" + world.getPackageName() + "' " + problem
                        + "; choose another package name");
            }
        } else if (!JavaNames.isReserved(worldName)) {
            String packageName = JavaNames.defaultPackageName(worldName);
            String problem = JavaNames.problemWithPackageName(packageName);
            if (problem != null) {
                error(world.xgetWorldName(), "world name '" + worldName + "' gives the package name '" + packageName
                        + "', which " + problem + "; add a <PackageName> or choose another world name");
            }
        }
        Map<String, XmlObject> participants = new HashMap<>();
        Map<String, XmlObject> participantsIgnoringCase = new HashMap<>();
        Map<String, ContainerOwner> containers = new HashMap<>();
        List<String> busPackageRoots = new ArrayList<>();
        for (EnvModuleListType environment : world.getEnvironmentArray()) {
            participant(participants, participantsIgnoringCase, environment.getEnvironmentName(),
                    environment.xgetEnvironmentName());
            checkEnvironment(environment);
            containerNames(containers, environment.getEnvironmentName(), environment.getX10ModuleArray());
            containerNames(containers, environment.getEnvironmentName(), environment.getModuleArray());
            if (environment.sizeOfModuleArray() > 0 && environment.isSetTalkToBusClass()) {
                busPackageRoots.add(environment.getTalkToBusClass());
            }
        }
        for (ModuleListType robot : world.getRobotDescriptionArray()) {
            participant(participants, participantsIgnoringCase, robot.getRobotName(), robot.xgetRobotName());
            checkRobot(robot);
            containerNames(containers, robot.getRobotName(), robot.getModuleArray());
            busPackageRoots.add(robot.getTalkToBusClass());
        }
        // generated code writes a qualified bus class in full: a participant named like its first segment hides it
        for (String busClass : busPackageRoots) {
            int dot = busClass.indexOf('.');
            XmlObject clash = dot > 0 ? participants.get(busClass.substring(0, dot)) : null;
            if (clash != null) {
                error(clash, "participant name '" + busClass.substring(0, dot) + "' would hide the package of the"
                        + " bus class " + busClass + " in generated code; choose another name");
            }
        }
    }

    private void participant(Map<String, XmlObject> seen, Map<String, XmlObject> seenIgnoringCase, String name,
                             XmlObject at) {
        boolean fresh = unique(seen, name, at, "participant name", "this world");
        XmlObject sameLetters = seenIgnoringCase.putIfAbsent(name.toLowerCase(Locale.ROOT), at);
        if (fresh && sameLetters != null) {
            error(at, "participant name '" + name + "' differs only in case from the one at line "
                    + SourcePositions.of(sameLetters)[0] + "; their classes would be the same file on Windows and"
                    + " macOS, choose another name");
        }
    }

    private void checkRobot(ModuleListType robot) {
        participantName(robot.xgetRobotName(), robot.getRobotName());
        moduleNames(robot.getModuleArray(), robot.getRobotName());
        busAddresses(robot.getModuleArray(), robot.getRobotName());
        busClass(robot.xgetTalkToBusClass(), robot.getTalkToBusClass(), robot.getModuleArray());
    }

    private void checkEnvironment(EnvModuleListType environment) {
        String name = environment.getEnvironmentName();
        participantName(environment.xgetEnvironmentName(), name);
        List<XmlObject> modules = new ArrayList<>(List.of(environment.getX10ModuleArray()));
        modules.addAll(List.of(environment.getModuleArray()));
        moduleNames(modules.toArray(XmlObject[]::new), name);
        ModuleType[] busModules = environment.getModuleArray();
        if (busModules.length > 0) {
            if (!environment.isSetBusPort()) {
                error(busModules[0], "environment '" + name + "' has robot-bus modules but no <BusPort>");
            }
            if (!environment.isSetTalkToBusClass()) {
                error(busModules[0], "environment '" + name + "' has robot-bus modules but no <TalkToBusClass>");
            }
        }
        if (environment.isSetTalkToBusClass()) {
            busClass(environment.xgetTalkToBusClass(), environment.getTalkToBusClass(), busModules);
        }
        busAddresses(busModules, name);
    }

    private void participantName(XmlObject at, String name) {
        String problem = JavaNames.problemWithParticipantName(name);
        if (problem != null) {
            error(at, "participant name '" + name + "' " + problem + "; choose another name");
        }
    }

    /**
     * The bus class as generated code names it ({@code robotworld.bus.<name>} unless qualified) must exist, open
     * a port given by name, close, and be what each bus module's hardware proxy
     * ({@code robotworld.bus.<Class>Proxy}) takes.
     */
    private void busClass(XmlObject at, String name, ModuleType[] modules) {
        for (String segment : name.split("\\.")) {
            if (JavaNames.isReserved(segment)) {
                error(at, "TalkToBusClass '" + name + "' contains the Java keyword '" + segment
                        + "'; the bus class is RS485Bus");
                return;
            }
        }
        if (modules.length == 0) {
            return; // not used by generated code
        }
        String qualified = name.contains(".") ? name : DEFAULT_BUS_PACKAGE + name;
        Class<?> bus = load(qualified);
        if (bus == null) {
            error(at, "TalkToBusClass '" + name + "' is not a bus class RobotWorldExplorer knows (no class "
                    + qualified + " on the class path); the bus class is RS485Bus");
            return;
        }
        if (!Modifier.isPublic(bus.getModifiers()) || Modifier.isAbstract(bus.getModifiers())
                || !AutoCloseable.class.isAssignableFrom(bus) || publicConstructor(bus, String.class) == null) {
            error(at, "TalkToBusClass '" + name + "' is not a bus class (a public class that opens a port by name"
                    + " and can be closed); the bus class is RS485Bus");
            return;
        }
        for (ModuleType module : modules) {
            String moduleClass = ModuleClassName.of(module);
            Class<?> proxy = load(DEFAULT_BUS_PACKAGE + moduleClass + "Proxy");
            if (proxy != null && publicConstructor(proxy, bus, int.class, String.class) == null) {
                error(at, "TalkToBusClass '" + name + "' cannot carry " + moduleClass + " modules (their proxy "
                        + proxy.getSimpleName() + " needs another bus class); the bus class is RS485Bus");
                return;
            }
        }
    }

    private static Class<?> load(String className) {
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        if (loader == null) {
            loader = DescriptionRules.class.getClassLoader();
        }
        try {
            return Class.forName(className, false, loader);
        } catch (ClassNotFoundException | LinkageError e) {
            return null;
        }
    }

    /** A public constructor that accepts arguments of exactly these types (or their supertypes). */
    private static Constructor<?> publicConstructor(Class<?> type, Class<?>... arguments) {
        for (Constructor<?> constructor : type.getConstructors()) {
            Class<?>[] parameters = constructor.getParameterTypes();
            if (parameters.length != arguments.length) {
                continue;
            }
            boolean fits = true;
            for (int i = 0; i < parameters.length; i++) {
                fits &= parameters[i].isAssignableFrom(arguments[i]);
            }
            if (fits) {
                return constructor;
            }
        }
        return null;
    }

    private void moduleNames(XmlObject[] modules, String participant) {
        Map<String, XmlObject> seen = new HashMap<>();
        for (XmlObject module : modules) {
            String name = module instanceof ModuleType bus ? bus.getName() : ((X10ModuleType) module).getName();
            unique(seen, name, module, "module name", "'" + participant + "'");
        }
    }

    private void busAddresses(ModuleType[] modules, String participant) {
        Map<String, XmlObject> seen = new HashMap<>();
        for (ModuleType module : modules) {
            unique(seen, Integer.toString(module.getNodeNumber()), module.xgetNodeNumber(),
                    "bus address (NodeNumber)", "the bus of '" + participant + "'");
        }
    }

    /**
     * Container names are participant + module name, so different pairs can spell the same name
     * ("Ab" + "cX" and "A" + "bcX"). Same-participant duplicates are already reported as duplicate modules.
     */
    private void containerNames(Map<String, ContainerOwner> seen, String participant, XmlObject[] modules) {
        for (XmlObject module : modules) {
            String name = module instanceof ModuleType bus ? bus.getName() : ((X10ModuleType) module).getName();
            ContainerOwner earlier = seen.putIfAbsent(participant + name, new ContainerOwner(participant, module));
            if (earlier != null && !earlier.participant().equals(participant)) {
                error(module, "space container name '" + participant + name + "REQUEST' is also built by"
                        + " participant '" + earlier.participant() + "' at line " + SourcePositions.of(earlier.module())[0]
                        + "; rename one of them");
            }
        }
    }

    private record ContainerOwner(String participant, XmlObject module) {
    }

    /**
     * Control characters, bidirectional overrides and other invisible formatting characters in any text or
     * attribute value ("Trojan source": text that displays differently from what a compiler reads).
     */
    private void invisibleCharacters(XmlObject document) {
        try (XmlCursor cursor = document.newCursor()) {
            while (!cursor.toNextToken().isNone()) {
                XmlCursor.TokenType token = cursor.currentTokenType();
                if (!token.isText() && !token.isAttr()) {
                    continue;
                }
                String text = token.isText() ? cursor.getChars() : cursor.getTextValue();
                int offending = firstInvisible(text);
                if (offending >= 0) {
                    int c = text.codePointAt(offending);
                    try (XmlCursor element = cursor.newCursor()) {
                        element.toParent();
                        String name = element.getName() == null ? "the text" : "<" + element.getName().getLocalPart() + ">";
                        error(element.getObject(), name + " contains the invisible character "
                                + String.format("U+%04X", c) + " (" + describe(c) + "), which can make text read"
                                + " differently from what it is; remove it");
                    }
                }
            }
        }
    }

    /** The index of the first character that may not appear in a description's text, or -1. */
    static int firstInvisible(String text) {
        for (int i = 0; i < text.length(); i = text.offsetByCodePoints(i, 1)) {
            if (isInvisible(text.codePointAt(i))) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Control characters other than tab and line breaks, line and paragraph separators, unpaired surrogates, and
     * formatting characters (bidirectional controls among them) other than the zero-width (non-)joiners that
     * some scripts and emoji need.
     */
    static boolean isInvisible(int c) {
        if (c == '\t' || c == '\n' || c == '\r' || c == 0x200C || c == 0x200D) {
            return false;
        }
        return switch (Character.getType(c)) {
            case Character.CONTROL, Character.FORMAT, Character.LINE_SEPARATOR, Character.PARAGRAPH_SEPARATOR,
                 Character.SURROGATE -> true;
            default -> false;
        };
    }

    private static String describe(int c) {
        String name = Character.getName(c);
        return name == null ? "a control character" : name.toLowerCase(Locale.ROOT);
    }

    /** Records a duplicate as an error; true when {@code value} was new. */
    private boolean unique(Map<String, XmlObject> seen, String value, XmlObject at, String what, String where) {
        XmlObject earlier = seen.putIfAbsent(value, at);
        if (earlier != null) {
            error(at, "duplicate " + what + " '" + value + "' in " + where + firstUsed(earlier, at));
            return false;
        }
        return true;
    }

    /** " (first used at line 8)", or " (first used in robot.xml at line 2)" when that is another file. */
    private String firstUsed(XmlObject earlier, XmlObject at) {
        int line = SourcePositions.of(earlier)[0];
        String earlierFile = SourcePositions.sourceOf(earlier, source);
        String where = earlierFile.equals(SourcePositions.sourceOf(at, source)) ? "" : " in " + earlierFile;
        return line > 0 ? " (first used" + where + " at line " + line + ")" : where.isEmpty() ? "" : " (first used" + where + ")";
    }

    private void error(XmlObject at, String message) {
        int[] position = SourcePositions.of(at);
        errors.add(new DescriptionError(SourcePositions.sourceOf(at, source), position[0], position[1], message));
    }
}
