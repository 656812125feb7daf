#!/usr/bin/env python3
"""Session 27 (issue 24 item 5): the EXACT small-strain contact of the real geometry: an elastic
spherical shell R - t <= rho <= R (E, nu) bonded to a rigid core (inner surface clamped), pressed
at its pole by a rigid frictionless plane, against the flat layer (thin_layer_exact_s27.py), the
FE skins at their smallest x and the law.

Per Legendre degree n (Lame's / Love's solution of the sphere; units R = 1, mu = 1): with
u_r = U(r) P_n(cos th), u_th = V(r) dP_n/dth, the four solutions are, for the solid harmonics
phi_m = r^m P_n (m = n and m = -n - 1),
    u = grad phi_m                     : U = m r^(m-1),        V = r^(m-1)
    u = r^2 grad phi_m + alpha_m x phi_m : U = (m + alpha_m) r^(m+1), V = r^(m+1)
    alpha_m = -[(4m + 2)(1 - 2nu) + 2m] / [2(1 - 2nu) + m + 3]   (Navier, derived in `modes`)
(n = 0: U = A r + B r^-2). Stresses: s_rr = lam (U' + (2U - n(n+1) V)/r) + 2 U' (x P_n),
s_rth = U/r + V' - V/r (x dP_n/dth). Inner surface r = 1 - t: U = V = 0; outer r = 1:
s_rr = -p_n, s_rth = -q_n (q: a shear traction along +th... see `compliance`). The 2x2 outer
compliance per degree, (w_n, v_n) = C_n (p_n, q_n), w = inward radial displacement.

Contact (`contact`): the pressure on the plane p(th) = sum_k b_k (1 - (th/th_a)^2)^(k + 1/2)
(smooth edge, p(th_a) = 0), its Legendre coefficients by Gauss quadrature (th = th_a sin psi);
two geometric readings of the same linear problem, which differ at O(x):
  'radial'  : radial pressure p on the sphere, inward radial displacement w = delta - (1 - cos th)
              (the brief's: normal load, zero shear);
  'vertical': the plane's traction -p cos(th) e_z per unit sphere area (radial p cos^2, shear
              p cos sin), the vertical displacement -u_z = delta - (1 - cos th).
The unknowns (b_k, delta) by least squares at collocation points in th < th_a; F = 2 pi int p
sin cos dth (projected area: the plane's force) in both. chi = F/F_Hertz(delta), F_H = (4/3) E*
delta^1.5 (R = 1).

Modes:
  --check     the per-degree compliance: n = 0 against Lame's shell; t/R -> 1 (core radius ->
              0) against the solid sphere; large n against the flat layer 2 L(k t)/(E* k),
              k = n + 1/2; thin shells at n t/R fixed; the contact's convergence (degrees, basis)
  --fe        chi_shell against the flat layer, the FE (k1e6 thin skins, core skins) and the law
              at x = 0.0025, 0.005, 0.01
  --table     F_shell/F_flat over (nu, t/R, a/t) at small x

Result (CORE_FORM.md "Thin skins: the shell on its core at small strain, session 27"): the
shell (radial reading) is the FE's small-strain limit within 1 %: the thin k1e6 skins' FE/shell
- 1 is linear in s = delta/t over x 0.0025-0.01 with intercepts -0.99..+0.42 % (the squeeze's
slope 3-52 %/unit s, falling with nu); the thick skins at x 0.01 to t/R 0.5 within -1.08..+1.79 %;
past t/R 0.55 the full shell's far field is not the FE's hemisphere clamped on its equator.

usage: PY tools/calibration/shell_on_core_s27.py [--check] [--fe] [--table]
       (PY: /work/main/target/fe-venv/bin/python)
"""
import argparse
import functools
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))


def alpha(m, nu):
    return -((4 * m + 2) * (1 - 2 * nu) + 2 * m) / (2 * (1 - 2 * nu) + m + 3)


def modes(n, nu, r, a_in):
    """U, U', V, V' of the four (n >= 1) solutions at radius r, scaled: the growing ones (m = n)
    by 1 at r = 1, the decaying ones (m = -n - 1) by 1 at r = a_in. Returns arrays (4, 4):
    rows U, U', V, V'; columns the solutions."""
    out = np.zeros((4, 4))
    for j, (m, kind) in enumerate(((n, "g"), (n, "p"), (-n - 1, "g"), (-n - 1, "p"))):
        sc = 1.0 if m > 0 else a_in  # scale radius
        if kind == "g":
            pu, cu, cv = m - 1, m, 1.0
        else:
            pu, cu, cv = m + 1, m + alpha(m, nu), 1.0
        # U = cu r^pu scaled by sc^-pu: cu (r/sc)^pu; derivative cu pu (r/sc)^pu / r
        f = (r / sc) ** pu
        out[:, j] = [cu * f, cu * pu * f / r, cv * f, cv * pu * f / r]
    return out


