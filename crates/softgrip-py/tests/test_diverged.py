"""A run whose simulation diverges raises softgrip.SimulationDiverged with its fields, keeps
the readout up to the fault (``e.result``) and finishes the recording with those steps.

The scene (tests/data/falling.toml, also crates/softgrip-cli/tests/diverge/falling.toml) is
valid: a stone falls under 1000 g at dt = 1 s; rapier caps its speed at 400 m/s, so it passes
the step's bound on a position (1e6 m) in step 2501."""

import math
import pickle

import pytest

import softgrip


def test_run_raises_simulation_diverged_with_its_fields(data, tmp_path):
    out = tmp_path / "falling.mcap"
    with pytest.raises(softgrip.SimulationDiverged) as info:
        softgrip.run(data / "falling.toml", mcap=out)
    e = info.value
    assert isinstance(e, softgrip.SoftgripError) and isinstance(e, ArithmeticError)
    assert (e.kind, e.step, e.time) == ("diverged", 2501, 2500.0)
    assert (e.subject, e.name, e.quantity, e.phase) == ("body", "stone", "position [m]", "after")
    # 2500 steps of 400 m from y = 1 m, less the first step's 400 m/s reached from rest.
    assert e.found == pytest.approx(-1000399.0, abs=1.0)
    assert e.bound == 1e6
    assert e.field == "position [m]" and float(e.value) == e.found
    assert "diverged at step 2501" in str(e) and "`stone`" in str(e)
    # Nothing recorded so far is lost: the readout of every step before the fault ...
    r = e.result
    assert isinstance(r, softgrip.RunResult)
    assert (r.steps, r.total_steps) == (2500, 3000)
    y = r.bodies["stone"]["position"][:, 1]
    assert len(y) == 2500 and all(math.isfinite(v) for v in y)
    assert y[-1] == pytest.approx(-999999.0, abs=1.0)
    # ... and the finished recording of them.
    rec = softgrip.open_recording(out)
    assert rec.recovery is None or not rec.recovery
    assert rec.time[-1] == pytest.approx(2500.0)
    assert rec.bodies["stone"]["position"][-1, 1] == pytest.approx(y[-1], abs=1.0)
    # It pickles with its fields (Ray and multiprocessing send exceptions back).
    e2 = pickle.loads(pickle.dumps(e))
    assert (type(e2), e2.step, e2.name, e2.found, str(e2)) == (
        softgrip.SimulationDiverged, 2501, "stone", e.found, str(e))


def test_run_toml_raises_it_too(data):
    text = (data / "falling.toml").read_text()
    with pytest.raises(softgrip.SimulationDiverged) as info:
        softgrip.run_toml(text)
    assert info.value.step == 2501 and info.value.name == "stone"
