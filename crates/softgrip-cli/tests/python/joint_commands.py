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
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "softgrip-testkit" / "python"))
from softgrip_dds import LATCHED, JointState, Participant, String, joint_state, stamp_ns  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--domain", type=int, required=True)
    ap.add_argument("--joint", required=True)
    ap.add_argument("--target", type=float, required=True)
    ap.add_argument("--topic", default="/robot_joint_command")
    ap.add_argument("--timeout", type=float, default=60.0)
    args = ap.parse_args()
    deadline = time.monotonic() + args.timeout

    p = Participant(args.domain)
    states = p.reader("/joint_states", JointState)
    description = p.reader("/robot_description", String, qos=LATCHED)
    writer = p.writer(args.topic, JointState)

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
            writer.write(joint_state([args.joint], [args.target]))
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
    del p


if __name__ == "__main__":
    main()
