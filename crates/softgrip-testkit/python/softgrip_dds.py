"""What softgrip's DDS test scripts share: Eclipse Cyclone DDS (PyPI `cyclonedds`) configured for
a private network namespace's loopback, softgrip's QoS classes, and IDL definitions of the ROS 2
types softgrip speaks, written from the ROS 2 Kilted interface definitions (rosidl's IDL mapping:
`pkg::msg::dds_::Type_`, fields in .msg order) rather than taken from softgrip.

Used by crates/softgrip-ros2/tests/python/dds_roundtrip.py,
crates/softgrip-cli/tests/python/joint_commands.py and
crates/softgrip-cli/tests/python/gripper_action.py; each puts this folder on `sys.path`.
"""

import json
import sys
import time
from dataclasses import dataclass

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import Domain, DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import array, float64, int8, int32, sequence, uint8, uint32
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration


# --- builtin_interfaces, std_msgs, geometry_msgs, sensor_msgs ---------------------------------

@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32
    nanosec: uint32


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time
    frame_id: str


@dataclass
class String(IdlStruct, typename="std_msgs::msg::dds_::String_"):
    data: str


@dataclass
class Point(IdlStruct, typename="geometry_msgs::msg::dds_::Point_"):
    x: float64
    y: float64
    z: float64


@dataclass
class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
    x: float64
    y: float64
    z: float64


@dataclass
class Wrench(IdlStruct, typename="geometry_msgs::msg::dds_::Wrench_"):
    force: Vector3
    torque: Vector3


@dataclass
class WrenchStamped(IdlStruct, typename="geometry_msgs::msg::dds_::WrenchStamped_"):
    header: Header
    wrench: Wrench


@dataclass
class JointState(IdlStruct, typename="sensor_msgs::msg::dds_::JointState_"):
    header: Header
    name: sequence[str]
    position: sequence[float64]
    velocity: sequence[float64]
    effort: sequence[float64]


def joint_state(name, position, velocity=(), effort=()):
    """A JointState with an empty header."""
    return JointState(header=Header(stamp=Time(sec=0, nanosec=0), frame_id=""), name=list(name),
                      position=list(position), velocity=list(velocity), effort=list(effort))


# --- softgrip_msgs (ros2/softgrip_msgs/msg) -----------------------------------------------------

@dataclass
class SoftContact(IdlStruct, typename="softgrip_msgs::msg::dds_::SoftContact_"):
    header: Header
    fingertip: str
    other: str
    point: Point
    normal: Vector3
    compression: float64
    ratio_x: float64
    normal_force: float64
    friction_force: Vector3
    torsional_moment: float64
    contact_radius: float64
    mean_pressure: float64
    peak_pressure: float64
    stiffness: float64
    level: uint8
    level_name: str
    validity_exceeded: bool
    sliding: bool
    peak_normal_force: float64
    max_compression: float64
    contact_duration: float64
    backing: uint8
    core_thickness: float64
    contact_radius2: float64
    patch_direction: Vector3
    counterpart: uint8
    counterpart_curvature1: float64
    counterpart_curvature2: float64


@dataclass
class SoftContactArray(IdlStruct, typename="softgrip_msgs::msg::dds_::SoftContactArray_"):
    header: Header
    contacts: sequence[SoftContact]


# --- control_msgs/action/ParallelGripperCommand (control_msgs 5.x, ROS 2 Kilted) ----------------
# Goal: sensor_msgs/JointState command. Result: JointState state, bool stalled, bool
# reached_goal. Feedback: JointState state. An action is two services and two topics
# (rcl_action): <name>/_action/send_goal, get_result, cancel_goal, feedback, status.

@dataclass
class UUID(IdlStruct, typename="unique_identifier_msgs::msg::dds_::UUID_"):
    uuid: array[uint8, 16]


@dataclass
class ParallelGripperCommand_Goal(IdlStruct, typename="control_msgs::action::dds_::ParallelGripperCommand_Goal_"):
    command: JointState


@dataclass
class ParallelGripperCommand_Result(IdlStruct, typename="control_msgs::action::dds_::ParallelGripperCommand_Result_"):
    state: JointState
    stalled: bool
    reached_goal: bool


