"""Bad input is a typed Python exception carrying the Rust error's message and naming the
field; never a panic (pyo3's PanicException) crossing into Python."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import softgrip
from softgrip import (
    ArgumentTypeError,
    OutOfRangeError,
    ParameterError,
    RecordingExistsError,
    SceneError,
    SoftgripError,
    SweepError,
    TrialIndexError,
)


@pytest.mark.parametrize(
    "kwargs,field,text",
    [
        (dict(youngs_modulus=-3e6), "youngs_modulus", "`youngs_modulus` must be finite and > 0 Pa, got -3000000"),
        (dict(youngs_modulus=math.nan), "youngs_modulus", "`youngs_modulus` must be"),
        (dict(poisson_ratio=0.7), "poisson_ratio", "`poisson_ratio` must be"),
        (dict(radius=0.0), "radius", "`radius` must be"),
        (dict(backing="core"), "thickness", "`thickness` is required with backing `core`"),
        (dict(backing="core", thickness=0.01), "thickness", "`thickness` must be finite and in (0, R) m"),
        (dict(backing="flat", thickness=0.002), "thickness", "`thickness` applies only to backing `core`, not to backing `flat`"),
        (dict(backing="glued"), "backing", "`backing` must be one of free, flat, core, got `glued`"),
        (dict(level="spring"), "level", "`level` must be one of linear, hertz, fit,"),
        (dict(level="hertz", k=1.0), "k", "`k` applies only to level `fit`, not to level `hertz`"),
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
    # A string is not a compression: a TypeError (softgrip's ArgumentTypeError), as numpy's
    # ufuncs refuse one (it was a ParameterError, a ValueError, before).
    with pytest.raises(ArgumentTypeError) as e:
        tip.force("four millimetres")
    assert e.value.field == "delta" and isinstance(e.value, TypeError)


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
    with pytest.raises(FileExistsError) as e:
        softgrip.run(data / "grasp.toml", mcap=out)
    assert isinstance(e.value, RecordingExistsError) and e.value.field == "mcap"
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
    with pytest.raises(TrialIndexError) as e:
        softgrip.Sweep.open(str(data / "grasp_sweep.toml")).run_trial(16)
    assert e.value.field == "trial" and "in 0..16" in str(e.value)
    assert isinstance(e.value, SweepError) and isinstance(e.value, IndexError)
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
    finite = np.isfinite(values)
    for level in softgrip.LEVELS:
        tip = softgrip.law(level, 3e6, 0.49, 0.01)
        for method in (
            "force", "stiffness", "energy", "radius", "pressure_shape", "pressure_taper",
            "mean_pressure", "peak_pressure",
        ):
            out = getattr(tip, method)(values)
            # finite for every finite compression; NaN (numpy's undefined) for NaN and +-inf
            assert np.all(np.isfinite(out[finite])), (level, method)
            assert np.all(np.isnan(out[~finite])), (level, method)
        p = tip.pressure(0.004, values)
        assert np.all(np.isfinite(p[~np.isnan(values)])) and np.all(np.isnan(p[np.isnan(values)]))
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


# --- numpy semantics and softgrip's own exceptions (issue 26) ---------------------------------

TIP = dict(level="calibrated", youngs_modulus=3e6, poisson_ratio=0.49, radius=0.01)


@pytest.mark.parametrize("method", ["force", "stiffness", "energy", "radius", "mean_pressure",
                                    "peak_pressure", "pressure_shape", "pressure_taper", "valid"])
def test_nan_in_gives_nan_out_not_zero_newtons(method):
    # Regression: NaN (and None in an array) gave 0 N silently.
    tip = softgrip.law(**TIP)
    f = getattr(tip, method)
    assert math.isnan(f(math.nan))
    out = f(np.array([0.004, math.nan, 0.002]))
    assert math.isnan(out[1]) and np.isfinite(out[0]) and np.isfinite(out[2])
    assert out[0] == f(0.004) and out[2] == f(0.002)
    if method != "valid":
        assert math.isnan(f(math.inf)) and math.isnan(f(-math.inf))
    # the float32 and integer dtypes convert; a NaN in float32 stays NaN
    assert math.isnan(f(np.array([math.nan], dtype=np.float32))[0])


def test_nan_force_and_radius_in_the_inverse_and_profile():
    tip = softgrip.law(**TIP)
    back = tip.delta_for_force(np.array([1.0, math.nan]))
    assert math.isnan(back[1]) and back[0] == tip.delta_for_force(1.0)
    p = tip.pressure(0.004, np.array([0.0, math.nan, math.inf]))
    assert p[0] == tip.peak_pressure(0.004) and math.isnan(p[1]) and p[2] == 0.0
    assert np.all(np.isnan(tip.pressure(math.nan, [0.0, 0.001])))
    with pytest.raises(ParameterError) as e:
        tip.delta_for_force(math.inf)
    assert e.value.field == "force" and "must be finite and >= 0 N" in str(e.value)


@pytest.mark.parametrize("bad", [None, "0.004", b"0.004", [0.001, None], ["0.001"], [1 + 2j],
                                 np.array([0.001, None], dtype=object), {"delta": 0.004}])
def test_none_and_strings_are_a_type_error(bad):
    # Regression: None gave 0 N silently; strings were a ValueError.
    tip = softgrip.law(**TIP)
    with pytest.raises(ArgumentTypeError) as e:
        tip.force(bad)
    assert isinstance(e.value, TypeError) and isinstance(e.value, SoftgripError)
    assert e.value.field == "delta" and "a number or an array-like of numbers" in str(e.value)


@pytest.mark.parametrize("field", ["youngs_modulus", "poisson_ratio", "radius"])
@pytest.mark.parametrize("bad", [None, "3e6", b"1", [3e6]])
def test_law_arguments_of_the_wrong_type(field, bad):
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.law(**{**TIP, field: bad})
    assert e.value.field == field and "must be a real number" in str(e.value)


@pytest.mark.parametrize(
    "kwargs,field",
    [
        (dict(level=3), "level"),
        (dict(level=None), "level"),
        (dict(backing=1), "backing"),
        (dict(backing="core", thickness="4 mm"), "thickness"),
        (dict(level="fit", k="1.1"), "k"),
        (dict(level="auto", tolerance=[0.01]), "tolerance"),
    ],
)
def test_named_arguments_of_the_wrong_type(kwargs, field):
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.law(**{**TIP, **kwargs})
    assert e.value.field == field


def test_numpy_scalars_and_ints_are_numbers():
    a = softgrip.law("calibrated", np.float32(3e6), np.float64(0.49), 0.01)
    b = softgrip.law("calibrated", 3_000_000, 0.49, np.float64(0.01))
    assert a.force(0.004) == softgrip.law(**TIP).force(np.int64(0) + 0.004) == b.force(0.004)
    with pytest.raises(ArgumentTypeError):
        softgrip.law(**TIP).force(0.004, checked="yes")


def test_fit_material_takes_its_levels_setting():
    # Regression: `fit_material(..., level="fit", k=...)` was refused though the stub took k.
    tip = softgrip.law("fit", 3e6, 0.49, 0.01, k=1.5)
    delta = np.linspace(0.0005, 0.006, 30)
    fit = softgrip.fit_material(delta, tip.force(delta), 0.01, 0.49, x_fit=0.6, level="fit", k=1.5)
    assert abs(fit.youngs_modulus / 3e6 - 1) < 1e-12
    default_k = softgrip.fit_material(delta, tip.force(delta), 0.01, 0.49, x_fit=0.6, level="fit")
    assert abs(default_k.youngs_modulus / 3e6 - 1) > 1e-3  # k = 10/9 does not fit k = 1.5 data
    with pytest.raises(ParameterError) as e:
        softgrip.fit_material(delta, tip.force(delta), 0.01, 0.49, level="hertz", k=1.5)
    assert e.value.field == "k"
    with pytest.raises(ParameterError) as e:
        softgrip.fit_material([0.001, math.nan, 0.002], [1.0, 2.0, 3.0], 0.01, 0.49)
    assert e.value.field == "samples"
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.fit_material(delta, None, 0.01, 0.49)
    assert e.value.field == "force"


@pytest.mark.parametrize("index", [-1, 16, 2**64, 2**70, -(2**70)])
def test_run_trial_out_of_range_is_a_trial_index_error(data: Path, index):
    # Regression: run_trial(-1) was an OverflowError.
    s = softgrip.Sweep.open(data / "grasp_sweep.toml")
    with pytest.raises(TrialIndexError) as e:
        s.run_trial(index)
    assert e.value.field == "trial" and str(index) in str(e.value) and "in 0..16" in str(e.value)
    with pytest.raises(TrialIndexError):
        s.scene_text(index)


@pytest.mark.parametrize("index", [1.0, "3", None, True])
def test_run_trial_index_of_the_wrong_type(data: Path, index):
    s = softgrip.Sweep.open(data / "grasp_sweep.toml")
    with pytest.raises(ArgumentTypeError) as e:
        s.run_trial(index)
    assert e.value.field == "trial"


def test_run_trial_takes_numpy_integers(data: Path):
    s = softgrip.Sweep.open(data / "grasp_sweep.toml")
    assert s.run_trial(np.int64(3))[0] == 3 and s.scene_text(np.uint8(3)) == s.scene_text(3)


def test_run_and_sweep_arguments(data: Path, tmp_path: Path):
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.run(42)
    assert e.value.field == "scene"
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.run(data / "grasp.toml", every=2.0)
    assert e.value.field == "every"
    with pytest.raises(ParameterError) as e:
        softgrip.run(data / "grasp.toml", every=-(2**70))
    assert e.value.field == "every"
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.run(data / "grasp.toml", mcap=tmp_path / "a.mcap", overwrite="no")
    assert e.value.field == "overwrite"
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.run_toml(None)
    assert e.value.field == "toml"
    sweep = data / "grasp_sweep.toml"
    for kwargs, cls, field in [
        (dict(threads=0), ParameterError, "threads"),
        (dict(threads=2.0), ArgumentTypeError, "threads"),
        (dict(backend=None), ArgumentTypeError, "backend"),
        (dict(shard=(0.0, 2)), ArgumentTypeError, "shard"),
        (dict(shard="a/b"), ParameterError, "shard"),
        (dict(table="pandas"), ParameterError, "table"),
    ]:
        with pytest.raises(cls) as e:
            softgrip.sweep(sweep, **kwargs)
        assert e.value.field == field, kwargs
    with pytest.raises(ArgumentTypeError) as e:
        softgrip.sweep(3.5)
    assert e.value.field == "sweep_path"
    with pytest.raises(ParameterError) as e:
        softgrip.Sweep.open(sweep).run(threads=10**6)
    assert e.value.field == "threads"


def test_the_hierarchy_is_the_builtins_a_user_catches():
    from softgrip import errors

    expect = {
        "ParameterError": ValueError,
        "OutOfRangeError": ValueError,
        "ArgumentTypeError": TypeError,
        "SceneError": ValueError,
        "SweepError": ValueError,
        "TrialIndexError": IndexError,
        "RecordingExistsError": FileExistsError,
        "RecordingFormatError": ValueError,
        "SimulationDiverged": ArithmeticError,
    }
    for name in errors.__all__:
        cls = getattr(errors, name)
        assert issubclass(cls, SoftgripError), name
        if name in expect:
            assert issubclass(cls, expect[name]), name
    assert set(expect) | {"SoftgripError", "RecordingError"} == set(errors.__all__)
