"""Robot scenes from Python (issue 25, item 7): `softgrip.run` on a hand scene returns each
moving joint's position, velocity, effort and command as arrays (`RunResult.joints`, units in
`softgrip.JOINT_ARRAYS`), named as in the URDF; the run's own recording gives back the same
arrays (`Recording.joints`, from /joint_states and /joint_commands) value for value. At the
end of the URDF gripper's hold each finger joint's effort equals J^T F, the pads' forces
projected on its axis, within 1 %: the driven joint's motor carries both pads, the mimic
joint's coupling its own. Sweeps vary a grasp's force and the gripper's approach offset
together, and a joint, robot or controller the scene does not have is a typed error naming it.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import softgrip
from softgrip import SceneError, SweepError

ROOT = Path(__file__).resolve().parents[3]
GRIPPER = ROOT / "scenes" / "robots" / "parallel_gripper_box.toml"
HAND = ROOT / "scenes" / "robots" / "three_finger_hand_ball.toml"


def moving_joints(urdf: Path):
    """The URDF's joints that move, in file order."""
    return [
        j.get("name")
        for j in ET.parse(urdf).getroot().iter("joint")
        if j.get("type") in ("revolute", "continuous", "prismatic")
    ]


def hold_end(run):
    """The last step of the gripper's hold: the step before its command's velocity turns to
    opening (the fingers close with a negative velocity, then hold at 0)."""
    opening = np.flatnonzero(run.joints["finger_joint"]["target_velocity"] > 0)
    assert opening.size, "the grasp never opened"
    return int(opening[0]) - 1


@pytest.fixture(scope="module")
def gripper_run(tmp_path_factory):
    path = tmp_path_factory.mktemp("gripper") / "run.mcap"
    run = softgrip.run(GRIPPER, mcap=path, every=1)
    return run, softgrip.open_recording(path)


@pytest.mark.parametrize(
    "scene, urdf",
    [
        (GRIPPER, ROOT / "robots" / "parallel_gripper" / "parallel_gripper.urdf"),
        (HAND, ROOT / "robots" / "three_finger_hand" / "three_finger_hand.urdf"),
    ],
)
def test_joint_names_are_the_urdfs_and_the_arrays_one_per_step(scene, urdf, gripper_run):
    run = gripper_run[0] if scene == GRIPPER else softgrip.run(scene)
    assert list(run.joints) == moving_joints(urdf)
    for name, arrays in run.joints.items():
        assert set(arrays) == set(softgrip.JOINT_ARRAYS), name
        for key, a in arrays.items():
            assert a.dtype == np.float64 and a.shape == run.time.shape, (name, key)
            # Every joint of these hands has a state and a command at every step.
            assert np.isfinite(a).all(), (name, key)
    assert softgrip.run(softgrip.scenes.path("default")).joints == {}


def test_a_run_equals_its_own_recording(gripper_run, tmp_path):
    run, rec = gripper_run
    assert list(rec.joints) == list(run.joints)
    np.testing.assert_array_equal(rec.step, np.arange(1, run.steps + 1))
    for name in run.joints:
        for key in softgrip.JOINT_ARRAYS:
            np.testing.assert_array_equal(rec.joints[name][key], run.joints[name][key], err_msg=f"{name} {key}")
    # Every 4th step: the same states and commands at the recorded steps; the velocity is the
    # rate since the previous *recorded* step there (JOINT_ARRAYS).
    path = tmp_path / "every4.mcap"
    again = softgrip.run(GRIPPER, mcap=path, every=4)
    rec4 = softgrip.open_recording(path)
    rows = rec4.step - 1
    for name in again.joints:
        for key in ("position", "effort", "target_position", "target_velocity", "effort_limit"):
            np.testing.assert_array_equal(rec4.joints[name][key], again.joints[name][key][rows])
        q = again.joints[name]["position"][rows]
        # (the simulation's clock, not step * dt, times the rate: 5e-8 apart)
        np.testing.assert_allclose(
            rec4.joints[name]["velocity"][1:], np.diff(q) / np.diff(rec4.time), rtol=1e-6, atol=1e-12
        )


