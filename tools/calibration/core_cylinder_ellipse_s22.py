#!/usr/bin/env python3
"""Session 22, issue 24: how an elliptical patch (a fingertip on a cylinder) loads a thin skin
bonded to a core, against the Hertz-equivalent disc that `core_map` maps it onto.

The core's plane law is taken at the patch argument rho_H x (rho_H = h^2, h Hertz's elliptical
force factor): exact for every term that depends on the patch through F/delta (Dimitriadis'
first order: the base shifts the displacement by ~F/(E* t), whatever the patch's shape). In the
thin-layer limit the shape matters:

- incompressible thin bonded layer (squeeze film, `lap p = -(3 mu/t^3) w`, p = dp/dn = 0 on the
  edge): on the gap A u^2 + B v^2 the pressure is P (1 - u^2/a^2 - v^2/b^2)^2 exactly, with
  g = a^2/b^2 the root of 3 (A/B) g^2 + (A/B - 1) g - 3 = 0 and, at delta = 1 (units cmu/t^3 = 1),
  s = 1/a^2 = A (1 + g)/(3 + g), F = pi / (12 s^2 (1 + g) sqrt(g)); on a disc of radius R_e
  (A = B = 1/(2 R_e)) F = (2 pi/3) R_e^2: the ellipse is the disc of R_thin = sqrt(3 F/(2 pi)).
- Winkler (compressible, patch >> l): F = (M/t)(pi/2) delta^2 / sqrt(A B): R_w = 1/(2 sqrt(A B)).

c_inc = (R_thin/rho_H)^2 and c_W = R_w/rho_H: the thin layer's force on the ellipse over the
Hertz-equivalent disc's at the same delta (1 on a ball). Prints them for cylinders of k R.

usage: /work/fe-scratch/fe-venv/bin/python tools/calibration/core_cylinder_ellipse_s22.py   (numpy, scipy; < 1 s)
"""
import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk


def hertz(a_hat, b_hat):
    """Hertz's ellipse of the gap a_hat u^2 + b_hat v^2 (a_hat <= b_hat), R = 1, delta = 1:
    (alpha, beta, h)."""
    if abs(a_hat - b_hat) < 1e-12:
        r = 1 / (2 * a_hat)
        return np.sqrt(r), np.sqrt(r), np.sqrt(r)

    def ratio(e):
        m = e * e
        k, ee = ellipk(m), ellipe(m)
        return (ee / (1 - m) - k) / (k - ee) - b_hat / a_hat

    e = brentq(ratio, 1e-6, 1 - 1e-9)
    m = e * e
    k, ee = ellipk(m), ellipe(m)
    a = np.sqrt((k - ee) / m / (a_hat * k))
    force = 2 * np.pi / 3 * a / k
    return a, a * np.sqrt(1 - m), force / (4 / 3)


def thin_incompressible(a_hat, b_hat):
    """R_thin of the gap a_hat u^2 + b_hat v^2 (module docs)."""
    q = a_hat / b_hat
    g = (-(q - 1) + np.sqrt((q - 1) ** 2 + 36 * q)) / (6 * q)
    s = a_hat * (1 + g) / (3 + g)
    force = np.pi / (12 * s * s * (1 + g) * np.sqrt(g))
    return np.sqrt(3 * force / (2 * np.pi))


def main():
    print("  k   alpha   beta    a/b   rho_H   R_thin  R_w     c_inc   c_W")
    for k in [1.0, 2.0, 3.0]:
        a_hat, b_hat = 0.5, 0.5 * (1 + 1 / k)
        alpha, beta, h = hertz(a_hat, b_hat)
        rho_h = h * h
        r_thin = thin_incompressible(a_hat, b_hat)
        r_w = 1 / (2 * np.sqrt(a_hat * b_hat))
        print(f"{k:4.0f}  {alpha:.4f}  {beta:.4f}  {alpha / beta:.3f}  {rho_h:.4f}  {r_thin:.4f}"
              f"  {r_w:.4f}  {(r_thin / rho_h) ** 2:.4f}  {r_w / rho_h:.4f}")
    # A ball is a disc: c = 1 (check).
    assert abs(thin_incompressible(0.75, 0.75) - 2 / 3) < 1e-12


if __name__ == "__main__":
    main()
