"""Type stubs of the extension module ``softgrip._native`` (Rust, pyo3). SI units: m, N, Pa,
J, s. ``ArrayLike`` arguments take a number (the result is a float) or an array-like of
numbers (the result is a float64 array of the same shape). As in numpy, a NaN in gives NaN
out, and None, strings or object arrays are a ``TypeError`` (softgrip's
``ArgumentTypeError``) naming the argument."""

import os
from typing import Any, Dict, List, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
LEVELS: tuple[str, ...]
BACKINGS: tuple[str, ...]
CONTROLLERS: tuple[str, ...]
OUTCOME_COLUMNS: tuple[str, ...]

_Number = Union[float, int, np.floating, np.integer]
_Array = npt.NDArray[np.float64]
_ArrayLike = Union[_Number, npt.ArrayLike]
_Path = Union[str, "os.PathLike[str]"]

class Law:
    """A level of the contact law bound to one fingertip.

    Methods taking ``delta`` [m] use the law's hot path (0 out of contact, the tangent
    extension past ``delta_max``; NaN for a NaN or infinite ``delta``) unless
    ``checked=True``, which raises ``ParameterError`` / ``OutOfRangeError``
    (``field == "delta"``) for a negative, non-finite or past-``delta_max`` compression.
    Pickles as its parameters; ``==`` and ``hash`` compare them."""

    @overload
    def force(self, delta: _Number, *, checked: bool = ...) -> float:
        """Normal force F(delta) [N]."""
    @overload
    def force(self, delta: npt.ArrayLike, *, checked: bool = ...) -> _Array: ...
    def stiffness(self, delta: _ArrayLike, *, checked: bool = ...) -> Union[float, _Array]:
        """Stiffness K = dF/d delta [N/m]."""
    def energy(self, delta: _ArrayLike, *, checked: bool = ...) -> Union[float, _Array]:
        """Stored elastic energy W [J]."""
    def radius(self, delta: _ArrayLike, *, checked: bool = ...) -> Union[float, _Array]:
        """Contact radius a [m]."""
    def mean_pressure(self, delta: _ArrayLike, *, checked: bool = ...) -> Union[float, _Array]:
        """Mean contact pressure F / (pi a^2) [Pa]."""
    def peak_pressure(self, delta: _ArrayLike, *, checked: bool = ...) -> Union[float, _Array]:
        """Peak (centre) pressure (m + 1)(m + 2)/(m + 2 + b) p_mean [Pa]."""
    def pressure_shape(self, delta: _ArrayLike, *, checked: bool = ...) -> Union[float, _Array]:
        """Shape exponent m [-] of p(r) = p0 (1 - r^2/a^2)^m (1 + b r^2/a^2), in [0, 2]."""
    def pressure_taper(self, delta: _ArrayLike, *, checked: bool = ...) -> Union[float, _Array]:
        """Taper b [-] of p(r)'s factor (1 + b r^2/a^2), in [-1, 0] (< 0: a skin over a core)."""
    def pressure(self, delta: float, r: _ArrayLike, *, checked: bool = ...) -> Union[float, _Array]:
        """Pressure p(r) [Pa] at distance r [m] from the centre, at compression delta [m]
        (0 outside the patch; NaN for a NaN r or a non-finite delta)."""
    def valid(self, delta: _ArrayLike) -> Union[float, _Array]:
        """1.0 where 0 <= delta <= delta_max, else 0.0 (NaN for NaN)."""
    def delta_for_force(self, force: _ArrayLike) -> Union[float, _Array]:
        """Inverse: delta [m] at which the law gives ``force`` [N] (in [0, force_max]; NaN for
        NaN); ``ParameterError`` for a negative or infinite force, ``OutOfRangeError``
        (``field == "force"``) past ``force_max``."""
    @property
    def x_max(self) -> float:
        """Largest compression ratio of the validity range [-]."""
    @property
    def delta_max(self) -> float:
        """x_max R [m]."""
    @property
    def force_max(self) -> float:
        """Force at delta_max [N]."""
    @property
    def level(self) -> str:
        """The level's name (one of ``softgrip.LEVELS``)."""
    @property
    def setting(self) -> Optional[float]:
        """The level's setting [-]: ``k`` of fit, ``tolerance`` of auto, ``match_x`` of linear."""
    @property
    def backing(self) -> str:
        """The construction: ``free``, ``flat`` or ``core``."""
    @property
    def thickness(self) -> Optional[float]:
        """Skin thickness t [m] of a core fingertip, else None."""
    @property
    def tip_radius(self) -> float:
        """Outer radius R [m]."""
    @property
    def effective_modulus(self) -> float:
        """E* = E / (1 - nu^2) [Pa]."""
    @property
    def youngs_modulus(self) -> float:
        """E [Pa], as given."""
    @property
    def poisson_ratio(self) -> float:
        """nu [-]."""
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

