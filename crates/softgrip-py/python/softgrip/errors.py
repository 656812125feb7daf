"""The exceptions softgrip raises. Each carries the Rust error's message (``str(e)``) and, where
the error names one, the field at fault (``e.field``, e.g. ``"youngs_modulus"``,
``"fingertip[0].material.youngs_modulus"``, ``"vary[1].random.n"``) and the value found
(``e.value``, as text), else ``None``.

::

    SoftgripError
    ├── ParameterError (also a ValueError)   a law argument or a Python argument out of range
    │   └── OutOfRangeError                   a compression or force past the level's validity
    ├── SceneError                            a scene that does not load (file, TOML, a field)
    ├── SweepError                            a sweep file that does not load, a bad shard/trial
    └── RecordingError                        the MCAP recording could not be written
"""

from __future__ import annotations

from typing import Optional

__all__ = [
    "SoftgripError",
    "ParameterError",
    "OutOfRangeError",
    "SceneError",
    "SweepError",
    "RecordingError",
]


class SoftgripError(Exception):
    """Base class of every softgrip error."""

    field: Optional[str] = None
    """The field the error names (a law argument, a scene or sweep field path), or None."""
    value: Optional[str] = None
    """The value found, as text, or None."""


class ParameterError(SoftgripError, ValueError):
    """An argument outside its valid range (``e.field`` names it; the message says the range
    and the unit)."""


class OutOfRangeError(ParameterError):
    """A compression (``field == "delta"``) or force (``field == "force"``) past the law
    level's validity range, from a checked query."""


class SceneError(SoftgripError):
    """A scene that cannot be loaded: unreadable, malformed TOML, or a field out of range
    (``e.field`` is its path, e.g. ``fingertip[0].material.youngs_modulus``)."""


class SweepError(SoftgripError):
    """A sweep file that cannot be loaded (``e.field`` names the sweep field, e.g.
    ``vary[0].field``), a bad shard, or a trial index past the sweep's trials."""


class RecordingError(SoftgripError):
    """The MCAP recording could not be created or finished."""
