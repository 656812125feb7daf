"""The example scenes shipped with softgrip (the repository's ``scenes/``, format in
crates/softgrip-scene/SCENES.md), usable wherever the package is installed:

>>> import softgrip
>>> "default" in softgrip.scenes.names()
True
>>> softgrip.scenes.path("default").name
'default.toml'
"""

from __future__ import annotations

from pathlib import Path
from typing import List

from . import _data


def names() -> List[str]:
    """The shipped scenes' names: ``default`` (the embedded grasp), ``ecoflex_sphere``, the
    three cells (``cell_live_hmsc``, ...)."""
    return _data.names("scenes")


def path(name: str) -> Path:
    """The file of the shipped scene ``name`` (``ParameterError`` naming the choices if there
    is none), e.g. ``softgrip.run(softgrip.scenes.path("ecoflex_sphere"))``."""
    return _data.path("scenes", name)
