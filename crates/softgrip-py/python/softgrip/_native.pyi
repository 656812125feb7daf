"""Type stubs of the extension module ``softgrip._native`` (Rust, pyo3). SI units: m, N, Pa,
J, s. ``ArrayLike`` arguments take a number (the result is a float) or an array-like of
numbers (the result is a float64 array of the same shape)."""

from typing import Any, Dict, List, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

_Number = Union[float, int, np.floating, np.integer]
_Array = npt.NDArray[np.float64]
_ArrayLike = Union[_Number, npt.ArrayLike]

class Law:
    """A level of the contact law bound to one fingertip.

    Methods taking ``delta`` [m] use the law's hot path (0 out of contact, the tangent
    extension past ``delta_max``) unless ``checked=True``, which raises ``ParameterError`` /
    ``OutOfRangeError`` (``field == "delta"``) for a negative, non-finite or
    past-``delta_max`` compression."""

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
        """Pressure p(r) [Pa] at distance r [m] from the centre, at compression delta [m]."""
    def valid(self, delta: _ArrayLike) -> Union[float, _Array]:
        """1.0 where 0 <= delta <= delta_max, else 0.0."""
    def delta_for_force(self, force: _ArrayLike) -> Union[float, _Array]:
        """Inverse: delta [m] at which the law gives ``force`` [N] (in [0, force_max]);
        ``OutOfRangeError`` (``field == "force"``) otherwise."""
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
    def level(self) -> str: ...
    @property
    def backing(self) -> str: ...
    @property
    def thickness(self) -> Optional[float]:
        """Skin thickness t [m] of a core fingertip."""
    @property
    def tip_radius(self) -> float:
        """Outer radius R [m]."""
    @property
    def effective_modulus(self) -> float:
        """E* [Pa]."""
    @property
    def youngs_modulus(self) -> float:
        """E [Pa]."""
    @property
    def poisson_ratio(self) -> float: ...

def law(
    level: str,
    youngs_modulus: float,
    poisson_ratio: float,
    radius: float,
    backing: str = ...,
    thickness: Optional[float] = ...,
    *,
    k: Optional[float] = ...,
    tolerance: Optional[float] = ...,
    match_x: Optional[float] = ...,
) -> Law: ...
def fit_material(
    delta: npt.ArrayLike,
    force: npt.ArrayLike,
    radius: float,
    poisson_ratio: float,
    x_fit: float = ...,
    level: str = ...,
    *,
    k: Optional[float] = ...,
    tolerance: Optional[float] = ...,
    match_x: Optional[float] = ...,
) -> Dict[str, Any]: ...
def run_scene(
    path: Optional[str] = ...,
    *,
    toml: Optional[str] = ...,
    base_dir: Optional[str] = ...,
    mcap: Optional[str] = ...,
    every: Optional[int] = ...,
    overwrite: bool = ...,
) -> Dict[str, Any]: ...

Row = Tuple[Any, ...]

class Sweep:
    """A checked sweep file (softgrip-sweep's ``Sweep``)."""

    @staticmethod
    def open(path: str) -> "Sweep": ...
    @staticmethod
    def from_toml(text: str, base_dir: str) -> "Sweep": ...
    @property
    def trials(self) -> int: ...
    @property
    def origin(self) -> str: ...
    @property
    def object(self) -> str: ...
    def fields(self) -> List[str]: ...
    def columns(self) -> List[str]: ...
    def kinds(self) -> List[str]:
        """``float``, ``int``, ``bool`` or ``text`` per varied field."""
    def scene_text(self, index: int) -> str: ...
    def run_trial(self, index: int) -> Row:
        """Trial ``index``'s row ``(trial, *values, held, slips, slip_distance, peak_force,
        peak_x, validity_excursions, wall_time, error)``."""
    def run(self, threads: int = ..., shard_index: int = ..., shard_count: int = ...) -> List[Row]: ...
    def write(self, rows: List[Row], path: str) -> None:
        """Writes ``rows`` as ``softgrip sweep --out`` does (.parquet or .csv)."""
    def to_csv(self, rows: List[Row]) -> str: ...
