#!/usr/bin/env python3
"""Session 32 (issue 24 item 5): deep fit runs in the deep-squeeze region and a deep term in the
thin-skin form that fades out by t/R 0.3.

Sessions 31 and 32 (CORE_FORM.md "Thin skins: the deep squeeze at nu 0.44-0.48, session 31" and
"Thin skins: cd with nu, session 32") found SFF (the law on main) 2-5 % too soft past delta/t
~0.45 on thin skins at nu 0.44-0.48, t/R 0.08-0.15, the extra stiffening gone by t/R ~0.3, and
no refit able to learn it: the FITTED set had no deep squeeze there. Session 32 ran five deep
penalty-1e6 skins as FIT data, declared so before any form was chosen (`tools/fe/fe_thin_rerun.py`,
`tests/data/fe/core/k1e6/`): nu 0.46 and 0.48 at t/R 0.15, nu 0.47 and 0.45 at t/R 0.2, nu 0.48
at t/R 0.25; and a deep nu 0.495 t/R 0.12 held out (is nu 0.49 t/R 0.12's "less" the nu 0.49-0.5
trend or that one curve?).

SFF's thin-skin squeeze (try_deep_squeeze_s29.py, backed.rs `ShellForce`) is

    T' = 1 + (l0 + l1 eps) s + lc (mu/M) D(s) + cf psi(z') (Phi_c(s, tau) - 1),  z' = z/(1 - s)

(s = delta/t, z = a_H/lambda, lambda = t sqrt(M/(3 mu)), psi Matthewson's flow share, D the
oedometer's large-strain stiffening, Phi_c the squeezed film), and chi = w chi_shell + (1 - w)
chi_law with w = 1 - z^2 (3 - 2 z), z = tau/0.3: every term added to T' is multiplied by w, so
it is 0 at t/R >= 0.3 by construction (the law there is not evaluated with it at all). Terms
(one amplitude each, fitted):

  M   c (psi(z) - psi(z')) (mu/M) D(s): the share of the bonded layer the thinning moves from
      flow into confinement (z' grows as 1/(1 - s)) stiffens as the oedometer does (theory c = 1,
      session 31's Mn/Mc; the FITTED set then had no deep data and sent c to -0.047)
  X   c 4 psi(z') (1 - psi(z')) (mu/M) D(s): the oedometer's stiffening on the crossover share,
      where the skin both flows and is confined (zero for the compressible skin, psi -> 0, and
      for the incompressible one, psi -> 1); a heuristic shape
  Y   c 4 psi(z') (1 - psi(z')) D(s): the same share with a deviatoric (mu, not M) stiffening:
      the flowing share's shear under the confined share's pressure (as session 32's B, but in
      the thin-skin form only, so faded out by t/R 0.3)
  F   c (psi(z) - psi(z')) (Phi_c - 1): the squeezed film's h^-3 stiffening on the share the
      thinning moves out of flow (the film that stops flowing is still squeezed)
  O   c (1 - psi(z')) (mu/M) D(s): the oedometer's stiffening on the whole confined share
      (session 31's O; with lc refitted it spans psi(z') (mu/M) D(s), the flow share's, too)
  G   c 4 psi(z') (1 - psi(z')) (Phi_c - 1): the squeezed film on the crossover share (with cf
      refitted: the film's weight peaked between the compressible and incompressible skin)
  H   c psi(z') (mu/M) (Phi_c - 1): the film's weight growing with the skin's compressibility,
      cf -> cf + c mu/M (with cf refitted: less film for the nearly incompressible skin, more
      at nu 0.44-0.48; psi(z') keeps it off the compressible skin's deep squeeze)
  R   no term: SFF's six refitted on the new fitted set (the control: what the new data alone do)

Suffixes: `L` the same term also in the law's share, faded by w (`w c term` added to the law's
squeeze, try_deep_squeeze_s31.law_with_film: a faded term in the law, 0 from t/R 0.3); `s` SFF's
six constants kept, only c fitted; `k` the film's cf kept at SFF's (the rest refitted); `n` SFF's
six and c = 1 (not fitted); several term letters add up (one amplitude each). Every variant is
fitted on the FITTED set of try_thin_skin_s26.sets() plus the five session-32 fit runs
("fitted+"); held-out, blind, deep and the s30/s31 blind skins and the nu 0.495 t/R 0.12 runs
(CAX8R, and CAX8 in tests/data/fe/core/cax8/k1e6/) are in no fit.

`--need` prints, per curve of t/R < 0.3, SFF's and the law's miss and what the thin-skin form
lacks, `dsq = (target - shell) / (excess coupling)` (target `(chi_FE - (1 - w) chi_law)/w`), at
delta/t ~0.4, ~0.6 and the end, beside psi(z), psi(z') and the terms' shapes (without their
amplitude). `--lin MODE ...` the refit linearised about SFF (SFF's four squeeze terms plus the
mode's, fitted to dsq on the fitted+ points by least squares; first order, cruder than the
refits): the largest remaining miss per group. `--var MODE ...` refits and prints max |F/F_FE - 1|
per set, `--curves` per curve and the count better / worse by > 0.1 % than SFF (and every t/R >=
0.3 file that moved at all), `--check-form MODE` runs fit_core.check.

Session 32 (CORE_FORM.md "Thin skins: deep fit runs and a faded deep term, session 32"):
`--var SFF R O X Y G F M OM YF GF YG OG Ok H --curves` (~80 s) and `--need`, `--lin "" O Y YG YF
OM H` print its tables. With the fit runs every refit meets the nu 0.44-0.48 deep skins, and every
one loses the held-out deep nu 0.49 t/R 0.12 (1.86 -> 4.15-15.35 %) and makes 19-24 thin curves
worse by > 0.1 %; the held-out nu 0.495 t/R 0.12 is +3.08 % with SFF on CAX8R (delta/t 0.48) and
+9.90 % on CAX8 (delta/t 0.79): the nu 0.49-0.5 excess is the trend, and a miss of SFF itself.
None adopted, the law unchanged.

usage: PY tools/calibration/try_deep_fade_s32.py [--need] [--lin MODE ...] [--var SFF R M X ...]
           [--curves] [--check-form MODE]
       (PY: /work/main/target/fe-venv/bin/python, under nice -n 10)
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
import try_cd_nu_s32 as s32  # noqa: E402
import try_deep_squeeze_s29 as s29  # noqa: E402
import try_deep_squeeze_s31 as s31  # noqa: E402
import try_shell_table_s28 as s28  # noqa: E402
import try_thin_skin_s23 as s23  # noqa: E402
import try_thin_skin_s25 as s25  # noqa: E402
import try_thin_skin_s26 as s26  # noqa: E402

SFF = s29.SFF
LAW = s25.LAW
_LAW_K = s25.form("K")
# session 32's deep penalty-1e6 runs (tests/data/fe/core/k1e6/), roles declared before any form
S32_FIT = ((0.46, 0.15), (0.48, 0.15), (0.47, 0.2), (0.45, 0.2), (0.48, 0.25))
S32_HELD = ((0.495, 0.12),)
# Run after this script's forms were judged (none adopted): nu 0.499 t/R 0.12 on CAX8, held out.
S32_HELD_499 = ((0.499, 0.12),)
TERMS = "MXYFOGH"


def k1e6(which, folder=s25.K1E6):
    out = []
    for nu, tau in which:
        path = os.path.join(folder, f"force_nu{nu:g}_t{tau:g}.csv")
        if not os.path.exists(path):
            continue
        x, F = s23.curve_csv(path)
        c = s23.as_curve(nu, tau, x, F, os.path.relpath(path, f.DATA))
        c["held"] = False
        out.append(c)
    return out


def z_of(x, nu, tau):
    return np.sqrt(3 * (1 - 2 * nu) / (2 * (1 - nu)) * x) / tau  # a_H / lambda


def term(mode, x, nu, tau):
    """The deep term's shape (its amplitude c aside), module docs."""
    s = x / tau
    z = z_of(x, nu, tau)
    p0, p1 = s25.psi(z), s25.psi(z / (1 - s))
    eps = f.eps_of(nu)
    share = eps / (1 + 4 * eps / 3)  # mu/M
    if "M" in mode:
        return (p0 - p1) * share * f.confined(s)
    if "X" in mode:
        return 4 * p1 * (1 - p1) * share * f.confined(s)
    if "Y" in mode:
        return 4 * p1 * (1 - p1) * f.confined(s)
    if "F" in mode:
        return (p0 - p1) * (s29.phi_c(s, tau) - 1)
    if "O" in mode:
        return (1 - p1) * share * f.confined(s)
    if "G" in mode:
        return 4 * p1 * (1 - p1) * (s29.phi_c(s, tau) - 1)
    if "H" in mode:
        return p1 * share * (s29.phi_c(s, tau) - 1)
    return 0.0 * s


