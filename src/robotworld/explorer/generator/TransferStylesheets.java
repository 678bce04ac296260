package robotworld.explorer.generator;

import java.io.InputStream;
import java.net.URI;
import java.net.URL;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import javax.xml.transform.Source;
import javax.xml.transform.stream.StreamSource;
import net.sf.saxon.lib.ResourceRequest;
import net.sf.saxon.lib.ResourceResolver;
import net.sf.saxon.s9api.Processor;
import net.sf.saxon.s9api.SaxonApiException;
import net.sf.saxon.s9api.XsltCompiler;
import net.sf.saxon.s9api.XsltExecutable;
import net.sf.saxon.trans.XPathException;

/**
 * The stylesheets of each communication type, loaded from the class path as
 * {@code transfer/<type>/build.xslt} and {@code transfer/<type>/source.xslt} and compiled once. A new type is
 * new files on the class path, not new code. Stylesheets may import each other by relative URI; those resolve
 * on the class path too.
 */
public final class TransferStylesheets {

    public static final String BUILD = "build.xslt";
    public static final String SOURCE = "source.xslt";
    private static final String SCHEME = "classpath";

    private final Processor processor;
    private final ClassLoader loader;
    private final Map<String, XsltExecutable> compiled = new ConcurrentHashMap<>();

    public TransferStylesheets(Processor processor, ClassLoader loader) {
        this.processor = processor;
        this.loader = loader;
    }

    public XsltExecutable get(String communicationType, String stylesheet) throws GenerationException {
        String path = "transfer/" + communicationType + "/" + stylesheet;
        XsltExecutable executable = compiled.get(path);
        if (executable == null) {
            executable = compile(path);
            compiled.put(path, executable);
        }
        return executable;
    }

    private XsltExecutable compile(String path) throws GenerationException {
        URL resource = loader.getResource(path);
        if (resource == null) {
            throw new GenerationException("no stylesheet " + path + " on the class path (communication type '"
                    + path.split("/")[1] + "' needs build.xslt and source.xslt in resources/transfer/)");
        }
        XsltCompiler compiler = processor.newXsltCompiler();
        compiler.setResourceResolver(new ClassPathResolver());
        try (InputStream in = resource.openStream()) {
            return compiler.compile(new StreamSource(in, SCHEME + ":/" + path));
        } catch (SaxonApiException e) {
            throw new GenerationException("stylesheet " + path + " does not compile: " + e.getMessage(), e);
        } catch (java.io.IOException e) {
            throw new GenerationException("cannot read stylesheet " + path + ": " + e.getMessage(), e);
        }
    }

    /**
     * Resolves every resource a stylesheet asks for (xsl:import, xsl:include, document()) relative to its
     * classpath:/ base, and only on the class path: a stylesheet cannot reach files or the network.
     */
    private final class ClassPathResolver implements ResourceResolver {
        @Override
        public Source resolve(ResourceRequest request) throws XPathException {
            String href = request.relativeUri != null ? request.relativeUri : request.uri;
            String base = request.baseUri == null ? SCHEME + ":/" : request.baseUri;
            URI target;
            try {
                target = URI.create(base).resolve(href);
            } catch (IllegalArgumentException e) {
                throw new XPathException("not a resource a stylesheet may use: " + href);
            }
            if (!SCHEME.equals(target.getScheme()) || target.getPath() == null) {
                throw new XPathException("stylesheets may only use resources on the class path: " + href);
            }
            String path = target.getPath().substring(1);
            InputStream in = loader.getResourceAsStream(path);
            if (in == null) {
                throw new XPathException("no resource " + path + " on the class path");
            }
            return new StreamSource(in, target.toString());
        }
    }
}
