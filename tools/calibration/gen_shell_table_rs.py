#!/usr/bin/env python3
"""Writes the Rust tables of the core law's thin-skin form (session 28's SFB0030, since session 29
SFF: SFB0030 with the squeezed film, `try_deep_squeeze_s29.py`; issue 24 item 5) and the
reference values its Rust test compares against (the tables are the shell's, the same for both).

The form (`try_shell_table_s28.py --var SFB0030`, the reference; CORE_FORM.md "Thin skins: the
shell table as the skeleton, session 28") needs chi_shell(x, nu, tau) = chi_lin(u, nu) (1 + tau
G(nu, tau, u)), u = sqrt(x)/tau. Rust gets both factors as tables:

  G        exactly the Python interpolant (`try_shell_table_s28.G_of`): per t/R node the bicubic
           `RectBivariateSpline` in (nu, ln u) as its knots and B-spline coefficients (evaluated
           in Rust by de Boor, nu clamped to the node grid's [0.3, 0.499] as FITPACK clamps), its
           u range (linear to 0 below, held above); across the eight nodes the not-a-knot
           `CubicSpline` in t/R as its cardinal basis (piecewise cubic coefficients per interval
           and node), t/R clamped to [0.05, 0.6]. Nothing refitted: the same numbers as the npz.
  chi_lin  the exact flat bonded layer (`thin_layer_exact_s27.chi_lin`, which Python solves
           afresh at each nu) sampled at NU_N Poisson ratios in [0.3, 0.5], uniform in
           ln(eps + EPS0) (`nu_coord`), and U_N points in ln u over [U_LO, U_HI], as
           ln(chi_lin - 1), and interpolated in Rust by the bicubic B-spline through those
           samples (`RectBivariateSpline`, s = 0). Below U_LO Rust
           continues chi_lin - 1 linearly to 0 (Python does so below its own table's start,
           u(a = 1e-3) = 0.00099962-0.00099971 by nu); above U_HI Rust holds it (Python holds at
           its table's end u(a = 20) = 10.65 (nu 0.5) to 14.23 (nu 0.3)): the two differ only for
           u > U_HI = 10.6, which the plane core never reaches (u <= sqrt(0.8/0.05) = 4).

Output: crates/softgrip-law/src/levels/shell_table.rs (the tables, with this provenance), and
crates/softgrip-law/tests/data/shell_s28_reference.csv (Python's chi_shell, the law and the full
SFF chi at nu x t/R x x points; the Rust test `shell_table::tests` and `backed::tests`
compare). Also prints the chi_lin table's interpolation error against Python at off-grid points.

usage: nice -n 10 /work/main/target/fe-venv/bin/python tools/calibration/gen_shell_table_rs.py
       (~3 min: chi_lin's per-nu solves)
"""
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))

import fit_core as f  # noqa: E402
import thin_layer_exact_s27 as tl  # noqa: E402
import try_deep_squeeze_s29 as s29  # noqa: E402
import try_shell_table_s28 as s28  # noqa: E402
import try_thin_skin_s25 as s25  # noqa: E402

OUT_RS = os.path.join(ROOT, "crates", "softgrip-law", "src", "levels", "shell_table.rs")
OUT_CSV = os.path.join(ROOT, "crates", "softgrip-law", "tests", "data", "shell_s28_reference.csv")

# The thin-skin form's constants: since session 29 SFF's [l0, l1, k0, k1, lc, cf]
# (try_deep_squeeze_s29.py --var PcTZ, refitted on the FITTED set; session 28's SFB0030 before it)
# as CORE_FORM.md prints them; the reference values use these six-digit numbers.
P_FORM = tuple(s29.SFF)
MODE = "SFF"

NU_N = 72  # chi_lin's Poisson ratios, 0.3 ... 0.5, uniform in ln(eps + EPS0)
EPS0 = 1e-3
U_LO, U_HI = 1e-3, 10.6
U_N = 187  # chi_lin's points in ln u (step 0.05)


def nu_coord(nu):
    """chi_lin's Poisson-ratio coordinate ln(eps + EPS0), eps = mu/kappa: near nu = 1/2 chi_lin
    is a function of eps u^2 (the compressibility crossover of a bonded layer, z^2 = (3/2)(1 -
    2 nu)/(1 - nu) u^2), so uniform in nu it would need a step ~1/u^2 (a uniform 41-point grid
    in nu was 1.3e-3 off at u 4, 6e-2 at u 10); in ln(eps + EPS0) its scale is the same at
    every u, and flat below EPS0."""
    return np.log(f.eps_of(nu) + EPS0)


