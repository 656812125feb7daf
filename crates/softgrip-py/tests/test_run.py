"""A scene run from Python equals `softgrip run` on the same scene value for value: the
summary lines character for character, the digest of every contact value of every step bit
for bit, and the recordings' exported CSVs byte for byte; the per-step readout equals the
recording's contacts."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

import softgrip

SCENES = ["tests/data/grasp.toml", "scenes/ecoflex_sphere.toml"]


def cli_run(cli, scene, *extra):
    _, out, _ = cli("run", scene, "--digest", *extra)
    lines = out.splitlines()
    digest = [l for l in lines if l.startswith("digest ")]
    summary = [l for l in lines if l.startswith("scene ") or l.startswith("fingertip ")]
    return summary, digest[0], lines


def scene_path(root: Path, rel: str) -> str:
    # The path as the CLI is given it (relative to the root), so that origins match.
    return rel if not rel.startswith("tests/") else str(Path("crates/softgrip-py") / rel)


@pytest.mark.parametrize("rel", SCENES)
def test_run_equals_cli(cli, root, monkeypatch, rel):
    scene = scene_path(root, rel)
    summary, digest, _ = cli_run(cli, scene)
    monkeypatch.chdir(root)
    r = softgrip.run(scene)
    assert r.summary_lines == summary
    assert r.digest == digest
    assert r.steps == r.total_steps == len(r.time)
    assert r.digest.split()[3] == str(r.steps)
    np.testing.assert_allclose(r.time, np.arange(1, r.steps + 1) * r.dt, rtol=1e-15)
    for name, s in r.summary.items():
        tip = r.fingertips[name]
        # the summary's peak is the largest substep force of any one contact (the readout's
        # `force` sums a fingertip's contacts: the sphere between two plates has two)
        assert tip["force"].max() > 0
        assert s["peak_force"] == tip["peak_force"].max()
        assert s["peak_x"] >= tip["x"].max()
        assert tip["friction_force"].shape == (r.steps, 3)


def test_default_scene_equals_cli(cli, monkeypatch, root):
    _, out, _ = cli("run", "--digest")
    monkeypatch.chdir(root)
    r = softgrip.run()
    assert r.digest in out.splitlines()
    assert all(l in out.splitlines() for l in r.summary_lines)


def test_run_toml_equals_run_file(data: Path):
    a = softgrip.run(data / "grasp.toml")
    b = softgrip.run_toml((data / "grasp.toml").read_text(), base_dir=data)
    assert a.digest == b.digest
    assert b.origin == "<toml>"
    for name in a.fingertips:
        for key, values in a.fingertips[name].items():
            np.testing.assert_array_equal(values, b.fingertips[name][key])
    for name in a.bodies:
        np.testing.assert_array_equal(a.bodies[name]["position"], b.bodies[name]["position"])


def read_csv(path: Path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_recording_equals_cli_recording(cli, root, tmp_path, monkeypatch):
    scene = "crates/softgrip-py/tests/data/grasp.toml"
    cli_mcap, py_mcap = tmp_path / "cli.mcap", tmp_path / "py.mcap"
    cli("run", scene, "--out", cli_mcap, "--every", "2")
    monkeypatch.chdir(root)
    r = softgrip.run(scene, mcap=py_mcap, every=2)
    rec = r.recording
    assert rec["path"] == str(py_mcap) and rec["every"] == 2
    assert rec["frames"] == r.steps // 2 and rec["bytes"] == py_mcap.stat().st_size > 0
    cli("export", cli_mcap, "--csv", tmp_path / "cli")
    cli("export", py_mcap, "--csv", tmp_path / "py")
    for name in ["contacts.csv", "wrenches.csv", "poses.csv", "clock.csv"]:
        a = (tmp_path / "cli" / name).read_bytes()
        b = (tmp_path / "py" / name).read_bytes()
        assert a == b, name
        assert a.count(b"\n") > 1, name
    # The readout at the recorded steps is the recording's contacts, value for value (one
    # contact per fingertip in this grasp).
    rows = read_csv(tmp_path / "py" / "contacts.csv")
    assert rows
    for row in rows:
        step = round(float(row["time_s"]) / r.dt)
        tip = r.fingertips[row["fingertip"]]
        i = step - 1
        assert tip["contacts"][i] == 1
        assert float(row["normal_force_N"]) == pytest.approx(tip["force"][i], rel=1e-15, abs=0)
        assert float(row["compression_m"]) == pytest.approx(tip["delta"][i], rel=1e-15, abs=0)
        assert float(row["ratio_x"]) == pytest.approx(tip["x"][i], rel=1e-15, abs=0)
        if float(row["contact_radius_m"]) > 0:
            assert float(row["contact_radius_m"]) == pytest.approx(tip["radius"][i], rel=1e-12)
    # Overwriting needs overwrite=True, and gives the same file contents.
    r2 = softgrip.run(scene, mcap=py_mcap, every=2, overwrite=True)
    assert r2.digest == r.digest


def test_runs_are_deterministic(data: Path):
    a = softgrip.run(data / "grasp.toml")
    b = softgrip.run(data / "grasp.toml")
    assert a.digest == b.digest
    np.testing.assert_array_equal(a.bodies["box"]["position"], b.bodies["box"]["position"])
    # the box is lifted 2 cm in the hold (y up)
    y = a.bodies["box"]["position"][:, 1]
    assert y.max() - y[0] > 0.01
