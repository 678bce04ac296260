package robotworld.cluster;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** Reads a space server's {@code GET <path>/health}, as an operator's script does before taking down a member. */
final class HealthProbe {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();

    private HealthProbe() {
    }

    /** The answer of {@code server}'s health path; an {@link IOException} for anything but 200. */
    static JsonNode read(URI server, Duration timeout) throws IOException, InterruptedException {
        HttpResponse<String> response = HTTP.send(HttpRequest.newBuilder(URI.create(server + "/health"))
                .timeout(timeout).GET().build(), HttpResponse.BodyHandlers.ofString());
        if (response.statusCode() != 200) {
            throw new IOException(server + "/health answered " + response.statusCode() + ": " + response.body());
        }
        return JSON.readTree(response.body());
    }
}
