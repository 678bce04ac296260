package robotworld.description;

import java.lang.module.ModuleFinder;
import java.lang.module.ModuleReference;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * What may stand as a Java identifier, class name or package name in generated code, and why a name may not.
 *
 * <p>The {@code problemWith...} methods return a message in the description author's words (to follow
 * "participant name 'x' ..."), or null when the name is fine. They hold everything a generated project's
 * compilation would otherwise fail on, so that a description that validates always generates and compiles.
 */
public final class JavaNames {

    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

    private static final Set<String> RESERVED = Set.of(
            "abstract", "assert", "boolean", "break", "byte", "case", "catch", "char", "class", "const",
            "continue", "default", "do", "double", "else", "enum", "extends", "final", "finally", "float", "for",
            "goto", "if", "implements", "import", "instanceof", "int", "interface", "long", "native", "new",
            "package", "private", "protected", "public", "return", "short", "static", "strictfp", "super",
            "switch", "synchronized", "this", "throw", "throws", "transient", "try", "void", "volatile", "while",
            "true", "false", "null", "_", "var", "yield", "record", "sealed", "permits");

    /**
     * The public types of {@code java.lang} (Java 17 to 25). Every Java source sees them without an import, so a
     * class of the same name in the generated package would hide them from the generated code and from the
     * control program written into it ({@code Thread.sleep}, {@code Math.abs}, {@code String}).
     */
    private static final Set<String> JAVA_LANG_TYPES = Set.of(
            "AbstractMethodError", "Appendable", "ArithmeticException", "ArrayIndexOutOfBoundsException",
            "ArrayStoreException", "AssertionError", "AutoCloseable", "Boolean", "BootstrapMethodError", "Byte",
            "CharSequence", "Character", "Class", "ClassCastException", "ClassCircularityError", "ClassFormatError",
            "ClassLoader", "ClassNotFoundException", "ClassValue", "CloneNotSupportedException", "Cloneable",
            "Comparable", "Compiler", "Deprecated", "Double", "Enum", "EnumConstantNotPresentException", "Error",
            "Exception", "ExceptionInInitializerError", "Float", "FunctionalInterface", "IO", "IllegalAccessError",
            "IllegalAccessException", "IllegalArgumentException", "IllegalCallerException",
            "IllegalMonitorStateException", "IllegalStateException", "IllegalThreadStateException",
            "IncompatibleClassChangeError", "IndexOutOfBoundsException", "InheritableThreadLocal",
            "InstantiationError", "InstantiationException", "Integer", "InternalError", "InterruptedException",
            "Iterable", "LayerInstantiationException", "LinkageError", "Long", "MatchException", "Math", "Module",
            "ModuleLayer", "NegativeArraySizeException", "NoClassDefFoundError", "NoSuchFieldError",
            "NoSuchFieldException", "NoSuchMethodError", "NoSuchMethodException", "NullPointerException", "Number",
            "NumberFormatException", "Object", "OutOfMemoryError", "Override", "Package", "Process",
            "ProcessBuilder", "ProcessHandle", "Readable", "Record", "ReflectiveOperationException", "Runnable",
            "Runtime", "RuntimeException", "RuntimePermission", "SafeVarargs", "ScopedValue", "SecurityException",
            "SecurityManager", "Short", "StableValue", "StackOverflowError", "StackTraceElement", "StackWalker",
            "StrictMath", "String", "StringBuffer", "StringBuilder", "StringIndexOutOfBoundsException",
            "SuppressWarnings", "System", "Thread", "ThreadDeath", "ThreadGroup", "ThreadLocal", "Throwable",
            "TypeNotPresentException", "UnknownError", "UnsatisfiedLinkError", "UnsupportedClassVersionError",
            "UnsupportedOperationException", "VerifyError", "VirtualMachineError", "Void", "WrongThreadException");

    /**
     * Classes of the runtime that generated code names without their package (it imports them), other than the
     * module interfaces and the {@code XVSM...} proxies, which are recognised by their form.
     */
    private static final Set<String> IMPORTED_RUNTIME_CLASSES = Set.of("XVSMRuntime", "RuntimeSettings",
            "ParticipantMain");

    /**
     * Names generated code uses for its own variables and constants, and the first segments of the qualified
     * names it writes ({@code robotworld.bus.RS485Bus}): a participant of the same name (its class and its field)
     * would hide them.
     */
    private static final Set<String> GENERATED_VARIABLES = Set.of("runtime", "bus", "x10", "program", "args",
            "settings");
    private static final Set<String> GENERATED_CONSTANTS = Set.of("NAME", "HOST", "SPACE_URL");
    private static final Set<String> QUALIFIED_ROOTS = Set.of("robotworld", "java", "javax");

    /** Module field names are {@code <Class><n>}, e.g. MotorModule1. */
    private static final Pattern GENERATED_FIELD_NAME = Pattern.compile("[A-Za-z0-9_]*Module[0-9]+");

