"""The package's law equals the Rust law (`softgrip curve`, shortest round-trip output) to
1e-12 at every level, backing and sample, past x_max included; the inverse, the pressure
profile, vectorisation and material fitting."""

from __future__ import annotations

import csv
import io
import math

import numpy as np
import pytest

import softgrip

E, R = 3.0e6, 0.010
CORE_T = 0.4  # t/R of the core backing
BACKINGS = [("free", None), ("flat", None), ("core", CORE_T * R)]
TOL = 1e-12


def close(a: float, b: float, tol: float = TOL) -> bool:
    """Relative to the larger magnitude; values below 1e-300 compare as zeros."""
    if abs(a) < 1e-300 and abs(b) < 1e-300:
        return True
    return abs(a - b) <= tol * max(abs(a), abs(b))


def curve(cli, level, nu, backing, t, *extra):
    args = ["curve", "--level", level, "--nu", nu, "--backing", backing, *extra]
    if t is not None:
        args += ["--thickness", t / R]
    code, out, err = cli(*args, check=False)
    return code, out, err


@pytest.mark.parametrize("nu", [0.3, 0.49])
@pytest.mark.parametrize("backing,thickness", BACKINGS)
@pytest.mark.parametrize("level", softgrip.LEVELS)
def test_law_equals_rust_curve(cli, level, nu, backing, thickness):
    code, out, err = curve(cli, level, nu, backing, thickness, "--x", "0.01:0.9:0.01")
    try:
        tip = softgrip.law(level, E, nu, R, backing, thickness)
    except softgrip.ParameterError as e:
        # The Rust law refuses the same combination.
        assert code != 0, f"Python refused ({e}) but `softgrip curve` did not"
        return
    assert code == 0, f"`softgrip curve` refused ({err}) but Python built {tip!r}"
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 90
    e_star = E / (1 - nu * nu)
    assert close(tip.effective_modulus, e_star, 1e-15)
    x = np.array([float(r["x"]) for r in rows])
    delta = x * R
    got = {
        "force_norm": tip.force(delta) / (e_star * R**2),
        "stiffness_norm": tip.stiffness(delta) / (e_star * R),
        "energy_norm": tip.energy(delta) / (e_star * R**3),
        "radius_norm": tip.radius(delta) / R,
        "p_mean_norm": tip.mean_pressure(delta) / e_star,
    }
    for col, values in got.items():
        for i, r in enumerate(rows):
            want = float(r[col])
            assert close(values[i], want), (col, r["x"], values[i], want)
    valid = tip.valid(delta)
    assert [int(v) for v in valid] == [int(r["valid"]) for r in rows]
    assert any(int(r["valid"]) == 0 for r in rows) or tip.x_max >= 0.9
    assert close(tip.delta_max, tip.x_max * R, 1e-15)


@pytest.mark.parametrize("backing,thickness", BACKINGS)
@pytest.mark.parametrize("level", ["hertz", "calibrated", "neo-hookean"])
def test_pressure_profile_equals_rust(cli, level, backing, thickness):
    nu = 0.49
    tip = softgrip.law(level, E, nu, R, backing, thickness)
    x = min(0.3, round(0.9 * tip.x_max, 3))  # inside the range (calibrated core: x_max 0.24)
    code, out, _ = curve(cli, level, nu, backing, thickness, "--profile", x)
    assert code == 0
    e_star = tip.effective_modulus
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 50
    r = np.array([float(row["r_norm"]) for row in rows]) * R
    p = tip.pressure(x * R, r) / e_star
    for i, row in enumerate(rows):
        # r/R printed and re-scaled: p(r) near the rim is steep; the centre is exact.
        assert close(p[i], float(row["p_norm"]), 1e-9), (row, p[i])
    assert close(p[0], float(rows[0]["p_norm"]))
    assert close(tip.peak_pressure(x * R), p[0] * e_star)
    assert p[-1] == 0.0  # r = a: the rim


def test_the_core_profile_is_tapered_and_carries_the_force():
    # p(r) = p0 (1 - r^2/a^2)^m (1 + b r^2/a^2): b = 0 for free and flat, < 0 over a core.
    for backing, thickness in [("free", None), ("flat", None)]:
        tip = softgrip.law("calibrated", E, 0.49, R, backing, thickness)
        assert tip.pressure_taper(0.2 * R) == 0.0
    tip = softgrip.law("calibrated", E, 0.49, R, "core", 0.3 * R)
    delta = 0.15 * R
    m, b = tip.pressure_shape(delta), tip.pressure_taper(delta)
    assert -1.0 <= b < -0.05 and 0.0 <= m <= 2.0, (m, b)
    a, p0 = tip.radius(delta), tip.peak_pressure(delta)
    r = np.linspace(0.0, a, 20001)[:-1]
    rho2 = (r / a) ** 2
    want = p0 * (1.0 - rho2) ** m * (1.0 + b * rho2)
    got = tip.pressure(delta, r)
    assert np.max(np.abs(got - want)) <= 1e-12 * p0
    # The integral of p over the patch is the force (midpoint rule in r).
    mid = 0.5 * (r[1:] + r[:-1])
    carried = np.sum(tip.pressure(delta, mid) * 2.0 * np.pi * mid * np.diff(r))
    assert abs(carried / tip.force(delta) - 1.0) < 1e-4


