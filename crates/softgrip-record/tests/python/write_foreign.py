"""Rewrite an MCAP recording with Python's `mcap` writer (a writer softgrip did not write), in
one of the layouts the MCAP spec allows, for softgrip's reader tests.

    write_foreign.py IN OUT [compression=zstd|lz4|none] [chunked=1|0] [chunk_size=N]
                            [statistics=1|0] [summary=1|0] [messages=N] [skip=TOPIC]

Every schema, channel, message (same log and publish times and sequence numbers, file order)
and metadata record of IN is written to OUT. `summary=0` leaves the summary section out
entirely (no statistics, no indexes, no repeated schemas or channels: the footer's
summary_start is 0); `statistics=0` leaves out only the Statistics record; `messages=N` keeps
the first N messages only and `skip=TOPIC` drops a topic (small test data). Prints one JSON
line: the messages, chunks and metadata records written."""

import json
import sys

from mcap.reader import make_reader
from mcap.writer import CompressionType, IndexType, Writer

COMPRESSION = {
    "zstd": CompressionType.ZSTD,
    "lz4": CompressionType.LZ4,
    "none": CompressionType.NONE,
}


def main(src, dst, *options):
    opts = dict(o.split("=", 1) for o in options)
    summary = opts.get("summary", "1") == "1"
    with open(src, "rb") as f:
        reader = make_reader(f)
        header = reader.get_header()
        messages = [
            m
            for m in reader.iter_messages(log_time_order=False)
            if m[1].topic != opts.get("skip")
        ]
        if "messages" in opts:
            messages = messages[: int(opts["messages"])]
        metadata = list(reader.iter_metadata())
    with open(dst, "wb") as out:
        writer = Writer(
            out,
            chunk_size=int(opts.get("chunk_size", 64 * 1024)),
            compression=COMPRESSION[opts.get("compression", "zstd")],
            index_types=IndexType.ALL if summary else IndexType.NONE,
            repeat_channels=summary,
            repeat_schemas=summary,
            use_chunking=opts.get("chunked", "1") == "1",
            use_statistics=summary and opts.get("statistics", "1") == "1",
            use_summary_offsets=summary,
        )
        writer.start(profile=header.profile, library="python mcap (softgrip's foreign-writer test)")
        schemas, channels = {}, {}
        for m in metadata:
            writer.add_metadata(m.name, m.metadata)
        for schema, channel, message in messages:
            if schema is not None and schema.id not in schemas:
                schemas[schema.id] = writer.register_schema(schema.name, schema.encoding, schema.data)
            if channel.id not in channels:
                channels[channel.id] = writer.register_channel(
                    channel.topic,
                    channel.message_encoding,
                    schemas.get(channel.schema_id, 0),
                    channel.metadata,
                )
            writer.add_message(
                channels[channel.id],
                message.log_time,
                message.data,
                message.publish_time,
                message.sequence,
            )
        writer.finish()
    with open(dst, "rb") as f:
        chunks = 0
        if summary:
            s = make_reader(f).get_summary()
            chunks = len(s.chunk_indexes)
    print(json.dumps({"messages": len(messages), "chunks": chunks, "metadata": len(metadata)}))


if __name__ == "__main__":
    main(*sys.argv[1:])
