package robotworld.space.remote;

import java.net.URI;

/**
 * Where a space server is: host, port and base path of its URL, plus its access token (or null) and the
 * authorization header line that carries it over HTTP (or "").
 */
record Endpoint(URI url, String host, int port, String basePath, String token, String authorization) {

    static Endpoint of(URI url, String token) {
        if (!"http".equalsIgnoreCase(url.getScheme())) {
            throw new IllegalArgumentException("a space URL starts with http://; was " + url);
        }
        if (url.getHost() == null) {
            throw new IllegalArgumentException("a space URL needs a host: " + url);
        }
        int port = url.getPort() < 0 ? 80 : url.getPort();
        String path = url.getRawPath() == null ? "" : url.getRawPath();
        if (path.endsWith("/")) {
            path = path.substring(0, path.length() - 1);
        }
        String host = url.getHost();
        if (host.startsWith("[") && host.endsWith("]")) {
            host = host.substring(1, host.length() - 1);
        }
        String authorization = token == null ? "" : "Authorization: Bearer " + token + "\r\n";
        return new Endpoint(url, host, port, path, token, authorization);
    }

    /** The value of an HTTP Host header for this server. */
    String hostHeader() {
        return host.contains(":") ? "[" + host + "]:" + port : host + ":" + port;
    }

    /** The request path of an operation. */
    String path(String operation) {
        return basePath + "/" + operation;
    }
}
