package robotworld.description;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UnsupportedEncodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.namespace.QName;
import org.apache.xmlbeans.XmlCursor;
import org.apache.xmlbeans.XmlError;
import org.apache.xmlbeans.XmlException;
import org.apache.xmlbeans.XmlObject;
import org.apache.xmlbeans.XmlOptions;
import org.xml.sax.SAXParseException;

/**
 * Loads and validates descriptions: RobotWorlds, robot descriptions, environments and module descriptions.
 *
 * <p>Loading parses without any DOCTYPE processing, checks the root element, validates against the schema
 * with XMLBeans and then applies the rules a schema cannot express ({@link DescriptionRules}). Any failure
 * is one {@link DescriptionException} listing every error as {@code source:line:column: message}.
 */
public final class DescriptionLoader {

    /** Descriptions are small; anything larger is a mistake (or an attack) and is refused before parsing. */
    public static final long MAX_BYTES = 4L * 1024 * 1024;

    private DescriptionLoader() {
    }

    public static RobotWorldDocument loadWorld(Path file) throws DescriptionException {
        return (RobotWorldDocument) load(file, DescriptionKind.ROBOT_WORLD);
    }

    /** Loads a RobotWorld validated against the given schemas (e.g. with extra module types). */
    public static RobotWorldDocument loadWorld(Path file, DescriptionSchemas schemas) throws DescriptionException {
        return (RobotWorldDocument) load(file, DescriptionKind.ROBOT_WORLD, schemas);
    }

    public static RobotWorldDocument loadWorld(InputStream in, String sourceName) throws DescriptionException {
        return (RobotWorldDocument) load(in, sourceName, DescriptionKind.ROBOT_WORLD);
    }

    public static RobotWorldDocument loadWorldFromString(String xml, String sourceName)
            throws DescriptionException {
        return (RobotWorldDocument) load(utf8(xml), sourceName, DescriptionKind.ROBOT_WORLD);
    }

    public static RobotDescriptionDocument loadRobot(Path file) throws DescriptionException {
        return (RobotDescriptionDocument) load(file, DescriptionKind.ROBOT);
    }

    public static EnvironmentDocument loadEnvironment(Path file) throws DescriptionException {
        return (EnvironmentDocument) load(file, DescriptionKind.ENVIRONMENT);
    }

    public static ModuleDescriptionDocument loadModuleDescription(Path file) throws DescriptionException {
        return (ModuleDescriptionDocument) load(file, DescriptionKind.MODULE);
    }

    /**
     * Loads a description of the expected kind, or of any kind when {@code expected} is null, validated against
     * {@link DescriptionSchemas#configured()}.
     */
    public static XmlObject load(Path file, DescriptionKind expected) throws DescriptionException {
        return load(file, expected, DescriptionSchemas.configured());
    }

    /** Loads a description of the expected kind (any kind when null), validated against {@code schemas}. */
    public static XmlObject load(Path file, DescriptionKind expected, DescriptionSchemas schemas)
            throws DescriptionException {
        String source = file.toString();
        byte[] bytes;
        try {
            long size = Files.size(file);
            if (size > MAX_BYTES) {
                throw failure(source, 1, 1, tooLarge(size + " bytes"));
            }
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw failure(source, 0, 0, "no such file");
        } catch (AccessDeniedException e) {
            throw failure(source, 0, 0, "not allowed to read this file (check its permissions)");
        } catch (IOException e) {
            if (Files.isDirectory(file)) {
                throw failure(source, 0, 0, "is a directory, not a description file");
            }
            throw failure(source, 0, 0, "cannot read: " + e.getMessage());
        }
        return parseAndCheck(bytes, source, expected, schemas);
    }

    /** Loads a description of the expected kind (any kind when null) from a stream; the stream is not closed. */
    public static XmlObject load(InputStream in, String sourceName, DescriptionKind expected)
            throws DescriptionException {
        byte[] bytes;
        try {
            bytes = in.readNBytes((int) MAX_BYTES + 1);
        } catch (IOException e) {
            throw failure(sourceName, 0, 0, "cannot read: " + e.getMessage());
        }
        if (bytes.length > MAX_BYTES) {
            throw failure(sourceName, 1, 1, tooLarge("more than " + MAX_BYTES + " bytes"));
        }
        return parseAndCheck(bytes, sourceName, expected, DescriptionSchemas.configured());
    }

    /** Which kind of description a loaded document is. */
    public static DescriptionKind kindOf(XmlObject document) {
        for (DescriptionKind kind : DescriptionKind.values()) {
            if (kind.documentType().isAssignableFrom(document.schemaType())) {
                return kind;
            }
        }
        throw new IllegalArgumentException("not a description document: " + document.schemaType());
    }

    /**
     * Validates a document that was built or changed in memory (for example by {@link RobotWorldAssembler}).
     * Positions are reported where the document still knows them.
     */
    public static void validate(XmlObject document, String sourceName) throws DescriptionException {
        List<XmlError> schemaErrors = new ArrayList<>();
        document.validate(new XmlOptions().setErrorListener(schemaErrors));
        check(document, sourceName, schemaErrors);
    }

