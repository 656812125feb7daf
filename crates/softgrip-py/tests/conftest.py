"""Shared fixtures: the repository root, the `softgrip` binary the package is compared with,
and the test data. The binary is SOFTGRIP_BIN, else target/debug/softgrip (what `cargo test
--workspace` and `cargo build -p softgrip-cli` leave): a missing binary fails the tests that
need it, it is never a skip."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
DATA = Path(__file__).resolve().parent / "data"


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def data() -> Path:
    return DATA


@pytest.fixture(scope="session")
def softgrip_bin() -> Path:
    path = Path(os.environ.get("SOFTGRIP_BIN", ROOT / "target" / "debug" / "softgrip"))
    if not path.is_file():
        pytest.fail(
            f"the softgrip binary {path} is missing: run `cargo build -p softgrip-cli` "
            "(or set SOFTGRIP_BIN)"
        )
    return path


@pytest.fixture(scope="session")
def cli(softgrip_bin):
    """`cli(*args)` runs the softgrip binary from the repository root: (returncode, stdout,
    stderr)."""

    def run(*args: str, check: bool = True):
        p = subprocess.run(
            [str(softgrip_bin), *map(str, args)],
            cwd=ROOT,
            capture_output=True,
            text=True,
            timeout=600,
        )
        if check and p.returncode != 0:
            raise AssertionError(f"softgrip {' '.join(map(str, args))}: exit {p.returncode}: {p.stderr}")
        return p.returncode, p.stdout, p.stderr

    return run
