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
    ├── RecordingError                         an MCAP recording that cannot be written or read
    │   ├── RecordingExistsError (FileExistsError)   the output exists (pass overwrite=True)
    │   └── RecordingFormatError (ValueError)        not MCAP, damaged, or not decodable
    └── SimulationDiverged (ArithmeticError)  a run whose state went non-finite or out of the
                                               engine's bounds, or rapier panicked

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
    "SimulationDiverged",
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


class SimulationDiverged(SoftgripError, ArithmeticError):
    """A run stopped by a step that went wrong numerically (``softgrip.run``): a body's
    position or velocity, or a multibody joint's coordinate, non-finite or beyond what the
    engine's ``f32`` holds, before or after the step (``kind == "diverged"``), or a panic
    inside rapier's pipeline (``kind == "engine_panicked"``). Everything up to the failed step
    is kept: the recording (``mcap=``) is finished with every step before it, and
    ``e.result`` is the run's dict as :func:`softgrip.run` returns it, over those steps.

    Attributes: ``step`` (the failed step, from 1), ``time`` (simulated time at its start,
    s), ``subject`` (``"body"``, ``"joint"`` or ``"contact"``; None for a panic), ``name`` (the
    scene's name of it: a body, ``robot/link``, ``robot/joint``, ``tip on other``; or None),
    ``quantity`` (e.g. ``"linear velocity [m/s]"``; None for a panic), ``found`` (the value,
    a float, NaN or inf included; None for a panic), ``bound`` (float; None for a panic),
    ``phase`` (``"before"``, ``"soft_solve"``, ``"after"``; None for a panic), ``result``.
    ``e.field`` is ``quantity`` and ``e.value`` the value as text; ``str(e)`` says it all,
    and for a panic rapier's message and where it was raised.
    """

    kind: Optional[str] = None
    step: Optional[int] = None
    time: Optional[float] = None
    subject: Optional[str] = None
    name: Optional[str] = None
    quantity: Optional[str] = None
    found: Optional[float] = None
    bound: Optional[float] = None
    phase: Optional[str] = None
    result: Optional[dict] = None

    def __reduce__(self):
        return (_rebuild_with, (type(self), self.args, dict(self.__dict__)))


def _rebuild_with(cls, args, attrs):
    e = cls(*args)
    e.__dict__.update(attrs)
    return e