def letters(mode):
    return [k for k in mode if k in TERMS]


def has_term(mode):
    return bool(letters(mode))


def form(mode):
    """SFF with the deep term of `mode`; p = SFF's six (l0 l1 k0 k1 lc cf) [+ c]."""
    if mode == "SFF":
        return s29.form("SFF")

    def chi(p, x, nu, tau):
        if np.ndim(tau):
            return np.array([float(np.squeeze(chi(p, np.array([x]), nu, float(t)))) for t in tau])
        x = np.asarray(x, dtype=float)
        w = s28.weight(tau, "SFB0030")
        out_law = _LAW_K(LAW, x, nu, tau) if w < 1 else 0.0
        if w <= 0:  # t/R >= 0.3: the law, exactly as on main
            return out_law
        l0, l1, k0, k1, lc, cf = p[:6]
        eps = f.eps_of(nu)
        fl = f.chi_flat(x, nu)
        hemi = s28.chi_hemi(x, nu, "F")
        excess = s28.chi_shell(x, nu, min(tau, s28.TAUS[-1])) - hemi
        s = x / tau
        share = eps / (1 + 4 * eps / 3)
        film = s25.psi(z_of(x, nu, tau) / (1 - s)) * (s29.phi_c(s, tau) - 1)
        extra = sum(c * term(k, x, nu, tau) for k, c in zip(letters(mode), p[6:]))
        squeeze = (l0 + l1 * eps) * s + lc * share * f.confined(s) + cf * film + extra
        shell = fl + excess * (1 + squeeze) * np.exp(-(k0 + k1 * eps) * (fl - 1))
        if "L" in mode and w < 1:
            out_law = s31.law_with_film(x, nu, tau, w * extra)
        return w * shell + (1 - w) * out_law
    return chi


