"""Bad input is a typed Python exception carrying the Rust error's message and naming the
field; never a panic (pyo3's PanicException) crossing into Python."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import softgrip
from softgrip import OutOfRangeError, ParameterError, SceneError, SoftgripError, SweepError


@pytest.mark.parametrize(
    "kwargs,field,text",
    [
        (dict(youngs_modulus=-3e6), "youngs_modulus", "`youngs_modulus` must be finite and > 0 Pa, got -3000000"),
        (dict(youngs_modulus=math.nan), "youngs_modulus", "`youngs_modulus` must be"),
        (dict(poisson_ratio=0.7), "poisson_ratio", "`poisson_ratio` must be"),
        (dict(radius=0.0), "radius", "`radius` must be"),
        (dict(backing="core"), "thickness", "`thickness` must be given"),
        (dict(backing="core", thickness=0.01), "thickness", "`thickness` must be finite and in (0, R) m"),
        (dict(backing="flat", thickness=0.002), "thickness", "`thickness` must be None"),
        (dict(backing="glued"), "backing", "unknown backing `glued`"),
        (dict(level="spring"), "level", "unknown level `spring`"),
        (dict(level="hertz", k=1.0), "k", "`k` must be given only with level \"fit\""),
        (dict(level="fit", k=11.0), "k", "`k` must be finite and in [0, 10]"),
        (dict(level="auto", tolerance=0.9), "tolerance", "`tolerance` must be in (0, 0.5]"),
        (dict(level="neo-hookean", poisson_ratio=0.5), "level", "cannot be used with Poisson ratio nu = 0.5"),
    ],
)
def test_law_parameter_errors_name_the_field(kwargs, field, text):
    args = dict(level="calibrated", youngs_modulus=3e6, poisson_ratio=0.49, radius=0.01)
    args.update(kwargs)
    with pytest.raises(ParameterError) as e:
        softgrip.law(**args)
    assert e.value.field == field
    assert text in str(e.value)
    assert isinstance(e.value, ValueError) and isinstance(e.value, SoftgripError)


def test_checked_queries_raise_out_of_range():
    tip = softgrip.law("fit", 3e6, 0.49, 0.01)
    with pytest.raises(OutOfRangeError) as e:
        tip.force(0.0095, checked=True)  # x = 0.95 > x_max = 0.81
    assert e.value.field == "delta"
    assert "outside the validity range of level `fit`" in str(e.value)
    with pytest.raises(OutOfRangeError) as e:
        tip.force(np.array([0.001, 0.002, 0.0095]), checked=True)
    assert "at flat index 2 of `delta`" in str(e.value)
    with pytest.raises(ParameterError) as e:
        tip.energy(-1e-3, checked=True)
    assert e.value.field == "delta" and "`delta` must be finite and >= 0 m" in str(e.value)
    with pytest.raises(OutOfRangeError) as e:
        tip.delta_for_force(1e9)
    assert e.value.field == "force" and "force 1000000000 N is outside the range" in str(e.value)
    with pytest.raises(ParameterError) as e:
        tip.force("four millimetres")
    assert e.value.field == "delta"


def test_fit_errors_name_the_field():
    with pytest.raises(ParameterError) as e:
        softgrip.fit_material([0.001], [1.0], 0.01, 0.49)
    assert e.value.field == "samples" and "need at least 2 samples" in str(e.value)
    with pytest.raises(ParameterError) as e:
        softgrip.fit_material([0.001, 0.002], [1.0], 0.01, 0.49)
    assert e.value.field == "force"
    with pytest.raises(ParameterError) as e:
        softgrip.fit_material([0.001, 0.002], [1.0, 2.0], -0.01, 0.49)
    assert e.value.field == "radius"


def test_scene_errors_name_the_field(data: Path):
    text = (data / "grasp.toml").read_text()
    bad = text.replace("youngs_modulus = 0.59e6", "youngs_modulus = -5.0", 1)
    assert bad != text
    with pytest.raises(SceneError) as e:
        softgrip.run_toml(bad)
    assert e.value.field == "fingertip[0].material.youngs_modulus"
    assert "<toml>" in str(e.value) and "youngs_modulus" in str(e.value)
    with pytest.raises(SceneError) as e:
        softgrip.run_toml(text.replace("duration = 1.2", "duration = 1.2\nbogus = 1", 1))
    assert "unknown field `bogus`" in str(e.value)
    with pytest.raises(SceneError) as e:
        softgrip.run(data / "no_such_scene.toml")
    assert "no_such_scene.toml" in str(e.value)
    with pytest.raises(ParameterError) as e:
        softgrip.run(data / "grasp.toml", every=0)
    assert e.value.field == "every"


def test_existing_recording_is_not_replaced(tmp_path: Path, data: Path):
    out = tmp_path / "run.mcap"
    out.write_bytes(b"precious")
    with pytest.raises(FileExistsError):
        softgrip.run(data / "grasp.toml", mcap=out)
    assert out.read_bytes() == b"precious"


def test_sweep_errors_name_the_field(tmp_path: Path, data: Path):
    bad = tmp_path / "bad.toml"
    bad.write_text(
        f'scene = "{(data / "grasp.toml").as_posix()}"\n'
        '[[vary]]\nfield = "fingertip[0].material.youngs_modulu"\nvalues = [1e6]\n'
    )
    with pytest.raises(SweepError) as e:
        softgrip.sweep(bad)
    assert e.value.field == "vary[0].field"
    assert "youngs_modulu" in str(e.value)
    with pytest.raises(SweepError) as e:
        softgrip.sweep(data / "grasp_sweep.toml", shard="3/2")
    assert e.value.field == "shard"
    with pytest.raises(SweepError) as e:
        softgrip.Sweep.open(str(data / "grasp_sweep.toml")).run_trial(16)
    assert e.value.field == "trial" and "in 0..16" in str(e.value)
    with pytest.raises(ParameterError) as e:
        softgrip.sweep(data / "grasp_sweep.toml", backend="dask")
    assert e.value.field == "backend"


def test_hostile_inputs_never_panic():
    # Whatever the numbers, the law's hot path returns finite values and no PanicException.
    rng = np.random.default_rng(1)
    values = np.concatenate(
        [
            rng.normal(0, 1, 2000) * 10.0 ** rng.integers(-300, 300, 2000),
            [math.nan, math.inf, -math.inf, 0.0, -0.0, 5e-324, 1.7e308],
        ]
    )
    for level in softgrip.LEVELS:
        tip = softgrip.law(level, 3e6, 0.49, 0.01)
        for method in ("force", "stiffness", "energy", "radius", "pressure_shape", "pressure_taper"):
            out = getattr(tip, method)(values)
            assert np.all(np.isfinite(out)), (level, method)
        for method in ("mean_pressure", "peak_pressure"):
            out = getattr(tip, method)(values)
            assert np.all(np.isfinite(out)), (level, method)
        assert np.all(np.isfinite(tip.pressure(0.004, values)))
        with pytest.raises(SoftgripError):
            tip.delta_for_force(values)


def test_pressure_at_subnormal_compression_is_finite():
    # ContactPatch's mean pressure F / (pi a^2) was inf when a^2 underflowed (delta = 5e-324 m
    # at level `linear`); it now tends to 0 with delta, like the pressure at any other small delta.
    for level in softgrip.LEVELS:
        tip = softgrip.law(level, 3e6, 0.49, 0.01)
        for method in ("mean_pressure", "peak_pressure"):
            p = getattr(tip, method)(np.array([5e-324, 1e-320, 1e-310]))
            assert np.all(np.isfinite(p)), (level, method, p)
            if level == "linear":
                # F / (pi a^2) = k delta / (pi R delta): the same at every compression (to the
                # few significant bits of a subnormal force: 0.6 % at 5e-324 m).
                ref = getattr(tip, method)(1e-11)
                assert np.allclose(p, ref, rtol=1e-2, atol=0.0), (level, method, p, ref)
            else:
                # p ~ E* sqrt(delta / R): far below 1 Pa here.
                assert np.all(p >= 0.0) and np.all(p < 1.0), (level, method, p)
