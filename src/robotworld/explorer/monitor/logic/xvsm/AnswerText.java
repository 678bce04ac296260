package robotworld.explorer.monitor.logic.xvsm;

import java.util.StringJoiner;
import robotworld.space.Entry;
import robotworld.space.IntEntry;
import robotworld.space.StringEntry;
import robotworld.space.Tuple;
import robotworld.xvsm.CallTuple;

/**
 * Answers in words, for any module type: who asked, which function, which values. Used by the console monitor
 * and for problem lines. An integer function code is the X10 appliance's (thesis table 4: below 0 off, else on).
 */
public final class AnswerText {

    /** The function name of an error answer (docs/runtime.md, "Error answers"). */
    public static final String ERROR = "ERROR";

    private AnswerText() {
    }

    /** Whether the answer reports a failed call. */
    public static boolean isError(CallTuple answer) {
        return answer.is(ERROR);
    }

    /** The host in an answer's key: {@code laptop} for {@code laptop#k3x9.7} and for {@code laptop}. */
    public static String host(CallTuple answer) {
        int hash = answer.key().indexOf('#');
        return hash < 0 ? answer.key() : answer.key().substring(0, hash);
    }

    /** The function: its name, {@code on}/{@code off} for an appliance code, the failed function for an error. */
    public static String function(CallTuple answer) {
        if (answer.function() instanceof IntEntry code) {
            return code.value() < 0 ? "off" : "on";
        }
        if (isError(answer) && !answer.fields().isEmpty()) {
            return text(answer.fields().get(0)) + " FAILED";
        }
        return answer.functionText();
    }

    /** The values: the fields after the key, space-separated; an error's message; empty when there are none. */
    public static String value(CallTuple answer) {
        if (isError(answer)) {
            return errorMessage(answer);
        }
        StringJoiner joined = new StringJoiner(" ");
        answer.fields().forEach(field -> joined.add(text(field)));
        return joined.toString();
    }

    /**
     * The values as {@link #value(CallTuple)}, in the units the monitor shows everywhere: a motor's speed as
     * -1..1 of full speed ({@code 1 +0.250}), not the per-mille it travels as.
     */
    public static String value(String moduleClass, CallTuple answer) {
        if ("MotorModule".equals(moduleClass) && !isError(answer) && answer.size() == 2
                && answer.fields().get(0) instanceof IntEntry motor && answer.fields().get(1) instanceof IntEntry speed) {
            return motor.value() + " " + String.format(java.util.Locale.ROOT, "%+.3f", speed.value() / 1000.0);
        }
        return value(answer);
    }

    /** An error answer's message with the serving host: {@code message (on robot-pc)}. */
    public static String errorMessage(CallTuple answer) {
        if (answer.fields().size() >= 2 && answer.fields().get(1) instanceof Tuple detail && detail.arity() == 4) {
            return text(detail.get(2)) + " (" + text(detail.get(0)) + " on " + text(detail.get(3)) + ")";
        }
        return answer.toString();
    }

    private static String text(Entry entry) {
        return entry instanceof StringEntry string ? string.value() : String.valueOf(entry);
    }
}
