"""The example sweeps shipped with softgrip (the repository's ``sweeps/``, format in
crates/softgrip-sweep/SWEEPS.md), usable wherever the package is installed:

>>> import softgrip
>>> softgrip.sweeps.names()
['default_grid', 'throughput']
"""

from __future__ import annotations

from pathlib import Path
from typing import List

from . import _data


def names() -> List[str]:
    """The shipped sweeps' names."""
    return _data.names("sweeps")


def path(name: str) -> Path:
    """The file of the shipped sweep ``name``, e.g.
    ``softgrip.sweep(softgrip.sweeps.path("default_grid"))``."""
    return _data.path("sweeps", name)
