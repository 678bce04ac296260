package robotworld.description;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.apache.xmlbeans.SchemaTypeLoader;
import org.apache.xmlbeans.SchemaTypeSystem;
import org.apache.xmlbeans.XmlBeans;
import org.apache.xmlbeans.XmlError;
import org.apache.xmlbeans.XmlException;
import org.apache.xmlbeans.XmlObject;
import org.apache.xmlbeans.XmlOptions;

/**
 * The schemas descriptions are validated against. Normally the ones compiled into RobotWorldExplorer
 * ({@link #builtIn()}); but a user who adds a module type adds its {@code <Class>} value to a copy of
 * {@code schemas/} and points RobotWorldExplorer at it ({@code --schemas DIR} or {@code -Drwe.schemas=DIR}):
 * those files are compiled at run time, so a new module type needs no rebuild of RobotWorldExplorer.
 * The Java view of a description stays the compiled one; only validation uses the run-time schemas.
 */
public final class DescriptionSchemas {

    /** Names a directory of schemas to use instead of the built-in ones. */
    public static final String DIRECTORY_PROPERTY = "rwe.schemas";
    /** The top-level schema files of a schema directory; they include the rest themselves. */
    private static final List<String> TOP_LEVEL = List.of("RobotWorld.xsd", "ModuleDescription.xsd");

    private static final DescriptionSchemas BUILT_IN = new DescriptionSchemas(null, null);
    private static final Map<Path, DescriptionSchemas> COMPILED = new ConcurrentHashMap<>();

    private final Path directory;
    private final SchemaTypeLoader loader;

    private DescriptionSchemas(Path directory, SchemaTypeLoader loader) {
        this.directory = directory;
        this.loader = loader;
    }

    /** The schemas compiled into RobotWorldExplorer from its {@code schemas/} folder. */
    public static DescriptionSchemas builtIn() {
        return BUILT_IN;
    }

    /** The directory named by {@value #DIRECTORY_PROPERTY}, or the built-in schemas when it is not set. */
    public static DescriptionSchemas configured() throws DescriptionException {
        String directory = System.getProperty(DIRECTORY_PROPERTY);
        return directory == null || directory.isBlank() ? BUILT_IN : fromDirectory(Path.of(directory));
    }

    /** Compiles {@code RobotWorld.xsd} and {@code ModuleDescription.xsd} of {@code directory} (kept per path). */
    public static DescriptionSchemas fromDirectory(Path directory) throws DescriptionException {
        Path key = directory.toAbsolutePath().normalize();
        DescriptionSchemas known = COMPILED.get(key);
        if (known == null) {
            known = compile(key);
            COMPILED.put(key, known);
        }
        return known;
    }

    boolean isBuiltIn() {
        return loader == null;
    }

    @Override
    public String toString() {
        return isBuiltIn() ? "built-in schemas" : "schemas in " + directory;
    }

    /** Validates the raw document against these schemas; the errors, in document order. */
    List<XmlError> validate(byte[] document, String source) throws DescriptionException {
        XmlOptions options = new XmlOptions().setLoadUseXMLReader(SecureXml.newReader()).setLoadLineNumbers()
                .setDocumentSourceName(source);
        try {
            XmlObject parsed = loader.parse(new ByteArrayInputStream(document), null, options);
            List<XmlError> errors = new ArrayList<>();
            parsed.validate(new XmlOptions().setErrorListener(errors));
            return errors;
        } catch (XmlException | IOException e) {
            throw DescriptionLoader.failure(source, 1, 1, "cannot validate with " + this + ": " + e.getMessage());
        }
    }

    private static DescriptionSchemas compile(Path directory) throws DescriptionException {
        List<XmlObject> schemas = new ArrayList<>();
        for (String name : TOP_LEVEL) {
            Path file = directory.resolve(name);
            if (!Files.isRegularFile(file)) {
                throw DescriptionLoader.failure(file.toString(), 0, 0, "no such schema file (a schema directory"
                        + " needs " + String.join(" and ", TOP_LEVEL) + ")");
            }
            try {
                schemas.add(XmlObject.Factory.parse(file.toFile(), new XmlOptions()
                        .setLoadUseXMLReader(SecureXml.newReader()).setLoadLineNumbers()
                        .setDocumentSourceName(file.toUri().toString())));
            } catch (XmlException | IOException e) {
                throw DescriptionLoader.failure(file.toString(), 1, 1, "cannot read schema: " + e.getMessage());
            }
        }
        List<XmlError> problems = new ArrayList<>();
        try {
            SchemaTypeSystem system = XmlBeans.compileXsd(schemas.toArray(XmlObject[]::new),
                    XmlBeans.getBuiltinTypeSystem(), new XmlOptions().setErrorListener(problems));
            return new DescriptionSchemas(directory, XmlBeans.typeLoaderUnion(system, XmlBeans.getBuiltinTypeSystem()));
        } catch (XmlException e) {
            List<DescriptionError> errors = new ArrayList<>();
            for (XmlError error : problems) {
                if (error.getSeverity() == XmlError.SEVERITY_ERROR) {
                    errors.add(new DescriptionError(String.valueOf(error.getSourceName()), Math.max(error.getLine(), 0),
                            Math.max(error.getColumn(), 0), "schema error: " + error.getMessage()));
                }
            }
            if (errors.isEmpty()) {
                errors.add(new DescriptionError(directory.toString(), 0, 0, "schemas do not compile: " + e.getMessage()));
            }
            throw new DescriptionException(errors);
        }
    }
}