def groups():
    train, thin, held, blind, dblind = s26.sets()
    dk = s29.deep_curves()
    new = k1e6(S32_FIT)
    return (("fitted+", train + new), ("FITTED (s26)", train), ("s32 fit", new),
            ("thin fit", thin), ("held out", held), ("blind", blind), ("deep CAX8 k1e5", dblind),
            ("deep k1e6 0.48 (blind)", [c for c in dk if c["role"] == "blind" and c["nu"] == 0.48]),
            ("deep k1e6 (0.49, 0.12) held", [c for c in dk if c["role"] == "held"]),
            ("deep k1e6 (0.45, 0.07) blind", [c for c in dk if c["nu"] == 0.45]),
            ("s30 blind", s31.s30_blind()),
            ("s31 blind (0.455, 0.12)", s31.s30_blind(s31.S31_BLIND)),
            ("s32 held (0.495, 0.12)", k1e6(S32_HELD)),
            ("s32 held CAX8 (0.495, 0.12)", k1e6(S32_HELD, s29.DEEP_K1E6)),
            ("s32 held CAX8 (0.499, 0.12)", k1e6(S32_HELD_499, s29.DEEP_K1E6)),
            ("thick t/R >= 0.3 (committed)", s32.thick_committed()))


def tagged_curves():
    train, thin, held, blind, dblind = s26.sets()
    return ([("fit", c) for c in train] + [("s32fit", c) for c in k1e6(S32_FIT)] +
            [("held", c) for c in held] + [("blind", c) for c in blind] +
            [("deep", c) for c in dblind] +
            [("k1e6 " + c["role"], c) for c in s29.deep_curves()] +
            [("s30 blind", c) for c in s31.s30_blind()] +
            [("s31 blind", c) for c in s31.s30_blind(s31.S31_BLIND)] +
            [("s32held", c) for c in k1e6(S32_HELD)] +
            [("s32held CAX8", c) for c in k1e6(S32_HELD, s29.DEEP_K1E6)] +
            [("thick " + c["name"], c) for c in s32.thick_committed()])


def fit_mode(mode, train):
    if mode == "SFF":
        return s29.form("SFF"), list(SFF)
    chi = form(mode)
    full = np.array(list(SFF) + [0.0] * len(letters(mode)), dtype=float)
    if mode.endswith("n"):  # SFF's six constants and the term's theory amplitude 1
        full[6:] = 1.0
        return chi, full
    idx = list(range(6, len(full))) if "s" in mode else \
        [i for i in range(len(full)) if not ("k" in mode and i == 5)]

    def sub(q, x, nu, tau):
        pp = full.copy()
        pp[idx] = q
        return chi(pp, x, nu, tau)
    f.chi_core = sub
    q = f.fit(train, list(full[idx]))
    p = full.copy()
    p[idx] = q
    return chi, p


