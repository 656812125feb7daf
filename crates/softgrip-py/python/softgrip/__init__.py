"""softgrip from Python: the large-deformation soft-fingertip contact law over numpy arrays,
material fitting from a squeeze, scene runs (the same schedule as ``softgrip run``) with their
per-step readout and MCAP recording, recordings opened as the same arrays, and grasp sweeps run
on local cores or as Ray tasks. The example scenes and sweeps ship with the package
(``softgrip.scenes``, ``softgrip.sweeps``).

SI units throughout: m, N, Pa, J, s. The compression ``delta`` [m] is >= 0 in contact,
``x = delta / R``. Errors are :class:`SoftgripError` subclasses that are also the built-in a
Python user catches (``ValueError``, ``TypeError``, ``IndexError``, ``FileExistsError``; see
:mod:`softgrip.errors`).

>>> import softgrip
>>> tip = softgrip.law("calibrated", 3.0e6, 0.49, 0.010)
>>> round(float(tip.force(0.004)), 3) > 0
True
"""

from __future__ import annotations

import os
from typing import Any, Optional, Union

from . import _native, scenes, sweeps
from ._native import Law, Sweep
from ._results import (
    BODY_ARRAYS,
    CONTACT_ROW_FIELDS,
    FINGERTIP_ARRAYS,
    JOINT_ARRAYS,
    SUMMARY_FIELDS,
    TACTILE_ARRAY,
    MaterialFit,
    Recording,
    RunResult,
)
from ._sweep import sweep
from .errors import (
    ArgumentTypeError,
    OutOfRangeError,
    ParameterError,
    RecordingError,
    RecordingExistsError,
    RecordingFormatError,
    SceneError,
    SimulationDiverged,
    SoftgripError,
    SweepError,
    TrialIndexError,
)

__version__: str = _native.__version__

__all__ = [
    "ArgumentTypeError",
    "BACKINGS",
    "BODY_ARRAYS",
    "CONTACT_ROW_FIELDS",
    "CONTROLLERS",
    "FINGERTIP_ARRAYS",
    "JOINT_ARRAYS",
    "LEVELS",
    "Law",
    "MaterialFit",
    "OutOfRangeError",
    "ParameterError",
    "Recording",
    "RecordingError",
    "RecordingExistsError",
    "RecordingFormatError",
    "RunResult",
    "SUMMARY_FIELDS",
    "SceneError",
    "SimulationDiverged",
    "SoftgripError",
    "Sweep",
    "SweepError",
    "TACTILE_ARRAY",
    "TrialIndexError",
    "fit_material",
    "law",
    "open_recording",
    "run",
    "run_toml",
    "scenes",
    "sweep",
    "sweeps",
]

PathLike = Union[str, "os.PathLike[str]"]

LEVELS = _native.LEVELS
"""The level names ``law`` accepts: the rows of softgrip-law's table ``LEVELS`` that
parameters alone build (a measured curve is a scene's ``level = { tabulated = "tip.csv" }``)."""

BACKINGS = _native.BACKINGS
"""The fingertip constructions ``law`` accepts."""

CONTROLLERS = _native.CONTROLLERS
"""The controller kinds: the names of softgrip-scene's table ``CONTROLLERS`` (``parallel_jaws``,
the ``[gripper]``; ``trajectory``, ``grasp``, a scene's ``[[controller]] type``;
``joint_commands``, every robot's commands from outside), the ``kind`` of each of a
:class:`Recording`'s ``controllers``."""


def law(
    level: str,
    youngs_modulus: float,
    poisson_ratio: float,
    radius: float,
    backing: str = "free",
    thickness: Optional[float] = None,
    *,
    k: Optional[float] = None,
    tolerance: Optional[float] = None,
    match_x: Optional[float] = None,
) -> Law:
    """One level of the contact law bound to a fingertip.

    Args:
        level: one of ``LEVELS`` (``"calibrated"``: softgrip's FE-fitted level; ``"auto"``:
            the cheapest level within ``tolerance`` of calibrated at each x).
        youngs_modulus: Young's modulus E [Pa], finite and > 0.
        poisson_ratio: Poisson ratio nu [-], in (-1, 0.5] (below 0.5 for the neo-Hookean
            levels).
        radius: outer radius R of the fingertip [m], finite and > 0.
        backing: ``"free"`` (a free sphere), ``"flat"`` (a hemisphere bonded at its flat face
            to a rigid finger) or ``"core"`` (a skin over a rigid core).
        thickness: skin thickness t [m] of a ``"core"`` fingertip, in (0, R); only there.
        k: slope of 1/chi = 1 - k x for ``"fit"`` (default 10/9), in [0, 10].
        tolerance: relative force tolerance of ``"auto"`` (default 0.01), in (0, 0.5].
        match_x: compression ratio where ``"linear"`` matches Hertz (default 0.05), in (0, 1].

    Returns:
        A :class:`Law`; its methods take a compression ``delta`` [m] (a number gives a float,
        an array-like a float64 array of its shape). A NaN or infinite ``delta`` gives NaN.
        The law pickles (``pickle``, ``copy``, Ray).

    Raises:
        ParameterError: an argument out of range; ``e.field`` names it.
        ArgumentTypeError: an argument of the wrong type (None or a string for a number).
    """
    return _native.law(
        level,
        youngs_modulus,
        poisson_ratio,
        radius,
        backing,
        thickness,
        k=k,
        tolerance=tolerance,
        match_x=match_x,
    )


