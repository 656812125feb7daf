"""The exceptions softgrip raises. Each carries the message (``str(e)``: what was wrong, the
value and the valid range or type) and, where the error names one, the field at fault
(``e.field``, e.g. ``"youngs_modulus"``, ``"fingertip[0].material.youngs_modulus"``,
``"vary[1].random.n"``) and the value found (``e.value``, as text), else ``None``.

Every class is also the built-in exception a Python user catches for that kind of mistake:

::

    SoftgripError
    ├── ParameterError (ValueError)           an argument of the right type out of its range
    │   └── OutOfRangeError                    a compression or force past the level's validity
    ├── ArgumentTypeError (TypeError)         an argument of the wrong type: None, a string
    │                                          where a number goes, a float where an int goes
    ├── SceneError (ValueError)               a scene that does not load (file, TOML, a field)
    ├── SweepError (ValueError)               a sweep file that does not load, a bad shard
    │   └── TrialIndexError (IndexError)       a trial index outside 0..trials
    └── RecordingError                         an MCAP recording that cannot be written or read
        ├── RecordingExistsError (FileExistsError)   the output exists (pass overwrite=True)
        └── RecordingFormatError (ValueError)        not MCAP, damaged, or not decodable

A missing input file is the built-in ``FileNotFoundError`` where Python's ``open`` would raise
it (``softgrip.open_recording``); a scene or sweep file that cannot be read is its
``SceneError`` / ``SweepError`` (the message names the file).
"""

from __future__ import annotations

from typing import Optional

__all__ = [
    "SoftgripError",
    "ParameterError",
    "OutOfRangeError",
    "ArgumentTypeError",
    "SceneError",
    "SweepError",
    "TrialIndexError",
    "RecordingError",
    "RecordingExistsError",
    "RecordingFormatError",
]


class SoftgripError(Exception):
    """Base class of every softgrip error."""

    field: Optional[str] = None
    """The field the error names (a law argument, a scene or sweep field path), or None."""
    value: Optional[str] = None
    """The value found, as text, or None."""

    def __reduce__(self):
        # Picklable with its field and value (Ray and multiprocessing send exceptions back).
        return (_rebuild, (type(self), self.args, self.field, self.value))


def _rebuild(cls, args, field, value):
    e = cls(*args)
    e.field, e.value = field, value
    return e


class ParameterError(SoftgripError, ValueError):
    """An argument outside its valid range (``e.field`` names it; the message says the range
    and the unit)."""


class OutOfRangeError(ParameterError):
    """A compression (``field == "delta"``) or force (``field == "force"``) past the law
    level's validity range, from a checked query or the inverse."""


class ArgumentTypeError(SoftgripError, TypeError):
    """An argument of the wrong type (``e.field`` names it, the message says the type
    expected): ``None`` or a string where a number goes, a float where an integer goes, a
    number where a name goes."""


class SceneError(SoftgripError, ValueError):
    """A scene that cannot be loaded: unreadable, malformed TOML, or a field out of range
    (``e.field`` is its path, e.g. ``fingertip[0].material.youngs_modulus``)."""


class SweepError(SoftgripError, ValueError):
    """A sweep file that cannot be loaded (``e.field`` names the sweep field, e.g.
    ``vary[0].field``), or a bad shard."""


class TrialIndexError(SweepError, IndexError):
    """A trial index outside ``0..trials`` (``e.field == "trial"``), negative ones included."""


class RecordingError(SoftgripError):
    """An MCAP recording that cannot be created, finished or read."""


class RecordingExistsError(RecordingError, FileExistsError):
    """The recording's output file exists and ``overwrite`` was not given."""


class RecordingFormatError(RecordingError, ValueError):
    """A file that is not an MCAP recording, is damaged (the message names the part), or
    holds a message that does not decode."""