def fit_table(modes, curves_too=False):
    gs = groups()
    train = gs[0][1]
    print(f"fitted+ = {len(train)} curves ({sum(len(c['x']) for c in train)} points); s32 fit: "
          + ", ".join(f"({c['nu']:g}, {c['tau']:g}) to x {c['x'][-1]:g} (delta/t "
                      f"{c['x'][-1] / c['tau']:.2f})" for c in gs[2][1]))
    print("| form | " + " | ".join(g for g, _ in gs) + " |")
    print("|---" * (len(gs) + 1) + "|")
    fits = {}
    for mode in modes:
        t0 = time.time()
        chi, p = fit_mode(mode, train)
        fits[mode] = (chi, p)
        cells = []
        for _, cs in gs:
            if not cs:
                cells.append("-")
                continue
            v = max(((s29.signed(p, c, chi), c) for c in cs), key=lambda r: abs(r[0][0]))
            cells.append(f"{abs(v[0][0]):.2f} ({v[1]['nu']:g}, {v[1]['tau']:g})")
        print(f"| {mode} | " + " | ".join(cells) + " |", flush=True)
        print("    constants " + " ".join(f"{v:.6f}" for v in p) +
              f"  ({time.time() - t0:.0f} s)", flush=True)
    if curves_too:
        per_curve(modes, fits)
    return fits


def per_curve(modes, fits):
    tagged = sorted(tagged_curves(), key=lambda tc: (tc[0].split()[0], tc[1]["tau"], tc[1]["nu"]))
    print("| curve | " + " | ".join(modes) + " |")
    print("|---" * (len(modes) + 1) + "|")
    worst = {m: [] for m in modes}
    for tag, c in tagged:
        cells = []
        for mode in modes:
            chi, p = fits[mode]
            v, xi = s29.signed(p, c, chi)
            worst[mode].append((abs(v), f"{tag} ({c['nu']:g}, {c['tau']:g})", c["tau"]))
            cells.append(f"{v:+.2f} (x {xi:g})")
        if not tag.startswith("thick"):
            print(f"| {tag} ({c['nu']:g}, {c['tau']:g}) | " + " | ".join(cells) + " |",
                  flush=True)
    ref = modes[0]
    for mode in modes:
        w = worst[mode]
        line = f"{mode}: {sum(v <= 2 for v, _, _ in w)} of {len(w)} curves within 2 %"
        if mode != ref:
            pairs = list(zip(worst[ref], w))
            better = [n for (a, n, _), (b, _, _) in pairs if b < a - 0.1]
            worse = [f"{n} {a:.2f} -> {b:.2f}" for (a, n, _), (b, _, _) in pairs if b > a + 0.1]
            thick = [f"{n} {a:.4f} -> {b:.4f}" for (a, n, t), (b, _, _) in pairs
                     if t >= 0.3 and abs(b - a) > 1e-9]
            line += (f"; {len(better)} better, {len(worse)} worse by > 0.1 % than {ref}"
                     + (": " + ", ".join(worse) if worse else "")
                     + f"\n    t/R >= 0.3 curves that moved at all ({len(thick)} of "
                     f"{sum(t >= 0.3 for _, _, t in w)}): " + ", ".join(thick))
        print(line)


def need_rows():
    """Per point of every curve of t/R < 0.3: (tag, curve, w, s, dsq, SFF's miss [%], the
    sensitivity d chi / chi per unit dsq, psi(z), psi(z'), mu/M, D(s), Phi_c - 1)."""
    sff = s29.form("SFF")
    l0, l1, k0, k1, lc, cf = SFF
    out = []
    for tag, c in tagged_curves():
        nu, tau, x = c["nu"], c["tau"], c["x"]
        if tau >= 0.3:
            continue
        s = x / tau
        w = float(s28.weight(tau, "SFB0030"))
        cl = _LAW_K(LAW, x, nu, tau)
        ct = sff(SFF, x, nu, tau)
        shell = (ct - (1 - w) * cl) / w
        target = (c["chi"] - (1 - w) * cl) / w
        eps = f.eps_of(nu)
        fl = f.chi_flat(x, nu)
        ex = s28.chi_shell(x, nu, tau) - s28.chi_hemi(x, nu, "F")
        cpl = ex * np.exp(-(k0 + k1 * eps) * (fl - 1))
        z = z_of(x, nu, tau)
        out.append(dict(tag=tag, c=c, w=w, s=s, dsq=(target - shell) / cpl,
                        err=100 * (ct / c["chi"] - 1), law=100 * (cl / c["chi"] - 1),
                        sens=w * cpl / ct, p0=s25.psi(z), p1=s25.psi(z / (1 - s)),
                        share=eps / (1 + 4 * eps / 3), D=f.confined(s),
                        phi=s29.phi_c(s, tau) - 1))
    return out


