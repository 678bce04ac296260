package robotworld.description;

import javax.xml.namespace.QName;
import org.apache.xmlbeans.XmlCursor;
import org.apache.xmlbeans.XmlObject;

/**
 * The {@code <Class>} of a module, bus or X10, read as text. The typed getters of the compiled types only know
 * the built-in module classes; a module type added through run-time schemas ({@link DescriptionSchemas}) must
 * be readable too.
 */
public final class ModuleClassName {

    private static final QName CLASS = new QName(DescriptionKind.NAMESPACE, "Class");

    private ModuleClassName() {
    }

    /** The class name of a {@code Module}, {@code X10Module} or {@code ModuleDescription} element. */
    public static String of(XmlObject module) {
        XmlObject[] children = module.selectChildren(CLASS);
        if (children.length == 0) {
            throw new IllegalArgumentException("not a module: " + module.schemaType());
        }
        try (XmlCursor cursor = children[0].newCursor()) {
            return cursor.getTextValue().strip();
        }
    }
}