def chi_lin_grid():
    eps_03 = f.eps_of(0.3)
    ls = np.linspace(np.log(EPS0), np.log(eps_03 + EPS0), NU_N)
    eps = np.exp(ls) - EPS0
    eps[0], eps[-1] = 0.0, eps_03
    nus = (3 - 2 * eps) / (6 + 2 * eps)  # eps = 3 (1 - 2 nu)/(2 (1 + nu)) inverted
    nus[0], nus[-1] = 0.5, 0.3
    lnu = np.linspace(np.log(U_LO), np.log(U_HI), U_N)
    vals = np.array([np.log(tl.chi_lin(np.exp(lnu), nu) - 1) for nu in nus])
    return ls, lnu, vals


def chi_lin_rust_model(sp):
    """Rust's chi_lin from the exported spline (the same arithmetic, in numpy)."""
    def chi(u, nu):
        u = np.asarray(u, dtype=float)
        uc = np.clip(u, U_LO, U_HI)
        ex = np.exp(sp.ev(np.full_like(uc, nu_coord(nu)), np.log(uc)))
        return 1 + np.where(u < U_LO, ex * u / U_LO, ex)
    return chi


def fmt(v):
    return repr(float(v))


def rs_array(name, vals, doc, per=4):
    vals = list(vals)
    lines = [f"/// {doc}", f"pub(super) static {name}: [f64; {len(vals)}] = ["]
    for i in range(0, len(vals), per):
        lines.append("    " + " ".join(fmt(v) + "," for v in vals[i:i + per]))
    lines.append("];")
    return "\n".join(lines)


