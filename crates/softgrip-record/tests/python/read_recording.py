"""Decode every message of an MCAP recording with an MCAP reader softgrip did not write
(mcap + mcap-ros2-support, which parse the embedded ros2msg schema text) and print one JSON
object per message: topic, log_time, publish_time, schema and the decoded fields."""

import json
import math
import sys

from mcap.reader import make_reader
from mcap_ros2.reader import read_ros2_messages


def plain(value):
    """A decoded ROS 2 message as JSON-able values (NaN/inf as strings)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else repr(value)
    if isinstance(value, (bool, int, str)) or value is None:
        return value
    if isinstance(value, (bytes, bytearray, memoryview)):
        return list(bytes(value))
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if hasattr(value, "__slots__"):
        return {name: plain(getattr(value, name)) for name in value.__slots__}
    if hasattr(value, "tolist"):
        return plain(value.tolist())
    raise TypeError(f"cannot convert {type(value)}")


def main(path):
    count = 0
    # log_time_order=False: file order, which is simulation order for softgrip's recordings.
    for m in read_ros2_messages(path, log_time_order=False):
        print(json.dumps({
            "topic": m.channel.topic,
            "schema": m.schema.name,
            "schema_encoding": m.schema.encoding,
            "encoding": m.channel.message_encoding,
            "log_time": m.log_time_ns,
            "publish_time": m.publish_time_ns,
            "msg": plain(m.ros_msg),
        }))
        count += 1
    with open(path, "rb") as f:
        reader = make_reader(f)
        summary = reader.get_summary()
        stats = summary.statistics if summary else None
        metadata = {m.name: dict(m.metadata) for m in reader.iter_metadata()}
        channels = {c.topic: dict(c.metadata) for c in summary.channels.values()} if summary else {}
        print(json.dumps({
            "summary": {
                "messages": count,
                "statistics_messages": stats.message_count if stats else None,
                "chunks": stats.chunk_count if stats else None,
                "chunk_indexes": len(summary.chunk_indexes) if summary else 0,
                "profile": reader.get_header().profile,
                "metadata": metadata,
                "channels": channels,
            }
        }))


if __name__ == "__main__":
    main(sys.argv[1])
