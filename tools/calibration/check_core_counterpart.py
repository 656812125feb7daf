#!/usr/bin/env python3
"""The skin on a core (`Backing::Core`) pressed on a rigid ball: the calibrated law's three maps
against softgrip's FE of it (tests/data/fe/ball/core/: sessions 11 and 12), each to its range.

    F / (E* R^2) = h (4/3) x^(3/2) chi(x) - t5 x^(5/2) - t7 x^(7/2)     h = sqrt(R_eff / R)
    session 10 (the plane's curve at rho x, `mapping`):   chi = chi_core(rho x)
    session 11:   chi = chi_flat(rho x) + L(rho_H x) T(x / tau) exp(-k (chi_flat(rho x) - 1))
    session 12 (`core_map`, kept):   chi = chi_core(rho_H x) Phi(x / tau)
                                     Phi(s) = chi_flat(rho s) / chi_flat(rho_H s)
      rho: the bonded pad's map, 1/rho - 1 = r (1/rho_H - 1), r = r0 + r1 eps; rho_H = h^2
      (Hertz's patch, a^2 = R_eff delta); t5 = (4/3) h g (h/k)^2, g = g0 + g1 eps;
      t7 = -(4/3) h q eps (1 - rho_H) (mapping.rs BONDED, Q_BONDED); chi_flat, L, T, chi_core:
      fit_core.py (backed.rs).
Session 10's map stops at 0.6 t/R (its range), 11's and 12's at 0.8 t/R (the plane core's). No
constant is fitted here. Prints, per FE curve, the largest |F_law / F_FE - 1| and a row of
signed errors (%), then the FE's force over the plane law's patch argument against delta/t
(the evidence for Phi: the same at the same delta/t whatever t/R).

usage: target/fe-venv/bin/python tools/calibration/check_core_counterpart.py   (numpy; 1 s)
"""
import glob
import os
import re

import numpy as np

import fit_core as fc

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data", "fe",
                    "ball", "core")
CORE = [0.849512, 0.676765, 1.022037, 0.266768, -1.622115, 1.470321, 0.234092]  # backed.rs CORE
BONDED = (0.840368, -0.991587, 0.328077, 0.225198)  # mapping.rs BONDED: r0, r1, g0, g1
Q_BONDED = 3.981922  # mapping.rs Q_BONDED (order 1 in eps)


def split(xf, xl, xs, nu, tau):
    """Session 11: chi_flat and the sharing exponent at xf, the layer excess at xl, the thinning
    at xs."""
    e0, l0, l1, k0, k1, m, lc = CORE
    eps = fc.eps_of(nu)
    flat = fc.chi_flat(xf, nu)
    a_flat, a_core = fc.radius(xl, nu, tau)
    h = 1 + tau * tau / (1 - tau)
    d1, e = fc.dimitriadis_d1(nu), e0 * np.exp(-m * eps)
    layer = lambda v, conf: v * (d1 + e * v / (1 + conf))  # noqa: E731
    excess = layer(a_core / (tau * h), eps * xl / tau ** 2) - layer(a_flat / h, eps * xl)
    s = xs / tau
    thinning = 1 + (l0 + l1 * eps) * s + lc * eps / (1 + 4 * eps / 3) * fc.confined(s)
    return flat + excess * thinning * np.exp(-(k0 + k1 * eps) * (flat - 1))


def maps(nu, k):
    eps = fc.eps_of(nu)
    r, g = BONDED[0] + BONDED[1] * eps, BONDED[2] + BONDED[3] * eps
    h = np.sqrt(k / (1 + k))
    rho_h = h * h
    rho = 1 / (1 + r * (1 / rho_h - 1))
    t5 = 4 / 3 * h * g * (h / k) ** 2
    t7 = -4 / 3 * h * Q_BONDED * eps * (1 - rho_h)
    return h, rho, rho_h, t5, t7


def law(x, nu, tau, k, session):
    h, rho, rho_h, t5, t7 = maps(nu, k)
    if session == 10:
        chi = fc.chi_core(CORE, rho * x, nu, tau)
    elif session == 11:
        chi = split(rho * x, rho_h * x, x, nu, tau)
    else:
        s = x / tau
        chi = (fc.chi_core(CORE, rho_h * x, nu, tau)
               * fc.chi_flat(rho * s, nu) / fc.chi_flat(rho_h * s, nu))
    return h * 4 / 3 * x ** 1.5 * chi - t5 * x ** 2.5 - t7 * x ** 3.5


def curves():
    for path in sorted(glob.glob(os.path.join(DATA, "force_nu*_t*_k*.csv"))):
        nu, tau, k = map(float, re.search(r"nu([\d.]+)_t([\d.]+)_k([\d.]+)\.csv$", path).groups())
        a = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        x, f = a["delta_over_R"], a["force_N"] / (2 * (1 + nu) / (1 - nu ** 2))
        yield os.path.basename(path), nu, tau, k, x, f


def main():
    for name, nu, tau, k, x, f in curves():
        for session, squeeze in ((10, 0.6), (11, 0.8), (12, 0.8)):
            keep = (x >= 0.01 - 1e-9) & (x <= squeeze * tau + 1e-9)
            err = 100 * (law(x[keep], nu, tau, k, session) / f[keep] - 1)
            i = int(np.argmax(np.abs(err)))
            row = " ".join(f"{xx:.2f}:{e:+.1f}" for xx, e in zip(x[keep][::3], err[::3]))
            print(f"{name} session {session}: max {abs(err[i]):.2f} % at x = "
                  f"{x[keep][i]:g} (to x = {x[keep][-1]:g}; FE's end {x[-1]:g})  {row}")
    print("\nFE force over the plane law's at Hertz's patch, h (4/3) x^1.5 chi_core(rho_H x), "
          "against delta/t (the plane law's own residual, up to 2 %, is in it):")
    for name, nu, tau, k, x, f in curves():
        h, _, rho_h, _, _ = maps(nu, k)
        ratio = f / (h * 4 / 3 * x ** 1.5 * fc.chi_core(CORE, rho_h * x, nu, tau))
        keep = x >= 0.01 - 1e-9
        print(f"{name}: " + " ".join(f"{xx / tau:.2f}:{q:.3f}"
                                      for xx, q in list(zip(x[keep], ratio[keep]))[::3]))


if __name__ == "__main__":
    main()
