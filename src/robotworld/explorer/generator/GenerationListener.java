package robotworld.explorer.generator;

/** Hears about each step of a generation, for progress displays. */
@FunctionalInterface
public interface GenerationListener {

    GenerationListener SILENT = (done, total, step) -> { };

    /**
     * @param done  steps finished so far
     * @param total steps in this generation
     * @param step  what is being done now, in words
     */
    void step(int done, int total, String step);
}