def need():
    """dsq = what SFF's thin-skin squeeze lacks, per unit of excess x coupling (module docs), at
    delta/t ~0.4, ~0.6 and the end, beside the terms' shapes M X Y F O G there."""
    rows = []
    for r in need_rows():
        c, s = r["c"], r["s"]
        picks = []
        for i in sorted({int(np.argmin(np.abs(s - 0.4))), int(np.argmin(np.abs(s - 0.6))),
                         len(s) - 1}):
            shapes = " ".join(f"{k} {float(term(k, c['x'][i:i + 1], c['nu'], c['tau'])[0]):.3f}"
                              for k in TERMS)
            picks.append(f"s {s[i]:.2f}: SFF {r['err'][i]:+.2f} %, law {r['law'][i]:+.2f} %, "
                         f"dsq {r['dsq'][i]:+.3f}, psi(z) {r['p0'][i]:.2f} psi(z') "
                         f"{r['p1'][i]:.2f} [{shapes}]")
        rows.append((c["nu"], c["tau"], f"{r['tag']} ({c['nu']:g}, {c['tau']:g}) w {r['w']:.2f} "
                     f"mu/M {r['share']:.3f} {c['name']}\n    " + "\n    ".join(picks)))
    for _, _, line in sorted(rows):
        print(line)


def lin(extras):
    """The linearised refit: dsq (SFF's need) fitted, on the points of the fitted+ set's curves
    of t/R < 0.3, by SFF's own squeeze terms (s, eps s, (mu/M) D, the film; their changes) plus
    the given terms, least squares in |F/F_FE - 1| (dsq times its sensitivity); printed: the
    largest remaining miss [%] per group (first order: k0, k1 and the law are not refitted)."""
    rows = need_rows()
    fits = {"fit", "s32fit"}

    def basis(r, k):
        eps = r["share"] / (1 - 4 * r["share"] / 3)
        own = {"s": r["s"], "es": eps * r["s"], "lc": r["share"] * r["D"],
               "film": r["p1"] * r["phi"]}
        if k in own:
            return own[k]
        return term(k, r["c"]["x"], r["c"]["nu"], r["c"]["tau"])
    for ex in extras:
        keys = ["s", "es", "lc", "film"] + [k for k in ex if k in TERMS]
        a = np.concatenate([np.stack([basis(r, k) for k in keys], 1) * 100 * r["sens"][:, None]
                            for r in rows if r["tag"] in fits])
        y = np.concatenate([100 * r["sens"] * r["dsq"] for r in rows if r["tag"] in fits])
        cc = np.linalg.lstsq(a, y, rcond=None)[0]
        worst = {}
        for r in rows:
            m = np.stack([basis(r, k) for k in keys], 1) * 100 * r["sens"][:, None]
            miss = r["err"] + m @ cc  # SFF's miss plus what the refit adds (first order)
            g = ("fit" if r["tag"] in fits else
                 "k1e6 (0.49, 0.12) CAX8" if r["tag"] == "k1e6 held" else
                 "nu >= 0.49 other" if r["c"]["nu"] >= 0.49 else
                 "nu 0.44-0.48 not fitted" if r["c"]["nu"] >= 0.44 else "nu < 0.44 not fitted")
            if r["tag"] == "deep":  # the penalty-1e5 CAX8 twins: superseded references
                continue
            worst[g] = max(worst.get(g, 0.0), float(np.max(np.abs(miss))))
        print(f"{ex or 'none':6s} " + ", ".join(f"{g} {v:.2f}" for g, v in sorted(worst.items()))
              + "; amplitudes " + " ".join(f"{k} {v:+.3f}" for k, v in zip(keys[4:], cc[4:])))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--var", nargs="*")
    ap.add_argument("--curves", action="store_true")
    ap.add_argument("--check-form")
    ap.add_argument("--need", action="store_true")
    ap.add_argument("--lin", nargs="*")
    a = ap.parse_args()
    if a.need:
        need()
    if a.lin is not None:
        lin(a.lin or [""])
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
