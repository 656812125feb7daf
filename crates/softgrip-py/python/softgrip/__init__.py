"""softgrip from Python: the large-deformation soft-fingertip contact law over numpy arrays,
material fitting from a squeeze, scene runs (the same schedule as ``softgrip run``) with their
per-step readout and MCAP recording, and grasp sweeps run on local cores or as Ray tasks.

SI units throughout: m, N, Pa, J, s. The compression ``delta`` [m] is >= 0 in contact,
``x = delta / R``.

>>> import softgrip
>>> tip = softgrip.law("calibrated", 3.0e6, 0.49, 0.010)
>>> round(float(tip.force(0.004)), 3) > 0
True
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Union

import numpy as np

from . import _native
from ._native import Law, Sweep
from ._sweep import sweep
from .errors import (
    OutOfRangeError,
    ParameterError,
    RecordingError,
    SceneError,
    SoftgripError,
    SweepError,
)

__version__: str = _native.__version__

__all__ = [
    "Law",
    "MaterialFit",
    "OutOfRangeError",
    "ParameterError",
    "RecordingError",
    "RunResult",
    "SceneError",
    "SoftgripError",
    "Sweep",
    "SweepError",
    "fit_material",
    "law",
    "run",
    "run_toml",
    "sweep",
]

PathLike = Union[str, "os.PathLike[str]"]

LEVELS = (
    "linear",
    "hertz",
    "fit",
    "incompressible",
    "neo-hookean",
    "neo-hookean-exact",
    "tatara",
    "calibrated",
    "auto",
)
"""The level names ``law`` accepts (softgrip-law's ``Level::ALL``)."""

BACKINGS = ("free", "flat", "core")
"""The fingertip constructions ``law`` accepts."""


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

    Raises:
        ParameterError: an argument out of range; ``e.field`` names it.
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


@dataclass(frozen=True)
class MaterialFit:
    """The result of :func:`fit_material`."""

    youngs_modulus: float
    """Fitted Young's modulus E [Pa] (from E* and the given nu)."""
    effective_modulus: float
    """Fitted E* = E / (1 - nu^2) [Pa]."""
    poisson_ratio: float
    """The given nu [-]."""
    fitted: int
    """Samples with x <= x_fit used for the fit."""
    predicted: np.ndarray
    """Compressions [m] of the samples past x_fit, where the levels are compared."""
    residuals: Dict[str, Dict[str, Any]]
    """Per level name: ``relative_errors`` (array over ``predicted``, (F_level - F) / F, NaN
    past the level's validity range), ``max_abs_error`` and ``rms_error`` [-]."""


def fit_material(
    delta: Any,
    force: Any,
    radius: float,
    poisson_ratio: float,
    x_fit: float = 0.1,
    level: str = "hertz",
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

    Raises:
        ParameterError: bad samples (``field == "samples"``), radius, nu or level.
    """
    r = _native.fit_material(delta, force, radius, poisson_ratio, x_fit, level)
    return MaterialFit(**r)


@dataclass(frozen=True)
class RunResult:
    """A scene run: the per-step readout, the summary ``softgrip run`` prints, the digest.

    Arrays have one entry per step taken (``steps``), after each step; ``time[i] = (i + 1) dt``.
    """

    origin: str
    """The scene file as given (``<toml>`` for text, ``<default scene>`` for the default)."""
    dt: float
    """Time step [s]."""
    steps: int
    """Steps taken."""
    total_steps: int
    """Steps of the scene's duration."""
    time: np.ndarray
    """Simulated time at the end of each step [s], shape (steps,)."""
    fingertips: Dict[str, Dict[str, np.ndarray]]
    """Per fingertip name (scene order), arrays over the steps: ``force`` (normal force summed
    over its contacts [N]), ``friction_force`` ((steps, 3), summed, world [N]),
    ``torsional_moment`` [N m], ``stiffness`` (summed law stiffness [N/m]), ``delta`` and ``x``
    (compression [m] and ratio [-] of its deepest contact), ``radius`` (that contact's radius
    [m]), ``peak_force`` (largest substep normal force [N]), ``contacts`` (int), ``sliding`` and
    ``validity_exceeded`` (bool)."""
    bodies: Dict[str, Dict[str, np.ndarray]]
    """Per body name: ``position`` ((steps, 3) [m]) and ``rotation`` ((steps, 4), x, y, z, w)."""
    summary: Dict[str, Dict[str, Any]]
    """Per fingertip: ``peak_force`` [N], ``peak_x`` [-], ``peak_radius`` [m], ``slips``,
    ``validity_excursions``, ``commanded_depth`` [m], ``squeeze_force`` [N], ``squeeze_delta``
    [m] (the last three None off a gripper) -- the figures of ``softgrip run``'s summary."""
    summary_lines: List[str]
    """The lines ``softgrip run`` prints that do not depend on the wall clock: the scene line
    and one ``fingertip ...`` line per fingertip, character for character."""
    digest: str
    """``digest <hex> steps <n> contacts <m>``: every contact value of every step, bit for bit
    (what ``softgrip run --digest`` prints)."""
    wall_time: float
    """Wall-clock time of the steps [s]."""
    recording: Optional[Dict[str, Any]] = field(default=None)
    """With ``mcap``: ``path``, ``frames``, ``messages``, ``chunks``, ``bytes``, ``every``."""

    @property
    def summary_text(self) -> str:
        """``summary_lines`` joined by newlines."""
        return "\n".join(self.summary_lines)


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
        overwrite: replace an existing ``mcap`` file (else FileExistsError).

    Raises:
        SceneError: the scene does not load (``e.field`` names the field).
        RecordingError: the recording could not be written.
        KeyboardInterrupt: Ctrl-C during the run (the recording is finished first).
    """
    path = None if scene is None else os.fspath(scene)
    r = _native.run_scene(
        path,
        mcap=None if mcap is None else os.fspath(mcap),
        every=every,
        overwrite=overwrite,
    )
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
    r = _native.run_scene(
        None,
        toml=text,
        base_dir=None if base_dir is None else os.fspath(base_dir),
        mcap=None if mcap is None else os.fspath(mcap),
        every=every,
        overwrite=overwrite,
    )
    return RunResult(**r)
