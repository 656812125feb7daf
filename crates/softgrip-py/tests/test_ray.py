"""The Ray backend: a local Ray (2 CPUs, every server on 127.0.0.1, no dashboard) runs each trial
as a task calling the extension; its rows equal the local run's row for row (every column but
wall_time), and its Parquet output equals the local run's. Skipped, with the reason printed,
only where Ray is not installed (CI installs it: requirements-test.txt)."""

from __future__ import annotations

import socket
import sys

import pytest

import softgrip

SWEEP = "crates/softgrip-py/tests/data/grasp_sweep.toml"

try:
    import ray
except ImportError as e:  # pragma: no cover
    print(f"test_ray.py: skipped: ray is not installed ({e})", file=sys.stderr)
    pytest.skip(f"ray is not installed ({e}); pip install -r requirements-test.txt", allow_module_level=True)


def only_loopback() -> bool:
    """Whether this process sees no network interface but loopback (a private network
    namespace, as ci/test.sh runs this file in)."""
    try:
        return [name for _, name in socket.if_nameindex()] == ["lo"]
    except OSError:
        return False


@pytest.fixture(scope="module")
def local_ray(tmp_path_factory):
    # Ray's gRPC servers (GCS, raylet, workers) listen on every interface whatever
    # _node_ip_address says (seen with ss on Ray 2.60): the test runs only where loopback is
    # the one interface there is.
    if not only_loopback():
        reason = (
            "Ray's servers bind to all interfaces: run this test in a private network "
            "namespace (crates/softgrip-py/ci/test.sh does: unshare --net)"
        )
        print(f"test_ray.py: skipped: {reason}", file=sys.stderr)
        pytest.skip(reason)
    # The node's address 127.0.0.1, no dashboard.
    ray.init(
        num_cpus=2,
        include_dashboard=False,
        _node_ip_address="127.0.0.1",
        object_store_memory=100 * 1024 * 1024,
        _temp_dir=str(tmp_path_factory.mktemp("ray")),
        log_to_driver=False,
        configure_logging=False,
    )
    yield
    ray.shutdown()


def drop_wall_time(rows, columns):
    w = columns.index("wall_time")
    return [tuple(v for j, v in enumerate(r) if j != w) for r in rows]


def test_ray_equals_local(root, local_ray, tmp_path):
    columns = softgrip.Sweep.open(str(root / SWEEP)).columns()
    local = softgrip.sweep(root / SWEEP, table="rows")
    on_ray = softgrip.sweep(root / SWEEP, backend="ray", table="rows", out=tmp_path / "ray.parquet")
    assert len(on_ray) == len(local) == 16
    assert drop_wall_time(on_ray, columns) == drop_wall_time(local, columns)
    assert [r[0] for r in on_ray] == list(range(16))
    # a shard on Ray is the same slice as a local shard
    part = softgrip.sweep(root / SWEEP, backend="ray", table="rows", shard="1/4")
    assert drop_wall_time(part, columns) == drop_wall_time(local[4:8], columns)
    pa = pytest.importorskip("pyarrow", reason="pyarrow is not installed")
    import pyarrow.parquet as pq

    back = pq.read_table(tmp_path / "ray.parquet")
    assert back.column_names == columns
    assert back.drop_columns(["wall_time"]).equals(
        softgrip.sweep(root / SWEEP, table="arrow").drop_columns(["wall_time"])
    )


def test_laws_sweeps_and_runs_go_through_ray(root, local_ray, tmp_path):
    # Ray pickles a task's arguments and results: a Law and a Sweep go to the workers, a
    # RunResult and a Recording come back, equal to the local ones.
    import numpy as np

    law = softgrip.law("auto", 3e6, 0.45, 0.01, "core", 0.004, tolerance=0.02)
    delta = np.linspace(0.0, 0.004, 41)

    @ray.remote(num_cpus=1)
    def forces(l, d):
        return l, l.force(d)

    back, f = ray.get(forces.remote(law, delta))
    assert back == law
    np.testing.assert_array_equal(f, law.force(delta))

    sweep = softgrip.Sweep.open(root / SWEEP)

    @ray.remote(num_cpus=1)
    def trial(s, i):
        return s.run_trial(i)

    columns = sweep.columns()
    rows = ray.get([trial.remote(sweep, i) for i in (0, 5)])
    assert drop_wall_time(rows, columns) == drop_wall_time([sweep.run_trial(0), sweep.run_trial(5)], columns)

    scene = root / "crates/softgrip-py/tests/data/grasp.toml"

    @ray.remote(num_cpus=1)
    def run(path, out):
        r = softgrip.run(path, mcap=out)
        return r, softgrip.open_recording(out)

    remote, rec = ray.get(run.remote(str(scene), str(tmp_path / "r.mcap")))
    local = softgrip.run(scene)
    assert remote.digest == local.digest and remote.summary_lines == local.summary_lines
    np.testing.assert_array_equal(remote.fingertips["left_tip"]["force"], local.fingertips["left_tip"]["force"])
    np.testing.assert_array_equal(rec.fingertips["left_tip"]["force"], local.fingertips["left_tip"]["force"][rec.step - 1])
