"""The reference Python mcap package as a test peer.

  mcap_peer.py read FILE      prints what the reference reader finds in FILE as one JSON object: header, summary
                              (schemas, channels, statistics, chunk/attachment/metadata indexes), the messages read
                              through the index (seeking, in log-time order) and by a linear stream read that checks
                              every CRC, attachments and metadata.
  mcap_peer.py write FILE SPEC  writes FILE from SPEC (a JSON file: compression none|zstd|lz4|default (the
                              writer's own default), chunk_size, schemas, channels, messages, metadata,
                              attachments) with the reference writer.
"""
import base64
import json
import sys

from mcap.reader import make_reader
from mcap.records import Attachment, Channel, DataEnd, Footer, Message, Metadata, Schema
from mcap.stream_reader import StreamReader
from mcap.writer import CompressionType, Writer


def read(path):
    out = {}
    with open(path, "rb") as f:
        reader = make_reader(f, validate_crcs=True)
        header = reader.get_header()
        out["header"] = {"profile": header.profile, "library": header.library}
        summary = reader.get_summary()
        if summary is None:
            out["summary"] = None
        else:
            stats = summary.statistics
            out["summary"] = {
                "schemas": [{"id": s.id, "name": s.name, "encoding": s.encoding,
                             "data": s.data.decode("utf-8")} for s in summary.schemas.values()],
                "channels": [{"id": c.id, "schema_id": c.schema_id, "topic": c.topic,
                              "message_encoding": c.message_encoding, "metadata": c.metadata}
                             for c in summary.channels.values()],
                "statistics": None if stats is None else {
                    "message_count": stats.message_count, "schema_count": stats.schema_count,
                    "channel_count": stats.channel_count, "attachment_count": stats.attachment_count,
                    "metadata_count": stats.metadata_count, "chunk_count": stats.chunk_count,
                    "message_start_time": stats.message_start_time, "message_end_time": stats.message_end_time,
                    "channel_message_counts": {str(k): v for k, v in stats.channel_message_counts.items()}},
                "chunk_indexes": len(summary.chunk_indexes),
                "attachment_indexes": [a.name for a in summary.attachment_indexes],
                "metadata_indexes": [m.name for m in summary.metadata_indexes],
            }
            out["indexed"] = [{"topic": c.topic, "sequence": m.sequence, "log_time": m.log_time,
                               "publish_time": m.publish_time, "data": m.data.decode("utf-8")}
                              for (_, c, m) in reader.iter_messages()]
            out["attachments"] = [{"name": a.name, "media_type": a.media_type, "data": a.data.decode("utf-8")}
                                  for a in reader.iter_attachments()]
            out["metadata"] = [{"name": m.name, "metadata": m.metadata} for m in reader.iter_metadata()]
    with open(path, "rb") as f:
        streamed = []
        ended = False
        for record in StreamReader(f, validate_crcs=True).records:
            if isinstance(record, Message):
                streamed.append({"channel": record.channel_id, "sequence": record.sequence,
                                 "log_time": record.log_time, "data": record.data.decode("utf-8")})
            elif isinstance(record, Footer):
                ended = True
        out["streamed"] = streamed
        out["footer"] = ended
    json.dump(out, sys.stdout)


def write(path, spec_path):
    with open(spec_path) as f:
        spec = json.load(f)
    # "default": the writer as a user's script makes it, Writer(f), with the package's own defaults (zstd chunks)
    options = {}
    if spec.get("compression", "none") != "default":
        options["compression"] = {"none": CompressionType.NONE, "zstd": CompressionType.ZSTD,
                                  "lz4": CompressionType.LZ4}[spec.get("compression", "none")]
    if "chunk_size" in spec:
        options["chunk_size"] = spec["chunk_size"]
    with open(path, "wb") as f:
        writer = Writer(f, **options)
        writer.start(profile=spec.get("profile", ""), library="python mcap peer")
        schema_ids = {}
        for s in spec["schemas"]:
            schema_ids[s["name"]] = writer.register_schema(s["name"], s["encoding"], s["data"].encode("utf-8"))
        channel_ids = {}
        for c in spec["channels"]:
            channel_ids[c["topic"]] = writer.register_channel(c["topic"], c["message_encoding"],
                                                              schema_ids.get(c.get("schema"), 0),
                                                              c.get("metadata", {}))
        for a in spec.get("attachments", []):
            writer.add_attachment(a["log_time"], a["log_time"], a["name"], a["media_type"],
                                  a["data"].encode("utf-8"))
        for m in spec.get("metadata", []):
            writer.add_metadata(m["name"], m["metadata"])
        for m in spec["messages"]:
            writer.add_message(channel_ids[m["topic"]], m["log_time"], m["data"].encode("utf-8"),
                               m.get("publish_time", m["log_time"]), m.get("sequence", 0))
        writer.finish()


if __name__ == "__main__":
    if sys.argv[1] == "read":
        read(sys.argv[2])
    elif sys.argv[1] == "write":
        write(sys.argv[2], sys.argv[3])
    else:
        sys.exit("usage: mcap_peer.py read FILE | write FILE SPEC")
