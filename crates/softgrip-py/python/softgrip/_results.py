"""The result types: :class:`RunResult` (a scene run), :class:`Recording` (a recording opened
from its MCAP file) and :class:`MaterialFit`. Every array a run returns per fingertip and per
body and robot joint is documented once, with its unit, in :data:`FINGERTIP_ARRAYS`,
:data:`BODY_ARRAYS` and :data:`JOINT_ARRAYS`;
a run and a recording return the same keys, shapes and dtypes. All three are frozen
dataclasses of numbers, strings, dicts and numpy arrays: they pickle (``pickle``, Ray,
multiprocessing)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

FINGERTIP_ARRAYS: Dict[str, Tuple[str, str]] = {
    "force": ("N", "normal force on the fingertip, summed over its contacts (step average), float64 (steps,)"),
    "friction_force": ("N", "friction force on the fingertip, summed, in the scene's axes, float64 (steps, 3)"),
    "torsional_moment": ("N m", "torsional friction moment about the normal, summed, float64 (steps,)"),
    "stiffness": ("N/m", "the law's stiffness dF/d delta, summed over the contacts, float64 (steps,)"),
    "delta": ("m", "compression of its deepest contact (0 without contact), float64 (steps,)"),
    "x": ("-", "compression ratio delta / R of that contact, float64 (steps,)"),
    "radius": ("m", "contact radius a of that contact, float64 (steps,)"),
    "peak_force": ("N", "largest normal force of any contact in any substep of the step, float64 (steps,)"),
    "contacts": ("count", "number of contacts of the fingertip, int64 (steps,)"),
    "sliding": ("bool", "friction saturated in some substep of some contact, bool (steps,)"),
    "validity_exceeded": ("bool", "some contact past the level's validity range (tangent extension), bool (steps,)"),
}
"""Per fingertip, the arrays of ``RunResult.fingertips[name]`` and ``Recording.fingertips[name]``:
key -> (unit, what). One entry per step (run) or per recorded step (recording)."""

BODY_ARRAYS: Dict[str, Tuple[str, str]] = {
    "position": ("m", "the body's position in the scene's axes, float64 (steps, 3); NaN where absent"),
    "rotation": ("-", "the body's orientation, unit quaternion (x, y, z, w) in the scene's axes, float64 (steps, 4)"),
}
"""Per body, the arrays of ``RunResult.bodies[name]`` and ``Recording.bodies[name]``."""

JOINT_ARRAYS: Dict[str, Tuple[str, str]] = {
    "position": ("m or rad", "the joint's position (prismatic m, revolute rad), float64 (steps,)"),
    "velocity": ("m/s or rad/s", "its rate of motion since the previous step (recording: since the previous recorded step), float64 (steps,)"),
    "effort": ("N or N m", "force or torque on the child link along the joint's axis: its motor's, or for a mimic joint of a multibody robot the load its coupling carries (-J^T F of the loads beyond it), float64 (steps,)"),
    "target_position": ("m or rad", "its motor's target position for the step (a mimic joint: its leader's through multiplier and offset); NaN without a command, float64 (steps,)"),
    "target_velocity": ("m/s or rad/s", "its motor's target velocity; NaN without a command, float64 (steps,)"),
    "effort_limit": ("N or N m", "its motor's largest force (the URDF's effort, 0 without one); NaN without a command, float64 (steps,)"),
}
"""Per robot joint that moves, the arrays of ``RunResult.joints[name]`` and
``Recording.joints[name]`` (``/joint_states`` and ``/joint_commands``): key -> (unit, what).
``name`` is the URDF joint's name, ``<robot>/<joint>`` in a scene with several robots; joints
in the recorder's order (robot by robot, URDF order). Empty in a scene without robots."""

TACTILE_ARRAY = ("Pa", "taxel mean pressures, float32 (steps, rows, columns), row-major from the pad's top-left taxel")
"""``RunResult.tactile[name]`` and ``Recording.tactile[name]``: (unit, what)."""

