package robotworld.explorer.cli;

import picocli.CommandLine.IVersionProvider;

/** The version comes from the jar manifest when there is one. */
final class VersionProvider implements IVersionProvider {

    @Override
    public String[] getVersion() {
        String version = Rwe.class.getPackage().getImplementationVersion();
        return new String[] {"RobotWorldExplorer " + (version == null ? "(development build)" : version)};
    }
}
