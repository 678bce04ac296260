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
        assertTrue(source.contains("settings.port(NAME, \"bus\", \"/dev/ttyUSB0\")"), source);
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
}
