"""`softgrip.open_recording`: a recording opens as the arrays a run returns, read from the file
without re-running anything. A run's own recording gives back its arrays value for value (every
step recorded, or every n-th); the committed recordings and the files of earlier softgrip
versions (before the fingertip's construction was recorded, before the z-up frames, before the
typed JSON metadata) open with their laws and summaries; the axes are the scene's by default
and the recording's z-up world on request."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

import softgrip
from softgrip import ArgumentTypeError, ParameterError, RecordingFormatError

ROOT = Path(__file__).resolve().parents[3]
LEGACY = ROOT / "crates" / "softgrip-record" / "tests" / "data"
COMMITTED = sorted((ROOT / "recordings").glob("*.mcap"))


def assert_run_equals_recording(run, rec, rows):
    """`run`'s arrays at the recorded steps `rows` (0-based) equal the recording's."""
    assert list(rec.fingertips) == list(run.fingertips)
    assert list(rec.bodies) == list(run.bodies)
    assert set(rec.tactile) == set(run.tactile)
    np.testing.assert_array_equal(rec.time, run.time[rows])
    for name, arrays in run.fingertips.items():
        assert set(rec.fingertips[name]) == set(arrays) == set(softgrip.FINGERTIP_ARRAYS)
        for key, values in arrays.items():
            got = rec.fingertips[name][key]
            assert got.dtype == values.dtype and got.shape == values[rows].shape, (name, key)
            # bit for bit: the recorder writes the readout's own f64 values
            np.testing.assert_array_equal(got, values[rows], err_msg=f"{name}.{key}")
    for name, arrays in run.bodies.items():
        # positions exactly (the z-up turn is a permutation with a sign), orientations to the
        # rounding of the quarter turn's 1/sqrt(2)
        np.testing.assert_array_equal(rec.bodies[name]["position"], arrays["position"][rows])
        np.testing.assert_allclose(rec.bodies[name]["rotation"], arrays["rotation"][rows], rtol=0, atol=4e-16)
    for name, images in run.tactile.items():
        assert rec.tactile[name].dtype == np.float32
        np.testing.assert_array_equal(rec.tactile[name], images[rows])
    for name, s in rec.summary.items():
        for key in ("peak_force", "peak_x", "slips", "validity_excursions"):
            assert s[key] == run.summary[name][key], (name, key)


@pytest.mark.parametrize("every", [1, 3])
def test_a_run_equals_its_own_recording(tmp_path: Path, every):
    # The default grasp: two flat pads with 16 x 16 tactile pads, a box lifted and held.
    path = tmp_path / "run.mcap"
    run = softgrip.run(softgrip.scenes.path("default"), mcap=path, every=every)
    rec = softgrip.open_recording(path)
    rows = np.arange(every - 1, run.steps, every)
    np.testing.assert_array_equal(rec.step, rows + 1)
    assert rec.every == every and rec.total_steps == run.total_steps == rec.summary_steps
    assert rec.dt == run.dt and rec.frame == "scene" and rec.recovery is None
    assert rec.fingertips["left_tip"]["force"].max() > 10.0  # the squeeze is in there
    assert rec.tactile["left_tip"].shape == (len(rows), 16, 16)
    assert_run_equals_recording(run, rec, rows)
    assert rec.scene == softgrip.scenes.path("default").read_text()
    # the run's controllers: the default scene's `[gripper]`, parallel_jaws (fixed code 0)
    assert rec.controllers == [{"name": "gripper", "kind": "parallel_jaws", "code": 0}]
    assert rec.controllers[0]["kind"] in softgrip.CONTROLLERS


def test_two_contacts_per_fingertip_sum_as_in_a_run(tmp_path: Path):
    # The Ecoflex sphere between two plates: its one fingertip has two contacts at once.
    path = tmp_path / "sphere.mcap"
    run = softgrip.run(softgrip.scenes.path("ecoflex_sphere"), mcap=path, every=5)
    rec = softgrip.open_recording(path)
    assert rec.fingertips["sphere"]["contacts"].max() == 2
    assert_run_equals_recording(run, rec, np.arange(4, run.steps, 5))
    # the body named as its fingertip is the body (the fingertip's frame is `sphere_tip`)
    assert "sphere" in rec.bodies and "sphere_tip" not in rec.bodies


def test_the_law_comes_back_from_the_metadata(tmp_path: Path):
    rec = softgrip.open_recording(ROOT / "recordings" / "default.mcap")
    p = rec.laws["left_tip"]
    assert (p["level"], p["setting"], p["backing"], p["core_thickness"]) == ("auto", 0.01, "flat", None)
    law = rec.law("left_tip")
    assert law == softgrip.law("auto", p["youngs_modulus"], p["poisson_ratio"], p["radius"], "flat", tolerance=0.01)
    # the recorded forces are this law's at the recorded compressions (the squeeze is
    # quasi-static: the step-average force is the law's at the end-of-step compression
    # within 1 %; the box's weight shares the grip)
    t = rec.fingertips["left_tip"]
    held = t["delta"] > 0.5 * t["delta"].max()
    assert held.sum() > 20
    ratio = law.force(t["delta"][held]) / t["force"][held]
    assert np.all(np.abs(ratio - 1) < 0.01), ratio
    with pytest.raises(ParameterError) as e:
        rec.law("thumb")
    assert e.value.field == "fingertip"


def committed_controllers(path: Path) -> list:
    """The controllers a committed recording names: none for those recorded before controllers
    were (session 10); the hand scenes' (session 11) their grasp and their robot's commands; the
    default scene's, re-made in session 20, its two-jaw gripper."""
    if path.stem == "default":
        return [{"name": "gripper", "kind": "parallel_jaws", "code": 0}]
    robots = {"parallel_gripper_": "gripper", "three_finger_hand_": "hand"}
    for prefix, robot in robots.items():
        if path.stem.startswith(prefix):
            return [
                {"name": "grasp", "kind": "grasp", "code": 2},
                {"name": f"{robot}/commands", "kind": "joint_commands", "code": 3},
            ]
    return []


