#!/usr/bin/env python3
"""Session 31 (issue 24 item 5): why SFF (session 29) is soft in the deep squeeze of thin skins at
nu 0.42-0.48, and forms tried on top of it.

SFF's thin-skin squeeze (try_deep_squeeze_s29.py) is

    T' = 1 + (l0 + l1 eps) s + lc (mu/M) D(s) + cf psi(z') (Phi_c(s, tau) - 1),  z' = z/(1 - s)

faded into the law by t/R 0.3 (w = 1 - z^2 (3 - 2z), z = tau/0.3). Variants (letters add up;
every one refitted on the FITTED set of try_thin_skin_s26.sets(), as session 29 did):

  O    the oedometer's large-strain stiffening on the confined share of the film: beside
       lc (mu/M) D(s), co (1 - psi(z')) (mu/M) D(s) (seven constants). Matthewson's layer
       splits its force into the flow share psi and the confined (oedometer) share 1 - psi;
       the thinned crossover moves force from the first to the second as the film thins, and
       the oedometer's stiffening (mu/M) D(s) is the confined share's (theory: co = 1;
  O1   co = 1, the theory's, six constants refitted)
  M    only the share the thinning moves from flow to confinement stiffens as the oedometer:
       + (psi(z) - psi(z')) (mu/M) D(s), weight 1 (theory); Mc its weight fitted (seven)
  R    lc (mu/M) D(s) -> lc (1 - psi(z')) (mu/M) D(s): the oedometer's stiffening on the
       confined share only (six constants)
  L    the film in the law's share too, faded as the thin-skin form is: the law's squeeze gains
       w cf psi(z') (Phi_c - 1) (no new constant; 0 from t/R 0.3, so the law there is unchanged)
  Lz   L, and the law's deviatoric cd D(s) giving way to the film as w grows:
       w (cf psi (Phi_c - 1) - cd D(s)) added to the law's squeeze
  G    the compressible film made consistent: Phi_c psi(z')/psi(z) - 1 in place of psi(z')
       (Phi_c - 1) (Matthewson's layer at the thinned film, over its small-strain crossover;
       the pole's (1 - s)^-3 replaced by Phi_c)
  H    (Phi_c - 1) psi(z')/psi(z): SFF's film over the small-strain flow share
  E    the compressible film's crossover thinned as J^(3/2) (z' = z/(1 - s)^1.5): the flow
       length scales with h (Poiseuille h^3 over the column's compliance h/kappa_t), and the
       FE's neo-Hookean volumetric U = kappa/2 (J - 1)^2 has kappa_t = kappa J

`--diag` prints, on every skin of t/R < 0.3 and nu >= 0.42, SFF's miss, the law's, the thin-skin
form's own (against its target (chi_FE - (1 - w) chi_law)/w) and the squeeze it lacks
(`dsq`, in units of its excess times coupling) beside psi(z'), Phi_c - 1 and D(s).
`--var MODE ...` refits and prints max |F/F_FE - 1| per set, with session 30's two blind k1e6
skins (nu 0.34 t/R 0.18, nu 0.44 t/R 0.09) as their own set and session 31's (nu 0.455 t/R
0.12, run after the forms were judged) as its own; `--curves` per curve; a MODE ending in `n`
is that form with SFF's six constants, not refitted.

Session 31 (CORE_FORM.md "Thin skins: the deep squeeze at nu 0.44-0.48, session 31"):
`--var SFF O O1 R L Lz LzO E G GE H HE --curves --check-form O` and `--var SFF Mn M Mc
--curves` print its tables; none of the forms was adopted.

usage: PY tools/calibration/try_deep_squeeze_s31.py [--diag] [--var MODE ...] [--curves]
           [--check-form MODE]     (PY: /work/main/target/fe-venv/bin/python, under nice -n 10)
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))
import fit_core as f  # noqa: E402
import try_deep_squeeze_s29 as s29  # noqa: E402
import try_shell_table_s28 as s28  # noqa: E402
import try_thin_skin_s23 as s23  # noqa: E402
import try_thin_skin_s25 as s25  # noqa: E402
import try_thin_skin_s26 as s26  # noqa: E402

SFF = s29.SFF
# session 30's blind k1e6 skins (no form had seen them when they ran)
S30_BLIND = ((0.34, 0.18), (0.44, 0.09))
# session 31's blind k1e6 skin, run after every form below was judged
S31_BLIND = ((0.455, 0.12),)


def s30_blind(which=S30_BLIND):
    out = []
    for nu, tau in which:
        path = os.path.join(s25.K1E6, f"force_nu{nu:g}_t{tau:g}.csv")
        x, F = s23.curve_csv(path)
        out.append(s23.as_curve(nu, tau, x, F, os.path.relpath(path, f.DATA)))
    return out


def form(mode):
    """SFF with the letters of the module docs. p = (l0, l1, k0, k1, lc, cf[, co])."""
    if mode == "SFF":
        return s29.form("SFF")
    law = s25.form("K")

    def chi(p, x, nu, tau):
        if np.ndim(tau):
            return np.array([float(np.squeeze(chi(p, np.array([x]), nu, float(t)))) for t in tau])
        x = np.asarray(x, dtype=float)
        w = s28.weight(tau, "SFB0030")
        l0, l1, k0, k1, lc, cf = p[:6]
        co = (1.0 if "O1" in mode else p[6]) if "O" in mode else 0.0
        eps = f.eps_of(nu)
        s = x / tau
        thinned = (1 - s) ** (1.5 if "E" in mode else 1.0)
        z = np.sqrt(3 * (1 - 2 * nu) / (2 * (1 - nu)) * x) / tau / thinned
        ps = s25.psi(z)
        film = ps * (s29.phi_c(s, tau) - 1)
        if "G" in mode or "H" in mode:
            z0 = np.sqrt(3 * (1 - 2 * nu) / (2 * (1 - nu)) * x) / tau
            ratio = ps / s25.psi(z0)
            film = ratio * s29.phi_c(s, tau) - 1 if "G" in mode else ratio * (s29.phi_c(s, tau) - 1)
        if w < 1:
            out_law = law(s25.LAW, x, nu, tau)
            if "Lz" in mode and w > 0:  # the law's cd D(s) gives way to the film as w grows
                cd = s25.LAW[7]
                out_law = law_with_film(x, nu, tau, w * (cf * film - cd * f.confined(s)))
            elif "L" in mode and w > 0:
                out_law = law_with_film(x, nu, tau, w * cf * film)
        else:
            out_law = 0.0
        if w <= 0:
            return out_law
        fl = f.chi_flat(x, nu)
        hemi = s28.chi_hemi(x, nu, "F")
        excess = s28.chi_shell(x, nu, min(tau, s28.TAUS[-1])) - hemi
        share = eps / (1 + 4 * eps / 3)
        oed = (1 - ps) if "R" in mode else 1.0
        squeeze = (l0 + l1 * eps) * s + lc * share * oed * f.confined(s) + cf * film
        if "O" in mode:
            squeeze = squeeze + co * (1 - ps) * share * f.confined(s)
        if "M" in mode:  # the share the thinning moves from flow to confinement, theory weight 1
            z0 = np.sqrt(3 * (1 - 2 * nu) / (2 * (1 - nu)) * x) / tau
            cm = p[6] if "Mc" in mode else 1.0
            squeeze = squeeze + cm * (s25.psi(z0) - ps) * share * f.confined(s)
        shell = fl + excess * (1 + squeeze) * np.exp(-(k0 + k1 * eps) * (fl - 1))
        return w * shell + (1 - w) * out_law
    return chi


def law_with_film(x, nu, tau, add):
    """The law (s25.form("K")) with `add` added to its squeeze factor: law = flat + excess
    thinning coupling, so chi_law + (chi_law - flat) add / thinning."""
    e0, l0, l1, k0, k1, m, lc, cd = s25.LAW[:8]
    law = s25.form("K")(s25.LAW, x, nu, tau)
    fl = f.chi_flat(x, nu)
    eps = f.eps_of(nu)
    s = x / tau
    thinning = 1 + (l0 + l1 * eps) * s + (lc * eps / (1 + 4 * eps / 3) + cd) * f.confined(s)
    return law + (law - fl) * add / thinning


def p0_of(mode):
    return list(SFF) + ([0.5] if ("O" in mode and "O1" not in mode) or "Mc" in mode else [])


def diag():
    law = s25.form("K")
    train, thin, held, blind, dblind = s26.sets()
    cs = ([("fit", c) for c in train] + [("held", c) for c in held] +
          [("blind", c) for c in blind] + [("deep k1e6", c) for c in s29.deep_curves()] +
          [("s30 blind", c) for c in s30_blind()] +
          [("s31 blind", c) for c in s30_blind(S31_BLIND)])
    l0, l1, k0, k1, lc, cf = SFF
    sff = s29.form("SFF")
    for tag, c in sorted(cs, key=lambda t: (t[1]["nu"], t[1]["tau"])):
        nu, tau, x = c["nu"], c["tau"], c["x"]
        if tau >= 0.3 or nu < 0.42:
            continue
        w = s28.weight(tau, "SFB0030")
        cl = law(s25.LAW, x, nu, tau)
        ct = sff(SFF, x, nu, tau)
        shell = (ct - (1 - w) * cl) / w
        target = (c["chi"] - (1 - w) * cl) / w
        eps = f.eps_of(nu)
        fl = f.chi_flat(x, nu)
        ex = s28.chi_shell(x, nu, tau) - s28.chi_hemi(x, nu, "F")
        cpl = np.exp(-(k0 + k1 * eps) * (fl - 1))
        s = x / tau
        z = np.sqrt(3 * (1 - 2 * nu) / (2 * (1 - nu)) * x) / tau / (1 - s)
        print(f"{tag} ({nu:g}, {tau:g}) w {w:.2f} {c['name']}")
        for i in np.unique(np.linspace(0, len(x) - 1, 7).astype(int)):
            print(f"   s {s[i]:.2f} x {x[i]:.4f}: SFF {100 * (ct[i] / c['chi'][i] - 1):+.2f} % "
                  f"law {100 * (cl[i] / c['chi'][i] - 1):+.2f} % "
                  f"form {100 * (shell[i] / target[i] - 1):+.2f} % "
                  f"dsq {(target[i] - shell[i]) / (ex[i] * cpl[i]):+.3f} "
                  f"psi {float(s25.psi(z[i])):.3f} Phi-1 {s29.phi_c(s[i], tau) - 1:.3f} "
                  f"D {f.confined(s[i]):.3f}")


def fit_table(modes, curves_too=False):
    train, thin, held, blind, dblind = s26.sets()
    dk = s29.deep_curves()
    sb = s30_blind()
    old = [c for c in train if c not in thin]
    groups = (("fitted", train), ("the 14", old), ("thin fit", thin), ("held out", held),
              ("blind", blind), ("deep CAX8 k1e5", dblind),
              ("deep k1e6 0.48 (blind)",
               [c for c in dk if c["role"] == "blind" and c["nu"] == 0.48]),
              ("deep k1e6 (0.49, 0.12) held", [c for c in dk if c["role"] == "held"]),
              ("deep k1e6 (0.45, 0.07) blind", [c for c in dk if c["nu"] == 0.45]),
              ("s30 blind", sb), ("s31 blind (0.455, 0.12)", s30_blind(S31_BLIND)))
    print("| form | " + " | ".join(g for g, _ in groups) + " |")
    print("|---" * (len(groups) + 1) + "|")
    fits = {}
    for mode in modes:
        t0 = time.time()
        if mode == "SFF":
            chi, p = form("SFF"), SFF
        elif mode.endswith("n"):  # SFF's six constants, not refitted
            chi, p = form(mode[:-1]), list(SFF)
        else:
            chi = form(mode)
            f.chi_core = chi
            p = f.fit(train, p0_of(mode))
        fits[mode] = (chi, p)
        cells = []
        for _, cs in groups:
            v = max(((s29.signed(p, c, chi), c) for c in cs), key=lambda r: abs(r[0][0]))
            cells.append(f"{abs(v[0][0]):.2f} ({v[1]['nu']:g}, {v[1]['tau']:g})")
        print(f"| {mode} | " + " | ".join(cells) + " |", flush=True)
        print("    constants " + " ".join(f"{v:.6f}" for v in p) +
              f"  ({time.time() - t0:.0f} s)", flush=True)
    if curves_too:
        tagged = ([("fit", c) for c in train] + [("held", c) for c in held] +
                  [("blind", c) for c in blind] + [("deep", c) for c in dblind] +
                  [("k1e6 " + c["role"], c) for c in dk] + [("s30 blind", c) for c in sb] +
                  [("s31 blind", c) for c in s30_blind(S31_BLIND)])
        print("| curve | " + " | ".join(modes) + " |")
        print("|---" * (len(modes) + 1) + "|")
        worst = {m: [] for m in modes}
        for tag, c in sorted(tagged, key=lambda tc: (tc[0], tc[1]["tau"], tc[1]["nu"])):
            cells = []
            for mode in modes:
                chi, p = fits[mode]
                v, xi = s29.signed(p, c, chi)
                worst[mode].append((abs(v), f"{tag} ({c['nu']:g}, {c['tau']:g})"))
                cells.append(f"{v:+.2f} (x {xi:g})")
            print(f"| {tag} ({c['nu']:g}, {c['tau']:g}) | " + " | ".join(cells) + " |",
                  flush=True)
        ref = modes[0]
        for mode in modes:
            w = worst[mode]
            line = f"{mode}: {sum(v <= 2 for v, _ in w)} of {len(w)} curves within 2 %"
            if mode != ref:
                pairs = list(zip(worst[ref], w))
                better = [n for (a, n), (b, _) in pairs if b < a - 0.1]
                worse = [f"{n} {a:.2f} -> {b:.2f}" for (a, n), (b, _) in pairs if b > a + 0.1]
                line += (f"; {len(better)} better, {len(worse)} worse by > 0.1 % than {ref}"
                         + (": " + ", ".join(worse) if worse else ""))
            print(line)
    return fits


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--diag", action="store_true")
    ap.add_argument("--var", nargs="*")
    ap.add_argument("--curves", action="store_true")
    ap.add_argument("--check-form")
    a = ap.parse_args()
    if a.diag:
        diag()
    if a.var:
        fits = fit_table(a.var, a.curves)
        if a.check_form:
            chi, p = fits[a.check_form]
            f.chi_core = chi
            t0 = time.time()
            print(a.check_form, f.check(p), f"({time.time() - t0:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
