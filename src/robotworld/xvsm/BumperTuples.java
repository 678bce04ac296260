package robotworld.xvsm;

import java.util.List;
import robotworld.space.Entry;
import robotworld.space.Tuple;

/**
 * Tuples of a bumper module (thesis table 7): {@code <key, value, function>}. In a request the value is the
 * bumper number (0 for {@code getAllBumper}). In an answer it is the result: the contact bit mask for
 * {@code getAllBumper}, and for {@code getSingleBumper} the pair {@code <bumperNr, contact 0|1>}, so that a
 * monitor knows which bumper the answer is about.
 */
final class BumperTuples {

    static final String GET_ALL_BUMPER = "getAllBumper";
    static final String GET_SINGLE_BUMPER = "getSingleBumper";
    /** The value of a {@code getAllBumper} request. */
    static final int ALL_BUMPERS = 0;

    private BumperTuples() {
    }

    static List<Entry> maskAnswer(int mask) {
        return List.of(Entry.of(mask));
    }

    static List<Entry> contactAnswer(int bumper, boolean contact) {
        return List.of(Tuple.of(bumper, contact ? 1 : 0));
    }

    static int mask(CallTuple answer) {
        return answer.expectFields(1).intAt(0);
    }

    static boolean contact(CallTuple answer, int bumper) {
        Tuple pair = answer.expectFields(1).tupleAt(0);
        if (pair.arity() != 2 || pair.longAt(0) != bumper) {
            throw new MalformedCallException("the answer " + answer + " is not about bumper " + bumper);
        }
        return pair.longAt(1) != 0;
    }
}