@pytest.mark.parametrize("path", COMMITTED, ids=[p.stem for p in COMMITTED])
def test_committed_recordings_open(path: Path):
    rec = softgrip.open_recording(path)
    assert rec.recovery is None and rec.softgrip_version
    assert rec.controllers == committed_controllers(path)
    assert len(rec.step) == rec.total_steps // rec.every
    assert set(rec.fingertips) == set(rec.laws) == set(rec.summary)
    for name, t in rec.fingertips.items():
        # the run's own peak (every substep) bounds the recorded steps' peaks
        assert 0 < t["peak_force"].max() <= rec.summary[name]["peak_force"] * (1 + 1e-12)
        assert np.all(t["delta"] >= 0) and np.all(np.isfinite(t["force"]))
        np.testing.assert_allclose(t["x"][t["delta"] > 0] * rec.laws[name]["radius"], t["delta"][t["delta"] > 0], rtol=1e-12)
    for b in rec.bodies.values():
        q = b["rotation"]
        np.testing.assert_allclose(np.einsum("ij,ij->i", q, q), 1.0, rtol=1e-6)
    rows = rec.contact_rows
    n = len(rows["step"])
    assert n == sum(int(t["contacts"].sum()) for t in rec.fingertips.values())
    assert rows["point"].shape == (n, 3) and len(rows["fingertip"]) == n
    assert np.all(rows["max_compression"] >= rows["compression"])


