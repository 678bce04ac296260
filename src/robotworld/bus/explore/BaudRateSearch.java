package robotworld.bus.explore;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;
import robotworld.bus.RS485Bus;
import robotworld.description.DescriptionException;

/**
 * Explores a bus at the common baud rates until one gives a clean result: modules found, and no sign of a baud-rate
 * mismatch (garbled replies, or replies paced at another rate). A rate that the replies' pace points to is tried
 * next. When no rate is clean, the result with the most modules wins.
 */
public final class BaudRateSearch {

    /** The rates tried, in this order (the first is the bus default), unless the replies point elsewhere. */
    public static final List<Integer> RATES = List.of(RS485Bus.DEFAULT_BAUD, 9_600, 19_200, 38_400, 57_600);

    /** Opens the bus at a rate; the search closes it. */
    @FunctionalInterface
    public interface BusOpener {
        RS485Bus open(int baud) throws IOException;
    }

    /**
     * The outcome.
     *
     * @param baud the rate whose result was taken
     * @param result that rate's exploration
     * @param tried every rate explored, in order
     */
    public record Outcome(int baud, ExplorationResult result, List<Integer> tried) {
    }

    private BaudRateSearch() {
    }

    /**
     * Explores at one rate after the other.
     *
     * @param explorerFor makes the explorer for a bus opened at a rate
     * @param said hears one line per rate tried, e.g. "9600 baud: 4 modules found, clean"
     */
    public static Outcome explore(BusOpener opener, java.util.function.Function<RS485Bus, RobotExplorer> explorerFor,
            String robotName, ExplorationListener listener, Consumer<String> said)
            throws IOException, DescriptionException {
        Set<Integer> queue = new LinkedHashSet<>(RATES);
        List<Integer> tried = new ArrayList<>();
        Outcome best = null;
        while (!queue.isEmpty()) {
            int baud = queue.iterator().next();
            queue.remove(baud);
            tried.add(baud);
            ExplorationResult result;
            try (RS485Bus bus = opener.open(baud)) {
                result = explorerFor.apply(bus).explore(robotName, listener);
            }
            boolean clean = !result.modules().isEmpty() && !result.baudMismatch();
            said.accept(baud + " baud: " + result.modules().size() + (result.modules().size() == 1 ? " module"
                    : " modules") + " found" + (clean ? ", clean" : result.baudMismatch()
                            ? ", replies look like another rate" : ""));
            Outcome outcome = new Outcome(baud, result, List.copyOf(tried));
            if (clean) {
                return outcome;
            }
            if (best == null || result.modules().size() > best.result().modules().size()) {
                best = outcome;
            }
            if (result.suggestedBaud().isPresent() && !tried.contains(result.suggestedBaud().getAsInt())) {
                Set<Integer> reordered = new LinkedHashSet<>();
                reordered.add(result.suggestedBaud().getAsInt()); // the replies' pace points there: next
                reordered.addAll(queue);
                queue = reordered;
            }
        }
        return new Outcome(best.baud(), best.result(), List.copyOf(tried));
    }
}