def fit_material(
    delta: Any,
    force: Any,
    radius: float,
    poisson_ratio: float,
    x_fit: float = 0.1,
    level: str = "hertz",
    *,
    k: Optional[float] = None,
    tolerance: Optional[float] = None,
    match_x: Optional[float] = None,
) -> MaterialFit:
    """Fits the material of a squeeze from its samples (softgrip-law's ``fit_material``).

    E* is the least-squares fit of ``F = E* R^2 f_level(delta / R)`` on the samples with
    ``x = delta / R <= x_fit`` (the paper: Hertz, x_fit = 0.1); every level's relative error
    is then reported on the samples past ``x_fit``.

    Args:
        delta: compressions [m] (array-like, >= 0; for two plates half the plate approach).
        force: measured forces [N], as many as ``delta``.
        radius: the fingertip's radius R [m], > 0.
        poisson_ratio: nu [-], in (-1, 0.5].
        x_fit: largest x used for the fit [-], > 0.
        level: the level that fits (any of ``LEVELS``).
        k, tolerance, match_x: that level's setting, as in :func:`law` (``k`` for ``"fit"``,
            ``tolerance`` for ``"auto"``, ``match_x`` for ``"linear"``).

    Raises:
        ParameterError: bad samples (``field == "samples"``: fewer than 2 in the fit range,
            NaN or negative values), radius, nu, level or a setting.
        ArgumentTypeError: an argument of the wrong type.
    """
    r = _native.fit_material(
        delta, force, radius, poisson_ratio, x_fit, level, k=k, tolerance=tolerance, match_x=match_x
    )
    return MaterialFit(**r)


def run(
    scene: Optional[PathLike] = None,
    *,
    mcap: Optional[PathLike] = None,
    every: Optional[int] = None,
    overwrite: bool = False,
) -> RunResult:
    """Runs a scene file (default: the embedded grasp) for its duration, through the same
    bevy_ecs schedule as ``softgrip run``, without the GIL.

    Args:
        scene: the scene file (TOML, crates/softgrip-scene/SCENES.md); None for the default.
        mcap: write an MCAP recording there (ROS 2 messages, as ``softgrip run --out``).
        every: record every N-th step (default the scene's ``record.every_n_steps``).
        overwrite: replace an existing ``mcap`` file (else RecordingExistsError, a
            FileExistsError).

    Returns:
        A :class:`RunResult`: per fingertip, per body and per robot joint the arrays of
        :data:`FINGERTIP_ARRAYS`, :data:`BODY_ARRAYS` and :data:`JOINT_ARRAYS` over every
        step, the tactile images,
        the summary and the digest. Open its ``mcap`` with :func:`open_recording`.

    Raises:
        SceneError: the scene does not load (``e.field`` names the field).
        RecordingError: the recording could not be written.
        ArgumentTypeError: an argument of the wrong type.
        KeyboardInterrupt: Ctrl-C during the run (the recording is finished first).
        SimulationDiverged: a step went wrong numerically (``e.step``, ``e.time``,
            ``e.name``, ``e.quantity``, ``e.found``, ``e.bound``); the recording is finished
            with every step before it and ``e.result`` is the :class:`RunResult` over them.
    """
    return _result(lambda: _native.run_scene(scene, mcap=mcap, every=every, overwrite=overwrite))


def _result(call) -> RunResult:
    """``RunResult`` of a native run; a ``SimulationDiverged``'s ``result`` made one too."""
    try:
        r = call()
    except SimulationDiverged as e:
        if isinstance(e.result, dict):
            e.result = RunResult(**e.result)
        raise
    return RunResult(**r)


def run_toml(
    text: str,
    *,
    base_dir: Optional[PathLike] = None,
    mcap: Optional[PathLike] = None,
    every: Optional[int] = None,
    overwrite: bool = False,
) -> RunResult:
    """Runs a scene given as TOML text; its relative paths (meshes, curves) are relative to
    ``base_dir`` (default: the current directory). Otherwise as :func:`run`; errors name the
    scene ``<toml>``."""
    if not isinstance(text, str):
        err = ArgumentTypeError(
            f"`toml` must be scene TOML text (a str), got {text!r} ({type(text).__name__})"
        )
        err.field, err.value = "toml", repr(text)
        raise err
    return _result(
        lambda: _native.run_scene(
            None, toml=text, base_dir=base_dir, mcap=mcap, every=every, overwrite=overwrite
        )
    )


def open_recording(path: PathLike, *, frame: str = "scene") -> Recording:
    """Opens an MCAP recording made by any softgrip version (``softgrip run --out``,
    ``softgrip.run(mcap=...)``, a sweep's ``mcap_dir``) as the arrays a run returns, without
    re-running anything: per fingertip the arrays of :data:`FINGERTIP_ARRAYS`, per body
    :data:`BODY_ARRAYS`, per robot joint :data:`JOINT_ARRAYS`, the tactile images, at the recorded steps (``Recording.step``); the
    run's summary and each fingertip's law (``Recording.law(name)`` builds it); every contact
    row. A killed writer's file is read up to its last complete chunk (``Recording.recovery``).

    Args:
        path: the ``.mcap`` file.
        frame: ``"scene"`` (vectors and poses in the scene's axes, as :func:`run` returns
            them) or ``"world"`` (the recording's z-up world frame, REP 103, as ROS tools
            and Foxglove show it).

    Raises:
        FileNotFoundError: no such file.
        RecordingFormatError: not an MCAP file, damaged (the message names the part), or a
            message that does not decode.
        ArgumentTypeError, ParameterError: a bad ``path`` or ``frame``.
    """
    return Recording(**_native.open_recording(path, frame=frame))
