#!/usr/bin/env bash
# The Python package's CI step (called by .ci/test after the workspace's tests, which leave
# target/debug/softgrip for the comparisons): builds the manylinux abi3 wheel with the dev
# profile (ci/build-wheel.sh: it shares the workspace's debug artifacts in target/debug, zig
# links the extension against glibc 2.17), checks it with auditwheel, installs it into the
# pinned venv target/py-wheel-venv (created from python3 -m venv and requirements-test.txt,
# idempotent) and runs pytest on crates/softgrip-py/tests. Prints the time of each part.
set -euo pipefail
cd "$(dirname "$0")/../../.."

VENV=target/py-wheel-venv
REQ=crates/softgrip-py/requirements-test.txt
t0=$(date +%s)

if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV"
fi
FROZEN=$("$VENV/bin/python" -m pip freeze 2>/dev/null || true)
MISSING=0
while read -r pin; do
  case "$pin" in ''|'#'*) continue ;; esac
  grep -qxi "$pin" <<<"$FROZEN" || MISSING=1
done <"$REQ"
if [ "$MISSING" = 1 ]; then
  "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check -r "$REQ"
fi
t1=$(date +%s)
echo "python venv $VENV: $((t1 - t0)) s"

# The wheel's build (softgrip-py alone) must see the workspace's features, or it recompiles
# most of the workspace (see the workspace hack in Cargo.toml).
python3 crates/softgrip-py/ci/features.py

WHEEL=$(PYTHON="$VENV/bin/python" bash crates/softgrip-py/ci/build-wheel.sh | tail -n 1)
t2=$(date +%s)
echo "wheel $WHEEL (dev profile, $(stat -c %s "$WHEEL") bytes) built: $((t2 - t1)) s"
# auditwheel (PyPA's checker) must find nothing outside the manylinux_2_17 policy.
"$VENV/bin/python" -m auditwheel show "$WHEEL" | tr '\n' ' ' | grep -q 'consistent with the following platform tag: "manylinux_2_17_x86_64"' \
  || { "$VENV/bin/python" -m auditwheel show "$WHEEL"; echo "auditwheel: not manylinux_2_17" >&2; exit 1; }
echo "auditwheel show: consistent with manylinux_2_17_x86_64"
"$VENV/bin/python" -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps "$WHEEL"
t3=$(date +%s)
echo "wheel installed into $VENV: $((t3 - t2)) s"

export SOFTGRIP_WHEEL="$PWD/$WHEEL" SOFTGRIP_BIN="$PWD/target/debug/softgrip"
"$VENV/bin/python" -m pytest crates/softgrip-py/tests -q -rs -p no:cacheprovider \
  --ignore crates/softgrip-py/tests/test_ray.py
# Ray's servers listen on every interface (whatever _node_ip_address says): its tests and the
# READMEs' Ray snippets run in a private network namespace whose one interface is loopback (as
# the DDS tests do).
t_ray=$(date +%s)
unshare --net -- sh -c 'ip link set lo up && exec "$0" -m pytest crates/softgrip-py/tests/test_ray.py crates/softgrip-py/tests/test_readme.py -k "ray" -q -rs -p no:cacheprovider' \
  "$VENV/bin/python"
echo "Ray tests (private network namespace): $(( $(date +%s) - t_ray )) s"
t4=$(date +%s)
echo "pytest: $((t4 - t3)) s; the Python step took $((t4 - t0)) s"