    /** File names Windows refuses whatever the extension (CON.java cannot be written there). */
    private static final Pattern WINDOWS_DEVICE = Pattern.compile("(?i)(con|prn|aux|nul|com[0-9]|lpt[0-9])");

    /** The viewpoint name of a program that owns no hardware; no participant can be called so. */
    public static final String EXTERNAL_VIEWPOINT = "external";

    private JavaNames() {
    }

    /** An ASCII Java identifier that is not a keyword, literal or restricted identifier. */
    public static boolean isIdentifier(String name) {
        return name != null && IDENTIFIER.matcher(name).matches() && !RESERVED.contains(name);
    }

    /** Dot-separated identifiers, e.g. a package or a qualified class name. */
    public static boolean isQualifiedName(String name) {
        if (name == null || name.isEmpty() || name.startsWith(".") || name.endsWith(".")) {
            return false;
        }
        for (String part : name.split("\\.", -1)) {
            if (!isIdentifier(part)) {
                return false;
            }
        }
        return true;
    }

    /** Whether the word is reserved in Java (so it cannot name a class, field or package segment). */
    public static boolean isReserved(String word) {
        return RESERVED.contains(word);
    }

    /** Whether {@code java.lang} has a public type of this name. */
    public static boolean isJavaLangType(String name) {
        return JAVA_LANG_TYPES.contains(name);
    }

    /**
     * Why a participant name cannot name a generated class and field, or null. Participant names become a class
     * ({@code <Name>.java}) in the generated package and a field of that class's type in every other class.
     */
    public static String problemWithParticipantName(String name) {
        if (RESERVED.contains(name)) {
            return "is a Java keyword";
        }
        if (EXTERNAL_VIEWPOINT.equals(name)) {
            return "is the name of the external viewpoint (a program that owns no hardware)";
        }
        if (GENERATED_FIELD_NAME.matcher(name).matches()) {
            return "has the form of a generated module field name (<Class><n>, e.g. MotorModule1)";
        }
        if (GENERATED_VARIABLES.contains(name)) {
            return "is a variable of the generated code (" + String.join(", ", new java.util.TreeSet<>(GENERATED_VARIABLES))
                    + ")";
        }
        if (GENERATED_CONSTANTS.contains(name)) {
            return "is a constant of the generated classes (NAME, HOST, SPACE_URL)";
        }
        if (QUALIFIED_ROOTS.contains(name)) {
            return "would hide the packages " + name + ".* from the generated code";
        }
        if (JAVA_LANG_TYPES.contains(name)) {
            return "would hide the class java.lang." + name + " from the generated code and your control program";
        }
        if (IMPORTED_RUNTIME_CLASSES.contains(name) || name.startsWith("XVSM")) {
            return "would hide RobotWorldExplorer's class " + name + " from the generated code";
        }
        if (name.endsWith("Module")) {
            return "ends in 'Module' like the module classes the generated code uses (MotorModule, X10LampModule, ...)";
        }
        if (WINDOWS_DEVICE.matcher(name).matches()) {
            return "cannot be a file name on Windows (" + name + ".java)";
        }
        return null;
    }

    /**
     * Why a package name cannot hold the generated classes, or null. Besides keywords: {@code java.*} is
     * forbidden to everybody but the JDK, a package of a Java platform module cannot be split by the unnamed
     * module (javac: "package exists in another module"), and {@code robotworld.*} is RobotWorldExplorer's own.
     */
    public static String problemWithPackageName(String name) {
        if (!isQualifiedName(name)) {
            for (String segment : name.split("\\.", -1)) {
                if (RESERVED.contains(segment)) {
                    return "contains the Java keyword '" + segment + "'";
                }
            }
            return "is not a Java package name (identifiers joined by dots)";
        }
        String first = name.split("\\.")[0];
        if (first.equals("java")) {
            return "is in java.*, which only the Java platform may use";
        }
        if (first.equals("robotworld")) {
            return "is in robotworld.*, RobotWorldExplorer's own packages";
        }
        String module = platformModuleOf(name);
        if (module != null) {
            return "is a package of the Java platform (module " + module + ")";
        }
        return null;
    }

    /** The package the generator uses when a world names none: the world name in lower case. */
    public static String defaultPackageName(String worldName) {
        return worldName.toLowerCase(Locale.ROOT);
    }

    private static String platformModuleOf(String packageName) {
        return PlatformPackages.MODULE_OF.get(packageName);
    }

    /** Package to module, for every module of the running Java platform; read once, when first needed. */
    private static final class PlatformPackages {
        static final Map<String, String> MODULE_OF = read();

        private static Map<String, String> read() {
            Map<String, String> moduleOf = new HashMap<>();
            for (ModuleReference module : ModuleFinder.ofSystem().findAll()) {
                for (String pkg : module.descriptor().packages()) {
                    moduleOf.putIfAbsent(pkg, module.descriptor().name());
                }
            }
            return Map.copyOf(moduleOf);
        }
    }
}