def stresses(row, n, nu, r):
    """(s_rr, s_rth) of a solution from its (U, U', V, V') at radius r (mu = 1)."""
    lam = 2 * nu / (1 - 2 * nu)
    u, du, v, dv = row
    ll = n * (n + 1)
    srr = lam * (du + (2 * u - ll * v) / r) + 2 * du
    srt = u / r + dv - v / r
    return srr, srt


@functools.lru_cache(maxsize=None)
def compliance(n, nu, tau):
    """The outer compliance of degree n: returns ((w_p, w_q), (v_p, v_q)) with w the inward
    radial displacement and v = V(1) (u_th = v dP_n/dth) under an outer traction
    s_rr = -p P_n (inward pressure p) and s_rth = q dP_n/dth, per unit p and q. tau = t/R; the
    inner surface r = 1 - tau clamped (tau = 1: the solid sphere, regular solutions only)."""
    a_in = 1 - tau
    if n == 0:
        if tau >= 1:
            # solid: U = A r, s_rr = (3 lam + 2) A = -p
            lam = 2 * nu / (1 - 2 * nu)
            return ((1 / (3 * lam + 2), 0.0), (0.0, 0.0))
        lam = 2 * nu / (1 - 2 * nu)
        # U = A r + B a^3 r^-2, U(a) = 0: B = -A ... U = A (r - a^3/r^2)
        # s_rr = (3 lam + 2) A + 4 A a^3 / r^3 at r = 1
        srr1 = (3 * lam + 2) + 4 * a_in ** 3
        aa = -1 / srr1
        return ((-(aa * (1 - a_in ** 3)), 0.0), (0.0, 0.0))
    if tau >= 1:
        if n == 1:  # a net force on a free solid sphere: no equilibrium
            return ((np.nan, np.nan), (np.nan, np.nan))
        m1 = modes(n, nu, 1.0, 1.0)[:, :2]
        s1 = np.array([stresses(m1[:, j], n, nu, 1.0) for j in range(2)]).T  # (2, 2)
        res = []
        for rhs in ([-1.0, 0.0], [0.0, 1.0]):
            c = np.linalg.solve(s1, rhs)
            res.append((-(m1[0] @ c), m1[2] @ c))
        return ((res[0][0], res[1][0]), (res[0][1], res[1][1]))
    m0 = modes(n, nu, a_in, a_in)
    m1 = modes(n, nu, 1.0, a_in)
    s1 = np.array([stresses(m1[:, j], n, nu, 1.0) for j in range(4)]).T
    mat = np.vstack([m0[0], m0[2], s1[0], s1[1]])
    res = []
    for rhs in ([0, 0, -1.0, 0], [0, 0, 0, 1.0]):
        c = np.linalg.solve(mat, np.array(rhs))
        res.append((-(m1[0] @ c), m1[2] @ c))
    return ((res[0][0], res[1][0]), (res[0][1], res[1][1]))


@functools.lru_cache(maxsize=64)
def comp_arrays(nmax, nu, tau):
    w_p = np.array([compliance(n, nu, tau)[0][0] for n in range(nmax + 1)])
    w_q = np.array([compliance(n, nu, tau)[0][1] for n in range(nmax + 1)])
    v_p = np.array([compliance(n, nu, tau)[1][0] for n in range(nmax + 1)])
    v_q = np.array([compliance(n, nu, tau)[1][1] for n in range(nmax + 1)])
    return w_p, w_q, v_p, v_q


def legendre_table(nmax, th):
    """P_n(cos th) and dP_n/dth for n = 0..nmax at angles th (> 0): arrays (nmax + 1, len th)."""
    mu = np.cos(th)
    s = np.sin(th)
    p = np.zeros((nmax + 1, len(th)))
    p[0] = 1
    if nmax >= 1:
        p[1] = mu
    for n in range(1, nmax):
        p[n + 1] = ((2 * n + 1) * mu * p[n] - n * p[n - 1]) / (n + 1)
    dp = np.zeros_like(p)
    nn = np.arange(1, nmax + 1)[:, None]
    # dP_n/dmu = n (mu P_n - P_{n-1})/(mu^2 - 1); dP/dth = -sin dP/dmu
    dp[1:] = nn * (mu * p[1:] - p[:-1]) / (s * s) * s
    return p, dp


