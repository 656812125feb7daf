"""The wheel CI builds (SOFTGRIP_WHEEL, from ci/build-wheel.sh) is what a user installs: abi3
(one wheel for every CPython >= 3.9), manylinux_2_17 (glibc 2.17: its extension links no newer
symbol version, and PyPA's auditwheel agrees), with the license texts, the stubs and the
example scenes and sweeps inside. It installs with pip into a fresh venv (the time is printed,
never asserted), imports, evaluates the law and runs a shipped scene."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


def wheel() -> Path:
    w = os.environ.get("SOFTGRIP_WHEEL")
    if not w:
        print("test_wheel.py: skipped: SOFTGRIP_WHEEL is not set (ci/test.sh sets it)", file=sys.stderr)
        pytest.skip("SOFTGRIP_WHEEL is not set: ci/test.sh sets it to the wheel it built")
    return Path(w)


def test_wheel_tags_are_abi3_and_manylinux2014():
    w = wheel()
    # softgrip-0.1.0-cp39-abi3-manylinux2014_x86_64.manylinux_2_17_x86_64.whl
    assert re.fullmatch(
        r"softgrip-[0-9.]+-cp39-abi3-manylinux2014_x86_64\.manylinux_2_17_x86_64\.whl", w.name
    ), w.name
    z = zipfile.ZipFile(w)
    tags = z.read(next(n for n in z.namelist() if n.endswith("/WHEEL"))).decode()
    assert "Tag: cp39-abi3-manylinux_2_17_x86_64" in tags and "Root-Is-Purelib: false" in tags, tags


def test_wheel_holds_licenses_stubs_and_data():
    w = wheel()
    z = zipfile.ZipFile(w)
    names = z.namelist()
    for f in ["softgrip/__init__.py", "softgrip/py.typed", "softgrip/_native.pyi", "softgrip/errors.py"]:
        assert f in names, f
    assert any(n.startswith("softgrip/_native") and n.endswith(".so") for n in names)
    licenses = {Path(n).name: n for n in names if "/licenses/" in n}
    assert set(licenses) == {"LICENSE-MIT", "LICENSE-APACHE"}, names
    for name, entry in licenses.items():
        assert z.read(entry) == (ROOT / name).read_bytes()
    meta = z.read(next(n for n in names if n.endswith("/METADATA"))).decode()
    assert "License-Expression: MIT OR Apache-2.0" in meta and "License-File: LICENSE-MIT" in meta
    for kind in ("scenes", "sweeps"):
        shipped = {Path(n).name for n in names if n.startswith(f"softgrip/data/{kind}/")}
        repo = {p.name for p in (ROOT / kind).glob("*.toml")}
        assert shipped == repo and repo, kind
        for f in repo:
            assert z.read(f"softgrip/data/{kind}/{f}") == (ROOT / kind / f).read_bytes()


def test_auditwheel_finds_it_manylinux_2_17():
    w = wheel()
    out = subprocess.run(
        [sys.executable, "-m", "auditwheel", "show", str(w)], capture_output=True, text=True, check=True
    ).stdout
    flat = " ".join(out.split())
    assert 'consistent with the following platform tag: "manylinux_2_17_x86_64"' in flat, out
    # every versioned glibc symbol it needs is at most 2.17
    versions = [tuple(map(int, v.split("."))) for v in re.findall(r"GLIBC_([0-9.]+)", flat)]
    assert versions and max(versions) <= (2, 17), versions


def test_wheel_installs_into_a_fresh_venv(tmp_path):
    w = wheel()
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    py = venv / "bin" / "python"
    start = time.perf_counter()
    # numpy from the index (or pip's cache) as the wheel's one dependency
    subprocess.run(
        [str(py), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", str(w)],
        check=True,
    )
    print(f"test_wheel.py: pip install of the wheel and numpy into a fresh venv: {time.perf_counter() - start:.1f} s",
          file=sys.stderr)
    code = (
        "import softgrip, numpy as np, pathlib;"
        "t = softgrip.law('calibrated', 3e6, 0.49, 0.01);"
        "f = t.force(np.array([0.0, 0.004]));"
        "assert f[0] == 0.0 and abs(f[1] - 230.659912239653) < 1e-9, f;"
        "p = pathlib.Path(softgrip.__file__).parent;"
        "assert (p / 'py.typed').exists() and (p / '_native.pyi').exists();"
        "s = softgrip.scenes.path('ecoflex_sphere'); assert s.is_relative_to(p), s;"
        "r = softgrip.run(s); assert r.steps == 450 and r.summary['sphere']['peak_x'] > 0.84;"
        "assert softgrip.sweeps.path('default_grid').is_file();"
        "print(softgrip.__version__, softgrip.__file__)"
    )
    out = subprocess.run([str(py), "-c", code], check=True, capture_output=True, text=True, cwd=tmp_path)
    assert str(venv) in out.stdout
