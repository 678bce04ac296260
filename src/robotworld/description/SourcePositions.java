package robotworld.description;

import org.apache.xmlbeans.XmlCursor;
import org.apache.xmlbeans.XmlLineNumber;
import org.apache.xmlbeans.XmlObject;

/** Line and column of a loaded element, from the bookmarks XMLBeans leaves when loading with line numbers. */
final class SourcePositions {

    private SourcePositions() {
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
}