SUMMARY_FIELDS: Dict[str, Tuple[str, str]] = {
    "peak_force": ("N", "largest normal force of any contact of the fingertip, over every substep"),
    "peak_x": ("-", "largest compression ratio x = delta / R"),
    "peak_radius": ("m", "largest contact radius (run only)"),
    "slips": ("count", "slip events (a contact started sliding)"),
    "validity_excursions": ("count", "times a contact went past the level's validity range"),
    "excursion_time": ("s", "how long its contacts were past the validity range, in all (run only)"),
    "commanded_depth": ("m", "the gripper's commanded squeeze depth, or None off a gripper (run only)"),
    "squeeze_force": ("N", "the force at the end of the squeeze, or None (run only)"),
    "squeeze_delta": ("m", "the compression at the end of the squeeze, or None (run only)"),
}
"""Per fingertip, ``RunResult.summary[name]`` (all) and ``Recording.summary[name]`` (those
the recording's ``softgrip_run_summary`` holds: all but the ones marked run only)."""

CONTACT_ROW_FIELDS: Dict[str, Tuple[str, str]] = {
    "step": ("-", "step number of the row (1-based), int64"),
    "fingertip": ("-", "the fingertip's name, list of str"),
    "other": ("-", "the other body's name, list of str"),
    "point": ("m", "contact point, float64 (n, 3)"),
    "normal": ("-", "unit normal from the other body to the fingertip, float64 (n, 3)"),
    "compression": ("m", "compression delta"),
    "ratio_x": ("-", "x = delta / R"),
    "normal_force": ("N", "normal force (step average)"),
    "friction_force": ("N", "friction force (step average), float64 (n, 3)"),
    "torsional_moment": ("N m", "torsional friction moment"),
    "contact_radius": ("m", "contact radius a"),
    "mean_pressure": ("Pa", "F / (pi a^2) (0 when the scene records no pressure)"),
    "peak_pressure": ("Pa", "pressure at the patch centre (0 when not recorded)"),
    "stiffness": ("N/m", "dF/d delta"),
    "peak_normal_force": ("N", "largest substep normal force"),
    "max_compression": ("m", "largest substep compression (>= compression)"),
    "contact_duration": ("s", "time in contact during the step"),
    "core_thickness": ("m", "skin thickness of a core fingertip, else 0"),
    "level": ("-", "code of the law level that computed the force, uint8"),
    "level_name": ("-", "its name, list of str"),
    "backing": ("-", "the fingertip's construction code (0 free, 1 flat, 2 core), uint8"),
    "validity_exceeded": ("bool", "past the level's validity range"),
    "sliding": ("bool", "friction saturated in some substep"),
}
"""``Recording.contact_rows``: one entry per recorded contact (the ``SoftContact`` message's
fields), float64 unless said."""


def _fields_doc(fields: Dict[str, Tuple[str, str]]) -> str:
    return "\n".join(f"    - ``{k}`` [{unit}]: {what}" for k, (unit, what) in fields.items())