def test_scalars_arrays_and_shapes():
    tip = softgrip.law("calibrated", E, 0.49, R)
    f = tip.force(0.004)
    assert isinstance(f, float)
    assert isinstance(tip.force(np.float64(0.004)), float)
    assert isinstance(tip.force(4), float)  # an int: 4 m, far past x_max (the extension)
    grid = np.linspace(0.0, 0.006, 12).reshape(3, 4)
    out = tip.force(grid)
    assert out.shape == (3, 4) and out.dtype == np.float64
    assert out[1, 2] == tip.force(float(grid[1, 2]))
    assert tip.force([0.001, 0.002]).tolist() == [tip.force(0.001), tip.force(0.002)]
    f32 = tip.force(np.array([0.004], dtype=np.float32))
    assert f32[0] == tip.force(float(np.float32(0.004)))
    assert tip.force(np.array(0.004)).shape == ()
    # hot path: no contact gives 0; a non-finite compression gives NaN as in numpy (it gave
    # 0 N silently before issue 26)
    out = tip.force([-1e-3, 0.0, math.nan])
    assert out[:2].tolist() == [0.0, 0.0] and math.isnan(out[2])
    assert math.isnan(tip.force(math.inf)) and math.isnan(tip.force(-math.inf))
    # stiffness is the derivative of the force (central difference)
    d, h = 0.004, 1e-8
    fd = (tip.force(d + h) - tip.force(d - h)) / (2 * h)
    assert abs(fd / tip.stiffness(d) - 1) < 1e-6


@pytest.mark.parametrize("level", softgrip.LEVELS)
def test_inverse_round_trip(level):
    tip = softgrip.law(level, E, 0.49, R)
    delta = np.linspace(0.05, 0.95, 19) * tip.delta_max
    force = tip.force(delta)
    back = tip.delta_for_force(force)
    assert back.shape == delta.shape
    np.testing.assert_allclose(back, delta, rtol=1e-9)
    assert tip.delta_for_force(0.0) == 0.0


def test_fit_material_recovers_the_modulus():
    # Samples of the calibrated law (E = 3 MPa): fitting with `calibrated` recovers E, Hertz
    # inflates it (the finite-size excess), and every level reports its residuals.
    nu = 0.49
    tip = softgrip.law("calibrated", E, nu, R)
    delta = np.linspace(0.002, 0.6, 60) * R
    force = tip.force(delta)
    fit = softgrip.fit_material(delta, force, R, nu, x_fit=0.1, level="calibrated")
    assert abs(fit.youngs_modulus / E - 1) < 1e-12
    assert fit.fitted == int(np.sum(delta / R <= 0.1))
    np.testing.assert_array_equal(fit.predicted, delta[delta / R > 0.1])
    assert fit.residuals["calibrated"]["max_abs_error"] < 1e-12
    assert set(fit.residuals) == set(softgrip.LEVELS)
    hertz = softgrip.fit_material(delta, force, R, nu)
    assert hertz.youngs_modulus > E  # Hertz is too soft at finite x: it fits a stiffer E
    errors = hertz.residuals["hertz"]["relative_errors"]
    assert errors.shape == fit.predicted.shape


def test_hertz_fit_is_exact_on_hertz_samples():
    # softgrip-law's doc example: Hertz samples with E* = 2 MPa, R = 5 mm.
    r = 0.005
    d = np.arange(1, 21) * 1e-4
    f = 4.0 / 3.0 * 2e6 * math.sqrt(r) * d**1.5
    fit = softgrip.fit_material(d, f, r, 0.5, 0.1, "hertz")
    assert abs(fit.effective_modulus / 2e6 - 1) < 1e-12


def _possible_values(help_text: str, option: str) -> list[str]:
    """The names under `Possible values:` of `--option` in `softgrip curve --help`."""
    rest = help_text[help_text.index(f"--{option} <"):]
    lines = rest[rest.index("Possible values:"):].splitlines()[1:]
    names = []
    for line in lines:
        line = line.strip()
        if not line.startswith("- "):
            break
        names.append(line[2:].split(":", 1)[0])
    return names


def test_kinds_are_the_law_tables(cli):
    # softgrip.LEVELS and BACKINGS come from softgrip-law's tables, as the CLI's --help does.
    _, out, _ = cli("curve", "--help")
    assert list(softgrip.LEVELS) == _possible_values(out, "level")
    assert list(softgrip.BACKINGS) == _possible_values(out, "backing")
    for level in softgrip.LEVELS:
        assert softgrip.law(level, 3e6, 0.45, 0.01).level == level
    # softgrip.CONTROLLERS: softgrip-scene's table of controller kinds, in its order (codes 0..3).
    assert softgrip.CONTROLLERS == ("parallel_jaws", "trajectory", "grasp", "joint_commands")
