package robotworld.explorer.generator;

import java.util.List;
import java.util.function.UnaryOperator;
import net.sf.saxon.s9api.ExtensionFunction;
import net.sf.saxon.s9api.ItemType;
import net.sf.saxon.s9api.OccurrenceIndicator;
import net.sf.saxon.s9api.Processor;
import net.sf.saxon.s9api.QName;
import net.sf.saxon.s9api.SaxonApiException;
import net.sf.saxon.s9api.SequenceType;
import net.sf.saxon.s9api.XdmAtomicValue;
import net.sf.saxon.s9api.XdmValue;

/**
 * The functions every transfer stylesheet may call, in the namespace {@value #NAMESPACE}. They are the only way
 * description values should reach generated code: {@code gen:identifier}, {@code gen:qualified},
 * {@code gen:package}, {@code gen:java-string}, {@code gen:comment}, {@code gen:house}, {@code gen:host} (the host name of a
 * {@code <Host>} that may be written as a URL; its result still goes through one of the others).
 */
public final class GeneratorFunctions {

    static final String NAMESPACE = "urn:robotworld:generator";

    private GeneratorFunctions() {
    }

    public static void registerWith(Processor processor) {
        for (ExtensionFunction function : List.of(
                function("identifier", JavaSource::identifier),
                function("qualified", JavaSource::qualifiedName),
                function("package", JavaSource::qualifiedName),
                function("java-string", JavaSource::stringLiteral),
                function("comment", JavaSource::commentText),
                function("house", JavaSource::houseCode),
                function("host", robotworld.description.HostValue::hostName))) {
            processor.registerExtensionFunction(function);
        }
    }

    private static ExtensionFunction function(String localName, UnaryOperator<String> body) {
        QName name = new QName(NAMESPACE, localName);
        SequenceType oneString = SequenceType.makeSequenceType(ItemType.STRING, OccurrenceIndicator.ONE);
        return new ExtensionFunction() {
            @Override
            public QName getName() {
                return name;
            }

            @Override
            public SequenceType getResultType() {
                return oneString;
            }

            @Override
            public SequenceType[] getArgumentTypes() {
                return new SequenceType[] {oneString};
            }

            @Override
            public XdmValue call(XdmValue[] arguments) throws SaxonApiException {
                String value = arguments[0].itemAt(0).getStringValue();
                try {
                    return new XdmAtomicValue(body.apply(value));
                } catch (IllegalArgumentException e) {
                    throw new SaxonApiException("gen:" + localName + ": " + e.getMessage());
                }
            }
        };
    }
}
