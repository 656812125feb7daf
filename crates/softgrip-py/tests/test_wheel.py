"""The wheel installs into a fresh venv and imports: SOFTGRIP_WHEEL (the wheel .ci/test builds)
is installed with pip into a new venv, which imports softgrip, evaluates the law and finds the
stubs. The wheel is abi3 (one wheel for every CPython >= 3.9)."""

from __future__ import annotations

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest


def wheel() -> Path:
    w = os.environ.get("SOFTGRIP_WHEEL")
    if not w:
        print("test_wheel.py: skipped: SOFTGRIP_WHEEL is not set (.ci/test sets it)", file=sys.stderr)
        pytest.skip("SOFTGRIP_WHEEL is not set: .ci/test sets it to the wheel it built")
    return Path(w)


def test_wheel_is_abi3_with_stubs():
    w = wheel()
    assert "-cp39-abi3-" in w.name, w.name
    names = zipfile.ZipFile(w).namelist()
    for f in ["softgrip/__init__.py", "softgrip/py.typed", "softgrip/_native.pyi", "softgrip/errors.py"]:
        assert f in names, f
    assert any(n.startswith("softgrip/_native") and n.endswith(".so") for n in names)


def test_wheel_installs_into_a_fresh_venv(tmp_path):
    w = wheel()
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    py = venv / "bin" / "python"
    # numpy from the index (or pip's cache) as the wheel's one dependency
    subprocess.run(
        [str(py), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", str(w)],
        check=True,
    )
    code = (
        "import softgrip, numpy as np;"
        "t = softgrip.law('calibrated', 3e6, 0.49, 0.01);"
        "f = t.force(np.array([0.0, 0.004]));"
        "assert f[0] == 0.0 and f[1] > 0, f;"
        "import pathlib; p = pathlib.Path(softgrip.__file__).parent;"
        "assert (p / 'py.typed').exists() and (p / '_native.pyi').exists();"
        "print(softgrip.__version__, softgrip.__file__)"
    )
    out = subprocess.run([str(py), "-c", code], check=True, capture_output=True, text=True, cwd=tmp_path)
    assert str(venv) in out.stdout
