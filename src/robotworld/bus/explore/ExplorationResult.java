package robotworld.bus.explore;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import robotworld.bus.BusStatistics;
import robotworld.description.RobotDescriptionDocument;

/**
 * What a bus exploration found.
 *
 * @param description the validated robot description; absent when no module was found (a robot description
 *        needs at least one module)
 * @param modules the modules found, by address
 * @param problems the addresses skipped and why, by address
 * @param notes remarks that are not problems (e.g. a port name the description cannot carry)
 * @param elapsed how long the exploration took
 * @param statistics bus counters of the exploration
 * @param suggestedBaud when replies looked like a baud-rate mismatch and their pace named a rate, that rate
 * @param baudMismatch whether replies looked like a baud-rate mismatch (garbled, or paced at another rate)
 */
public record ExplorationResult(Optional<RobotDescriptionDocument> description, List<FoundModule> modules,
        List<AddressProblem> problems, List<String> notes, Duration elapsed, BusStatistics statistics,
        OptionalInt suggestedBaud, boolean baudMismatch) {

    public ExplorationResult {
        modules = List.copyOf(modules);
        problems = List.copyOf(problems);
        notes = List.copyOf(notes);
    }

    /** One line for people, e.g. "4 modules found, 1 address skipped, 247 addresses in 2.9 s". */
    public String summary(int addressesScanned) {
        return modules.size() + (modules.size() == 1 ? " module" : " modules") + " found, " + problems.size()
                + (problems.size() == 1 ? " address" : " addresses") + " skipped, " + addressesScanned
                + " addresses in " + String.format(java.util.Locale.ROOT, "%.1f s", elapsed.toNanos() / 1e9);
    }
}
