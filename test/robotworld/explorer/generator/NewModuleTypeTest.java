package robotworld.explorer.generator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robotworld.core.GripperModule;
import robotworld.description.DescriptionLoader;
import robotworld.description.DescriptionSchemas;
import robotworld.description.DescriptionSchemasTest;
import robotworld.description.RobotWorldDocument;
import robotworld.explorer.FrameworkGenerator;
import robotworld.space.EmbeddedSpace;
import robotworld.testsupport.ProjectFiles;
import robotworld.xvsm.XVSMGripperModuleLocal;
import robotworld.xvsm.XVSMGripperModuleRemote;
import robotworld.xvsm.XVSMRuntime;

/**
 * A module type that exists only in test sources (interface {@code robotworld.core.GripperModule}, hardware
 * proxy, {@code XVSMGripperModuleLocal/Remote}, a schema value and a description) goes through validation,
 * generation, compilation and the space without any change to existing code.
 */
class NewModuleTypeTest {

    @TempDir
    Path temp;

    private RobotWorldDocument worldWithGripper() throws Exception {
        DescriptionSchemas schemas = DescriptionSchemas.fromDirectory(
                DescriptionSchemasTest.schemasWithBusModuleClass(temp.resolve("schemas"), "GripperModule"));
        String chapter5 = Files.readString(ProjectFiles.resolve("docs/examples/chapter5-world.xml"));
        String gripper = """
                    <Module>
                      <Name>Gripper</Name>
                      <NodeID>GRIP01</NodeID>
                      <NodeNumber>3</NodeNumber>
                      <Class>GripperModule</Class>
                      <Version>0.1</Version>
                    </Module>
                  </RobotDescription>""";
        Path world = Files.writeString(temp.resolve("gripper-world.xml"),
                chapter5.replace("  </RobotDescription>", gripper));
        return DescriptionLoader.loadWorld(world, schemas);
    }

    @Test
    void generatedProjectsUseTheNewTypeLocallyAndRemotely() throws Exception {
        RobotWorldDocument world = worldWithGripper();
        Path testClasses = Path.of(GripperModule.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        FrameworkGenerator generator = new FrameworkGenerator();
        for (String viewpoint : new String[] {"CaterpillarRobot", "DimRoom", "external"}) {
            GenerationResult result = generator.generate(world, viewpoint, null, temp.resolve(viewpoint), false,
                    GenerationListener.SILENT);
            GeneratedProject project = new GeneratedProject(result.destination());
            String robot = project.read("src/chapter5/CaterpillarRobot.java");
            assertTrue(robot.contains("public final GripperModule GripperModule1;"), robot);
            if (viewpoint.equals("CaterpillarRobot")) {
                assertTrue(robot.contains("new XVSMGripperModuleLocal(runtime, NAME, \"Gripper\",\n"
                        + "                new robotworld.bus.GripperModuleProxy(bus, 3, \"Gripper\"))"), robot);
            } else {
                assertTrue(robot.contains("new XVSMGripperModuleRemote(runtime, NAME, \"Gripper\")"), robot);
            }
            project.insertControlLogic("src/" + result.mainClass().replace('.', '/') + ".java",
                    "GripperModule1.grip(40);\nint held = GripperModule1.force();\nMotorModule1.setMotor(1, 0.1);");
            assertEquals("", project.compile(temp.resolve(viewpoint + "-classes"), testClasses), viewpoint);
        }
    }

    @Test
    void theNewTypeIsSharedThroughTheSpaceByTheExistingRuntime() throws Exception {
        AtomicInteger applied = new AtomicInteger();
        GripperModule hardware = new GripperModule() {
            @Override
            public void grip(int force) {
                applied.set(force);
            }

            @Override
            public int force() {
                return applied.get();
            }
        };
        try (EmbeddedSpace space = EmbeddedSpace.open();
             XVSMRuntime robot = XVSMRuntime.using(space, "robot-laptop");
             XVSMRuntime room = XVSMRuntime.using(space, "room-pc")) {
            robot.own(new XVSMGripperModuleLocal(robot, "CaterpillarRobot", "Gripper", hardware));
            GripperModule remote = room.own(new XVSMGripperModuleRemote(room, "CaterpillarRobot", "Gripper"));
            remote.grip(70);
            assertEquals(70, applied.get());
            assertEquals(70, remote.force());
        }
    }
}
