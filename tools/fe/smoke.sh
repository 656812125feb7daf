#!/usr/bin/env bash
# CI smoke test of softgrip's FE pipeline: installs what is missing (setup.sh), then runs TWO
# coarse-mesh cases end to end, side by side (one ccx each, the machine's two cores), and
# compares each one's force with the committed campaign result:
#  1. axisymmetric: flat, nu = 0.48, mesh R/30, load increments <= 0.005 to x = 0.1, <= 0.01
#     beyond, to x = 0.3, against tests/data/fe/flat/force_nu0.48.csv (mesh R/40, the same
#     increments) at x = 0.1, 0.2, 0.3;
#  2. 3D: flat on a rigid cylinder of radius R (k = 1), nu = 0.48, quarter model with element
#     edge R/12 at the pole, increments <= 0.005, to x = SMOKE3D_X, against
#     tests/data/fe/cylinder/flat/force_nu0.48_k1.csv (R/20, the same increments) there.
# Fails if any |F_smoke / F_committed - 1| exceeds its tolerance (see README for the values).
# SOFTGRIP_FE_SMOKE_SERIAL=1 runs the two cases one after the other (one ccx at a time).
# Last line: "2 passed, 0 failed" (or how many failed).
set -uo pipefail
cd "$(dirname "$0")/../.."
# 1 %: the measured R/30-vs-R/40 difference at these x is 0.05-0.07 %, while a lost bond
# (free instead of flat: -14 % at x = 0.1) or a wrong force scale (x 180) is far outside it.
TOL_PCT="${SOFTGRIP_FE_SMOKE_TOL_PCT:-1.0}"
# the 3D case: see README (the measured R/12-vs-R/20 difference and what the tolerance catches)
TOL3D_PCT="${SOFTGRIP_FE_SMOKE3D_TOL_PCT:-2.0}"
SMOKE3D_X=0.06
t0=$(date +%s)
fail() { echo "smoke: $*"; echo "0 passed, 2 failed"; exit 1; }

PY="$(bash tools/fe/setup.sh)" || fail "setup.sh failed"
t1=$(date +%s)
D="$(mktemp -d /tmp/softgrip-fe-smoke.XXXXXX)"
TIMEFORMAT="smoke: %R s wall, %U s CPU (user)"
axi() {
  ( time "$PY" tools/fe/fe_run.py flat --nu 0.48 --h 30 --tend 0.3 --dt-small 0.005 \
      --dir "$D/axi" --timeout 900 > "$D/axi.csv" ) 2> "$D/axi.time"
}
cyl() {
  ( time "$PY" tools/fe/fe_run.py flat --counterpart cylinder --k 1 --nu 0.48 --h 12 \
      --tend "$SMOKE3D_X" --dt-small 0.005 --dir "$D/cyl" --timeout 900 > "$D/cyl.csv" ) \
      2> "$D/cyl.time"
}
if [ "${SOFTGRIP_FE_SMOKE_SERIAL:-0}" = 1 ]; then  # one ccx at a time (one free core)
  axi || fail "fe_run.py (axisymmetric) failed (see $D/axi/log)"
  cyl || fail "fe_run.py (3D cylinder) failed (see $D/cyl/log)"
else
  axi &
  p1=$!
  cyl &
  p2=$!
  wait $p1 || fail "fe_run.py (axisymmetric) failed (see $D/axi/log)"
  wait $p2 || fail "fe_run.py (3D cylinder) failed (see $D/cyl/log)"
fi
t2=$(date +%s)
failed=0
compare() {  # name, smoke csv, committed csv, tolerance [%], x...
  local name=$1 mine=$2 ref=$3 tol=$4
  shift 4
  head -1 "$mine"
  "$PY" - "$mine" "$ref" "$tol" "$@" <<'PYEOF'
import sys
import numpy as np
mine = np.genfromtxt(sys.argv[1], delimiter=",", names=True, skip_header=1)  # line 1: "# ..."
ref = np.genfromtxt(sys.argv[2], delimiter=",", names=True, skip_header=1)  # provenance
tol = float(sys.argv[3])
ok = True
for x in map(float, sys.argv[4:]):
    m = mine["force_N"][np.isclose(mine["delta_over_R"], x)]
    r = ref["force_N"][np.isclose(ref["delta_over_R"], x)]
    if len(m) == 0 or len(r) == 0:
        print(f"x = {x}: missing (smoke {len(m)}, committed {len(r)})")
        ok = False
        continue
    d = 100 * (m[0] / r[0] - 1)
    print(f"x = {x}: F smoke {m[0]:.6g} N, committed {r[0]:.6g} N, {d:+.3f} % (tol {tol} %)")
    ok &= abs(d) <= tol
sys.exit(0 if ok else 1)
PYEOF
  local rc=$?
  if [ $rc -ne 0 ]; then
    echo "smoke: $name: force differs from the committed result by more than $tol %"
    failed=$((failed + 1))
  fi
}
compare axisymmetric "$D/axi.csv" tests/data/fe/flat/force_nu0.48.csv "$TOL_PCT" 0.1 0.2 0.3
cat "$D/axi.time"
compare "3D cylinder" "$D/cyl.csv" tests/data/fe/cylinder/flat/force_nu0.48_k1.csv "$TOL3D_PCT" \
  0.03 "$SMOKE3D_X"
cat "$D/cyl.time"
mode="side by side"
[ "${SOFTGRIP_FE_SMOKE_SERIAL:-0}" = 1 ] && mode="one after the other"
echo "smoke: setup $((t1 - t0)) s, FE runs $((t2 - t1)) s ($mode), total $(( $(date +%s) - t0 )) s"
if [ $failed -eq 0 ]; then
  rm -rf "$D"
fi
echo "$((2 - failed)) passed, $failed failed"
[ $failed -eq 0 ]
