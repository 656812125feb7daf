#!/usr/bin/env python3
"""Session 34 (issue 24 item 5): predictions of SFF (the law) and the deep-only film attenuation
Hm4 / Hm6 (try_film_att_s34.py; CORE_FORM.md "Thin skins: a deep-only film attenuation, session
34") for two NEW held-out deep CAX8 skins, written and committed BEFORE either FE run existed.

Hm<n>: SFF's film term times att = m^n / (m^n + m0^n), m = mu/M = (1 - 2 nu) / (2 (1 - nu)),
SFF's six constants kept; m0 as fitted and printed by try_film_att_s34.py (Hm4 0.011118, Hm6
0.012064). What neither fit could see (CORE_FORM.md): the threshold's shape between nu 0.49 and
0.495 and its t/R dependence (the deep nearly incompressible FE was at t/R 0.12 / 0.15 only).

The two skins (tools/fe/fe_thin_rerun.py `DEEP`, CAX8, penalty 1e6 MPa/mm, ~9 elements through
the skin, to delta/t = 1 or divergence; exported to tests/data/fe/core/cax8/k1e6/):
  (a) nu 0.4925 t/R 0.12 (core_nu0.4925_t0.12_h75_k1e6_cax8): inside the threshold; Hm4's att
      is 0.757, Hm6's 0.772 (m alone: no x or t/R in att); SFF's film in full.
  (b) nu 0.497 t/R 0.2 (core_nu0.497_t0.2_h45_k1e6_cax8): the t/R dependence. t/R 0.2 rather
      than 0.08 because (i) it converges further and cheaper (R/45, increments 0.001; the nu 0.497
      t/R 0.15 skin reached delta/t 0.92 in 573 s, while t/R 0.08 needs R/110 and increments
      0.0005: nu 0.48 t/R 0.08 took 2899 s and stopped at delta/t 0.62), and (ii) it still
      separates the forms: Hm4 / SFF differ by up to 4.8 % there (16.9 % at t/R 0.08, 1.1 % at
      t/R 0.25, where the thin-skin form fades out), `--spread`.

ADOPTION RULE (declared with the predictions, before the runs): Hm4 is adopted (ported to the
Rust law) if on BOTH new skins, over the law's comparison window (FE rows x >= 0.01 and x <= 0.8
t/R, the calibration's as_curve window),
  1. |F_Hm4 / F_FE - 1| <= 2 % at every row with delta/t <= 0.6, and <= 3 % at every row past
     delta/t 0.6, and
  2. Hm4's max |F/F_FE - 1| over the window is smaller than SFF's.
Hm6 is printed and judged by the same rule, as the alternative; it is not the one to be ported
unless Hm4 fails and Hm6 passes (then nothing is ported this session; the lead decides).

usage: nice -n 19 PY tools/calibration/hm4_predict_s34.py [--compare] [--spread] [--parts]
       (PY: /work/main/target/fe-venv/bin/python). Without flags: the prediction table. With
       --compare: each FE file of the two skins that exists, row by row, and the rule.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))
import fit_core as f  # noqa: E402
import try_film_att_s34 as a  # noqa: E402

M0 = {"Hm4": 0.011118, "Hm6": 0.012064}  # try_film_att_s34.py's fits, as printed
SKINS = [(0.4925, 0.12), (0.497, 0.2)]
FE = os.path.join(f.DATA, "cax8", "k1e6")


def e_star(nu):
    return 2 / (1 - nu)  # E* = E/(1 - nu^2) with mu = 1 MPa, R = 1 mm


def force(mode, x, nu, tau):
    """F [N] (mu = 1 MPa, R = 1 mm) of SFF or Hm<n> at x = delta/R."""
    x = np.asarray(x, dtype=float)
    chi = a._R(a.SFF, x, nu, tau) if mode == "SFF" else a.form(mode)([M0[mode]], x, nu, tau)
    return chi * e_star(nu) * 4 / 3 * x ** 1.5


def att(mode, nu):
    m = (1 - 2 * nu) / (2 * (1 - nu))
    return m ** 4 / (m ** 4 + M0["Hm4"] ** 4) if mode == "Hm4" else \
        m ** 6 / (m ** 6 + M0["Hm6"] ** 6)


def predict():
    for nu, tau in SKINS:
        print(f"== nu {nu:g} t/R {tau:g}: att Hm4 {att('Hm4', nu):.3f}, Hm6 {att('Hm6', nu):.3f}")
        print("| x | delta/t | F_SFF [N] | F_Hm4 [N] | F_Hm6 [N] | Hm4/SFF - 1 [%] |")
        print("|---|---|---|---|---|---|")
        step = 0.005 if tau < 0.15 else 0.01
        for x in np.round(np.arange(0.01, 0.8 * tau + 1e-9, step), 6):
            fs, f4, f6 = (float(force(m, [x], nu, tau)[0]) for m in ("SFF", "Hm4", "Hm6"))
            print(f"| {x:g} | {x / tau:.3f} | {fs:.6g} | {f4:.6g} | {f6:.6g} | "
                  f"{100 * (f4 / fs - 1):+.2f} |")


def spread():
    for nu, tau in [(0.4925, 0.12), (0.4925, 0.2), (0.497, 0.08), (0.497, 0.2), (0.497, 0.25)]:
        xs = np.round(np.arange(0.01, 0.8 * tau + 1e-9, 0.0025), 6)
        r = force("Hm4", xs, nu, tau) / force("SFF", xs, nu, tau) - 1
        print(f"nu {nu:g} t/R {tau:g}: max |F_Hm4/F_SFF - 1| {100 * np.max(np.abs(r)):.2f} %")


def compare():
    verdict = {}
    for nu, tau in SKINS:
        path = os.path.join(FE, f"force_nu{nu:g}_t{tau:g}.csv")
        if not os.path.exists(path):
            print(f"== {os.path.relpath(path)}: not there")
            continue
        d = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        x, F = np.atleast_1d(d["delta_over_R"]), np.atleast_1d(d["force_N"])
        keep = (x >= 0.01 - 1e-9) & (x <= min(f.flat_x_max(nu), f.SQUEEZE * tau) + 1e-9)
        x, F = x[keep], F[keep]
        errs = {m: 100 * (force(m, x, nu, tau) / F - 1) for m in ("SFF", "Hm4", "Hm6")}
        print(f"== {os.path.relpath(path)} (nu {nu:g}, t/R {tau:g}; window x 0.01-{x[-1]:g}, "
              f"delta/t to {x[-1] / tau:.3f})")
        print("| x | delta/t | F_FE [N] | SFF [%] | Hm4 [%] | Hm6 [%] |")
        print("|---|---|---|---|---|---|")
        for i in range(len(x)):
            print(f"| {x[i]:g} | {x[i] / tau:.3f} | {F[i]:.6g} | {errs['SFF'][i]:+.2f} | "
                  f"{errs['Hm4'][i]:+.2f} | {errs['Hm6'][i]:+.2f} |")
        deep = x / tau > 0.6 + 1e-9
        for m in ("SFF", "Hm4", "Hm6"):
            e = errs[m]
            i = int(np.argmax(np.abs(e)))
            lo = float(np.max(np.abs(e[~deep]))) if np.any(~deep) else 0.0
            hi = float(np.max(np.abs(e[deep]))) if np.any(deep) else 0.0
            ok1 = lo <= 2.0 and hi <= 3.0
            ok2 = m != "SFF" and np.max(np.abs(e)) < np.max(np.abs(errs["SFF"]))
            verdict.setdefault(m, []).append(ok1 and ok2)
            print(f"{m}: max |err| {abs(e[i]):.2f} % (signed {e[i]:+.2f} at x {x[i]:g}, delta/t "
                  f"{x[i] / tau:.3f}); delta/t <= 0.6: {lo:.2f} %, past 0.6: {hi:.2f} %"
                  + ("" if m == "SFF" else f"; within 2 %/3 %: {ok1}; better than SFF: {ok2}"))
    for m in ("Hm4", "Hm6"):
        v = verdict.get(m, [])
        print(f"rule for {m}: {'MET' if len(v) == 2 and all(v) else 'NOT MET'} "
              f"({len(v)} of 2 skins there, passing {sum(v)})")


def parts():
    """Added after skin (b) was compared (a diagnostic, no role changed): where the deep excess
    near nu 0.5 sits. chi = w chi_S + (1 - w) chi_law (the thin-skin form faded by t/R 0.3); per
    skin at delta/t ~0.4, 0.6, 0.7, 0.8: the error with the film removed entirely (att = 0, the
    most any film attenuation can do), the law's share alone against the FE (chi_law/chi_FE - 1,
    the thin-skin form's weight w), and the thin-skin part the FE wants, (chi_FE - (1 - w)
    chi_law)/w, against SFF's, Hm4's and no film's chi_S; and the film attenuation the FE wants,
    (chi_FE - chi(att = 0))/(chi_SFF - chi(att = 0)) (chi is linear in att), against Hm4's."""
    import try_deep_squeeze_s29 as s29
    import try_shell_table_s28 as s28
    import try_thin_skin_s25 as s25
    law = s25.form("K")
    for nu, tau in [(0.49, 0.12), (0.4925, 0.12), (0.495, 0.12), (0.499, 0.12), (0.497, 0.15),
                    (0.497, 0.2)]:
        path = os.path.join(FE, f"force_nu{nu:g}_t{tau:g}.csv")
        if not os.path.exists(path):
            continue
        d = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        x, F = np.atleast_1d(d["delta_over_R"]), np.atleast_1d(d["force_N"])
        w = s28.weight(tau, "SFB0030")
        print(f"== nu {nu:g} t/R {tau:g}: thin-skin weight w {w:.3f}")
        print("| delta/t | SFF [%] | Hm4 [%] | no film [%] | law share alone [%] | chi_S wanted "
              "| chi_S SFF | chi_S Hm4 | chi_S no film | att wanted | Hm4's att |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        for v in (0.4, 0.6, 0.7, 0.8):
            i = int(np.argmin(np.abs(x - v * tau)))
            if abs(x[i] / tau - v) > 0.02 or x[i] > 0.8 * tau + 1e-9:
                continue
            xi = x[i:i + 1]
            fe = F[i] / (e_star(nu) * 4 / 3 * xi[0] ** 1.5)
            c_sff = float(a._R(a.SFF, xi, nu, tau)[0])
            c_h4 = float(a.form("Hm4")([M0["Hm4"]], xi, nu, tau)[0])
            c_nf = float(a.form("Hm4")([1e6], xi, nu, tau)[0])
            c_law = float(np.squeeze(law(s25.LAW, xi, nu, tau)))

            def part(c):
                return (c - (1 - w) * c_law) / w
            print(f"| {xi[0] / tau:.3f} | {100 * (c_sff / fe - 1):+.2f} | {100 * (c_h4 / fe - 1):+.2f} | "
                  f"{100 * (c_nf / fe - 1):+.2f} | {100 * (c_law / fe - 1):+.2f} | {part(fe):.4f} | "
                  f"{part(c_sff):.4f} | {part(c_h4):.4f} | {part(c_nf):.4f} | "
                  f"{(fe - c_nf) / (c_sff - c_nf):+.3f} | {att('Hm4', nu):.3f} |")
    assert s29 is not None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--compare", action="store_true")
    ap.add_argument("--spread", action="store_true")
    ap.add_argument("--parts", action="store_true", help="where the deep excess sits (diagnostic)")
    o = ap.parse_args()
    if o.parts:
        parts()
    if o.spread:
        spread()
    if o.compare:
        compare()
    if not (o.compare or o.spread or o.parts):
        predict()
    return 0


if __name__ == "__main__":
    sys.exit(main())
