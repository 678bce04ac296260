/**
 * The remote client: {@link robotworld.space.remote.RemoteSpace} implements {@link robotworld.space.Capi} against a
 * {@code SpaceServer}, with the same semantics as the embedded space. See {@code docs/space.md} ("Remote access").
 */
package robotworld.space.remote;
