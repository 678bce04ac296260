package robotworld.explorer.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.explorer.FrameworkGenerator;
import robotworld.testsupport.ProjectFiles;

/** Communication type none: the thesis's listing 3.5 as a single-participant project on the hardware proxies. */
class NoneFrameworkTest {

    private static final Path LISTING_3_5 = ProjectFiles.resolve("docs/examples/listing-3-5-world.xml");

    @TempDir
    Path temp;

    @Test
    void generatesACompilingSingleParticipantProject() throws Exception {
        GenerationResult result = new FrameworkGenerator().generate(LISTING_3_5, "MyRobot", null,
                temp.resolve("MyRobot"), false, GenerationListener.SILENT);
        assertEquals("mypackage.MyRobot", result.mainClass());
        GeneratedProject project = new GeneratedProject(result.destination());
        assertEquals(List.of(project.root().resolve("src/mypackage/MyRobot.java")), project.sources());

        String source = project.read("src/mypackage/MyRobot.java");
        assertTrue(source.contains("public final MotorModule MotorModule1;"), source);
        assertTrue(source.contains("new robotworld.bus.MotorModuleProxy(bus, 1, \"Motor-Controller\")"), source);
        assertTrue(source.contains("bus = ParticipantMain.open(NAME, \"bus\", \"/dev/ttyUSB0\", robotworld.bus.RS485Bus::new);"),
                source);
        assertFalse(source.contains("xvsm") || source.contains("XVSM"), "no space in a 'none' project");

        project.insertControlLogic("src/mypackage/MyRobot.java", """
                MotorModule1.setMotor(1, 0.25);
                MotorModule1.setMotorQuiet(2, -0.25);
                Thread.sleep(10);
                """);
        assertEquals("", project.compile(temp.resolve("classes")));
    }

    @Test
    void projectHasAntBuildEclipseFilesAndExactlyTheFrameworkJars() throws Exception {
        GenerationResult result = new FrameworkGenerator().generate(LISTING_3_5, "MyRobot", "my.robots",
                temp.resolve("p"), false, GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        assertTrue(Files.isRegularFile(project.root().resolve("src/my/robots/MyRobot.java")));
        String build = project.read("build.xml");
        for (String target : new String[] {"name=\"compile\"", "name=\"run\"", "name=\"clean\""}) {
            assertTrue(build.contains(target), build);
        }
        assertTrue(build.contains("value=\"my.robots.MyRobot\""), build);
        assertTrue(project.read(".project").contains("<nature>org.eclipse.jdt.core.javanature</nature>"));

        List<Path> jars = project.libraries();
        assertTrue(jars.stream().anyMatch(j -> j.getFileName().toString().equals("robotworld-runtime.jar")));
        assertTrue(jars.stream().noneMatch(j -> j.getFileName().toString().startsWith("Saxon")),
                "design-time tools do not belong in a generated project: " + jars);
        String classpath = project.read(".classpath");
        long libEntries = classpath.lines().filter(l -> l.contains("kind=\"lib\"")).count();
        assertEquals(jars.size(), libEntries, classpath);
        for (Path jar : jars) {
            assertTrue(classpath.contains("path=\"lib/" + jar.getFileName() + "\""), jar.toString());
        }
        assertTrue(classpath.contains("<classpathentry kind=\"src\" path=\"src\"/>"), classpath);
    }

    /** The IDE gets the runtime's sources and javadoc, and the project the module pages its description names. */
    @Test
    void sourcesJavadocAndModulePagesComeWithTheProject() throws Exception {
        GenerationResult result = new FrameworkGenerator().generate(LISTING_3_5, "MyRobot", null,
                temp.resolve("My Project"), false, GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        for (String attachment : List.of("robotworld-runtime-sources.jar", "robotworld-runtime-javadoc.jar")) {
            assertTrue(Files.size(project.root().resolve("lib/" + attachment)) > 10_000, attachment);
        }
        try (var jar = new java.util.jar.JarFile(project.root().resolve("lib/robotworld-runtime-sources.jar").toFile())) {
            assertTrue(jar.getEntry("robotworld/core/MotorModule.java") != null, "sources of the module interfaces");
        }
        try (var jar = new java.util.jar.JarFile(project.root().resolve("lib/robotworld-runtime-javadoc.jar").toFile())) {
            assertTrue(jar.getEntry("robotworld/core/MotorModule.html") != null, "javadoc of the module interfaces");
        }
        String classpath = project.read(".classpath");
        assertTrue(classpath.contains("<classpathentry kind=\"lib\" path=\"lib/robotworld-runtime.jar\""
                + " sourcepath=\"lib/robotworld-runtime-sources.jar\">"), classpath);
        assertTrue(classpath.contains("<attribute name=\"javadoc_location\" value=\"jar:platform:/resource/My%20Project/"
                + "lib/robotworld-runtime-javadoc.jar!/\"/>"), classpath);
        assertFalse(classpath.contains("kind=\"lib\" path=\"lib/robotworld-runtime-sources.jar\""),
                "an attachment is no library");
        assertTrue(project.read("build.xml").contains("excludes=\"*-sources.jar,*-javadoc.jar\""));

        assertEquals(Files.readString(ProjectFiles.resolve("docs/modules/motor.md")), project.read("docs/modules/motor.md"));
        String index = project.read("docs/index.md");
        assertTrue(index.contains("| MotorModule1 | MyRobot | Motor-Controller | MotorModule | bus 1 | [motor.md](modules/motor.md) |"),
                index);
        assertTrue(project.read("src/mypackage/MyRobot.java").contains(
                "     * Documentation: docs/modules/motor.md in this project (index: docs/index.md).\n"));
    }

    /** A DocRef outside the RobotWorldExplorer documentation is listed, never copied; a URL is linked. */
    @Test
    void docRefsCannotFetchOtherFiles() throws Exception {
        Path secret = Files.writeString(temp.resolve("secret.md"), "TOP SECRET");
        Path world = Files.writeString(temp.resolve("world.xml"), Files.readString(LISTING_3_5)
                .replace("<DocRef>docs/modules/motor.md</DocRef>", "<DocRef>../../../../../../.." + secret + "</DocRef>"));
        GenerationResult result = new FrameworkGenerator().generate(world, "MyRobot", null, temp.resolve("p"), false,
                GenerationListener.SILENT);
        GeneratedProject project = new GeneratedProject(result.destination());
        assertFalse(Files.exists(project.root().resolve("docs/modules/secret.md")));
        assertTrue(project.read("docs/index.md").contains("not found: ../../"), project.read("docs/index.md"));
        Path linked = Files.writeString(temp.resolve("linked.xml"), Files.readString(LISTING_3_5)
                .replace("<DocRef>docs/modules/motor.md</DocRef>", "<DocRef>https://example.org/motor#setMotor</DocRef>"));
        result = new FrameworkGenerator().generate(linked, "MyRobot", null, temp.resolve("q"), false,
                GenerationListener.SILENT);
        project = new GeneratedProject(result.destination());
        assertTrue(project.read("docs/index.md").contains("<https://example.org/motor#setMotor>"));
        assertTrue(project.read("src/mypackage/MyRobot.java").contains("Documentation: https://example.org/motor#setMotor."));
    }
}