def flat_l(u, nu):
    import thin_layer_exact_s27 as tl
    return tl.kernel_l(u, nu)


def check():
    print("n = 0 (uniform pressure), shell against Lame (U = A r + B/r^2, clamped at 1 - t): the "
          "code's radial compliance; solid sphere (1 - 2nu)/(2 (1 + nu)) = 1/(3K) (mu = 1):")
    for nu in (0.3, 0.49):
        k3 = 2 * (1 + nu) / (1 - 2 * nu)
        print(f"  nu {nu}: solid {compliance(0, nu, 1.0)[0][0]:.6f} vs 1/(3K) {1 / k3:.6f}; "
              f"t/R 0.999 {compliance(0, nu, 0.999)[0][0]:.6f}")
    print("\nt/R -> 1 (core radius -> 0) against the solid sphere (n >= 2; n = 1 carries the net "
          "force to the core: 1/radius):")
    for nu in (0.3, 0.49):
        for n in (2, 3, 5, 10):
            sol = compliance(n, nu, 1.0)[0][0]
            row = [compliance(n, nu, tau)[0][0] / sol - 1 for tau in (0.9, 0.99, 0.999)]
            print(f"  nu {nu} n {n}: solid w_p {sol:.6f}; shell/solid - 1 at t/R 0.9/0.99/0.999: "
                  + " ".join(f"{v:+.2e}" for v in row))
    print("\nSolid sphere at large n against the half-space 2/(E* k), k = n + 1/2 "
          "(E* = 2/(1 - nu)):")
    for nu in (0.3, 0.49):
        es = 2 / (1 - nu)
        print(f"  nu {nu}: " + " ".join(
            f"n {n}: {compliance(n, nu, 1.0)[0][0] * es * (n + 0.5) / 2 - 1:+.2e}"
            for n in (10, 100, 1000)))
    print("\nThin shell at n t/R fixed against the flat layer 2 L(k t)/(E* k), k = n + 1/2 "
          "[w_p over flat - 1]:")
    for nu in (0.3, 0.48, 0.499):
        es = 2 / (1 - nu)
        for kt in (0.5, 1.0, 2.0, 4.0):
            cells = []
            for tau in (0.1, 0.05, 0.02, 0.01, 0.005):
                n = int(round(kt / tau - 0.5))
                k = n + 0.5
                flat = 2 * flat_l(k * tau, nu) / (es * k)
                cells.append(f"t/R {tau:g} (n {n}) {compliance(n, nu, tau)[0][0] / flat - 1:+.2e}")
            print(f"  nu {nu} k t {kt:g}: " + "; ".join(cells))
    print("\nContact: the flat limit, shell over the flat layer at a_H/t = 1 as t/R -> 0 (radial):")
    import thin_layer_exact_s27 as tl
    for nu in (0.3, 0.49):
        fl = tl.chi_exact(1.0, nu)[0]
        print(f"  nu {nu}: " + " ".join(
            f"t/R {tau:g}: {100 * (chi_at(tau * tau, nu, tau, 'radial')[0] / fl - 1):+.3f} %"
            for tau in (0.05, 0.02, 0.01)))
    print("\nContact: convergence of chi in the number of degrees (nmax) and the basis (K):")
    for nu, tau, x in ((0.3, 0.05, 0.0025), (0.49, 0.12, 0.01), (0.48, 0.4, 0.0025)):
        for nmax, k in ((2000, 6), (4000, 6), (4000, 10), (8000, 10)):
            c = chi_at(x, nu, tau, "radial", nmax, k)
            print(f"  nu {nu} t/R {tau} x {x}: nmax {nmax} K {k}: chi {c[0]:.6f} "
                  f"a/a_H {c[1]:.5f} resid {c[2]:.1e}")


