"""An rclpy node (real rclpy, ROS 2 Kilted's PyPI wheels with rmw_fastrtps; the venv of
.ci/rclpy-venv.sh) that closes a gripper of `softgrip run --ros2` with
control_msgs/action/ParallelGripperCommand through rclpy's own ActionClient: once /joint_states
arrive and the action server is ready, it sends one goal, waits for the answer and the result,
and records every /joint_states, /softgrip/contacts and feedback message until the result has
arrived (and `--after` seconds more).

Run by crates/softgrip-cli/tests/run_ros2_rclpy_gripper_action.rs inside a private network
namespace; also the command the crate READMEs give a ROS 2 user to close the hand from rclpy.
Prints one JSON document on stdout: the goal's answer, its result (status and fields), the
feedback, the joint states and contact arrays received (keyed by stamp, in stamp order). Exit 0
when the goal was accepted and its result came; 2 (with the reason on stderr) otherwise.

Usage: rclpy_gripper_action.py --action /gripper/gripper_cmd --joint NAME --position Q
       [--velocity V] [--effort E] [--timeout 60] [--after 0.5]
(the ROS domain is ROS_DOMAIN_ID's, as for any rclpy node)
"""

import json
import sys
import time
from pathlib import Path

import rclpy
from control_msgs.action import ParallelGripperCommand
from rclpy.action import ActionClient
from rclpy.node import Node
from sensor_msgs.msg import JointState
from softgrip_msgs.msg import SoftContactArray

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "softgrip-testkit" / "python"))
from gripper_client import Received, parse_args  # noqa: E402
from softgrip_rclpy import DATA, fail, stamp_ns, to_dict  # noqa: E402

SCRIPT = "rclpy_gripper_action.py"


class Client(Node):
    """The node: two subscriptions and the action client; what it received in `got`."""

    def __init__(self, action):
        super().__init__("softgrip_rclpy_gripper_client")
        self.got = Received()
        self.create_subscription(JointState, "/joint_states", self.on_state, DATA)
        self.create_subscription(SoftContactArray, "/softgrip/contacts", self.on_contacts, DATA)
        self.action = ActionClient(self, ParallelGripperCommand, action)

    def on_state(self, msg):
        self.got.state(stamp_ns(msg.header), to_dict(msg))

    def on_contacts(self, msg):
        self.got.contact_array(stamp_ns(msg.header), to_dict(msg))

    def on_feedback(self, msg):
        self.got.feedback.append(to_dict(msg.feedback))

    def out(self):
        return self.got.out()


def goal(args):
    g = ParallelGripperCommand.Goal()
    g.command.name = [args.joint]
    g.command.position = [args.position]
    if args.velocity is not None:
        g.command.velocity = [args.velocity]
    if args.effort is not None:
        g.command.effort = [args.effort]
    return g


def main():
    args = parse_args(domain=False)
    end = time.monotonic() + args.timeout

    rclpy.init()
    node = Client(args.action)

    def spin_until(what, ready):
        while not ready():
            if time.monotonic() > end:
                fail(SCRIPT, f"timed out waiting for {what}", node.out())
            rclpy.spin_once(node, timeout_sec=0.05)

    # Discovery: the simulation publishes, and rclpy sees the action server's services and topics.
    spin_until("/joint_states", lambda: node.got.states)
    spin_until("the action server", node.action.server_is_ready)

    sent = node.action.send_goal_async(goal(args), feedback_callback=node.on_feedback)
    spin_until("the goal's answer", sent.done)
    handle = sent.result()
    node.got.answer = {"accepted": handle.accepted}
    if not handle.accepted:
        fail(SCRIPT, "the goal was refused", node.out())

    result = handle.get_result_async()
    spin_until("the goal's result", result.done)
    r = result.result()
    node.got.result = {"status": r.status, "result": to_dict(r.result)}
    after = time.monotonic() + args.after
    while time.monotonic() < after:
        rclpy.spin_once(node, timeout_sec=0.05)
    print(json.dumps(node.out()))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
