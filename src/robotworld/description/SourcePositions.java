package robotworld.description;

import org.apache.xmlbeans.XmlCursor;
import org.apache.xmlbeans.XmlLineNumber;
import org.apache.xmlbeans.XmlObject;

/**
 * Line, column and file of a loaded element, from the bookmarks XMLBeans leaves when loading with line numbers;
 * and, for a world assembled from parts, the bookmarks carried over from each part's file.
 */
final class SourcePositions {

    private SourcePositions() {
    }

    /** Marks the root element of a part copied into an assembled world with the part's file. */
    static final class PartSource extends XmlCursor.XmlBookmark {
        final String file;

        PartSource(String file) {
            this.file = file;
        }
    }

    /** {line, column} of the element's start tag, or {0, 0} when the document was not loaded from text. */
    static int[] of(XmlObject element) {
        try (XmlCursor cursor = element.newCursor()) {
            XmlLineNumber position = (XmlLineNumber) cursor.getBookmark(XmlLineNumber.class);
            if (position == null) {
                return new int[] {0, 0};
            }
            return new int[] {position.getLine(), position.getColumn()};
        }
    }

    /** The file the element came from: its part's, in an assembled world; otherwise {@code fallback}. */
    static String sourceOf(XmlObject element, String fallback) {
        try (XmlCursor cursor = element.newCursor()) {
            do {
                XmlCursor.XmlBookmark part = cursor.getBookmark(PartSource.class);
                if (part != null) {
                    return ((PartSource) part).file;
                }
            } while (cursor.toParent());
        }
        return fallback;
    }

    /**
     * Gives the elements of {@code copy} (made with {@code set} from {@code original}, so of the same structure)
     * the positions of their originals, and marks it as coming from {@code file} (if not null).
     */
    static void copy(XmlObject original, XmlObject copy, String file) {
        try (XmlCursor from = original.newCursor(); XmlCursor to = copy.newCursor()) {
            if (file != null) {
                to.setBookmark(new PartSource(file));
            }
            copyPositions(from, to);
        }
    }

    private static void copyPositions(XmlCursor from, XmlCursor to) {
        XmlLineNumber position = (XmlLineNumber) from.getBookmark(XmlLineNumber.class);
        if (position != null) {
            to.setBookmark(new XmlLineNumber(position.getLine(), position.getColumn(), position.getOffset()));
        }
        if (from.toFirstChild()) {
            if (!to.toFirstChild()) {
                from.toParent();
                return;
            }
            do {
                copyPositions(from, to);
            } while (from.toNextSibling() && to.toNextSibling());
            from.toParent();
            to.toParent();
        }
    }
}