def contact(th_a, nu, tau, geom="radial", nmax=4000, kb=8, nq=None, nc=None):
    """One contact solve at half-angle th_a: returns (delta, F, chi, residual) (R = 1, mu = 1).
    geom 'radial' / 'vertical' (module docs); a trailing '2' ('radial2'): the same contact at
    both poles (the shell between two plates: even degrees only, doubled), a bracket for the
    FE's far field (a hemispherical shell clamped on its equatorial annulus too)."""
    sym = geom.endswith("2")
    geom = geom.rstrip("2")
    nq = nq or max(200, int(3 * nmax * th_a) + 100)
    nc = nc or 3 * kb
    g, wg = np.polynomial.legendre.leggauss(nq)
    psi = np.pi / 4 * (g + 1)
    wpsi = np.pi / 4 * wg
    th = th_a * np.sin(psi)
    dth = th_a * np.cos(psi) * wpsi
    rho2 = (th / th_a) ** 2
    basis = np.stack([(1 - rho2) ** (k + 0.5) for k in range(kb)])  # (kb, nq)
    pq, dpq = legendre_table(nmax, th)
    w_p, w_q, v_p, v_q = comp_arrays(nmax, nu, tau)
    nn = np.arange(nmax + 1)
    if sym:  # the mirror load at the south pole: factor 1 + (-1)^n on every entry
        fac = 1.0 + (-1.0) ** nn
        w_p, w_q, v_p, v_q = w_p * fac, w_q * fac, v_p * fac, v_q * fac
    if geom == "radial":
        load_p = basis
        load_q = np.zeros_like(basis)
    else:  # the plane's traction -p cos e_z per unit sphere area: radial p cos^2, shear
        load_p = basis * np.cos(th) ** 2
        # tangential traction along +th: -p cos (-sin) ... e_z = cos e_r - sin e_th: -p cos e_z
        # has th-component +p cos sin
        load_q = basis * np.cos(th) * np.sin(th)
    wt = dth * np.sin(th)
    pn = (2 * nn[:, None] + 1) / 2 * (pq * wt[None, :]) @ load_p.T  # (nmax+1, kb)
    norm = np.where(nn > 0, 2 * nn * (nn + 1) / (2 * nn + 1.0), 1.0)
    qn = ((dpq * wt[None, :]) @ load_q.T) / norm[:, None]
    qn[0] = 0
    # outer shear s_rth = q dP/dth with q_n as expanded (s_rth = +traction_th)
    wn = w_p[:, None] * pn + w_q[:, None] * qn  # inward radial
    vn = v_p[:, None] * pn + v_q[:, None] * qn
    thc = th_a * (np.arange(nc) + 0.5) / nc
    pc, dpc = legendre_table(nmax, thc)
    w_c = pc.T @ wn  # (nc, kb) inward radial
    if geom == "radial":
        disp = w_c
    else:  # -u_z = w cos + u_th sin
        u_th = dpc.T @ vn
        disp = w_c * np.cos(thc)[:, None] + u_th * np.sin(thc)[:, None]
    amat = np.hstack([disp, -np.ones((nc, 1))])
    rhs = -(1 - np.cos(thc))
    sol, *_ = np.linalg.lstsq(amat, rhs, rcond=None)
    resid = np.max(np.abs(amat @ sol - rhs)) / np.max(np.abs(rhs))
    b, delta = sol[:kb], sol[kb]
    p = b @ basis
    force = 2 * np.pi * np.sum(p * np.sin(th) * np.cos(th) * dth)
    es = 2 / (1 - nu)
    chi = force / (4 / 3 * es * delta ** 1.5)
    return delta, force, chi, resid


def chi_at(x, nu, tau, geom="vertical", nmax=None, kb=8):
    """chi = F/F_H at delta/R = x: th_a by the secant method on log delta (slope ~2 in log th_a).
    nmax (degrees) by default 120/th_a (converged to ~1e-4: --check). Returns (chi, th_a/a_H,
    collocation residual)."""
    a_h = np.sqrt(x)
    la = np.log(1.25 * a_h)
    nm = nmax or int(120 / (1.25 * a_h))
    f0 = np.log(contact(np.exp(la), nu, tau, geom, nm, kb)[0] / x)
    la1 = la - f0 / 2
    for _ in range(30):
        f1 = np.log(contact(np.exp(la1), nu, tau, geom, nm, kb)[0] / x)
        if abs(f1) < 1e-9:
            break
        la, la1, f0 = la1, la1 - f1 * (la1 - la) / (f1 - f0), f1
    d, force, chi, res = contact(np.exp(la1), nu, tau, geom, nm, kb)
    return chi, np.exp(la1) / a_h, res