    private static XmlObject parseAndCheck(byte[] bytes, String source, DescriptionKind expected,
                                           DescriptionSchemas schemas) throws DescriptionException {
        XmlObject parsed = parse(bytes, source);
        DescriptionKind kind = checkRoot(parsed, source, expected);
        XmlObject typed = parsed.changeType(kind.documentType());
        if (schemas.isBuiltIn()) {
            validate(typed, source);
        } else {
            check(typed, source, schemas.validate(bytes, source));
        }
        return typed;
    }

    /** Schema errors first; only a schema-valid document is worth the semantic rules. */
    private static void check(XmlObject document, String source, List<XmlError> schemaErrors)
            throws DescriptionException {
        List<DescriptionError> errors = new ArrayList<>(schemaErrors.size());
        List<String> cascadeKeys = new ArrayList<>(schemaErrors.size());
        for (XmlError error : schemaErrors) {
            ErrorMessages.Described described = ErrorMessages.schemaError(error);
            errors.add(new DescriptionError(source, Math.max(error.getLine(), 0), Math.max(error.getColumn(), 0),
                    described.message()));
            cascadeKeys.add(described.cascadeKey());
        }
        errors = ErrorMessages.withoutCascades(errors, cascadeKeys);
        if (errors.isEmpty()) {
            errors = DescriptionRules.check(document, source);
        }
        if (!errors.isEmpty()) {
            throw new DescriptionException(errors);
        }
    }

    private static XmlObject parse(byte[] bytes, String source) throws DescriptionException {
        XmlOptions options = new XmlOptions()
                .setLoadUseXMLReader(SecureXml.newReader())
                .setLoadLineNumbers()
                .setDocumentSourceName(source);
        try {
            return XmlObject.Factory.parse(new ByteArrayInputStream(bytes), options);
        } catch (XmlException e) {
            throw new DescriptionException(parseErrors(e, source));
        } catch (UnsupportedEncodingException e) {
            throw failure(source, 1, encodingColumn(bytes), "unknown character encoding '" + e.getMessage()
                    + "' in the XML declaration; save the file as UTF-8 (encoding=\"UTF-8\")");
        } catch (IOException e) {
            throw failure(source, 1, 1, "cannot read: " + e.getMessage());
        }
    }

    private static String tooLarge(String size) {
        return "the file is " + size + "; a description may be at most 4 MiB (" + MAX_BYTES + " bytes)";
    }

    /** The column of {@code encoding} in the XML declaration on the first line, else 1. */
    private static int encodingColumn(byte[] bytes) {
        int end = 0;
        while (end < bytes.length && end < 200 && bytes[end] != '\n') {
            end++;
        }
        int at = new String(bytes, 0, end, StandardCharsets.ISO_8859_1).indexOf("encoding");
        return at < 0 ? 1 : at + 1;
    }

    private static List<DescriptionError> parseErrors(XmlException e, String source) {
        List<DescriptionError> errors = new ArrayList<>();
        if (e.getErrors() != null) {
            for (XmlError error : e.getErrors()) {
                errors.add(new DescriptionError(source, Math.max(error.getLine(), 1),
                        Math.max(error.getColumn(), 1), ErrorMessages.parserMessage(error.getMessage())));
            }
        }
        if (errors.isEmpty()) {
            Throwable cause = e.getCause();
            if (cause instanceof SAXParseException sax) {
                errors.add(new DescriptionError(source, sax.getLineNumber(), sax.getColumnNumber(),
                        ErrorMessages.parserMessage(sax.getMessage())));
            } else {
                errors.add(new DescriptionError(source, 1, 1, ErrorMessages.parserMessage(e.getMessage())));
            }
        }
        return errors;
    }

    private static DescriptionKind checkRoot(XmlObject parsed, String source, DescriptionKind expected)
            throws DescriptionException {
        try (XmlCursor cursor = parsed.newCursor()) {
            if (!cursor.toFirstChild()) {
                throw failure(source, 1, 1, "the document has no root element");
            }
            QName root = cursor.getName();
            int[] at = SourcePositions.of(cursor.getObject());
            DescriptionKind kind = DescriptionKind.byLocalName(root.getLocalPart());
            if (kind == null) {
                throw failure(source, at[0], at[1], "<" + root.getLocalPart() + "> is not a description;"
                        + " expected " + (expected == null ? "one of RobotWorld, RobotDescription, Environment,"
                        + " ModuleDescription" : expected.rootElement().getLocalPart()));
            }
            if (!DescriptionKind.NAMESPACE.equals(root.getNamespaceURI())) {
                throw failure(source, at[0], at[1], "<" + root.getLocalPart() + "> is in namespace '"
                        + root.getNamespaceURI() + "' but descriptions use xmlns=\"" + DescriptionKind.NAMESPACE
                        + "\"");
            }
            if (expected != null && kind != expected) {
                throw failure(source, at[0], at[1], "expected a " + expected.rootElement().getLocalPart()
                        + " description but found <" + root.getLocalPart() + ">");
            }
            return kind;
        }
    }

    static DescriptionException failure(String source, int line, int column, String message) {
        return new DescriptionException(new DescriptionError(source, line, column, message));
    }


    private static InputStream utf8(String xml) {
        return new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8));
    }
}