@dataclass
class ParallelGripperCommand_Feedback(IdlStruct, typename="control_msgs::action::dds_::ParallelGripperCommand_Feedback_"):
    state: JointState


@dataclass
class ParallelGripperCommand_SendGoal_Request(
        IdlStruct, typename="control_msgs::action::dds_::ParallelGripperCommand_SendGoal_Request_"):
    goal_id: UUID
    goal: ParallelGripperCommand_Goal


@dataclass
class ParallelGripperCommand_SendGoal_Response(
        IdlStruct, typename="control_msgs::action::dds_::ParallelGripperCommand_SendGoal_Response_"):
    accepted: bool
    stamp: Time


@dataclass
class ParallelGripperCommand_GetResult_Request(
        IdlStruct, typename="control_msgs::action::dds_::ParallelGripperCommand_GetResult_Request_"):
    goal_id: UUID


@dataclass
class ParallelGripperCommand_GetResult_Response(
        IdlStruct, typename="control_msgs::action::dds_::ParallelGripperCommand_GetResult_Response_"):
    status: int8
    result: ParallelGripperCommand_Result


@dataclass
class ParallelGripperCommand_FeedbackMessage(
        IdlStruct, typename="control_msgs::action::dds_::ParallelGripperCommand_FeedbackMessage_"):
    goal_id: UUID
    feedback: ParallelGripperCommand_Feedback


# --- participant and QoS -------------------------------------------------------------------------

# Cyclone on the namespace's loopback only, with unicast discovery to 127.0.0.1 (RustDDS also
# announces itself to the well-known unicast discovery ports on 127.0.0.1).
CYCLONE_CONFIG = """<CycloneDDS><Domain id="any">
  <General><Interfaces><NetworkInterface name="lo"/></Interfaces></General>
  <Discovery><ParticipantIndex>auto</ParticipantIndex>
    <Peers><Peer address="127.0.0.1"/></Peers></Discovery>
</Domain></CycloneDDS>"""

# softgrip_ros2::qos::data: reliable, keep last 10, volatile; XCDR1, the encoding ROS 2 uses.
DATA = Qos(
    Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
    Policy.History.KeepLast(10),
    Policy.Durability.Volatile,
    Policy.DataRepresentation(use_cdrv0_representation=True),
)
# softgrip_ros2::qos::tf_static (the description's and the action status's class).
LATCHED = Qos(
    Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
    Policy.History.KeepLast(1),
    Policy.Durability.TransientLocal,
    Policy.DataRepresentation(use_cdrv0_representation=True),
)


class Participant:
    """A Cyclone participant on `domain`, on loopback only. Keep it alive while reading: its
    Domain holds the configuration."""

    def __init__(self, domain):
        self.domain = Domain(domain, CYCLONE_CONFIG)
        self.dp = DomainParticipant(domain)

    def reader(self, ros_topic, kind, qos=DATA, prefix="rt"):
        """A reader of `ros_topic` (absolute ROS name) as DDS names it (`rt/...`)."""
        return DataReader(self.dp, Topic(self.dp, prefix + ros_topic, kind, qos=qos), qos=qos)

    def writer(self, ros_topic, kind, qos=DATA, prefix="rt"):
        return DataWriter(self.dp, Topic(self.dp, prefix + ros_topic, kind, qos=qos), qos=qos)


def stamp_ns(header):
    return header.stamp.sec * 1_000_000_000 + header.stamp.nanosec


def take(reader, kind, n=256):
    """The samples of `kind` the reader has (take() also returns InvalidSample for a writer that
    went away: those are skipped)."""
    return [s for s in reader.take(N=n) if isinstance(s, kind)]


def dumps(value):
    """JSON of decoded samples (a UUID's bytes as a list of numbers)."""
    return json.dumps(value, default=lambda b: list(b) if isinstance(b, (bytes, bytearray)) else str(b))


def fail(script, reason, partial):
    """Prints what was received and the reason, exits 2."""
    print(dumps(partial))
    print(f"{script}: {reason}", file=sys.stderr)
    sys.exit(2)


class Deadline:
    def __init__(self, seconds):
        self.end = time.monotonic() + seconds

    def left(self):
        return self.end - time.monotonic()

    def passed(self):
        return self.left() <= 0