def main():
    from scipy.interpolate import CubicSpline, RectBivariateSpline
    t0 = time.time()
    nodes = s28._table()
    # --- chi_lin ---
    ls, lnu, vals = chi_lin_grid()
    sp_lin = RectBivariateSpline(ls, lnu, vals, kx=3, ky=3, s=0)
    print(f"chi_lin grid {NU_N} x {U_N} ({time.time() - t0:.0f} s)", flush=True)
    model = chi_lin_rust_model(sp_lin)
    worst = 0.0
    uq = np.exp(np.linspace(np.log(U_LO), np.log(U_HI), 4 * U_N + 3))
    uq = np.concatenate([[1e-5, 5e-4], uq])
    w4 = 0.0
    for nu in (0.3025, 0.3333, 0.3871, 0.4, 0.4419, 0.4777, 0.4912, 0.4975, 0.4993, 0.4999,
               0.49999, 0.5):
        r = model(uq, nu) / tl.chi_lin(uq, nu) - 1
        worst = max(worst, float(np.max(np.abs(r))))
        w4 = max(w4, float(np.max(np.abs(r[uq <= 4]))))
    print(f"chi_lin table against Python's chi_lin at 12 nu x {len(uq)} u in (0, {U_HI}]: max "
          f"rel {worst:.2e} ({w4:.2e} to u 4)", flush=True)
    tx_l, ty_l = sp_lin.get_knots()
    c_l = sp_lin.get_coeffs()
    # --- G ---
    g_parts = []
    for j, (sp, lo, hi, us, g) in enumerate(nodes):
        tx, ty = sp.get_knots()
        g_parts.append((tx, ty, sp.get_coeffs(), lo, hi))
    # --- the cubic in t/R: cardinal basis ---
    cs = CubicSpline(s28.TAUS, np.eye(len(s28.TAUS)), axis=0)
    # cs.c: (4, intervals, nodes); value on interval i at t: sum_k c[k, i, j] (t - TAUS[i])^(3-k)
    basis = cs.c

    # --- write Rust ---
    cmd = "nice -n 10 /work/main/target/fe-venv/bin/python tools/calibration/gen_shell_table_rs.py"
    out = [
        "//! Generated by `tools/calibration/gen_shell_table_rs.py`: do not edit. Regenerate with",
        f"//! `{cmd}`",
        "//! (reads `tools/calibration/shell_table_s28.npz` through `try_shell_table_s28.py` and solves",
        "//! `thin_layer_exact_s27.chi_lin` at each tabulated nu; also rewrites",
        "//! `crates/softgrip-law/tests/data/shell_s28_reference.csv`).",
        "//!",
        "//! The tables of the exact small-strain shell on its core (session 28, `--var SFB0030`):",
        "//! `chi_shell = chi_lin(u, nu) (1 + tau G(nu, tau, u))`, `u = sqrt(x)/tau`. `G`: per t/R node",
        "//! the Python interpolant's bicubic B-spline in `(nu, ln u)` (knots, coefficients, u range)",
        "//! and the not-a-knot cubic across the nodes as its cardinal basis; `chi_lin`:",
        "//! `ln(chi_lin - 1)` sampled on a (nu, ln u) grid and interpolated by the bicubic B-spline",
        "//! through the samples (exported the same way). Evaluated in `super::shell`.",
        "",
        "// Data, not code: knots that happen to be near ln 2 or sqrt 2 are the grid's values.",
        "#![allow(",
        "    clippy::unreadable_literal,",
        "    clippy::excessive_precision,",
        "    clippy::approx_constant",
        ")]",
        "",
        rs_array("TAUS", s28.TAUS, "The t/R nodes of `G`."),
        "",
        f"/// The Poisson ratio range of `G`'s splines (FITPACK clamps its argument to it).",
        f"pub(super) const G_NU: [f64; 2] = [{fmt(s28.NUS[0])}, {fmt(s28.NUS[-1])}];",
        "",
        f"/// The cubic in t/R across the nodes: `BASIS[i][j]`, on interval i (from `TAUS[i]`), node",
        f"/// j's cardinal function `c0 d^3 + c1 d^2 + c2 d + c3`, `d = tau - TAUS[i]`.",
        f"pub(super) const BASIS: [[[f64; 4]; {len(s28.TAUS)}]; {len(s28.TAUS) - 1}] = [",
    ]
    for i in range(basis.shape[1]):
        out.append("    [")
        for j in range(basis.shape[2]):
            out.append("        [" + ", ".join(fmt(basis[k, i, j]) for k in range(4)) + "],")
        out.append("    ],")
    out.append("];")
    out.append("")
    for j, (tx, ty, c, lo, hi) in enumerate(g_parts):
        out.append(rs_array(f"G{j}_TX", tx, f"`G` at t/R {s28.TAUS[j]}: knots in nu."))
        out.append(rs_array(f"G{j}_TY", ty, f"`G` at t/R {s28.TAUS[j]}: knots in ln u."))
        out.append(rs_array(f"G{j}_C", c, f"`G` at t/R {s28.TAUS[j]}: B-spline coefficients, "
                                          f"row-major in (nu, ln u)."))
        out.append("")
    out.append("/// One t/R node of `G`: knots in nu, knots in ln u, coefficients, the node's first and last u.")
    out.append("pub(super) type GNode = (&'static [f64], &'static [f64], &'static [f64], f64, f64);")
    out.append("")
    out.append("/// Per t/R node, `GNode`.")
    out.append("pub(super) static G_NODES: [GNode; 8] = [")
    for j, (tx, ty, c, lo, hi) in enumerate(g_parts):
        out.append(f"    (&G{j}_TX, &G{j}_TY, &G{j}_C, {fmt(lo)}, {fmt(hi)}),")
    out.append("];")
    out.append("")
    out.append(f"/// `chi_lin`'s u range: `chi_lin - 1` linear to 0 below, held above.")
    out.append(f"pub(super) const LIN_EPS0: f64 = {fmt(EPS0)};")
    out.append(f"pub(super) const LIN_U: [f64; 2] = [{fmt(U_LO)}, {fmt(U_HI)}];")
    out.append(rs_array("LIN_TX", tx_l, f"`ln(chi_lin - 1)`: knots in `ln(eps + LIN_EPS0)` ({NU_N} samples, nu 0.5 to 0.3)."))
    out.append(rs_array("LIN_TY", ty_l, f"`ln(chi_lin - 1)`: knots in ln u ({U_N} samples)."))
    out.append(rs_array("LIN_C", c_l, "`ln(chi_lin - 1)`: B-spline coefficients, row-major in (ln(eps + LIN_EPS0), ln u)."))
    with open(OUT_RS, "w") as fh:
        fh.write("\n".join(out) + "\n")
    print(f"wrote {OUT_RS}")

    # --- reference values ---
    law = s25.form("K")
    chi = s29.form(MODE)
    rows = []
    for nu in (0.3, 0.33, 0.37, 0.4, 0.43, 0.45, 0.47, 0.48, 0.49, 0.495, 0.499, 0.5):
        for tau in (0.05, 0.06, 0.08, 0.1, 0.12, 0.15, 0.18, 0.2, 0.23, 0.25, 0.28, 0.3):
            x_max = min(f.flat_x_max(nu), 0.8 * tau)
            for k in (1e-4, 0.003, 0.02, 0.06, 0.13, 0.22, 0.33, 0.47, 0.61, 0.75, 0.88, 1.0):
                x = x_max * k * k
                cs_ = float(s28.chi_shell(np.array([x]), nu, tau)[0])
                cl = float(np.squeeze(law(s25.LAW, np.array([x]), nu, tau)))
                cf = float(np.squeeze(chi(P_FORM, np.array([x]), nu, tau)))
                rows.append((nu, tau, x, cs_, cl, cf))
    os.makedirs(os.path.dirname(OUT_CSV), exist_ok=True)
    with open(OUT_CSV, "w") as fh:
        fh.write(f"# {cmd}: try_shell_table_s28.py chi_shell, the law (s25.form K, LAW) and "
                 f"{MODE} (try_deep_squeeze_s29.py) with {list(P_FORM)}\n")
        fh.write("nu,tau,x,chi_shell,chi_law,chi_form\n")
        for r in rows:
            fh.write(",".join(repr(float(v)) for v in r) + "\n")
    print(f"wrote {OUT_CSV} ({len(rows)} rows) in {time.time() - t0:.0f} s")


if __name__ == "__main__":
    sys.exit(main())
