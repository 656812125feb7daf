"""``softgrip.sweep``: a sweep file's trials on local threads (Rust, rayon) or as Ray tasks
(one task per trial, calling the same ``Sweep.run_trial`` in the extension), and the results
table with the Rust ``ResultsTable``'s columns."""

from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _native
from .errors import ArgumentTypeError, ParameterError

PathLike = Union[str, "os.PathLike[str]"]
Row = Tuple[Any, ...]

OUTCOME_COLUMNS: Tuple[str, ...] = _native.OUTCOME_COLUMNS
"""The columns after the varied fields, in order (softgrip-sweep's ``OUTCOME_COLUMNS``)."""

# Column types of the outcomes: (numpy dtype, arrow type name, nullable).
_OUTCOME_TYPES = {
    "held": ("bool", "bool_", True),
    "slips": ("int64", "int64", True),
    "slip_distance": ("float64", "float64", True),
    "peak_force": ("float64", "float64", True),
    "peak_x": ("float64", "float64", True),
    "validity_excursions": ("int64", "int64", True),
    "hold_force": ("float64", "float64", True),
    "wall_time": ("float64", "float64", False),
    "error": ("object", "string", True),
}
_KIND_TYPES = {
    "float": ("float64", "float64"),
    "int": ("int64", "int64"),
    "bool": ("bool", "bool_"),
    "text": ("object", "string"),
}


def _error(cls, field: str, value: Any, expected: str):
    """``cls`` (a softgrip error) saying ``field`` must be ``expected``, naming the value."""
    kind = f" ({type(value).__name__})" if cls is ArgumentTypeError else ""
    err = cls(f"`{field}` must be {expected}, got {value!r}{kind}")
    err.field, err.value = field, repr(value)
    return err


def _open(sweep_path: Optional[PathLike], toml: Optional[str], base_dir: Optional[PathLike]):
    if (sweep_path is None) == (toml is None):
        raise _error(
            ParameterError,
            "toml",
            toml,
            "given exactly when `sweep_path` is not (a sweep file or sweep text, one of the two)",
        )
    if sweep_path is not None:
        return _native.Sweep.open(sweep_path)
    return _native.Sweep.from_toml(toml, base_dir if base_dir is not None else ".")


def _shard(shard: Union[None, str, Tuple[int, int]]) -> Tuple[int, int]:
    if shard is None:
        return (0, 1)
    expected = "\"i/n\" or (i, n) with 0 <= i < n"
    if isinstance(shard, str):
        i, sep, n = shard.partition("/")
        if sep and i.strip().isdigit() and n.strip().isdigit():
            return (int(i), int(n))
        raise _error(ParameterError, "shard", shard, expected)
    if isinstance(shard, tuple) and len(shard) == 2:
        ints = all(isinstance(v, int) and not isinstance(v, bool) for v in shard)
        if ints:
            return (shard[0], shard[1])
    raise _error(ArgumentTypeError, "shard", shard, expected)


