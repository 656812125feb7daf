"""Every Python snippet of every Markdown file of the repository (```python blocks of the root
README, the crates' READMEs and any other .md) runs as written, in a fresh interpreter, from a
directory that looks like the repository's root (its top-level entries linked in), so that
the paths a snippet names resolve as they do for a user in a checkout and the files it writes
land in a temporary directory. A block of `>>>` lines runs as a doctest (its printed output
and its traceback are checked). A snippet that imports Ray runs only in a private network
namespace (ci/test.sh runs this file's Ray snippets under `unshare --net`); elsewhere it is
skipped saying why."""

from __future__ import annotations

import doctest
import os
import re
import socket
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
FENCE = re.compile(r"^```(python|py|pycon)[^\n]*\n(.*?)^```", re.M | re.S)


def markdown_files():
    skip = {"target", ".git", "node_modules"}
    for path in sorted(ROOT.rglob("*.md")):
        if not skip.intersection(path.relative_to(ROOT).parts):
            yield path


def snippets():
    for md in markdown_files():
        text = md.read_text(encoding="utf-8")
        for k, m in enumerate(FENCE.finditer(text)):
            line = text[: m.start()].count("\n") + 1
            code = m.group(2)
            ray = re.search(r"^\s*import ray\b|^\s*import ray,|\bimport .*\bray\b", code, re.M) is not None
            name = f"{md.relative_to(ROOT)}:{line}" + ("-ray" if ray else "")
            yield pytest.param(md, line, code, ray, id=name)


SNIPPETS = list(snippets())


def only_loopback() -> bool:
    try:
        return [name for _, name in socket.if_nameindex()] == ["lo"]
    except OSError:
        return False


@pytest.fixture
def checkout(tmp_path: Path) -> Path:
    """A directory whose entries are links to the repository root's (writes stay here)."""
    for entry in ROOT.iterdir():
        if entry.name not in (".git", "target"):
            (tmp_path / entry.name).symlink_to(entry)
    return tmp_path


def test_there_are_snippets():
    # The package's README and the root README's quick start at least.
    files = {p.values[0].relative_to(ROOT).as_posix() for p in SNIPPETS}
    assert {"README.md", "crates/softgrip-py/README.md"} <= files, files


@pytest.mark.parametrize("md,line,code,ray", SNIPPETS)
def test_snippet_runs_as_written(md: Path, line: int, code: str, ray: bool, checkout: Path):
    if ray and not only_loopback():
        reason = "a Ray snippet: run in a private network namespace (ci/test.sh: unshare --net)"
        print(f"{md.name}:{line}: skipped: {reason}", file=sys.stderr)
        pytest.skip(reason)
    where = f"{md.relative_to(ROOT)}, the block at line {line}"
    if code.lstrip().startswith(">>>"):
        script = (
            "import doctest, sys\n"
            f"test = doctest.DocTestParser().get_doctest({code!r}, {{}}, {where!r}, None, {line})\n"
            "runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)\n"
            "runner.run(test)\n"
            "sys.exit(1 if runner.summarize(verbose=False).failed else 0)\n"
        )
    else:
        script = code
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    p = subprocess.run(
        [sys.executable, "-c", script], cwd=checkout, capture_output=True, text=True,
        timeout=900, env=env,
    )
    assert p.returncode == 0, f"{where} failed:\n{p.stdout}\n{p.stderr}"


def test_a_broken_snippet_fails(checkout: Path):
    # The harness itself: a snippet naming an undefined variable (the README's first snippet
    # did: `delta_measured`) or a file that does not exist (its Ray snippet did) fails.
    for code in ("import softgrip\nsoftgrip.fit_material(delta_measured, [1.0], 0.01, 0.49)\n",
                 "import softgrip\nsoftgrip.sweep('sweep.toml')\n"):
        p = subprocess.run([sys.executable, "-c", code], cwd=checkout, capture_output=True, text=True)
        assert p.returncode != 0
    assert doctest.DocTestParser().get_examples(">>> 1 + 1\n3\n")
