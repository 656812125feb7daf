#!/usr/bin/env python3
"""Session 32 (issue 24 item 5): the law's deep-squeeze weight `cd` made to depend on nu, with
the thick-skin law and the thin-skin form (SFF) refitted together.

Session 31 (CORE_FORM.md "Thin skins: the deep squeeze at nu 0.44-0.48, session 31") found part
of SFF's deep-squeeze miss at nu 0.44-0.48, t/R 0.1-0.25 in the law's own share of the fade:
the law's squeeze is

    T = 1 + (l0 + l1 eps) s + (lc mu/M + cd) D(s)        (try_thin_skin_s25.form("K"), LAW)

with one deviatoric weight cd at every nu (session 24: the incompressible skin's flow out of
the gap is a shear, its stiffening goes with mu). The law alone is 2-9 % soft at the deep ends
of nu 0.42-0.48 (t/R 0.1-0.25) and +2.9 % stiff at nu 0.49 t/R 0.3's; the combined weight
`lc mu/M + cd` is linear in mu/M (0.027 at nu 0.5, 0.036 at nu 0.3), monotone in nu, so it
cannot be larger at 0.46-0.48 than at both 0.49 and 0.4. Variants (the law's cd D(s) -> cd g
D(s); each refits the law's eight constants (+ its own) and SFF's six together on the FITTED
set of try_thin_skin_s26.sets(), fewer with the suffixes f and s; held-out, blind and deep sets
stay out of every fit):

  K    g = 1: the law's form unchanged, refitted together with SFF (the control: what a joint
       refit alone does)
  C    g = 1 - psi(z'), z' = a_H/(lambda (1 - s)), lambda = t sqrt(M/(3 mu)): the confined
       share of Matthewson's bonded layer at the thinned skin (SFF's own z'). D(s) is the
       oedometer's large-strain stiffening (no lateral strain); in a bonded layer only the
       confined share 1 - psi is an oedometer, the flow share psi flows out (its large-strain
       part is the film, which the thin-skin form carries, not the law). Nearly incompressible
       skins (psi -> 1 at nu -> 0.5) lose the term; the thinning moves force into the confined
       share (z' grows as 1/(1 - s)), so it switches on deeper at nu 0.46-0.48. No new constant.
  C0   the same with the unthinned crossover z = a_H/lambda (psi of the small-strain layer)
  Cc   (cd + cc (1 - psi(z'))) D(s): a shear part at every nu (session 24's) and a confined
       part, both fitted (nine law constants)
  S    g = (mu/M)/(mu/M + cs), cs fitted: the confined share of a bonded layer at a fixed
       patch-to-skin ratio (Matthewson's 1 - psi is a function of z^2 = 3 (mu/M) (a/t)^2
       alone): small for a nearly incompressible skin, 1 for a compressible one, without the
       patch's geometry. Note lc (mu/M) D(s) is already linear in mu/M; S is its saturation.
       (A factor in the compressibility kappa/mu is this one again: kappa/mu = M/mu - 4/3.)
  B    (cd + cb 4 psi(z') (1 - psi(z'))) D(s): the shear part at every nu and a part that lives
       where the skin is at its crossover (both flowing and confined: the flow's shear under
       the confined share's pressure), zero for the compressible and the incompressible skin;
       a heuristic, cb fitted (nine law constants)
  f    (a suffix) only lc, cd and the variant's own law constant refitted, the law's e0 l0 l1
       k0 k1 m kept at LAW (the thick skins move only by the deep weight); s: SFF's six kept
  X    (a suffix) the thin-skin form gets the same cd g D(s) (SFF dropped cd: "the film is what
       cd stood in for"; with g the confined share, film and oedometer are complementary
       shares). No new constant.

A MODE ending in `n` is that form with the law's and SFF's constants, not refitted (`Kn` is
SFF exactly). `--var MODE ...` prints max |F/F_FE - 1| per set as session 31's table plus
every committed core FE file of t/R >= 0.3 ("thick"); `--curves` prints every curve and,
against SFF (the law on main, not refitted), how many curves got better / worse by more than
0.1 % (thick ones listed); `--check-form MODE` runs fit_core.check on that fit (chi >= 1, F
increasing, core -> flat, no rise with t/R). `--need` prints, per curve with a point at
delta/t >= 0.45, the change of the law's deviatoric weight (`lc mu/M + cd`, 0.027-0.034 today)
that would meet the FE there if the law's share of the fade alone took it (SFF as on main):
the nu-shape a cd(nu) would need.

Session 32 (CORE_FORM.md "Thin skins: cd with nu, session 32"): `--var SFF K C C0 Cc S CX CcX
B Kf Cf Ccf Bf Cfs Ccfs Bfs --curves --check-form B` (~2 min) prints its tables; none of the
forms is better than SFF on every set and every refit moves some t/R >= 0.3 file past its
pinned tolerance: none adopted, the law unchanged.

usage: PY tools/calibration/try_cd_nu_s32.py [--need] [--var SFF K C C0 Cc S CX ...] [--curves]
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
import try_deep_squeeze_s31 as s31  # noqa: E402
import try_shell_table_s28 as s28  # noqa: E402
import try_thin_skin_s23 as s23  # noqa: E402
import try_thin_skin_s25 as s25  # noqa: E402
import try_thin_skin_s26 as s26  # noqa: E402

SFF = s29.SFF
LAW = s25.LAW  # e0 l0 l1 k0 k1 m lc cd (backed.rs CORE, CORE_DEVIATORIC)
_LAW_K = s25.form("K")


def n_law(mode):
    return 8 + (1 if ("Cc" in mode or "S" in mode or "B" in mode) else 0)


def free_of(mode):
    """Indices of the constants refitted: all, or with `f` the law's e0 l0 l1 k0 k1 m frozen at
    LAW (only lc, cd and the variant's own refitted, so the law's thick skins move as little as
    the new weight makes them), with `s` SFF's six frozen."""
    nl = n_law(mode)
    idx = list(range(nl + 6))
    if "f" in mode:
        idx = [i for i in idx if i >= 6]
    if "s" in mode:
        idx = [i for i in idx if i < nl]
    return idx


