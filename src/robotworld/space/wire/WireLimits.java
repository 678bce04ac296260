package robotworld.space.wire;

/**
 * Bounds on what one message may contain, checked while parsing so that no request can make the reader
 * allocate more than these allow.
 *
 * @param maxBodyBytes   the largest request body (larger ones are refused with 413 before being read)
 * @param maxDepth       how deeply tuples (and tuple templates) may nest; a flat tuple has depth 1
 * @param maxStringChars the longest string (entry, key or name)
 * @param maxCount       the largest selector count (besides "all"); bounds what a selection pre-allocates
 * @param maxSelectors   the longest selector chain
 * @param maxItems       the most items in one write or shift
 */
public record WireLimits(int maxBodyBytes, int maxDepth, int maxStringChars, int maxCount, int maxSelectors,
                         int maxItems) {

    /** The defaults: 1 MiB bodies, depth 32, 64 Ki-char strings, counts up to 100 000, 16 selectors, 10 000 items. */
    public static final WireLimits DEFAULTS = new WireLimits(1 << 20, 32, 1 << 16, 100_000, 16, 10_000);

    /** Validates the values. */
    public WireLimits {
        if (maxBodyBytes < 1024 || maxDepth < 1 || maxStringChars < 1 || maxCount < 1 || maxSelectors < 1
                || maxItems < 1) {
            throw new IllegalArgumentException("wire limits must be positive (bodies at least 1 KiB)");
        }
    }

    /** These limits with another body size. */
    public WireLimits withMaxBodyBytes(int bytes) {
        return new WireLimits(bytes, maxDepth, maxStringChars, maxCount, maxSelectors, maxItems);
    }
}
