package robotworld.explorer;

import java.io.StringWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import javax.xml.transform.dom.DOMSource;
import net.sf.saxon.s9api.Processor;
import net.sf.saxon.s9api.QName;
import net.sf.saxon.s9api.SaxonApiException;
import net.sf.saxon.s9api.Serializer;
import net.sf.saxon.s9api.XdmAtomicValue;
import net.sf.saxon.s9api.XdmNode;
import net.sf.saxon.s9api.Xslt30Transformer;
import robotworld.description.DescriptionException;
import robotworld.description.DescriptionLoader;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.generator.FrameworkLibraries;
import robotworld.explorer.generator.GenerationException;
import robotworld.explorer.generator.GenerationListener;
import robotworld.explorer.generator.GenerationResult;
import robotworld.explorer.generator.EclipseProject;
import robotworld.explorer.generator.GeneratorFunctions;
import robotworld.explorer.generator.PreparedWorld;
import robotworld.explorer.generator.ProjectDirectory;
import robotworld.explorer.generator.TransferStylesheets;

/**
 * Turns a RobotWorld and a viewpoint into a ready project: an Ant {@code build.xml}, one Java class per
 * participant under {@code src/<package>/}, the framework jars under {@code lib/} (with the runtime's sources and
 * javadoc), the module pages the descriptions name under {@code docs/} with an index, and Eclipse
 * {@code .project} and {@code .classpath} (sources and javadoc attached).
 *
 * <p>The work is done by the stylesheets of the world's communication type,
 * {@code transfer/<type>/build.xslt} and {@code source.xslt}, found on the class path. Generation is atomic:
 * on any error nothing is left at the destination. One generator may be used for many generations (compiled
 * stylesheets are kept); it is safe to use from several threads.
 */
public final class FrameworkGenerator {

    /** The viewpoint of a computer that owns no hardware and reaches every module through the space. */
    public static final String EXTERNAL = "external";

    private final Processor processor = new Processor(false);
    private final TransferStylesheets stylesheets;
    private final Path frameworkDirectory;

    /** A generator that copies the framework jars from {@link FrameworkLibraries#defaultDirectory()}. */
    public FrameworkGenerator() {
        this(FrameworkLibraries.defaultDirectory());
    }

    /** A generator that copies the framework jars from {@code frameworkDirectory}. */
    public FrameworkGenerator(Path frameworkDirectory) {
        this(frameworkDirectory, FrameworkGenerator.class.getClassLoader());
    }

    /**
     * A generator that copies the framework jars from {@code frameworkDirectory} and finds the
     * {@code transfer/<type>/} stylesheets through {@code stylesheetLoader} (e.g. to add communication types
     * from a plug-in jar).
     */
    public FrameworkGenerator(Path frameworkDirectory, ClassLoader stylesheetLoader) {
        this.frameworkDirectory = frameworkDirectory;
        GeneratorFunctions.registerWith(processor);
        this.stylesheets = new TransferStylesheets(processor, stylesheetLoader);
    }

    /**
     * Validates {@code worldFile} and generates the project of {@code viewpoint} into {@code destination}.
     *
     * @param packageName the Java package, or null for the world's {@code <PackageName>} (or its lower-cased name)
     * @param force       replace a non-empty destination (only once the new project is complete)
     * @throws DescriptionException the world is invalid (every error with file, line and column)
     * @throws GenerationException  anything else went wrong; the message says what and where
     */
    public GenerationResult generate(Path worldFile, String viewpoint, String packageName, Path destination,
                                     boolean force, GenerationListener listener)
            throws DescriptionException, GenerationException {
        long started = System.nanoTime();
        listener.step(0, 1, "validating " + worldFile);
        RobotWorldDocument world = DescriptionLoader.loadWorld(worldFile);
        return generate(world, viewpoint, packageName, destination, force, listener, started);
    }

    /** As {@link #generate(Path, String, String, Path, boolean, GenerationListener)} for a loaded world. */
    public GenerationResult generate(RobotWorldDocument world, String viewpoint, String packageName,
                                     Path destination, boolean force, GenerationListener listener)
            throws GenerationException {
        return generate(world, viewpoint, packageName, destination, force, listener, System.nanoTime());
    }

