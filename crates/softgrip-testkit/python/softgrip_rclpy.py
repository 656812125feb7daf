"""Shared pieces of the tests' rclpy nodes (real rclpy from ROS 2 Kilted's PyPI wheels, with
softgrip_msgs and control_msgs' ParallelGripperCommand generated into the same venv by
.ci/rclpy-venv.sh): softgrip's QoS classes as rclpy profiles, messages as plain dicts for JSON,
and the exit path with what was received.
"""

import json
import sys

from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

# softgrip_ros2::qos::data is reliable, keep last 10, volatile. The tests' readers keep every
# sample of a run (a deeper history than the writer's: nothing is dropped on this side).
DATA = QoSProfile(
    reliability=ReliabilityPolicy.RELIABLE,
    history=HistoryPolicy.KEEP_LAST,
    depth=10000,
    durability=DurabilityPolicy.VOLATILE,
)


def to_dict(msg):
    """A ROS message (rosidl-generated Python class) as plain dicts, lists and numbers: every
    field, recursively; arrays of numbers (array.array, numpy: both have tolist) and bytes as
    lists of Python numbers."""
    if hasattr(msg, "get_fields_and_field_types"):
        return {name: to_dict(getattr(msg, name)) for name in msg.get_fields_and_field_types()}
    if isinstance(msg, (list, tuple)) or hasattr(msg, "tolist"):
        items = msg.tolist() if hasattr(msg, "tolist") else msg
        return [to_dict(x) for x in items]
    if isinstance(msg, (bytes, bytearray)):
        return list(msg)
    return msg


def stamp_ns(header):
    return header.stamp.sec * 1_000_000_000 + header.stamp.nanosec


def fail(script, reason, partial):
    """Prints what was received and the reason, exits 2."""
    print(json.dumps(partial))
    print(f"{script}: {reason}", file=sys.stderr)
    sys.exit(2)
