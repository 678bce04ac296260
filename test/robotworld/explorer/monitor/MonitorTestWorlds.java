package robotworld.explorer.monitor;

import java.nio.file.Files;
import java.nio.file.Path;
import robotworld.description.DescriptionLoader;
import robotworld.testsupport.ProjectFiles;

/** Worlds for the monitor tests: chapter 5's, and one with every built-in module type. */
final class MonitorTestWorlds {

    static final String ROOM = "DimRoom";
    static final String ROBOT = "CaterpillarRobot";

    private MonitorTestWorlds() {
    }

    static Path chapter5() {
        return ProjectFiles.resolve("docs/examples/chapter5-world.xml");
    }

    /** Chapter 5's world plus a lamp in the room and a servo and an IR module on the robot. */
    static Path everyModuleType(Path folder) throws Exception {
        String world = Files.readString(chapter5())
                .replace("    </X10Module>\n  </Environment>", """
                            </X10Module>
                            <X10Module>
                              <Name>Ceiling</Name>
                              <HouseCode>A</HouseCode>
                              <UnitCode>ONE</UnitCode>
                              <Class>X10LampModule</Class>
                              <Version>1.0</Version>
                            </X10Module>
                          </Environment>""")
                .replace("  </RobotDescription>", """
                            <Module>
                              <Name>Head-Servo</Name>
                              <NodeID>15B63C1</NodeID>
                              <NodeNumber>3</NodeNumber>
                              <Class>ServoModule</Class>
                              <Version>1.0</Version>
                            </Module>
                            <Module>
                              <Name>IR-Sensors</Name>
                              <NodeID>15B63D7</NodeID>
                              <NodeNumber>4</NodeNumber>
                              <Class>IRDistanceModule</Class>
                              <Version>1.0</Version>
                            </Module>
                          </RobotDescription>""");
        Path file = Files.writeString(folder.resolve("every-module-world.xml"), world);
        DescriptionLoader.loadWorld(file); // fails the test early if the fixture is not valid
        return file;
    }
}