def fe_rows(xs=(0.0025, 0.005, 0.0075, 0.01)):
    """For each FE skin (thin_layer_exact_s27.fe_curves: k1e6 thin skins, the core skins) at
    each x it has in xs: (nu, tau, tag, x, chi_FE, chi_shell vertical, chi_shell radial,
    chi_flat_layer, chi_law)."""
    import thin_layer_exact_s27 as tl
    rows = []
    for nu, t, x, chi, name, tag in sorted(tl.fe_curves(), key=lambda r: (r[1], r[0])):
        for xx in xs:
            i = np.where(np.abs(x - xx) < 1e-9)[0]
            if not len(i):
                continue
            cv = chi_at(xx, nu, t, "vertical")[0]
            cr = chi_at(xx, nu, t, "radial")[0]
            c2 = chi_at(xx, nu, t, "radial2")[0]
            fl = tl.chi_exact(np.sqrt(xx) / t, nu)[0]
            lw = tl.law_chi(np.array([xx]), nu, t)[0]
            rows.append((nu, t, tag, xx, chi[i[0]], cv, cr, c2, fl, lw))
            fe = chi[i[0]]
            pc = lambda a, b: f"{100 * (a / b - 1):+.2f}"  # noqa: E731
            print(f"| {tag} nu {nu:g} t/R {t:g} | {xx:g} | {np.sqrt(xx) / t:.2f} | {fe:.4f} | "
                  f"{cr:.4f} | {pc(cr, fl)} | {pc(fe, cr)} | {pc(fe, cv)} | {pc(fe, c2)} | "
                  f"{pc(fe, fl)} | {pc(lw, cr)} | {pc(lw, fe)} |", flush=True)
    return rows


def fe_table():
    print("chi = F/F_Hertz; shell = this script ('radial' reading unless said); flat = the flat "
          "layer (thin_layer_exact_s27.chi_exact); law = today's law "
          "(thin_layer_exact_s27.law_chi)")
    print("| skin | x | a_H/t | FE | shell (radial) | shell/flat - 1 | FE/shell - 1 | "
          "FE/shell vertical - 1 | FE/shell two plates - 1 | FE/flat - 1 | law/shell - 1 | "
          "law/FE - 1 |")
    print("|---" * 12 + "|")
    rows = fe_rows()
    print("\nThe thin skins' FE over the shell against the squeeze s = delta/t = x/(t/R) at "
          "x 0.0025"
          " - 0.01: FE/shell - 1 = c0 + c1 s (least squares) [%]; c0 = the small-strain miss")
    print("| skin | c0 | c1 | max |fit - data| |")
    print("|---|---|---|---|")
    for key in sorted({(r[0], r[1]) for r in rows if r[2] == "k1e6"}, key=lambda k: (k[1], k[0])):
        sel = [r for r in rows if (r[0], r[1]) == key]
        sq = np.array([r[3] / key[1] for r in sel])
        y = np.array([100 * (r[4] / r[6] - 1) for r in sel])
        c1, c0 = np.polyfit(sq, y, 1)
        print(f"| nu {key[0]:g} t/R {key[1]:g} | {c0:+.2f} | {c1:+.1f} | "
              f"{np.max(np.abs(c0 + c1 * sq - y)):.2f} |")
    return rows


def table(nus=(0.3, 0.4, 0.45, 0.48, 0.49, 0.499), taus=(0.05, 0.1, 0.2, 0.4, 0.7),
          us=(0.25, 0.5, 1.0, 1.5, 2.0), xmax=0.04):
    """F_shell/F_flat - 1 [%] at the same x (radial reading), over nu, t/R and u = a_H/t
    (x = (u t/R)^2 <= xmax; a/t = u times the flat layer's a/a_H)."""
    import thin_layer_exact_s27 as tl
    print(f"F_shell/F_flat - 1 [%] at x = (u t/R)^2 (u = a_H/t; '-' where x > {xmax:g})")
    print("| nu, t/R \\ u = a_H/t | " + " | ".join(f"{u:g}" for u in us) + " |")
    print("|---" * (len(us) + 1) + "|")
    for nu in nus:
        for tau in taus:
            cells = []
            for u in us:
                x = (u * tau) ** 2
                if x > xmax:
                    cells.append("-")
                    continue
                ratio = chi_at(x, nu, tau, "radial")[0] / tl.chi_exact(u, nu)[0]
                cells.append(f"{100 * (ratio - 1):+.2f}")
            print(f"| {nu}, {tau} | " + " | ".join(cells) + " |", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--fe", action="store_true")
    ap.add_argument("--table", action="store_true")
    a = ap.parse_args()
    if a.check:
        check()
    if a.fe:
        fe_table()
    if a.table:
        table()
    return 0


if __name__ == "__main__":
    sys.exit(main())
