package robotworld.recording.mcap;

/** A record of a file's data section as {@link McapReader.Cursor} hands it out, in file order. */
public sealed interface DataRecord permits Schema, Channel, Message, Attachment, Metadata {
}
