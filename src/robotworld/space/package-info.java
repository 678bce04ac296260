/**
 * The space: a Linda-style coordination space after XVSM. Entries ({@link robotworld.space.Entry}) live in
 * containers with a capacity, a uniqueness rule, a base order and optional KEY and VECTOR views; operations
 * choose entries through {@link robotworld.space.Selector}s, block with a {@link robotworld.space.Timeout}, and
 * can be observed through notifications. {@link robotworld.space.Capi} is the API; {@link
 * robotworld.space.EmbeddedSpace} implements it in-process. See {@code docs/space.md}.
 */
package robotworld.space;