@dataclass(frozen=True)
class MaterialFit:
    """The result of :func:`softgrip.fit_material`."""

    youngs_modulus: float
    """Fitted Young's modulus E [Pa] (from E* and the given nu)."""
    effective_modulus: float
    """Fitted E* = E / (1 - nu^2) [Pa]."""
    poisson_ratio: float
    """The given nu [-]."""
    fitted: int
    """Samples with x <= x_fit used for the fit [count]."""
    predicted: np.ndarray
    """Compressions [m] of the samples past x_fit, where the levels are compared."""
    residuals: Dict[str, Dict[str, Any]]
    """Per level name: ``relative_errors`` ([-], array over ``predicted``, (F_level - F) / F,
    NaN past the level's validity range), ``max_abs_error`` and ``rms_error`` [-]."""


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
    """Steps taken [count]."""
    total_steps: int
    """Steps of the scene's duration [count]."""
    time: np.ndarray
    """Simulated time at the end of each step [s], float64 (steps,)."""
    fingertips: Dict[str, Dict[str, np.ndarray]]
    """Per fingertip name (scene order), the arrays of :data:`FINGERTIP_ARRAYS`."""
    bodies: Dict[str, Dict[str, np.ndarray]]
    """Per body name (scene order), the arrays of :data:`BODY_ARRAYS`."""
    joints: Dict[str, Dict[str, np.ndarray]]
    """Per robot joint that moves (its URDF name; ``<robot>/<joint>`` with several robots),
    the arrays of :data:`JOINT_ARRAYS`; empty without robots."""
    summary: Dict[str, Dict[str, Any]]
    """Per fingertip, the figures of ``softgrip run``'s summary (:data:`SUMMARY_FIELDS`)."""
    summary_lines: List[str]
    """The lines ``softgrip run`` prints that do not depend on the wall clock: the scene line
    and one ``fingertip ...`` line per fingertip, character for character."""
    digest: str
    """``digest <hex> steps <n> contacts <m>``: every contact value of every step, bit for bit
    (what ``softgrip run --digest`` prints)."""
    wall_time: float
    """Wall-clock time of the steps [s]."""
    recording: Optional[Dict[str, Any]] = field(default=None)
    """With ``mcap``: ``path``, ``frames`` [count], ``messages`` [count], ``chunks`` [count],
    ``bytes`` [B], ``every`` [steps]."""
    tactile: Dict[str, np.ndarray] = field(default_factory=dict)
    """Per fingertip with a tactile pad, its images [Pa]: float32 (steps, rows, columns)
    (:data:`TACTILE_ARRAY`)."""

    @property
    def summary_text(self) -> str:
        """``summary_lines`` joined by newlines."""
        return "\n".join(self.summary_lines)


