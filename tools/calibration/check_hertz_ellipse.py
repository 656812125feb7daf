#!/usr/bin/env python3
"""Hertz's elliptical contact by an independent route: SciPy's complete elliptic integrals
(`ellipk`, `ellipe`, parameter m = e^2) and `brentq` on Johnson's (Contact Mechanics, 1985,
Eq. 4.39) relation B/A = (E/(1 - e^2) - K)/(K - E), then a^2 = delta (K - E)/(e^2 A K) and
F = (2 pi/3) E* a delta / K. Prints, per gap h R = A R u^2 + B R v^2, the semi-axes over
sqrt(R delta) and the force over the plane's (4/3) E* R^2 x^1.5: the reference values of
`crates/softgrip-law/src/elliptic.rs`'s test `hertz_ellipse_matches_an_independent_solution`.

Usage: python3 tools/calibration/check_hertz_ellipse.py   (numpy + scipy)
"""
import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk


def ellipse(a_hat, b_hat):
    """(alpha, beta, force factor) of the gap a_hat u^2 + b_hat v^2 (in units of 1/R)."""
    small, large = min(a_hat, b_hat), max(a_hat, b_hat)
    lam = large / small
    f = lambda e2: (ellipe(e2) / (1 - e2) - ellipk(e2)) / (ellipk(e2) - ellipe(e2)) - lam
    e2 = brentq(f, 1e-14, 1 - 1e-14, xtol=1e-16, rtol=1e-15)
    k, e = ellipk(e2), ellipe(e2)
    long = np.sqrt((k - e) / (e2 * small * k))
    short = long * np.sqrt(1 - e2)
    factor = 2 * np.pi / 3 * long / k / (4 / 3)
    return (long, short, factor) if a_hat <= b_hat else (short, long, factor)


if __name__ == "__main__":
    print("A R, B R, alpha, beta, force factor")
    for a_hat, b_hat in [(0.5, 1.0), (0.5, 2 / 3), (0.3, 2.0), (1.5, 0.5)]:
        print(a_hat, b_hat, *(repr(float(v)) for v in ellipse(a_hat, b_hat)))