def law(
    level: str,
    youngs_modulus: float,
    poisson_ratio: float,
    radius: float,
    backing: Optional[str] = ...,
    thickness: Optional[float] = ...,
    *,
    k: Optional[float] = ...,
    tolerance: Optional[float] = ...,
    match_x: Optional[float] = ...,
) -> Law:
    """The law of ``level`` for E [Pa], nu [-], R [m], ``backing`` (default ``free``) and the
    core's ``thickness`` [m]; ``k``, ``tolerance``, ``match_x`` [-] the level's setting."""

def _law_from_state(
    level: str,
    setting: Optional[float],
    youngs_modulus: float,
    poisson_ratio: float,
    radius: float,
    backing: str,
    thickness: Optional[float],
) -> Law:
    """Unpickles a ``Law`` (its ``__reduce__`` state)."""

def fit_material(
    delta: npt.ArrayLike,
    force: npt.ArrayLike,
    radius: float,
    poisson_ratio: float,
    x_fit: Optional[float] = ...,
    level: Optional[str] = ...,
    *,
    k: Optional[float] = ...,
    tolerance: Optional[float] = ...,
    match_x: Optional[float] = ...,
) -> Dict[str, Any]:
    """The fields of ``softgrip.MaterialFit``: E and E* [Pa] fitted on the samples (delta [m],
    force [N]) with delta / R <= ``x_fit`` (default 0.1) by ``level`` (default ``hertz``)."""

def run_scene(
    path: Optional[_Path] = ...,
    *,
    toml: Optional[str] = ...,
    base_dir: Optional[_Path] = ...,
    mcap: Optional[_Path] = ...,
    every: Optional[int] = ...,
    overwrite: Optional[bool] = ...,
) -> Dict[str, Any]:
    """The fields of ``softgrip.RunResult`` (arrays: ``softgrip.FINGERTIP_ARRAYS``,
    ``softgrip.BODY_ARRAYS``, ``softgrip.JOINT_ARRAYS``, ``softgrip.TACTILE_ARRAY``)."""

def open_recording(path: _Path, *, frame: Optional[str] = ...) -> Dict[str, Any]:
    """The fields of ``softgrip.Recording``; ``frame`` ``"scene"`` (default) or ``"world"``."""

Row = Tuple[Any, ...]

class Sweep:
    """A checked sweep file (softgrip-sweep's ``Sweep``). Pickles as its text, origin and
    directory."""

    @staticmethod
    def open(path: _Path) -> "Sweep": ...
    @staticmethod
    def from_toml(text: str, base_dir: _Path) -> "Sweep": ...
    @property
    def trials(self) -> int:
        """Number of trials."""
    @property
    def origin(self) -> str:
        """The sweep file as given, or ``<sweep>``."""
    @property
    def object(self) -> str:
        """The body whose hold decides ``held``."""
    @property
    def text(self) -> str:
        """The sweep file's text."""
    def fields(self) -> List[str]: ...
    def columns(self) -> List[str]: ...
    def kinds(self) -> List[str]:
        """``float``, ``int``, ``bool`` or ``text`` per varied field."""
    def scene_text(self, index: int) -> str:
        """Trial ``index``'s scene (TOML); ``TrialIndexError`` outside 0..trials."""
    def run_trial(self, index: int) -> Row:
        """Trial ``index``'s row ``(trial, *values, held, slips, slip_distance [m], peak_force
        [N], peak_x [-], validity_excursions, hold_force [N], wall_time [s], error)``; ``TrialIndexError``
        (an ``IndexError``) outside 0..trials."""
    def run(
        self,
        threads: Optional[int] = ...,
        shard_index: Optional[int] = ...,
        shard_count: Optional[int] = ...,
    ) -> List[Row]:
        """The rows of shard ``shard_index`` of ``shard_count`` on ``threads`` threads (0 or
        None: one per core; at most 4096)."""
    def write(self, rows: List[Row], path: _Path) -> None:
        """Writes ``rows`` as ``softgrip sweep --out`` does (.parquet or .csv)."""
    def to_csv(self, rows: List[Row]) -> str: ...