    private GenerationResult generate(RobotWorldDocument world, String viewpoint, String packageName,
                                      Path destination, boolean force, GenerationListener listener, long started)
            throws GenerationException {
        PreparedWorld prepared = PreparedWorld.of(world, viewpoint, packageName);
        List<Path> jars = FrameworkLibraries.in(frameworkDirectory);
        Map<String, String> classes = prepared.classes();
        Map<String, Path> pages = prepared.pageCopies();
        int total = classes.size() + jars.size() + 4;
        int done = 0;
        XdmNode input = toXdm(prepared.document());
        String type = prepared.communicationType();
        // compile both stylesheets before touching the destination: a missing one fails early and cleanly
        stylesheets.get(type, TransferStylesheets.BUILD);
        stylesheets.get(type, TransferStylesheets.SOURCE);
        try (ProjectDirectory project = ProjectDirectory.forDestination(destination, force)) {
            listener.step(++done, total, "writing build.xml");
            project.writeText("build.xml", transformBuild(type, input, prepared.mainClass()));
            String sourceDir = "src/" + prepared.packageName().replace('.', '/') + "/";
            for (Map.Entry<String, String> entry : classes.entrySet()) {
                listener.step(++done, total, "writing " + entry.getValue() + ".java");
                project.writeText(sourceDir + entry.getValue() + ".java",
                        transformSource(type, input, entry.getKey(), entry.getValue()));
            }
            for (Path jar : jars) {
                listener.step(++done, total, "copying " + jar.getFileName());
                project.copy(jar, "lib/" + jar.getFileName());
            }
            listener.step(++done, total, "gathering the module pages in docs/");
            for (Map.Entry<String, Path> page : pages.entrySet()) {
                project.copy(page.getValue(), page.getKey());
            }
            project.writeText("docs/index.md", prepared.pageIndex());
            listener.step(++done, total, "writing Eclipse .project and .classpath");
            String projectName = destination.toAbsolutePath().normalize().getFileName().toString();
            project.writeText(".project", EclipseProject.projectFile(projectName));
            project.writeText(".classpath", EclipseProject.classpathFile(projectName,
                    jars.stream().map(jar -> jar.getFileName().toString()).toList()));
            listener.step(total, total, "moving the project into " + destination);
            List<Path> files = project.commit();
            String mainClass = prepared.packageName() + "." + prepared.mainClass();
            return new GenerationResult(destination.toAbsolutePath().normalize(), mainClass, files,
                    Duration.ofNanos(System.nanoTime() - started));
        }
    }

    private XdmNode toXdm(RobotWorldDocument document) throws GenerationException {
        try {
            return processor.newDocumentBuilder().build(new DOMSource(document.getDomNode()));
        } catch (SaxonApiException e) {
            throw new GenerationException("cannot hand the world to the stylesheets: " + e.getMessage(), e);
        }
    }

    private String transformBuild(String type, XdmNode input, String mainClass) throws GenerationException {
        return transform(type, "build.xslt", input, Map.of("main-class", mainClass));
    }

    private String transformSource(String type, XdmNode input, String participant, String className)
            throws GenerationException {
        return transform(type, "source.xslt", input, Map.of("participant", participant, "class-name", className));
    }

    private String transform(String type, String stylesheet, XdmNode input, Map<String, String> parameters)
            throws GenerationException {
        Xslt30Transformer transformer = stylesheets.get(type, stylesheet).load30();
        try {
            transformer.setStylesheetParameters(parameters.entrySet().stream().collect(
                    java.util.stream.Collectors.toMap(e -> new QName(e.getKey()),
                            e -> new XdmAtomicValue(e.getValue()))));
            transformer.setGlobalContextItem(input); // the stylesheets' global variables read the world
            StringWriter out = new StringWriter();
            Serializer serializer = processor.newSerializer(out);
            transformer.applyTemplates(input, serializer);
            return out.toString();
        } catch (SaxonApiException e) {
            throw new GenerationException("transfer/" + type + "/" + stylesheet + " failed"
                    + (parameters.containsKey("participant") ? " for " + parameters.get("participant") : "")
                    + ": " + e.getMessage(), e);
        }
    }
}
