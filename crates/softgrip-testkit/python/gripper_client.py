"""What the two gripper action clients share (crates/softgrip-cli/tests/python/gripper_action.py on
Cyclone DDS and rclpy_gripper_action.py on rclpy): their command line and the record of what they
received, printed as one JSON document (the shape crates/softgrip-cli/tests/gripper_ros2/mod.rs
reads)."""

import argparse


def parse_args(domain):
    """The goal's command line: --action, --joint, --position, optional --velocity and --effort,
    --timeout [s] and --after [s]; with `domain`, --domain N too (rclpy takes ROS_DOMAIN_ID)."""
    ap = argparse.ArgumentParser()
    if domain:
        ap.add_argument("--domain", type=int, required=True)
    ap.add_argument("--action", required=True)
    ap.add_argument("--joint", required=True)
    ap.add_argument("--position", type=float, required=True)
    ap.add_argument("--velocity", type=float)
    ap.add_argument("--effort", type=float)
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--after", type=float, default=0.5)
    return ap.parse_args()


class Received:
    """Every /joint_states and /softgrip/contacts message by stamp (the first at a stamp counts),
    every feedback message in order, the goal's answer and its result."""

    def __init__(self):
        self.states = {}
        self.contacts = {}
        self.feedback = []
        self.answer = None
        self.result = None

    def state(self, stamp, message):
        self.states.setdefault(stamp, message)

    def contact_array(self, stamp, message):
        self.contacts.setdefault(stamp, message)

    def out(self):
        """The JSON document: answer, result, feedback, states and contacts in stamp order."""
        return {
            "answer": self.answer,
            "result": self.result,
            "feedback": self.feedback,
            "states": [self.states[k] for k in sorted(self.states)],
            "contacts": [self.contacts[k] for k in sorted(self.contacts)],
        }