def _shard_range(trials: int, index: int, count: int) -> range:
    # Shard::range: [i * N / n, (i + 1) * N / n).
    return range(index * trials // count, (index + 1) * trials // count)


# --- Ray -------------------------------------------------------------------------------------

# One checked sweep per worker process, by how it was given (a task re-uses it).
_WORKER_SWEEPS: Dict[Tuple[Optional[str], Optional[str], Optional[str]], Any] = {}


def _worker_sweep(path: Optional[str], toml: Optional[str], base_dir: Optional[str]):
    key = (path, toml, base_dir)
    s = _WORKER_SWEEPS.get(key)
    if s is None:
        s = _open(path, toml, base_dir)
        _WORKER_SWEEPS[key] = s
    return s


def _ray_trial(path: Optional[str], toml: Optional[str], base_dir: Optional[str], index: int) -> Row:
    """A Ray task's body: trial ``index`` of the sweep, by the extension (its row tuple)."""
    return tuple(_worker_sweep(path, toml, base_dir).run_trial(index))


def _has_working_dir(ray, options: Dict[str, Any]) -> bool:
    """Whether the tasks run in a runtime_env ``working_dir`` (theirs or the job's): then a
    relative path is relative to that directory, as on the driver."""
    task_env = options.get("runtime_env") or {}
    try:
        job_env = ray.get_runtime_context().runtime_env or {}
    except Exception:  # pragma: no cover - older Ray
        job_env = {}
    return bool(task_env.get("working_dir") or job_env.get("working_dir"))


def _run_ray(
    path: Optional[str],
    toml: Optional[str],
    base_dir: Optional[str],
    indices: range,
    ray_options: Optional[Dict[str, Any]],
) -> List[Row]:
    try:
        import ray
    except ImportError as e:  # pragma: no cover - exercised only without ray
        raise ImportError(
            "backend=\"ray\" needs Ray: pip install 'softgrip[ray]' (or ray)"
        ) from e
    if not ray.is_initialized():
        # A local cluster on this machine (ray.init() with no address); to use a cluster,
        # call ray.init(address=...) before softgrip.sweep.
        ray.init()
    options = dict(ray_options or {"num_cpus": 1})
    if not _has_working_dir(ray, options):
        # Without a runtime_env working_dir the workers' current directory is not the
        # driver's: hand them absolute paths (on a cluster, paths every node sees).
        path = None if path is None else os.path.abspath(path)
        base_dir = os.path.abspath(base_dir if base_dir is not None else ".")
    task = ray.remote(_ray_trial).options(**options)
    refs = [task.remote(path, toml, base_dir, i) for i in indices]
    rows = [tuple(r) for r in ray.get(refs)]
    rows.sort(key=lambda r: r[0])
    return rows


# --- Tables ----------------------------------------------------------------------------------


def _columns(s) -> List[str]:
    return list(s.columns())


def _to_numpy(s, rows: Sequence[Row]) -> Dict[str, np.ndarray]:
    cols = _columns(s)
    kinds = list(s.kinds())
    out: Dict[str, np.ndarray] = {}
    by_col = list(zip(*rows)) if rows else [() for _ in cols]
    out["trial"] = np.array(by_col[0], dtype=np.int64)
    for j, kind in enumerate(kinds):
        dtype = _KIND_TYPES[kind][0]
        out[cols[1 + j]] = np.array(by_col[1 + j], dtype=dtype)
    for j, name in enumerate(OUTCOME_COLUMNS):
        values = by_col[1 + len(kinds) + j]
        dtype, _, nullable = _OUTCOME_TYPES[name]
        if name == "error":
            out[name] = np.array(values, dtype=object)
        elif nullable:
            mask = np.array([v is None for v in values], dtype=bool)
            filled = [0 if v is None else v for v in values]
            out[name] = np.ma.MaskedArray(np.array(filled, dtype=dtype), mask=mask)
        else:
            out[name] = np.array(values, dtype=dtype)
    return out


def _to_arrow(s, rows: Sequence[Row]):
    import pyarrow as pa

    cols = _columns(s)
    kinds = list(s.kinds())
    by_col = list(zip(*rows)) if rows else [() for _ in cols]
    fields = [pa.field("trial", pa.int64(), nullable=False)]
    for j, kind in enumerate(kinds):
        fields.append(pa.field(cols[1 + j], getattr(pa, _KIND_TYPES[kind][1])(), nullable=False))
    for name in OUTCOME_COLUMNS:
        _, arrow, nullable = _OUTCOME_TYPES[name]
        fields.append(pa.field(name, getattr(pa, arrow)(), nullable=nullable))
    schema = pa.schema(fields)
    arrays = [pa.array(list(by_col[j]), type=schema.field(j).type) for j in range(len(cols))]
    return pa.Table.from_arrays(arrays, schema=schema)


def _table(s, rows: Sequence[Row], table: str):
    if table == "rows":
        return list(rows)
    if table == "numpy":
        return _to_numpy(s, rows)
    if table in ("auto", "arrow"):
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            if table == "arrow":
                raise
            return _to_numpy(s, rows)
        return _to_arrow(s, rows)
    raise _error(ParameterError, "table", table, "\"auto\", \"arrow\", \"numpy\" or \"rows\"")


def sweep(
    sweep_path: Optional[PathLike] = None,
    backend: str = "local",
    threads: Optional[int] = None,
    shard: Union[None, str, Tuple[int, int]] = None,
    *,
    toml: Optional[str] = None,
    base_dir: Optional[PathLike] = None,
    out: Optional[PathLike] = None,
    table: str = "auto",
    ray_options: Optional[Dict[str, Any]] = None,
):
    """Runs a sweep's trials and returns the results table.

    Args:
        sweep_path: the sweep file (crates/softgrip-sweep/SWEEPS.md); or give ``toml`` (sweep
            text whose ``scene`` is relative to ``base_dir``, default the current directory).
        backend: ``"local"`` (every trial on this machine's cores, Rust threads, without the
            GIL) or ``"ray"`` (one Ray task per trial; uses the running Ray if ``ray.init`` was
            called -- e.g. ``ray.init(address="auto")`` on a cluster -- else starts a local one).
        threads: worker threads for ``"local"`` (default: one per core).
        shard: only slice ``"i/n"`` (or ``(i, n)``) of the trials, as ``softgrip sweep --shard``.
        out: also write the results as ``softgrip sweep --out`` does (``.parquet`` or ``.csv``).
        table: ``"auto"`` (a ``pyarrow.Table`` if pyarrow is installed, else ``"numpy"``),
            ``"arrow"``, ``"numpy"`` (a dict of numpy arrays: the outcome columns as
            ``numpy.ma.MaskedArray``, masked on error rows; ``error`` an object array of str or
            None) or ``"rows"`` (a list of row tuples in column order).
        ray_options: options of each Ray task (default ``{"num_cpus": 1}``).

    Returns:
        The rows in trial order with the columns ``trial``, one per varied field (named by its
        path), ``held``, ``slips``, ``slip_distance`` [m], ``peak_force`` [N], ``peak_x``,
        ``validity_excursions``, ``hold_force`` [N], ``wall_time`` [s], ``error``. The Ray and the local run give
        the same rows (all columns but ``wall_time``).

    Raises:
        SweepError: the sweep file does not load (``e.field`` names the sweep field), a bad
            shard.
    """
    s = _open(sweep_path, toml, base_dir)
    # Ray tasks get the paths as text (made absolute unless a working_dir ships them).
    path = None if sweep_path is None else os.fspath(sweep_path)
    base = None if base_dir is None else os.fspath(base_dir)
    index, count = _shard(shard)
    if not isinstance(backend, str):
        raise _error(ArgumentTypeError, "backend", backend, "\"local\" or \"ray\"")
    if not isinstance(table, str):
        raise _error(ArgumentTypeError, "table", table, "\"auto\", \"arrow\", \"numpy\" or \"rows\"")
    if table not in ("auto", "arrow", "numpy", "rows"):
        raise _error(ParameterError, "table", table, "\"auto\", \"arrow\", \"numpy\" or \"rows\"")
    if backend == "local":
        if threads is not None:
            if not isinstance(threads, int) or isinstance(threads, bool):
                raise _error(ArgumentTypeError, "threads", threads, "an integer >= 1 or None")
            if threads < 1:
                raise _error(ParameterError, "threads", threads, "an integer >= 1 or None")
        rows = [tuple(r) for r in s.run(threads or 0, index, count)]
    elif backend == "ray":
        if not (0 <= index < count):
            # The same check and message as the local run's.
            s.run(1, index, count)
        rows = _run_ray(path, toml, base, _shard_range(s.trials, index, count), ray_options)
    else:
        raise _error(ParameterError, "backend", backend, "\"local\" or \"ray\"")
    if out is not None:
        s.write(rows, out)
    return _table(s, rows, table)
