package robotworld.description;

import java.util.Set;
import java.util.regex.Pattern;

/** What may stand as a Java identifier or package name in generated code. */
public final class JavaNames {

    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

    private static final Set<String> RESERVED = Set.of(
            "abstract", "assert", "boolean", "break", "byte", "case", "catch", "char", "class", "const",
            "continue", "default", "do", "double", "else", "enum", "extends", "final", "finally", "float", "for",
            "goto", "if", "implements", "import", "instanceof", "int", "interface", "long", "native", "new",
            "package", "private", "protected", "public", "return", "short", "static", "strictfp", "super",
            "switch", "synchronized", "this", "throw", "throws", "transient", "try", "void", "volatile", "while",
            "true", "false", "null", "_", "var", "yield", "record", "sealed", "permits");

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
}
