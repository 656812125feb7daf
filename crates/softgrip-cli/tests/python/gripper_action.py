"""An action client softgrip did not write (Eclipse Cyclone DDS, PyPI `cyclonedds`, with the IDL of
control_msgs/action/ParallelGripperCommand in crates/softgrip-testkit/python/softgrip_dds.py) that
closes a gripper of `softgrip run --ros2`: once /joint_states arrive and the action's services
are matched, it sends one goal on <action>/_action/send_goal, asks <action>/_action/get_result,
and records every /joint_states, /softgrip/contacts and feedback message until the result
arrives (and `--after` seconds more).

Run by crates/softgrip-cli/tests/run_ros2_gripper_action.rs inside a private network namespace.
Prints one JSON document on stdout: the goal's answer, its result, the feedback, the joint
states and contact arrays received (keyed by stamp). Exit 0 when the goal was accepted and its
result came; 2 (with the reason on stderr) otherwise.

Usage: gripper_action.py --domain N --action /gripper/gripper_cmd --joint NAME --position Q
       [--velocity V] [--effort E] [--timeout 60] [--after 0.5]
"""

import dataclasses
import sys
import time
import uuid
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "softgrip-testkit" / "python"))
from gripper_client import Received, parse_args  # noqa: E402
from softgrip_dds import (  # noqa: E402
    UUID, Deadline, JointState, ParallelGripperCommand_FeedbackMessage,
    ParallelGripperCommand_GetResult_Request, ParallelGripperCommand_GetResult_Response,
    ParallelGripperCommand_Goal, ParallelGripperCommand_SendGoal_Request,
    ParallelGripperCommand_SendGoal_Response, Participant, SoftContactArray, dumps, fail, joint_state,
    stamp_ns, take,
)


def main():
    args = parse_args(domain=True)
    deadline = Deadline(args.timeout)

    p = Participant(args.domain)
    states = p.reader("/joint_states", JointState)
    contacts = p.reader("/softgrip/contacts", SoftContactArray)
    base = args.action + "/_action/"
    goal_rq = p.writer(base + "send_goalRequest", ParallelGripperCommand_SendGoal_Request, prefix="rq")
    goal_rr = p.reader(base + "send_goalReply", ParallelGripperCommand_SendGoal_Response, prefix="rr")
    result_rq = p.writer(base + "get_resultRequest", ParallelGripperCommand_GetResult_Request, prefix="rq")
    result_rr = p.reader(base + "get_resultReply", ParallelGripperCommand_GetResult_Response, prefix="rr")
    feedback = p.reader(base + "feedback", ParallelGripperCommand_FeedbackMessage)

    got = Received()

    def drain():
        for s in take(states, JointState):
            got.state(stamp_ns(s.header), dataclasses.asdict(s))
        for s in take(contacts, SoftContactArray):
            got.contact_array(stamp_ns(s.header), dataclasses.asdict(s))
        for s in take(feedback, ParallelGripperCommand_FeedbackMessage):
            got.feedback.append(dataclasses.asdict(s))

    out = got.out

    def matched(writer):
        return writer.get_publication_matched_status().current_count > 0

    def wait_for(what, ready):
        while not ready():
            if deadline.passed():
                fail("gripper_action.py", f"timed out waiting for {what}", out())
            time.sleep(0.005)
            drain()

    # Discovery: the simulation publishes, and the action's request readers see us.
    wait_for("/joint_states", lambda: got.states)
    wait_for("the send_goal and get_result servers", lambda: matched(goal_rq) and matched(result_rq))
    # The reply writers must match our reply readers too (no reply is lost): a short settle.
    wait_for("the reply writers", lambda: goal_rr.get_subscription_matched_status().current_count > 0
             and result_rr.get_subscription_matched_status().current_count > 0)

    goal_id = UUID(uuid=list(uuid.uuid4().bytes))
    command = joint_state(
        [args.joint], [args.position],
        [args.velocity] if args.velocity is not None else [],
        [args.effort] if args.effort is not None else [],
    )
    goal_rq.write(ParallelGripperCommand_SendGoal_Request(
        goal_id=goal_id, goal=ParallelGripperCommand_Goal(command=command)))

    def answered():
        for s in take(goal_rr, ParallelGripperCommand_SendGoal_Response):
            got.answer = dataclasses.asdict(s)
        return got.answer is not None

    wait_for("the goal's answer", answered)
    if not got.answer["accepted"]:
        fail("gripper_action.py", "the goal was refused", out())
    result_rq.write(ParallelGripperCommand_GetResult_Request(goal_id=goal_id))

    def resulted():
        for s in take(result_rr, ParallelGripperCommand_GetResult_Response):
            got.result = dataclasses.asdict(s)
        return got.result is not None

    wait_for("the goal's result", resulted)
    after = time.monotonic() + args.after
    while time.monotonic() < after:
        time.sleep(0.005)
        drain()
    print(dumps(out()))
    del p


if __name__ == "__main__":
    main()