def z_of(x, nu, tau, thinned=True):
    z = np.sqrt(3 * (1 - 2 * nu) / (2 * (1 - nu)) * x) / tau  # a_H / lambda
    return z / (1 - x / tau) if thinned else z


def g_of(mode, pl, x, nu, tau):
    """The law's deviatoric weight times D(s)'s coefficient: cd g (with Cc: cd + cc (1 - psi))."""
    cd = pl[7]
    if "Cc" in mode:
        return cd + pl[8] * (1 - s25.psi(z_of(x, nu, tau)))
    if "B" in mode:  # a shear part at every nu and the crossover's share psi (1 - psi)
        ps = s25.psi(z_of(x, nu, tau))
        return cd + pl[8] * 4 * ps * (1 - ps)
    if "C0" in mode:
        return cd * (1 - s25.psi(z_of(x, nu, tau, False)))
    if "C" in mode:
        return cd * (1 - s25.psi(z_of(x, nu, tau)))
    if "S" in mode:
        eps = f.eps_of(nu)
        share = eps / (1 + 4 * eps / 3)
        return cd * share / (share + abs(pl[8]))
    return cd * np.ones_like(np.asarray(x, dtype=float))


def law(mode, pl, x, nu, tau):
    """s25.form("K") with cd D(s) -> g_of(...) D(s): chi = flat + excess T coupling, so the law
    with cd = 0 plus (chi0 - flat) g D / T0 is exact."""
    p0 = list(pl[:7]) + [0.0]
    chi0 = _LAW_K(p0, x, nu, tau)
    if mode == "law":
        return _LAW_K(pl[:8], x, nu, tau)
    fl = f.chi_flat(x, nu)
    eps = f.eps_of(nu)
    s = x / tau
    l0, l1, lc = pl[1], pl[2], pl[6]
    t0 = 1 + (l0 + l1 * eps) * s + lc * eps / (1 + 4 * eps / 3) * f.confined(s)
    return chi0 + (chi0 - fl) * g_of(mode, pl, x, nu, tau) * f.confined(s) / t0


def form(mode):
    """The law (mode's g) faded into SFF's thin-skin form (try_deep_squeeze_s29.form("PcTZ"))
    by t/R 0.3; p = law constants (n_law) + SFF's six (l0 l1 k0 k1 lc cf)."""
    nl = n_law(mode)

    def chi(p, x, nu, tau):
        if np.ndim(tau):
            return np.array([float(np.squeeze(chi(p, np.array([x]), nu, float(t)))) for t in tau])
        x = np.asarray(x, dtype=float)
        pl, ps = p[:nl], p[nl:]
        w = s28.weight(tau, "SFB0030")
        out_law = law(mode, pl, x, nu, tau) if w < 1 else 0.0
        if w <= 0:
            return out_law
        l0, l1, k0, k1, lc, cf = ps[:6]
        eps = f.eps_of(nu)
        fl = f.chi_flat(x, nu)
        hemi = s28.chi_hemi(x, nu, "F")
        excess = s28.chi_shell(x, nu, min(tau, s28.TAUS[-1])) - hemi
        s = x / tau
        share = eps / (1 + 4 * eps / 3)
        z = z_of(x, nu, tau)
        film = s25.psi(z) * (s29.phi_c(s, tau) - 1)
        squeeze = (l0 + l1 * eps) * s + lc * share * f.confined(s) + cf * film
        if "X" in mode:
            squeeze = squeeze + g_of(mode, pl, x, nu, tau) * f.confined(s)
        shell = fl + excess * (1 + squeeze) * np.exp(-(k0 + k1 * eps) * (fl - 1))
        return w * shell + (1 - w) * out_law
    return chi


