package robotworld.explorer.demo;

import java.util.Locale;

/** Where the demo's control program runs: in the robot's main class (thesis 5.3) or in the environment's. */
public enum Viewpoint {
    /** Control program in CaterpillarRobot, the environment framework DimRoom runs unchanged as provider. */
    ROBOT,
    /** Control program in DimRoom (the robot is remote controlled), the robot framework runs unchanged. */
    ENVIRONMENT;

    public static Viewpoint parse(String text) {
        for (Viewpoint viewpoint : values()) {
            if (viewpoint.name().equalsIgnoreCase(text.trim())) {
                return viewpoint;
            }
        }
        throw new IllegalArgumentException("unknown viewpoint '" + text + "' (robot or environment)");
    }

    @Override
    public String toString() {
        return name().toLowerCase(Locale.ROOT);
    }
}
