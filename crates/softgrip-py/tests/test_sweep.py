"""`softgrip.sweep` locally: the results table has exactly the Rust ResultsTable's columns and
equals `softgrip sweep`'s output row for row (every column but wall_time); its Parquet file read
back with pyarrow equals the returned table; shards concatenate to the whole; a bad trial is an
error row naming the field."""

from __future__ import annotations

import csv
import io
from pathlib import Path

import numpy as np
import pytest

import softgrip

SWEEP = "crates/softgrip-py/tests/data/grasp_sweep.toml"
COLUMNS = [
    "trial",
    "fingertip[0].material.youngs_modulus",
    "body[1].shape[0].density",
    "gripper.squeeze.depth",
    "fingertip[1].level",
    "held",
    "slips",
    "slip_distance",
    "peak_force",
    "peak_x",
    "validity_excursions",
    "hold_force",
    "wall_time",
    "error",
]


@pytest.fixture(scope="module")
def local_rows(root):
    return softgrip.sweep(root / SWEEP, table="rows", threads=2)


def without_wall_time(rows):
    w = COLUMNS.index("wall_time")
    return [tuple(v for j, v in enumerate(r) if j != w) for r in rows]


def test_columns_are_the_rust_tables(root):
    s = softgrip.Sweep.open(str(root / SWEEP))
    assert s.columns() == COLUMNS
    assert s.trials == 16
    assert s.kinds() == ["float", "float", "float", "text"]


def test_local_equals_cli(cli, root, local_rows, tmp_path):
    _, out, _ = cli("sweep", root / SWEEP, "--threads", "1")  # the same origin in errors
    cli_rows = list(csv.reader(io.StringIO(out)))
    assert cli_rows[0] == COLUMNS
    s = softgrip.Sweep.open(str(root / SWEEP))
    # The package's rows written as the CLI writes them: the same CSV, but for wall_time.
    ours = list(csv.reader(io.StringIO(s.to_csv(local_rows))))
    w = COLUMNS.index("wall_time")
    assert len(ours) == len(cli_rows) == 17
    for a, b in zip(ours, cli_rows):
        assert a[:w] + a[w + 1 :] == b[:w] + b[w + 1 :]
    held = [r for r in local_rows if r[COLUMNS.index("held")]]
    errors = [r for r in local_rows if r[-1] is not None]
    assert len(errors) == 8 and len(held) >= 1
    for r in errors:
        assert r[1] == -1.0
        assert "`fingertip[0].material.youngs_modulus` must be" in r[-1]
        assert all(v is None for v in r[5:11])
    assert [r[0] for r in local_rows] == list(range(16))


def test_parquet_read_back_equals_the_table(root, tmp_path):
    pa = pytest.importorskip("pyarrow", reason="pyarrow is not installed: the Parquet check needs it")
    import pyarrow.parquet as pq

    out = tmp_path / "results.parquet"
    table = softgrip.sweep(root / SWEEP, out=out)
    assert isinstance(table, pa.Table)
    assert table.column_names == COLUMNS
    back = pq.read_table(out)
    assert back.schema.equals(table.schema), (back.schema, table.schema)
    assert back.equals(table)
    assert table.num_rows == 16
    assert table.column("error").null_count == 8
    assert table.column("held").null_count == 8
    # and the CSV the package writes reads back with the csv module to the same values
    csv_out = tmp_path / "results.csv"
    rows = table.to_pylist()
    s = softgrip.Sweep.open(str(root / SWEEP))
    s.write([tuple(r[c] for c in COLUMNS) for r in rows], str(csv_out))
    with open(csv_out, newline="") as f:
        back_csv = list(csv.DictReader(f))
    for r, c in zip(rows, back_csv):
        assert int(c["trial"]) == r["trial"]
        assert float(c["wall_time"]) == r["wall_time"]
        if r["error"] is None:
            assert float(c["peak_force"]) == r["peak_force"]
            assert c["held"] == str(r["held"]).lower()
        else:
            assert c["error"] == r["error"] and c["peak_force"] == ""


def test_numpy_table(root, local_rows):
    t = softgrip.sweep(root / SWEEP, table="numpy")
    assert list(t) == COLUMNS
    assert t["trial"].dtype == np.int64
    assert t["fingertip[1].level"].tolist() == [r[4] for r in local_rows]
    assert isinstance(t["peak_force"], np.ma.MaskedArray)
    assert t["peak_force"].mask.sum() == 8
    ok = [i for i, r in enumerate(local_rows) if r[-1] is None]
    np.testing.assert_array_equal(
        t["peak_force"].data[ok], [local_rows[i][COLUMNS.index("peak_force")] for i in ok]
    )


def test_shards_concatenate_to_the_whole(root, local_rows):
    parts = []
    for i in range(3):
        parts += softgrip.sweep(root / SWEEP, table="rows", shard=f"{i}/3")
    assert without_wall_time(parts) == without_wall_time(local_rows)
    assert softgrip.sweep(root / SWEEP, table="rows", shard=(1, 3))[0][0] == 5


def test_trial_by_index_reproduces_its_row(root, local_rows):
    s = softgrip.Sweep.open(str(root / SWEEP))
    for i in (0, 3, 12):
        assert without_wall_time([s.run_trial(i)]) == without_wall_time([local_rows[i]])