@dataclass(frozen=True)
class Recording:
    """A recording opened by :func:`softgrip.open_recording`: the arrays a run returns, at the
    recorded steps, read from the file (nothing is re-run).

    ``fingertips``, ``bodies``, ``joints`` and ``tactile`` have the keys, dtypes and units of
    :class:`RunResult`'s (one entry per *recorded* step: ``run.fingertips[n][k][rec.step - 1]
    == rec.fingertips[n][k]``), in the scene's axes (``frame="scene"``) or the recording's
    z-up world (``frame="world"``).
    """

    path: str
    """The file opened."""
    origin: Optional[str]
    """The scene the run was of (a path, ``default scene``, ...), None without metadata."""
    softgrip_version: Optional[str]
    """The softgrip version that wrote the file."""
    scene: Optional[str]
    """The scene file's text as run."""
    dt: Optional[float]
    """Time step [s] (None if the file does not say)."""
    every: Optional[int]
    """Every how many steps a step was recorded [steps]."""
    total_steps: Optional[int]
    """Steps the run was to take [count]."""
    frame: str
    """``"scene"`` or ``"world"``: the axes of the vectors and poses."""
    step: np.ndarray
    """Step number of each recorded step (1-based), int64 (n,)."""
    time: np.ndarray
    """Simulated time at the end of each recorded step [s] (``step * dt``), float64 (n,)."""
    log_time_ns: np.ndarray
    """The MCAP log time of each recorded step [ns], uint64 (n,)."""
    fingertips: Dict[str, Dict[str, np.ndarray]]
    """Per fingertip (scene order), the arrays of :data:`FINGERTIP_ARRAYS` over the recorded
    steps."""
    bodies: Dict[str, Dict[str, np.ndarray]]
    """Per body, the arrays of :data:`BODY_ARRAYS` over the recorded steps."""
    joints: Dict[str, Dict[str, np.ndarray]]
    """Per robot joint, the arrays of :data:`JOINT_ARRAYS` over the recorded steps (from
    ``/joint_states`` and ``/joint_commands``); empty without them."""
    tactile: Dict[str, np.ndarray]
    """Per fingertip with a tactile pad, its images [Pa], float32 (n, rows, columns)."""
    summary: Optional[Dict[str, Dict[str, Any]]]
    """Per fingertip, the run's own summary over every step (``peak_force`` [N], ``peak_x``
    [-], ``slips``, ``validity_excursions``; :data:`SUMMARY_FIELDS`); None if the run did not
    finish."""
    summary_steps: Optional[int]
    """Steps the summary counts [count]."""
    laws: Dict[str, Dict[str, Any]]
    """Per fingertip, its law's parameters as recorded: ``level``, ``setting`` (``k``,
    ``tolerance`` or ``match_x``, else None), ``youngs_modulus`` [Pa], ``poisson_ratio`` [-],
    ``radius`` [m], ``friction`` [-], ``restitution`` [-], ``backing``, ``core_thickness``
    [m] (None unless ``core``). :meth:`law` builds the :class:`softgrip.Law`."""
    controllers: List[Dict[str, Any]]
    """The run's controllers in the order they ran: ``name``, ``kind`` (one of
    :data:`softgrip.CONTROLLERS`) and ``code`` (the kind's fixed code in files); empty for a
    recording made before softgrip recorded them (session 10, 2026-12-05)."""
    contact_rows: Dict[str, Any]
    """Every recorded contact, column by column (:data:`CONTACT_ROW_FIELDS`)."""
    channels: List[Dict[str, Any]]
    """The topics: ``topic``, ``schema_name``, ``message_encoding``, ``message_count``."""
    recovery: Optional[Dict[str, Any]]
    """None for a finished file; for a killed writer's file, what was kept: ``chunks``,
    ``bytes_kept`` [B], ``file_len`` [B], ``stopped_because``."""

    def law(self, fingertip: str):
        """The :class:`softgrip.Law` of ``fingertip`` as recorded (its level, material, radius
        and construction)."""
        from . import law as make_law
        from .errors import ParameterError

        if fingertip not in self.laws:
            err = ParameterError(
                f"`fingertip` must be one of {sorted(self.laws)}, got {fingertip!r}"
            )
            err.field, err.value = "fingertip", repr(fingertip)
            raise err
        p = self.laws[fingertip]
        setting = {"fit": "k", "auto": "tolerance", "linear": "match_x"}.get(p["level"])
        kwargs = {setting: p["setting"]} if setting and p["setting"] is not None else {}
        return make_law(
            p["level"],
            p["youngs_modulus"],
            p["poisson_ratio"],
            p["radius"],
            p["backing"],
            p["core_thickness"],
            **kwargs,
        )


if RunResult.__doc__ and Recording.__doc__:  # None under python -OO
    RunResult.__doc__ += "\n\n    Per fingertip (``fingertips[name]``):\n\n" + _fields_doc(FINGERTIP_ARRAYS)
    RunResult.__doc__ += "\n\n    Per body (``bodies[name]``):\n\n" + _fields_doc(BODY_ARRAYS)
    RunResult.__doc__ += "\n\n    Per joint (``joints[name]``):\n\n" + _fields_doc(JOINT_ARRAYS)
    Recording.__doc__ += "\n\n    Per fingertip (``fingertips[name]``):\n\n" + _fields_doc(FINGERTIP_ARRAYS)
    Recording.__doc__ += "\n\n    Per body (``bodies[name]``):\n\n" + _fields_doc(BODY_ARRAYS)
    Recording.__doc__ += "\n\n    Per joint (``joints[name]``):\n\n" + _fields_doc(JOINT_ARRAYS)
    Recording.__doc__ += "\n\n    Contact rows (``contact_rows``):\n\n" + _fields_doc(CONTACT_ROW_FIELDS)