def test_recording_of_the_default_scene_is_y_up_in_scene_axes_and_z_up_in_world():
    path = ROOT / "recordings" / "default.mcap"
    scene = softgrip.open_recording(path)
    world = softgrip.open_recording(path, frame="world")
    assert world.frame == "world"
    box_s, box_w = scene.bodies["box"]["position"], world.bodies["box"]["position"]
    # scene (x, y, z) -> world (x, -z, y): the box rests 2 cm up the scene's y, the world's z
    np.testing.assert_array_equal(box_w, np.stack([box_s[:, 0], -box_s[:, 2], box_s[:, 1]], axis=1))
    assert abs(scene.bodies["box"]["position"][0, 1] - 0.02) < 1e-3
    f_s = scene.fingertips["left_tip"]["friction_force"]
    f_w = world.fingertips["left_tip"]["friction_force"]
    np.testing.assert_array_equal(f_w, np.stack([f_s[:, 0], -f_s[:, 2], f_s[:, 1]], axis=1))
    np.testing.assert_array_equal(scene.fingertips["left_tip"]["force"], world.fingertips["left_tip"]["force"])


def test_recorded_before_the_construction_existed():
    # crates/softgrip-record/tests/data/default_before_backing.mcap: the default grasp as
    # recorded on 2026-12-02 before `backing` was a SoftContact field (z-up, JSON metadata).
    rec = softgrip.open_recording(LEGACY / "default_before_backing.mcap")
    assert rec.laws["left_tip"]["backing"] == "free"
    assert set(rec.contact_rows["backing"].tolist()) == {0}
    assert abs(rec.summary["left_tip"]["peak_force"] - 11.82) < 0.005
    assert rec.fingertips["left_tip"]["force"].max() == pytest.approx(11.82, abs=0.01)
    assert rec.tactile["left_tip"].shape == (75, 16, 16)
    # z-up in the file: the box's 2 cm height is the scene's y
    assert abs(rec.bodies["box"]["position"][0, 1] - 0.02) < 1e-3


@pytest.mark.parametrize(
    "name,era",
    [
        ("default_text_metadata.mcap", "laws as text lines, summary as flat keys, y-up, /tf holds the fingertips"),
        ("default_y_up_tactile.mcap", "typed JSON metadata, tactile pads, y-up"),
    ],
)
def test_recordings_of_earlier_versions(name, era):
    # The default grasp as softgrip recorded it before 2026-12-01 (git show
    # 12ba9ad:recordings/default.mcap) and before the z-up frames (3d922f2): every value read
    # back in today's arrays, in the scene's axes (these files hold them already).
    rec = softgrip.open_recording(LEGACY / name)
    assert rec.frame == "scene" and list(rec.fingertips) == ["left_tip", "right_tip"], era
    assert list(rec.bodies) == ["table", "box", "left_jaw", "right_jaw"]
    law = rec.laws["left_tip"]
    assert (law["level"], law["setting"], law["youngs_modulus"], law["backing"]) == ("auto", 0.01, 590000.0, "free")
    assert rec.law("right_tip").tip_radius == 0.01
    assert rec.summary["left_tip"] == {
        "peak_force": 11.82173681913686, "peak_x": 0.2002445684016837, "slips": 2, "validity_excursions": 0,
    }
    assert rec.summary_steps == 300 and rec.every == 4 and len(rec.step) == 75
    assert rec.fingertips["left_tip"]["force"].max() == 11.82173681913686
    assert abs(rec.bodies["box"]["position"][0, 1] - 0.02) < 1e-3  # resting on the table, y-up
    world = softgrip.open_recording(LEGACY / name, frame="world")
    assert abs(world.bodies["box"]["position"][0, 2] - 0.02) < 1e-3
    if "tactile" in name:
        assert rec.tactile["left_tip"].shape == (75, 16, 16) and rec.tactile["left_tip"].max() > 0


