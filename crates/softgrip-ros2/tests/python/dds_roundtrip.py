"""A DDS participant softgrip did not write (Eclipse Cyclone DDS, PyPI `cyclonedds`) that
subscribes to softgrip's ROS 2 topics, decodes SoftContactArray and WrenchStamped with its own
IDL definitions of the ROS 2 types, and publishes one command back on /softgrip/command.

Run by crates/softgrip-ros2/tests/dds_roundtrip.rs inside a private network namespace, next to
`softgrip-ros2-probe`. Prints one JSON document on stdout: every distinct message received
(keyed by stamp) and how often the command was written. Exit status 0 when everything expected
arrived and the command was sent; 2 (with the reason on stderr) otherwise.

Usage: dds_roundtrip.py --domain N --steps K --tips thumb,index_finger [--timeout 30] [--no-command]

With --no-command (used against `softgrip run --ros2`, which subscribes to nothing) it prints
what it received as soon as K steps have arrived on every topic, and sends nothing.
"""

import argparse
import dataclasses
import json
import sys
import time
from dataclasses import dataclass

from cyclonedds.core import InstanceState, Policy, Qos, ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.domain import Domain, DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import float64, int32, sequence, uint8, uint32
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration


# ROS 2 types as DDS sees them (rosidl's IDL mapping: pkg::msg::dds_::Type_), field order and
# types as in the .msg files. Only the top-level type name is compared when matching topics.
@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32
    nanosec: uint32


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time
    frame_id: str


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


# Cyclone on the namespace's loopback only, with unicast discovery to 127.0.0.1 (RustDDS also
# announces itself to the well-known unicast discovery ports on 127.0.0.1).
CYCLONE_CONFIG = """<CycloneDDS><Domain id="any">
  <General><Interfaces><NetworkInterface name="lo"/></Interfaces></General>
  <Discovery><ParticipantIndex>auto</ParticipantIndex>
    <Peers><Peer address="127.0.0.1"/></Peers></Discovery>
</Domain></CycloneDDS>"""

# softgrip's data QoS (softgrip_ros2::qos::data): reliable, keep last 10, volatile; XCDR1, the
# encoding ROS 2 uses.
QOS = Qos(
    Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
    Policy.History.KeepLast(10),
    Policy.Durability.Volatile,
    Policy.DataRepresentation(use_cdrv0_representation=True),
)

# The command sent back (the same literals are in src/bin/softgrip-ros2-probe/script.rs).
COMMAND = WrenchStamped(
    header=Header(stamp=Time(sec=42, nanosec=123456789), frame_id="gripper/base \u2713"),
    wrench=Wrench(
        force=Vector3(x=1.5, y=-2.25, z=3.333333333333333e-10),
        torque=Vector3(x=0.1, y=-0.2, z=3.3e-300),
    ),
)


def stamp_ns(header):
    return header.stamp.sec * 1_000_000_000 + header.stamp.nanosec


def fail(reason, partial):
    print(json.dumps(partial))
    print(f"dds_roundtrip.py: {reason}", file=sys.stderr)
    sys.exit(2)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--domain", type=int, required=True)
    ap.add_argument("--steps", type=int, required=True)
    ap.add_argument("--tips", required=True, help="wrench topic tokens, comma-separated")
    ap.add_argument("--timeout", type=float, default=30.0)
    ap.add_argument("--no-command", action="store_true", help="receive only; send no command")
    args = ap.parse_args()
    deadline = time.monotonic() + args.timeout

    domain = Domain(args.domain, CYCLONE_CONFIG)  # keep alive: it holds the configuration
    dp = DomainParticipant(args.domain)
    contacts_reader = DataReader(dp, Topic(dp, "rt/softgrip/contacts", SoftContactArray, qos=QOS), qos=QOS)
    wrench_readers = {
        tip: DataReader(dp, Topic(dp, f"rt/softgrip/{tip}/wrench", WrenchStamped, qos=QOS), qos=QOS)
        for tip in args.tips.split(",")
    }
    command_writer = DataWriter(dp, Topic(dp, "rt/softgrip/command", WrenchStamped, qos=QOS), qos=QOS)

    waitset = WaitSet(dp)
    mask = ViewState.Any | InstanceState.Any | SampleState.NotRead
    for reader in [contacts_reader, *wrench_readers.values()]:
        waitset.attach(ReadCondition(reader, mask))

    contacts = {}  # stamp [ns] -> decoded SoftContactArray
    wrenches = {tip: {} for tip in wrench_readers}
    last_contacts_at = None

    def drain():
        nonlocal last_contacts_at
        # take() also returns InvalidSample for a writer that went away: skip those.
        for s in contacts_reader.take(N=256):
            if not isinstance(s, SoftContactArray):
                continue
            contacts.setdefault(stamp_ns(s.header), dataclasses.asdict(s))
            last_contacts_at = time.monotonic()
        for tip, reader in wrench_readers.items():
            for s in reader.take(N=256):
                if not isinstance(s, WrenchStamped):
                    continue
                wrenches[tip].setdefault(stamp_ns(s.header), dataclasses.asdict(s))

    def result(writes):
        return {
            "contacts": [contacts[k] for k in sorted(contacts)],
            "wrenches": {tip: [w[k] for k in sorted(w)] for tip, w in wrenches.items()},
            "command_writes": writes,
        }

    def complete():
        return len(contacts) >= args.steps and all(len(w) >= args.steps for w in wrenches.values())

    # 1. Discovery and data: wait (on the waitset, with a deadline) until every scripted step
    # has arrived on every topic.
    while not complete():
        left = deadline - time.monotonic()
        if left <= 0:
            fail(f"timed out after {args.timeout} s: {len(contacts)} contact arrays, "
                 f"{ {t: len(w) for t, w in wrenches.items()} } wrenches of {args.steps} steps",
                 result(0))
        waitset.wait(duration(seconds=min(left, 1.0)))
        drain()

    if args.no_command:
        print(json.dumps(result(0)))
        del domain
        return

    # 2. The command: write it (again every 100 ms: the probe's reader may match our writer
    # after we matched it) until the probe, which stops publishing once it has the command,
    # has been silent for 0.5 s.
    writes = 0
    last_write = None
    while True:
        now = time.monotonic()
        if now > deadline:
            fail("timed out sending the command: the probe kept publishing", result(writes))
        due = last_write is None or now - last_write >= 0.1
        if due and command_writer.get_publication_matched_status().current_count > 0:
            command_writer.write(COMMAND)
            writes += 1
            last_write = now
        if writes > 0 and last_contacts_at is not None and now - last_contacts_at > 0.5:
            break
        waitset.wait(duration(milliseconds=100))
        drain()

    print(json.dumps(result(writes)))
    del domain


if __name__ == "__main__":
    main()
