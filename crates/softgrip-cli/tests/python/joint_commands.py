"""A DDS participant softgrip did not write (Eclipse Cyclone DDS, PyPI `cyclonedds`, with its own
IDL definition of sensor_msgs/JointState and std_msgs/String) that drives a robot of
`softgrip run --ros2`: it reads /robot_description (transient local: it may join late) and
/joint_states, and once a state has arrived it writes a position command for one joint on the
command topic (every 50 ms, as a controller would) until that joint's state is within 1e-3 of it.

Run by crates/softgrip-cli/tests/run_ros2_joints.rs inside a private network namespace. Prints
one JSON document on stdout: the description, every /joint_states message received (keyed by
stamp) and the number of commands written. Exit 0 when the joint reached the target; 2 (with the
reason on stderr) otherwise.

Usage: joint_commands.py --domain N --joint NAME --target Q [--topic /robot_joint_command]
       [--timeout 60]
"""

import argparse
import dataclasses
import json
import sys
import time
from dataclasses import dataclass

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import Domain, DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import float64, int32, sequence, uint32
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration


@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32
    nanosec: uint32


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time
    frame_id: str


@dataclass
class JointState(IdlStruct, typename="sensor_msgs::msg::dds_::JointState_"):
    header: Header
    name: sequence[str]
    position: sequence[float64]
    velocity: sequence[float64]
    effort: sequence[float64]


@dataclass
class String(IdlStruct, typename="std_msgs::msg::dds_::String_"):
    data: str


CYCLONE_CONFIG = """<CycloneDDS><Domain id="any">
  <General><Interfaces><NetworkInterface name="lo"/></Interfaces></General>
  <Discovery><ParticipantIndex>auto</ParticipantIndex>
    <Peers><Peer address="127.0.0.1"/></Peers></Discovery>
</Domain></CycloneDDS>"""

# softgrip_ros2::qos::data and ::tf_static (the description's class).
DATA = Qos(
    Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
    Policy.History.KeepLast(10),
    Policy.Durability.Volatile,
    Policy.DataRepresentation(use_cdrv0_representation=True),
)
LATCHED = Qos(
    Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
    Policy.History.KeepLast(1),
    Policy.Durability.TransientLocal,
    Policy.DataRepresentation(use_cdrv0_representation=True),
)


def stamp_ns(header):
    return header.stamp.sec * 1_000_000_000 + header.stamp.nanosec


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--domain", type=int, required=True)
    ap.add_argument("--joint", required=True)
    ap.add_argument("--target", type=float, required=True)
    ap.add_argument("--topic", default="/robot_joint_command")
    ap.add_argument("--timeout", type=float, default=60.0)
    args = ap.parse_args()
    deadline = time.monotonic() + args.timeout

    domain = Domain(args.domain, CYCLONE_CONFIG)  # keep alive: it holds the configuration
    dp = DomainParticipant(args.domain)
    states = DataReader(dp, Topic(dp, "rt/joint_states", JointState, qos=DATA), qos=DATA)
    description = DataReader(dp, Topic(dp, "rt/robot_description", String, qos=LATCHED), qos=LATCHED)
    writer = DataWriter(dp, Topic(dp, "rt" + args.topic, JointState, qos=DATA), qos=DATA)

    received = {}
    urdf = None
    writes = 0
    last_write = None
    reached = False
    while time.monotonic() < deadline:
        for s in states.take(N=256):
            if isinstance(s, JointState):
                received.setdefault(stamp_ns(s.header), dataclasses.asdict(s))
        for s in description.take(N=4):
            if isinstance(s, String):
                urdf = s.data
        if received:
            last = received[max(received)]
            if args.joint in last["name"]:
                q = last["position"][last["name"].index(args.joint)]
                reached = abs(q - args.target) < 1e-3
        if reached and urdf is not None:
            break
        now = time.monotonic()
        if received and (last_write is None or now - last_write >= 0.05):
            writer.write(JointState(
                header=Header(stamp=Time(sec=0, nanosec=0), frame_id=""),
                name=[args.joint], position=[args.target], velocity=[], effort=[],
            ))
            writes += 1
            last_write = now
        time.sleep(0.005)

    out = {
        "description": urdf,
        "states": [received[k] for k in sorted(received)],
        "command_writes": writes,
    }
    print(json.dumps(out))
    if not (reached and urdf is not None):
        print(f"joint_commands.py: reached={reached}, description={'yes' if urdf else 'no'}, "
              f"{len(received)} states, {writes} commands", file=sys.stderr)
        sys.exit(2)
    del domain


if __name__ == "__main__":
    main()
