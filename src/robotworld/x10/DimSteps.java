package robotworld.x10;

/**
 * Conversions between brightness amounts in percent and the two scales of the CM11A: 22 steps in a transmission
 * header, 210 levels in an upload.
 */
public final class DimSteps {

    private DimSteps() {
    }

    /**
     * The number of steps (0..22) nearest to {@code percent} of the full range.
     *
     * @throws IllegalArgumentException outside 0..100
     */
    public static int ofPercent(int percent) {
        if (percent < 0 || percent > 100) {
            throw new IllegalArgumentException("a brightness amount is 0..100 percent, was " + percent);
        }
        return Math.round(percent * X10Constants.DIM_STEPS_FULL_RANGE / 100f);
    }

    /** The percentage (0..100, rounded) of {@code steps} out of 22. */
    public static int toPercent(int steps) {
        return Math.round(steps * 100f / X10Constants.DIM_STEPS_FULL_RANGE);
    }

    /** The upload level (0..210) that corresponds to {@code steps} out of 22. */
    public static int toUploadLevel(int steps) {
        return Math.round(steps * (float) X10Constants.UPLOAD_LEVELS_FULL_RANGE / X10Constants.DIM_STEPS_FULL_RANGE);
    }

    /** The nearest number of steps (0..22) to an upload level (0..210). */
    public static int ofUploadLevel(int level) {
        return Math.round(level * (float) X10Constants.DIM_STEPS_FULL_RANGE / X10Constants.UPLOAD_LEVELS_FULL_RANGE);
    }
}