def p0_of(mode):
    extra = [0.0] if ("Cc" in mode or "B" in mode) else ([0.05] if "S" in mode else [])
    return list(LAW) + extra + list(SFF)


def thick_committed():
    """Every committed core FE file of t/R >= 0.3: the campaign's (penalty 1e5, CAX8R), the CAX8
    ones of cax8/ and the penalty-1e6 nu 0.49 t/R 0.3 (as the Rust tests read them: 0.01 to
    x_max)."""
    out = [c for c in f.load() if c["tau"] >= 0.3]
    for c in out:
        c["name"] = "core/" + c["name"]
    for sub in ("cax8", "k1e6"):
        d = os.path.join(f.DATA, sub)
        for name in sorted(os.listdir(d)):
            if not name.startswith("force_nu"):
                continue
            nu, tau = (float(v) for v in name[len("force_nu"):-len(".csv")].split("_t"))
            if tau < 0.3:
                continue
            x, F = s23.curve_csv(os.path.join(d, name))
            out.append(s23.as_curve(nu, tau, x, F, f"{sub}/{name}"))
    return out


def groups():
    train, thin, held, blind, dblind = s26.sets()
    dk = s29.deep_curves()
    old = [c for c in train if c not in thin]
    return (("fitted", train), ("the 14", old), ("thin fit", thin), ("held out", held),
            ("blind", blind), ("deep CAX8 k1e5", dblind),
            ("deep k1e6 0.48 (blind)", [c for c in dk if c["role"] == "blind" and c["nu"] == 0.48]),
            ("deep k1e6 (0.49, 0.12) held", [c for c in dk if c["role"] == "held"]),
            ("deep k1e6 (0.45, 0.07) blind", [c for c in dk if c["nu"] == 0.45]),
            ("s30 blind", s31.s30_blind()),
            ("s31 blind (0.455, 0.12)", s31.s30_blind(s31.S31_BLIND)),
            ("thick t/R >= 0.3 (committed)", thick_committed()))


def tagged_curves():
    train, thin, held, blind, dblind = s26.sets()
    return ([("fit", c) for c in train] + [("held", c) for c in held] +
            [("blind", c) for c in blind] + [("deep", c) for c in dblind] +
            [("k1e6 " + c["role"], c) for c in s29.deep_curves()] +
            [("s30 blind", c) for c in s31.s30_blind()] +
            [("s31 blind", c) for c in s31.s30_blind(s31.S31_BLIND)] +
            [("thick " + c["name"], c) for c in thick_committed()])


