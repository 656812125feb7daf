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
from pathlib import Path

from cyclonedds.core import InstanceState, ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.util import duration

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "softgrip-testkit" / "python"))
from softgrip_dds import (  # noqa: E402
    Header, Participant, SoftContactArray, Time, Vector3, Wrench, WrenchStamped, stamp_ns,
)
import softgrip_dds  # noqa: E402

# The command sent back (the same literals are in src/bin/softgrip-ros2-probe/script.rs).
COMMAND = WrenchStamped(
    header=Header(stamp=Time(sec=42, nanosec=123456789), frame_id="gripper/base \u2713"),
    wrench=Wrench(
        force=Vector3(x=1.5, y=-2.25, z=3.333333333333333e-10),
        torque=Vector3(x=0.1, y=-0.2, z=3.3e-300),
    ),
)


def fail(reason, partial):
    softgrip_dds.fail("dds_roundtrip.py", reason, partial)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--domain", type=int, required=True)
    ap.add_argument("--steps", type=int, required=True)
    ap.add_argument("--tips", required=True, help="wrench topic tokens, comma-separated")
    ap.add_argument("--timeout", type=float, default=30.0)
    ap.add_argument("--no-command", action="store_true", help="receive only; send no command")
    args = ap.parse_args()
    deadline = time.monotonic() + args.timeout

    p = Participant(args.domain)  # keep alive: its Domain holds the configuration
    contacts_reader = p.reader("/softgrip/contacts", SoftContactArray)
    wrench_readers = {
        tip: p.reader(f"/softgrip/{tip}/wrench", WrenchStamped) for tip in args.tips.split(",")
    }
    command_writer = p.writer("/softgrip/command", WrenchStamped)

    waitset = WaitSet(p.dp)
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
        del p
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
    del p


if __name__ == "__main__":
    main()
