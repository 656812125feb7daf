"""The example files shipped in the package (``softgrip/data``): the repository's ``scenes/``
and ``sweeps/`` (a sweep names its scene as ``../scenes/NAME.toml``, which resolves inside the
package as it does in the repository)."""

from __future__ import annotations

from importlib import resources
from pathlib import Path
from typing import List

from .errors import ArgumentTypeError, ParameterError


def _dir(kind: str) -> Path:
    # A wheel installs as files: the package's directory is a real one.
    return Path(str(resources.files("softgrip") / "data" / kind))


def names(kind: str) -> List[str]:
    """The names (file stems) of the shipped ``kind`` files, sorted."""
    return sorted(p.stem for p in _dir(kind).glob("*.toml"))


def path(kind: str, name: str) -> Path:
    """The path of the shipped ``kind`` file ``name`` (with or without ``.toml``)."""
    if not isinstance(name, str):
        err = ArgumentTypeError(f"`name` must be a str, got {name!r} ({type(name).__name__})")
        err.field, err.value = "name", repr(name)
        raise err
    stem = name[:-5] if name.endswith(".toml") else name
    p = _dir(kind) / f"{stem}.toml"
    if stem not in names(kind):
        err = ParameterError(f"`name` must be one of {names(kind)}, got {name!r}")
        err.field, err.value = "name", repr(name)
        raise err
    return p