def fit_table(modes, curves_too=False):
    gs = groups()
    train = gs[0][1]
    print("| form | " + " | ".join(g for g, _ in gs) + " |")
    print("|---" * (len(gs) + 1) + "|")
    fits = {}
    for mode in modes:
        t0 = time.time()
        if mode == "SFF":
            chi, p = s29.form("SFF"), SFF
        elif mode.endswith("n"):  # the law's and SFF's constants, not refitted
            chi, p = form(mode[:-1]), p0_of(mode[:-1])
        else:
            chi = form(mode)
            full = np.array(p0_of(mode), dtype=float)
            idx = free_of(mode)

            def sub(q, x, nu, tau, full=full, idx=idx, chi=chi):
                pp = full.copy()
                pp[idx] = q
                return chi(pp, x, nu, tau)
            f.chi_core = sub
            q = f.fit(train, list(full[idx]))
            p = full.copy()
            p[idx] = q
        fits[mode] = (chi, p)
        cells = []
        for _, cs in gs:
            v = max(((s29.signed(p, c, chi), c) for c in cs), key=lambda r: abs(r[0][0]))
            cells.append(f"{abs(v[0][0]):.2f} ({v[1]['nu']:g}, {v[1]['tau']:g})")
        print(f"| {mode} | " + " | ".join(cells) + " |", flush=True)
        if mode != "SFF":
            nl = n_law(mode)
            print("    law " + " ".join(f"{v:.6f}" for v in p[:nl]) + "; thin " +
                  " ".join(f"{v:.6f}" for v in p[nl:]) + f"  ({time.time() - t0:.0f} s)",
                  flush=True)
            pl = p[:nl]
            gl = [float(np.squeeze(g_of(mode, pl, np.array([0.6 * tau]), nu, tau)))
                  for nu, tau in ((0.3, 0.2), (0.4, 0.2), (0.46, 0.15), (0.48, 0.1), (0.49, 0.3),
                                  (0.499, 0.4))]
            print("    law's deviatoric weight lc mu/M + cd g at delta/t 0.6: " + ", ".join(
                f"({nu:g}, {tau:g}) {pl[6] * f.eps_of(nu) / (1 + 4 * f.eps_of(nu) / 3) + v:.4f}"
                for (nu, tau), v in zip(((0.3, 0.2), (0.4, 0.2), (0.46, 0.15), (0.48, 0.1),
                                         (0.49, 0.3), (0.499, 0.4)), gl)), flush=True)
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
        print(f"| {tag} ({c['nu']:g}, {c['tau']:g}) | " + " | ".join(cells) + " |", flush=True)
    ref = modes[0]
    for mode in modes:
        w = worst[mode]
        line = f"{mode}: {sum(v <= 2 for v, _, _ in w)} of {len(w)} curves within 2 %"
        if mode != ref:
            pairs = list(zip(worst[ref], w))
            better = [n for (a, n, _), (b, _, _) in pairs if b < a - 0.1]
            worse = [f"{n} {a:.2f} -> {b:.2f}" for (a, n, _), (b, _, _) in pairs if b > a + 0.1]
            thick = [f"{n} {a:.2f} -> {b:.2f}" for (a, n, t), (b, _, _) in pairs
                     if t >= 0.3 and b > a + 1e-9]
            line += (f"; {len(better)} better, {len(worse)} worse by > 0.1 % than {ref}"
                     + (": " + ", ".join(worse) if worse else "")
                     + f"\n    t/R >= 0.3 curves worse at all ({len(thick)}): " + ", ".join(thick))
        print(line)


def need():
    """Per curve with points at delta/t >= 0.45: dW = (chi_FE - chi_SFF) / ((1 - w) (chi_law -
    flat) D(s) / T), the change of the law's weight lc mu/M + cd (d chi_law / d cd = (chi_law -
    flat) D / T) that meets the FE at that point with SFF's thin-skin share unchanged; printed
    at delta/t ~0.5, ~0.6 and the deepest point within x_max, beside the weight itself."""
    sff = s29.form("SFF")
    e0, l0, l1, k0, k1, m, lc, cd = LAW
    seen = set()
    rows = []
    for tag, c in tagged_curves():
        nu, tau, x = c["nu"], c["tau"], c["x"]
        key = (c["name"], nu, tau)
        if key in seen:
            continue
        seen.add(key)
        s = x / tau
        deep = s >= 0.45
        w = float(s28.weight(tau, "SFB0030"))
        if not deep.any() or w >= 1:
            continue
        cl = _LAW_K(LAW, x, nu, tau)
        ct = sff(SFF, x, nu, tau)
        fl = f.chi_flat(x, nu)
        eps = f.eps_of(nu)
        weight = lc * eps / (1 + 4 * eps / 3) + cd
        t = 1 + (l0 + l1 * eps) * s + weight * f.confined(s)
        dw = (c["chi"] - ct) / ((1 - w) * (cl - fl) * f.confined(s) / t)
        picks = []
        for target in (0.5, 0.6):
            i = int(np.argmin(np.abs(s - target) + 10 * (~deep)))
            picks.append(f"s {s[i]:.2f} {dw[i]:+.4f} ({100 * (ct[i] / c['chi'][i] - 1):+.2f} %)")
        i = len(x) - 1
        picks.append(f"end s {s[i]:.2f} {dw[i]:+.4f} ({100 * (ct[i] / c['chi'][i] - 1):+.2f} %)")
        rows.append((nu, tau, f"{tag.split()[0]} ({nu:g}, {tau:g}) {c['name']} w {w:.2f} "
                     f"weight {weight:.4f}: " + "; ".join(picks)))
    for _, _, line in sorted(rows):
        print(line)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--var", nargs="*")
    ap.add_argument("--curves", action="store_true")
    ap.add_argument("--check-form")
    ap.add_argument("--need", action="store_true")
    a = ap.parse_args()
    if a.need:
        need()
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
