package robotworld.space;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * A pattern an entry either matches or not; used by {@link Selector#template}.
 *
 * <p>A tuple template fixes the arity and says, per field, what is accepted: anything ({@link #ANY}, written
 * {@code ?}), any value of one type, exactly one value, or (for a nested tuple) another template. Example:
 * {@code Template.tuple(EntryType.INTEGER, "test", Template.ANY)} is the thesis's {@code <integer, "test", ?>}.
 */
public sealed interface Template permits Template.Any, Template.OfType, Template.Value, Template.TupleOf {

    /** The wildcard {@code ?}: matches every entry. */
    Template ANY = new Any();

    /** Whether {@code entry} fits this template. */
    boolean matches(Entry entry);

    /** Matches every entry of {@code type}. */
    static Template type(EntryType type) {
        return new OfType(type);
    }

    /** Matches entries equal to {@code entry}. */
    static Template value(Entry entry) {
        return new Value(entry);
    }

    /**
     * A tuple template. Each field may be a {@code Template}, an {@link EntryType} (any value of that type) or a
     * plain value converted with {@link Entry#from(Object)} (exactly that value).
     */
    static Template tuple(Object... fields) {
        List<Template> patterns = new ArrayList<>(fields.length);
        for (Object field : fields) {
            if (field instanceof Template template) {
                patterns.add(template);
            } else if (field instanceof EntryType type) {
                patterns.add(new OfType(type));
            } else {
                patterns.add(new Value(Entry.from(field)));
            }
        }
        return new TupleOf(patterns);
    }

    /** The wildcard. */
    record Any() implements Template {
        @Override
        public boolean matches(Entry entry) {
            return true;
        }

        @Override
        public String toString() {
            return "?";
        }
    }

    /** Any value of one type. */
    record OfType(EntryType type) implements Template {
        public OfType {
            Objects.requireNonNull(type, "type");
        }

        @Override
        public boolean matches(Entry entry) {
            return entry.type() == type;
        }

        @Override
        public String toString() {
            return type.name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /** Exactly one value. */
    record Value(Entry value) implements Template {
        public Value {
            Objects.requireNonNull(value, "value");
        }

        @Override
        public boolean matches(Entry entry) {
            return value.equals(entry);
        }

        @Override
        public String toString() {
            return value.toString();
        }
    }

    /** A tuple of exactly {@code fields.size()} fields, each matching its field template. */
    record TupleOf(List<Template> fields) implements Template {
        public TupleOf {
            fields = List.copyOf(fields);
        }

        @Override
        public boolean matches(Entry entry) {
            if (!(entry instanceof Tuple tuple) || tuple.arity() != fields.size()) {
                return false;
            }
            for (int i = 0; i < fields.size(); i++) {
                if (!fields.get(i).matches(tuple.get(i))) {
                    return false;
                }
            }
            return true;
        }

        /** Number of fields a matching tuple has. */
        public int arity() {
            return fields.size();
        }

        @Override
        public String toString() {
            return fields.toString().replace('[', '<').replace(']', '>');
        }
    }
}
