#!/usr/bin/env python3
"""The skin on a core (`Backing::Core`) pressed on a rigid ball: the calibrated law's two maps
against softgrip's FE of it (tests/data/fe/ball/core/, session 11), each to its range.

    F / (E* R^2) = h (4/3) x^(3/2) chi(x) - tail x^(5/2)      h = sqrt(R_eff / R), a ball of k R
    session 10 (the plane's curve at rho x, `mapping`):     chi = chi_core(rho x)
    session 11 (`core_map`):                                chi = chi_flat(rho x)
                    + L(rho_H x) T(x / tau) exp(-k (chi_flat(rho x) - 1))
      rho: the bonded pad's map, 1/rho - 1 = r (1/rho_H - 1), r = r0 + r1 eps; rho_H = h^2
      (Hertz's patch, a^2 = R_eff delta); tail = (4/3) h g (h/k)^2, g = g0 + g1 eps
      (mapping.rs BONDED); chi_flat, L, T, the core's constants: fit_core.py (backed.rs).
The session-10 map stops at 0.6 t/R (its range), session 11's at 0.8 t/R (the plane core's).
No constant is fitted here. Prints, per FE curve, the largest |F_law / F_FE - 1| and a row of
signed errors.

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
BONDED = (0.830973, -1.294969, 0.335914, -0.480372)  # mapping.rs BONDED: r0, r1, g0, g1


def parts(xf, xl, xs, nu, tau):
    """chi_flat and the sharing exponent at xf, the layer excess at xl, the thinning at xs."""
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


def law(x, nu, tau, k, session):
    eps = fc.eps_of(nu)
    r, g = BONDED[0] + BONDED[1] * eps, BONDED[2] + BONDED[3] * eps
    h = np.sqrt(k / (1 + k))
    rho_h = h * h
    rho = 1 / (1 + r * (1 / rho_h - 1))
    tail = 4 / 3 * h * g * (h / k) ** 2
    if session == 10:
        chi = parts(rho * x, rho * x, rho * x, nu, tau)
    else:
        chi = parts(rho * x, rho_h * x, x, nu, tau)
    return h * 4 / 3 * x ** 1.5 * chi - tail * x ** 2.5


def main():
    for path in sorted(glob.glob(os.path.join(DATA, "force_nu*_t*_k*.csv"))):
        nu, tau, k = map(float, re.search(r"nu([\d.]+)_t([\d.]+)_k([\d.]+)\.csv$", path).groups())
        a = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        x, f = a["delta_over_R"], a["force_N"] / (2 * (1 + nu) / (1 - nu ** 2))
        for session, squeeze in ((10, 0.6), (11, 0.8)):
            keep = (x >= 0.01 - 1e-9) & (x <= squeeze * tau + 1e-9)
            err = 100 * (law(x[keep], nu, tau, k, session) / f[keep] - 1)
            i = int(np.argmax(np.abs(err)))
            row = " ".join(f"{xx:.2f}:{e:+.1f}" for xx, e in zip(x[keep][::3], err[::3]))
            print(f"{os.path.basename(path)} session {session}: max {abs(err[i]):.2f} % at x = "
                  f"{x[keep][i]:g} (to x = {x[keep][-1]:g}; FE's end {x[-1]:g})  {row}")


if __name__ == "__main__":
    main()