def test_a_killed_writers_file_is_recovered(tmp_path: Path):
    src = ROOT / "recordings" / "ecoflex_sphere.mcap"
    cut = tmp_path / "killed.mcap"
    data = src.read_bytes()
    cut.write_bytes(data[: len(data) // 2])
    rec = softgrip.open_recording(cut)
    assert rec.recovery is not None and rec.recovery["file_len"] == len(data) // 2
    whole = softgrip.open_recording(src)
    n = len(rec.step)
    assert 0 <= n < len(whole.step)
    np.testing.assert_array_equal(rec.fingertips["sphere"]["force"], whole.fingertips["sphere"]["force"][:n])


def test_bad_files_and_arguments(tmp_path: Path):
    with pytest.raises(FileNotFoundError):
        softgrip.open_recording(tmp_path / "nothing.mcap")
    junk = tmp_path / "junk.mcap"
    junk.write_bytes(b"not an mcap file at all")
    with pytest.raises(RecordingFormatError) as e:
        softgrip.open_recording(junk)
    assert isinstance(e.value, ValueError) and "not an MCAP file" in str(e.value)
    damaged = tmp_path / "damaged.mcap"
    data = bytearray((ROOT / "recordings" / "default.mcap").read_bytes())
    data[len(data) // 3] ^= 0xFF
    damaged.write_bytes(bytes(data))
    with pytest.raises(RecordingFormatError) as e:
        softgrip.open_recording(damaged)
    assert "corrupt" in str(e.value) or "decode" in str(e.value)
    with pytest.raises(ParameterError) as e:
        softgrip.open_recording(ROOT / "recordings" / "default.mcap", frame="z-up")
    assert e.value.field == "frame"
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.open_recording(None)
    assert e.value.field == "path"


def test_a_sweeps_trial_recordings_open(tmp_path: Path, data: Path):
    # mcap_dir recordings of a sweep's trials are ordinary recordings: each opens, and its
    # summary's peak force is the trial row's.
    scene = tmp_path / "grasp.toml"
    shutil.copy(data / "grasp.toml", scene)
    sweep = tmp_path / "s.toml"
    sweep.write_text(
        'scene = "grasp.toml"\nmcap_dir = "runs"\n[[vary]]\nfield = "gripper.squeeze.depth"\nvalues = [0.001, 0.002]\n'
    )
    rows = softgrip.sweep(sweep, table="rows", threads=1)
    files = sorted((tmp_path / "runs").glob("*.mcap"))
    assert len(files) == 2
    cols = softgrip.Sweep.open(sweep).columns()
    for row, f in zip(rows, files):
        rec = softgrip.open_recording(f)
        peak = max(s["peak_force"] for s in rec.summary.values())
        assert math.isclose(peak, row[cols.index("peak_force")], rel_tol=1e-12)


def test_every_returned_field_is_documented_with_its_unit(data: Path, tmp_path: Path):
    # The tables of units are the documentation (RunResult's and Recording's docstrings are
    # made from them): every key a run or a recording returns is in one, with a unit.
    run = softgrip.run(softgrip.scenes.path("default"), mcap=tmp_path / "d.mcap")
    rec = softgrip.open_recording(tmp_path / "d.mcap")
    for r in (run, rec):
        for arrays in r.fingertips.values():
            assert set(arrays) == set(softgrip.FINGERTIP_ARRAYS)
        for arrays in r.bodies.values():
            assert set(arrays) == set(softgrip.BODY_ARRAYS)
        for s in r.summary.values():
            assert set(s) <= set(softgrip.SUMMARY_FIELDS)
    assert set(run.summary["left_tip"]) == set(softgrip.SUMMARY_FIELDS)
    assert set(rec.contact_rows) == set(softgrip.CONTACT_ROW_FIELDS)
    tables = (softgrip.FINGERTIP_ARRAYS, softgrip.BODY_ARRAYS, softgrip.SUMMARY_FIELDS, softgrip.CONTACT_ROW_FIELDS)
    for table in tables:
        for key, (unit, what) in table.items():
            assert unit and what, key
    for key in softgrip.FINGERTIP_ARRAYS:
        assert f"``{key}`` [{softgrip.FINGERTIP_ARRAYS[key][0]}]" in softgrip.RunResult.__doc__
        assert f"``{key}``" in softgrip.Recording.__doc__