def test_finger_joint_efforts_at_the_hold_equal_jt_f(gripper_run):
    # The fingers close along the scene's x (both joints' axes); the pads' normals are along
    # it and their friction (carrying the box's weight) across it, the links' weights too:
    # J^T F of the right finger's joint is its pad's normal force, and the driven joint's
    # motor holds both pads (the mimic's multiplier is 1).
    run, _ = gripper_run
    k = hold_end(run)
    left = run.fingertips["left_pad"]["force"][k]
    right = run.fingertips["right_pad"]["force"][k]
    assert 4.5 < left < 5.5 and 4.5 < right < 5.5, (left, right)
    driven = run.joints["finger_joint"]["effort"][k]
    mimic = run.joints["right_finger_joint"]["effort"][k]
    assert abs(driven + (left + right)) < 0.01 * (left + right), (driven, left, right)
    assert abs(mimic + right) < 0.01 * right, (mimic, right)
    # The command: the target froze where the force was reached; the limit is the URDF's.
    assert run.joints["finger_joint"]["target_velocity"][k] == 0.0
    assert run.joints["finger_joint"]["effort_limit"][k] == 20.0


def test_robot_errors_name_the_field_the_value_and_what_is_valid():
    text = GRIPPER.read_text()
    bad = text.replace("initial = { finger_joint = 0.028 }", "initial = { wrist = 0.028 }")
    assert bad != text
    with pytest.raises(SceneError) as e:
        softgrip.run_toml(bad, base_dir=GRIPPER.parent)
    assert e.value.field == "robot[0].initial.wrist"
    assert "its moving joints: finger_joint, right_finger_joint" in str(e.value)
    bad = text.replace('joints = ["finger_joint"]', 'joints = ["thumb"]')
    with pytest.raises(SceneError) as e:
        softgrip.run_toml(bad, base_dir=GRIPPER.parent)
    assert e.value.field == "controller[0].joints[0]" and "no joint `thumb`" in str(e.value)
    bad = text.replace('link = "gripper/left_finger"', 'link = "hand/left_finger"')
    with pytest.raises(SceneError) as e:
        softgrip.run_toml(bad, base_dir=GRIPPER.parent)
    assert e.value.field == "fingertip[0].link" and "(robots: gripper)" in str(e.value)


SWEEP = ROOT / "sweeps" / "robots" / "hand_grasp_force.toml"


def test_a_sweep_of_grasp_force_and_approach_offset_holds_each_force():
    # Two of the shipped sweep's six trials (the Rust test runs all six): 3 N and 7 N, each
    # from 2 mm off the box's centre line.
    text = SWEEP.read_text().replace("values = [3.0, 5.0, 7.0]", "values = [3.0, 7.0]")
    text = text.replace("values = [0.0, 0.002]", "values = [0.002]")
    assert text != SWEEP.read_text()
    t = softgrip.sweep(None, toml=text, base_dir=SWEEP.parent, table="numpy")
    assert list(t["controller[0].force"]) == [3.0, 7.0]
    # Within 5 % of the force, plus what the off-centre push adds to each pad: half the table's
    # friction on the 200 g box and one step's motor advance (crates/softgrip-sweep's test).
    extra = (0.5 * 0.2 * 9.81 + 2000.0 * 0.01 / 60.0) / 2.0
    for force, held, hold in zip(t["controller[0].force"], t["held"], t["hold_force"]):
        assert held
        assert 0.95 * force <= hold <= 1.05 * force + extra, (force, hold)
    assert t["hold_force"][1] > 7.0  # the push's extra is there


@pytest.mark.parametrize(
    "field, value, says",
    [
        ("robot[0].initial.wrist", "0.01", "its moving joints: finger_joint, right_finger_joint"),
        ("controller[grip].force", "5.0", "no entry of `controller` is named `grip` (names: `grasp`)"),
        ("controller[0].robot", '"hand"', "no robot is named `hand` (robots: gripper)"),
    ],
)
def test_sweep_fields_naming_nothing_are_sweep_errors(field, value, says):
    text = f'scene = "{GRIPPER.name}"\nobject = "box"\n[[vary]]\nfield = "{field}"\nvalues = [{value}]\n'
    with pytest.raises(SweepError) as e:
        softgrip.sweep(None, toml=text, base_dir=GRIPPER.parent)
    assert e.value.field == "vary[0].field"
    assert says in str(e.value) and field in str(e.value)
