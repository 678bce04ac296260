package robotworld.description;

import javax.xml.namespace.QName;
import org.apache.xmlbeans.SchemaType;

/** The kinds of description document, told apart by their root element. */
public enum DescriptionKind {
    ROBOT_WORLD("RobotWorld", RobotWorldDocument.type),
    ROBOT("RobotDescription", RobotDescriptionDocument.type),
    ENVIRONMENT("Environment", EnvironmentDocument.type),
    MODULE("ModuleDescription", ModuleDescriptionDocument.type);

    /** The namespace every description element lives in. */
    public static final String NAMESPACE = "urn:robotworld:description";

    private final QName rootElement;
    private final SchemaType documentType;

    DescriptionKind(String rootElement, SchemaType documentType) {
        this.rootElement = new QName(NAMESPACE, rootElement);
        this.documentType = documentType;
    }

    public QName rootElement() {
        return rootElement;
    }

    SchemaType documentType() {
        return documentType;
    }

    /** The kind whose root element has this local name, in any namespace; null if none. */
    static DescriptionKind byLocalName(String localName) {
        for (DescriptionKind kind : values()) {
            if (kind.rootElement.getLocalPart().equals(localName)) {
                return kind;
            }
        }
        return null;
    }
}
