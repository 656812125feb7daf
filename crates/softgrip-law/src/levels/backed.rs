//! softgrip's calibrated level of a backed fingertip ([`Backing::Flat`], [`Backing::Core`]):
//! `F = chi(x, nu, t/R) F_H`, fitted to softgrip's own finite-element pipeline (`tools/fe/`,
//! data in `tests/data/fe/{flat,core}/`, CalculiX, axisymmetric neo-Hookean, R = 1 mm).
//!
//! ## Flat: a hemisphere bonded at its flat face
//!
//! ```text
//! chi_flat = N S / D
//!   N = 1 - x + x^2/3                          numerator of chi_IC (Eq. 36)
//!   S = 1 - d x + c(nu) sqrt(x) + e(nu) x^2    finite-thickness factor of the bonded base
//!   D = (1 - x)^2 + b^2 eps x^2                lateral-area pole, softened by compressibility
//!   c = c0 + c1 eps,  e = e0 + e1 eps,  eps = mu/kappa = 3 (1 - 2nu) / (2 (1 + nu))
//! ```
//!
//! - `c sqrt(x)` is the first-order correction of a contact on a body of finite depth bonded to a
//!   rigid base (Dimitriadis' `a/h` term, here h = R): FE gives 1.066 x Hertz at x = 0.01 for
//!   nu = 0.3 and 1.078 for nu >= 0.4, the incompressible body being the more constrained.
//! - `e x^2` is the bonded base restraining the lateral bulge at large x: at nu = 0.49 the
//!   hemisphere carries 1.3x the free sphere at x = 0.2 and 1.6x at 0.4; much less for a
//!   compressible body, which loses volume instead (`e` linear in eps).
//! - `D` is the free sphere's pole `(1 - x)^2` with a compressible softening linear in eps (the
//!   free sphere's is quadratic: its equator is free to expand).
//!
//! Constants: least squares on all four FE curves (nu = 0.3, 0.4, 0.48, 0.499, each for
//! 0.01 <= x <= its reach): c0 = 0.681614, c1 = -0.341872, e0 = 1.754842, e1 = -2.984330,
//! b = 0.791282, d = 0.329388. Residuals: within 0.95 % at every fitted nu; each nu held out
//! of the fit in turn: 1.31 % (0.4), 0.76 % (0.48), 0.75 % (0.499), i.e. within 2 % between the
//! fitted points (`cargo test -p softgrip-law --test backed`). Held out at nu = 0.3 (an
//! extrapolation below every fitted nu) it is 4.4 %: below nu = 0.3 the form is not validated.
//!
//! Poisson ratio: `0.3 <= nu <= 0.5` (an [`Error::IncompatibleLevel`] below: the FE data start
//! at 0.3 and the form extrapolated to nu = 0 is not monotone).
//!
//! Validity: `0 <= x <= x_max(nu)`, where the FE stops: 0.53 at nu <= 0.3 (the element volume
//! ratio falls below 0.2), 0.46 at 0.4 and 0.44 at nu >= 0.48 (the free surface folds over the
//! bonded edge), linear in between. At nu = 0.499 the FE solver stops at x = 0.31 (increment
//! below its minimum, no fold-over): the form there is validated to 0.31 only and follows the
//! nu = 0.48 curve it is within 1.5 % of.
//!
//! ## Core: a skin of thickness t over a rigid core
//!
//! ```text
//! chi_core = chi_flat + L T exp(-k (chi_flat - 1))
//!   L   = X (1 + (Lt / X)^4)^(1/4)                  the series, at least the thin layer (session 21)
//!   X   = B(a_w / (t h), eps x/tau^2) - B(a_flat / (R h), eps x)   skin's layer less hemisphere's
//!   a_w = a_flat (1 + t1 w / sqrt(t1^2 + w^2)),  w = a_core/a_flat - 1,  t1 = (d1/3) a_H/(t h)
//!   Lt  = max(chi_thin(x, nu, tau) - 1, 0)       Matthewson's thin bonded layer (theory)
//!   B(v, E) = v (d1 + e v / (1 + E))            a contact of radius v h on a bonded layer of depth h
//!   h   = 1 + tau^2 / (1 - tau),  tau = t/R       the skin's mean depth over r <= 2t, over t
//!   T   = 1 + lambda s + (lc (mu/M) + cd) D(s)   the skin over the pole under the squeeze s = x/tau
//!   D(s) = (2/3) (1 - s)^(-5/3) (2 - s) - 4/3    confined neo-Hookean skin beyond linear (theory)
//!   d1  = 2 (1.2876 - 1.4678 nu + 1.3442 nu^2) / ((1 - nu) pi)    Dimitriadis' first order (theory)
//!   e = e0 exp(-m eps),  lambda = l0 + l1 eps,  k = k0 + k1 eps,  mu/M = eps / (1 + 4 eps/3)
//!   a_flat, a_core: the radius forms (Radius, below; a thin skin reports another radius), over R
//! ```
//!
//! - `B(v, E)`: the correction of a contact of radius a on a layer of depth h bonded to a rigid
//!   base, at `v = a/h`. Its first order is Dimitriadis' `d1(nu)` (no fit); the second, `e v`,
//!   is the confinement of the layer's material (it must flow out past the contact), lost as
//!   the material becomes compressible (`e0 exp(-m eps)`: `e0 (1 - m eps)` to first order, but
//!   never negative; with m fixed at 1, the former `e0 (1 - eps)`, the fit is 2.79 % fitted and
//!   2.67 % held out, against 2.31 % and 2.25 %; m = 1.56 loses the confinement faster at small
//!   eps, as the FE's thin skins do between nu 0.499 and 0.4, `tools/calibration/CORE_FORM.md`).
//!   `1 + E`: a bonded layer acts incompressibly only over lengths below its confinement
//!   length `l ~ depth sqrt(kappa/mu)`, beyond which it is an oedometer whose stiffening grows
//!   only linearly in a/h; `E = (a_H / l)^2` with Hertz's `a_H = sqrt(R
//!   delta)`: `eps (a_H/t)^2 = eps x/tau^2` for the skin, the radius' own `E = eps u^2` (one
//!   confinement measure for the patch's width and its force; coefficient 1, not fitted), and
//!   `eps x` for the hemisphere's depth R. (With the law's own radius in E, `eps v^2`, as
//!   before the radius had its crossover: refitted on today's radius 3.39 % fitted, 3.18 % held
//!   out, against 2.79 % and 2.21 % for this one with m = 1.)
//! - `a`: Dimitriadis' radius is the real contact radius, which on a thin skin is wider than
//!   Hertz's; the level's own radius carries that (the single largest gain over a Hertz radius).
//! - `h`: the core is a sphere of radius R - t, not a plane: at a distance r from the pole the
//!   skin is `t (1 + (r/t)^2 tau^2 / (2 (1 - tau)))` thick, and its mean over `r <= 2t` is
//!   `t h` (coefficient fixed at 1). As t -> R, h -> infinity: the excess vanishes and core ->
//!   flat (0.000 % apart at t/R = 0.999); as t/R -> 0, h -> 1: a flat bonded layer.
//! - `- B(a_flat / (R h), eps x)`: the layer of depth R that chi_flat (a bonded hemisphere)
//!   already has (its depth scaled by h as the skin's, so that the two cancel as t -> R).
//! - `T`: the skin over the core's pole is squeezed by `s = delta/t = x/tau` (up to 0.8 here)
//!   between two rigid surfaces, the core and the plane: a confined layer. `lambda s` is its
//!   small-strain thinning (a compressible skin stiffens more under it). `D(s)` is the
//!   large-strain part, from the FE's own material with no fit: a neo-Hookean layer
//!   (`C10 = mu/2`, `D1 = 2/kappa`) squeezed to the stretch `lam = 1 - s` with no lateral strain
//!   carries the nominal stress `P = (2/3) mu lam^(-5/3) (lam^2 - 1) + kappa (lam - 1)`; over its
//!   linear `-M s` (`M = kappa + 4 mu/3`, the oedometer modulus) that is `1 + (mu/M) D(s)`, the
//!   volumetric part cancelling. `D = (14/9) s + O(s^2)`, unbounded as the layer collapses;
//!   `mu/M` is 0 for an incompressible skin (no collapse: it flows out instead) and 0.28 at
//!   nu = 0.3, where the FE's skin elements near volume collapse at delta/t = 0.8 (J = 0.2).
//!   `lc` (0.23) is the share of the layer excess that stiffens as the pole's skin does (the
//!   rest of the patch is squeezed less; 0.027 since session 24). `cd` (session 24) is the
//!   deviatoric share of the same stiffening at every nu (below). With the linear thinning alone the law left the FE
//!   past delta/t = 0.6 (18 % at nu 0.3, t/R 0.2, x = 0.16); four other seven-constant
//!   thinnings (a cubic, a pole, the remaining depth) reached the FE's ends at 3.1-5.2 %
//!   fitted, 4.1-6.5 % held out (`tools/calibration/extend_core_range.py`).
//! - `exp(-k (chi_flat - 1))`: the hemisphere's large-deformation stiffening and the layer
//!   excess do not multiply (k = 0.24 at nu = 0.5, -0.37 at nu = 0.3). Equal to the former
//!   `1 / (1 + k (chi_flat - 1))` to first order, it cannot vanish: that one did, for a
//!   compressible skin at large x, when nu = 0.3 was held out of the fit (a pole; 8.05 % now).
//! - Cost: neither form is evaluated on the hot path. At construction each is tabulated as a
//!   cubic Hermite interpolant in `sqrt(x)` on 128 (flat) or 320 (core) cells through the
//!   form's value and slope (the private `ChiTable`; within 5.3e-8 of the form in force,
//!   5.4e-6 in stiffness), so an
//!   evaluation is the square root the force needs anyway, a cell lookup and two short
//!   polynomials, whatever the form costs. `cargo bench -p softgrip-law --bench law --
//!   force_stiffness`, 2-core machine at load 0.9 (two other processes running): fit
//!   5.1-5.6 ns, calibrated-flat 10.7-11.1 ns, calibrated-core 9.9-10.9 ns per evaluation, i.e.
//!   1.9-2.0x fit (evaluated directly, the previous core form was 26.6 ns, the flat one 9.8 ns).
//! - **The thin-layer floor (session 21).** `L` above is the series part `X`; the excess is
//!   `X (1 + (Lt/X)^4)^(1/4)`, at least Matthewson's thin bonded layer `Lt = max(chi_thin - 1,
//!   0)` ([`super::thin_layer`]: the layer's pressure `p - l^2 lap p = (M/t) w`, `l = t sqrt(M/(3
//!   mu))`; no fitted constant). It holds both thin-layer limits and their Poisson ratio: a
//!   patch wider than l sees the compressible oedometer (Winkler, `M = E (1 - nu)/((1 + nu)(1 -
//!   2 nu))`, F/F_H linear in a/t), a narrower one (always at nu = 1/2) the incompressible
//!   bulging layer (`(3 pi/8)(a_H/t)^3`). The series cannot grow like either; the floor takes
//!   over where the patch outgrows the skin (`a_H/t ~ 2`, t/R <= 0.1). Power 4 (session 20's;
//!   fitted it is 3.88 and no error moves by 0.1 %). Before it the law was up to 16.2 % too soft
//!   on the FE's t/R 0.05-0.1 skins (nu 0.3, t/R 0.05, x = 0.03).
//! - **The small-patch widening (session 11's blend, adopted in session 21).** The layer term
//!   takes the patch `a_flat (1 + t1 w / sqrt(t1^2 + w^2))`, `w = a_core/a_flat - 1` the radius
//!   form's widening, `t1 = (d1/3) a_H/(t h)` the bonded layer's first order: while the patch is
//!   small against the skin it widens no more than that (the radius form's widening at x = 0.01
//!   was larger, and the layer excess there ~5 % too large on every skin of t/R 0.12-0.3).
//!
//! - **The squeezed skin's deviatoric stiffening (session 24).** `lc (mu/M) D(s)` is the
//!   oedometer's share: 0 for a nearly incompressible skin, which cannot compress over the
//!   pole but flows out of the gap between the core and the counterpart. That flow is a shear
//!   of the squeezed skin, and its large-strain stiffening goes with the shear modulus, not
//!   with `mu/M`: `cd D(s)` at every nu (`D`'s large-strain shape, theory; its weight `cd`
//!   fitted, `CORE_DEVIATORIC`). Without it the FE of nu 0.48, t/R 0.4 on full-integration
//!   CAX8 elements was 3.07 % stiffer than the law at the law's x_max (delta/t 0.8), the blind
//!   nu 0.46, t/R 0.25 skin 4.77 %, and the core on a cylinder of 3R 3.29 % (all at their deep
//!   ends); with it 1.98 %, 2.18 % and 2.68 % (session 23's variant K,
//!   `tools/calibration/try_thin_skin_s23.py`; `tools/calibration/CORE_FORM.md`, "Session 24").
//!   It is taken at the patch's squeeze `rho_H delta/t` on a curved counterpart, like the rest
//!   of the plane form (`crate::core_map`; at the true `delta/t` balls were up to 11.3 % too
//!   stiff).
//!
//! - **The thin-skin form (session 28).** Below t/R 0.3 the force is `w chi_S + (1 - w) chi_core`,
//!   `w = 1 - z^2 (3 - 2 z)`, `z = tau / SHELL_FADE` (0.93 at t/R 0.05, 0.26 at 0.2, 0 from
//!   0.3), with `chi_S = chi_flat + (chi_shell - 1 - c sqrt(x)) T' exp(-k' (chi_flat - 1))`:
//!   the exact small-strain skin bonded to its rigid core (`chi_shell`, [`super::shell`], no
//!   fitted constant) in place of the layer series and the thin-layer floor, less the bonded
//!   hemisphere's own first order `c = c0 + c1 eps` (chi_flat's), with the squeeze `T' = 1 +
//!   lambda' s + (lc' mu/M + cd') D(s)` and the coupling `k' = k0' + k1' eps` refitted on it
//!   (`SHELL`; `tools/calibration/try_shell_table_s28.py --var SFB0030`, the reference, which
//!   this form followed to 5.1e-8; since session 29 with the squeezed film, below). Fitted 6.21 -> 2.42 %, held out 3.70 -> 2.84 %, blind 5.89
//!   -> 2.88 %, deep CAX8 2.90 -> 2.49 % (the fade's end chosen after those sets were seen;
//!   `tools/calibration/CORE_FORM.md`, session 28). The radius is unchanged. `chi_shell` is C0
//!   only in `u = a_H/t` (as its Python reference), which the table rounds over a cell.
//!
//! - **The squeezed film (session 29).** In the thin-skin form the deviatoric `cd' D(s)` gives
//!   way to the squeezed film: `T' = 1 + lambda' s + lc' (mu/M) D(s) + cf psi(z') (Phi_c(s,
//!   tau) - 1)`. Under the patch a thin skin is a film between the plane and the core's sphere,
//!   `h = t - delta + r^2/(2 (R - t))`; an incompressible film's lubrication stiffness goes as
//!   `h^-3`, and over Matthewson's patch that is `Phi_c = 6 int_0^1 v (1 - v)/h(v)^3 dv` over
//!   its small-strain force ([`squeezed_film`], theory). A compressible film flows only over
//!   the crossover length `lambda = t sqrt(M/(3 mu))`, which scales with the film's own
//!   thickness: its flow share is Matthewson's `psi(z')` at `z' = a_H/(lambda (1 - s))`
//!   ([`flow_share`]). `cf` fitted (0.35), the other five refitted, on the fitted set only
//!   (`SHELL`; `tools/calibration/try_deep_squeeze_s29.py --var SFF`). Against the deep
//!   penalty-1e6 CAX8 skins, which no constant saw: nu 0.48 t/R 0.08 -6.29 -> -3.49 % at x
//!   0.05, t/R 0.1 -8.19 -> -4.91 % at 0.07, nu 0.49 t/R 0.12 (held out, to delta/t 0.79) -5.16
//!   -> +1.86 %; thin fitted 2.06 -> 1.55 %, held out 2.84 -> 2.67 %, blind 2.88 -> 1.81 %
//!   (CORE_FORM.md, session 29).
//!
//! Since session 24: e0 = 1.206147, l0 = 0.098330, l1 = 1.073688, k0 = 0.279726, k1 =
//! -1.858645, m = 1.251425, lc = 0.027101, cd = 0.026678, refitted with the deviatoric term on
//! session 21's 20 curves with the CAX8 curve of nu 0.48, t/R 0.4 in place of its CAX8R one
//! (`tools/calibration/try_thin_skin_s23.py --var K`).
//!
//! Session 21's: e0 = 1.174920, l0 = 0.215824, l1 = 0.794899, k0 = 0.238558, k1 =
//! -1.731562, m = 1.195527, lc = 0.134278, refitted with the two terms above on the 14 curves
//! below plus the six t/R 0.05-0.1 skins of session 20 (nu 0.3, 0.4, 0.48; the nu 0.48 t/R 0.05
//! run from its directory, 3 rows), `tools/calibration/try_thin_skin_s21.py`
//! (`tools/calibration/CORE_FORM.md`, "Thin skins: session 21": the errors per curve, nine
//! variants, a leave-out of the thin skins). The paragraphs below, to "The session-7 form",
//! are the session-10 form's (without the two terms), kept for its history; the errors today
//! are in the crate README and `tests/backed.rs`.
//!
//! Session 10's constants:
//! e0 = 0.849512, l0 = 0.676765, l1 = 1.022037, k0 = 0.266768, k1 = -1.622115, m = 1.470321,
//! lc = 0.234092: seven constants, the smallest largest relative error (least squares, then of
//! its 2nd and 4th power) over the 14 fitted FE curves (t/R = 0.2, 0.4, 0.6, 0.8 at nu = 0.3,
//! 0.48, 0.499, and t/R = 0.2, 0.4 at nu = 0.4), `0.01 <= x <=` each curve's reach or x_max
//! (`tools/calibration/fit_core.py` prints all of this; `tools/calibration/CORE_FORM.md`). The
//! force depends on the radius constants: refitting those means re-running `fit_core.py`.
//!
//! Largest error per fitted curve, each to its FE reach (`cargo test -p softgrip-law --test
//! backed`), nu = 0.3 / 0.4 / 0.48 / 0.499: t/R = 0.2: 2.12 / 2.48 / 1.87 / 2.20 %; 0.4: 1.95 /
//! 2.34 / 2.10 / 1.84 %; 0.6: 1.47 / - / 1.55 / 2.01 %; 0.8: 0.80 / - / 2.03 / 1.76 %. Held out
//! of the fit: (nu 0.35, t/R 0.7) 1.39 %, (0.45, 0.5) 2.24 %, (0.4, 0.3) 1.05 %, (0.49, 0.3)
//! 2.17 %; the second held-out set (nu, t/R) = (0.46, 0.25) 1.80 %, (0.33, 0.25) 2.37 %, (0.42,
//! 0.55) 1.88 %, (0.36, 0.2) 2.31 %, (0.44, 0.8) 1.23 %, (0.495, 0.35) 1.76 % (that set was made
//! after the five-constant form was chosen; `m` and this thinning were chosen among variants
//! with all of them in view, so it is no longer blind). Past delta/t = 0.6 (the range this form
//! adds) every curve is within 2.24 %; the errors above 2 % are at delta/t <= 0.6, where they
//! were before (t/R 0.2 at x = 0.01-0.09). Each t/R held out of the fit in turn: 4.70 % (0.4),
//! 3.31 % (0.6), and as extrapolations 10.34 % (0.2), 2.04 % (0.8); each nu: 2.74 % (0.4), 2.19 %
//! (0.48), and as extrapolations 5.80 % (0.3), 2.60 % (0.499); each fitted curve in turn: within
//! 2.93 % except (0.3, 0.4) 3.73 % and (0.3, 0.2) 6.17 % (the only fitted curves that reach
//! delta/t = 0.8 at a compressible nu: without one, `lc` is set by the other; with `lc` held at
//! its value, (0.3, 0.2) out is 2.81 %).
//!
//! The session-7 form (thinning `1 + lambda s`, six constants) was, to x_max = 0.6 t/R: t/R 0.2:
//! 1.80 / 2.31 / 1.74 / 2.13 %; 0.4: 1.65 / 2.05 / 1.99 / 1.73 %; 0.6: 1.40 / - / 1.36 / 1.94 %;
//! 0.8: 1.11 / - / 2.16 / 1.78 %; held out 1.01-2.25 % (both sets); each t/R out 8.11 / 2.96 /
//! 2.10 / 2.17 %, each nu out 6.86 / 2.38 / 2.15 / 3.58 %; carried to the FE's reach it was 18 %
//! off (nu 0.3, t/R 0.2). Before it: `e = e0 (1 - eps)` 2.79 % fitted, 2.67 % held out; with the
//! previous core radius (`S = s0 + s1 eps`) the previous form (crossover `eps v^2`, K linear)
//! 2.44 % / 2.75 %; a ten-constant form (a fitted rational for how much of a layer the core is)
//! 2.37 % fitted but 7.2 % and 4.7 % with t/R 0.4 and 0.6 held out.
//!
//! **The 2 % target is missed** by up to 0.48 % on the fitted curves (nu 0.4 at t/R 0.2, at
//! x = 0.01) and 0.37 % held out ((0.33, 0.25) at x = 0.15). At t/R = 0.2 the residual still
//! changes with nu (the FE is converged there: R/60 within 0.3 % of R/40 at nu 0.4, 0.48,
//! 0.499; `tools/calibration/CORE_FORM.md`).
//!
//! Validity: `0 <= x <= min(x_max_flat, 0.8 t/R)`: the FE's furthest reach over the core's pole
//! (delta/t = 0.8 at t/R 0.2, 0.25, 0.4 and nu 0.3-0.36, where the skin's elements approach
//! volume collapse); at t/R 0.3 that is x = 0.24, at 0.5 x = 0.4. The FE of a nearly
//! incompressible skin stops earlier (its mesh folds; delta/t 0.45 at nu 0.499 and t/R 0.2,
//! 0.65-0.7 at t/R 0.3-0.4): there the form is validated to the FE's reach only, and carries
//! the confined term, which is zero at nu = 0.5, beyond it. The t/R = 0.2 data are
//! mesh-converged: R/60 against the campaign's R/40 within 0.22 %
//! (`tests/data/fe/core/convergence.csv`).
//!
//! ## Radius
//!
//! ```text
//! a_flat = a_free (1 + (q0 + q1 eps) x + q2 x^2)
//! a_core = a_flat (1 + S rc^2 (u / (u + c)) / (1 + k x / rc)),  u = sqrt(x) / tau
//!   S = s0 (1 - w E / (1 + E)),  E = eps u^2
//!   a_free = artanh(sqrt x) (1 + g1 x + g3 x^3) (1 - x) / (1 - x + eps x / 4)   (calibrated.rs)
//!   rc = 1 - tau = (R - t)/R, the core's radius
//! ```
//!
//! - `(q0 + q1 eps) x`: the bonded base pushes the material under the contact outwards (less
//!   so when compressible, which loses volume instead); `q2 x^2 < 0`: it holds back the bulge
//!   the free sphere's equator would make at large x.
//! - `u / (u + c)`: Hertz's radius over the skin's thickness, saturating: a patch on a bonded
//!   layer thinner than itself is wider than Hertz's (`a^2 -> 2 R delta` for a compressible thin
//!   layer, `4 R delta` incompressible), a thick skin is the flat hemisphere (u -> 0, and
//!   `rc^2 -> 0` as t -> R: how much of a layer the core is). `1 / (1 + k x / rc)`: the rigid core
//!   holds back the large-deformation expansion the hemisphere has (`x / rc = delta / (R - t)`).
//! - `S`: how much wider. A bonded layer acts incompressibly only over lengths below its
//!   confinement length `l ~ t sqrt(kappa/mu)`; `E = eps u^2 = (a_H / l)^2` is the patch over it
//!   (the force's crossover `1 + eps v^2`, coefficient 1, not fitted). While the patch is
//!   shorter than l every skin widens it as an incompressible one (`s0`); a longer patch on a
//!   compressible skin widens less, towards the Winkler layer's `2 R delta` (`1 - w`: the fit's
//!   0.30; the two thin-layer limits' widenings over Hertz, `sqrt 2 - 1` over `2 - 1`: 0.41).
//!   The previous `S = s0 + s1 eps`, the same at every u, could not be both: at t/R = 0.2 it
//!   was on average +2.0 / +2.8 / -1.2 % off at nu = 0.3 / 0.4 / 0.48 (not monotone in nu; the
//!   pressure's peak ~ 1/a^2 scattered twice that); with a free linear `eps` term next to the
//!   crossover the fit puts that term at -0.04.
//!
//! **Thin skins (session 30).** Below t/R 0.2 the reported radius (`patch(delta).radius`) is
//!
//! ```text
//! a = w a_H A_lin(a_H/t, nu) + (1 - w) a_core,   w = 1 - z^2 (3 - 2 z),  z = tau / 0.2
//! ```
//!
//! `A_lin` the contact radius over Hertz's of the exact small-strain layer bonded to a rigid base
//! ([`super::shell::LayerRadius`]: the same solves as the thin-skin form's `chi_lin`; no fitted
//! constant): Hertz's 1 as `a_H/t -> 0` (`(d1/3) a_H/t` above it, Dimitriadis' first order), the
//! oedometer's `sqrt 2` or the incompressible layer's 2 as `a_H/t -> inf`, Matthewson's crossover
//! between; the force's fade shape, ending at the thinnest skin the radius form was fitted on
//! (`RADIUS_FADE`: at t/R >= 0.2 nothing moves). The force's layer term keeps `a_core` as its
//! patch length (its constants were fitted with it: every force number is unchanged); the
//! pressure integrates to the force over the reported radius. On the seventeen thin re-runs
//! (`tests/data/fe/core/k1e6/`, mean over 0.02 <= x <= x_max against the column plus half an
//! element) -0.69 .. +2.33 %, was -5.02 .. +3.11 % (`tools/calibration/try_thin_skin_radius_s30.py`,
//! `cargo test -p softgrip-law --test radius_pressure -- --nocapture thin_skin_radius`). The
//! curved core's exact shell is 0.3-0.9 % wider than the flat layer there (`--shell`), not taken.
//! The layer alone at t/R 0.2-0.25, x >= 0.1 is up to 1.5-6.4 % too wide (the form 0.6-2.2 %);
//! faded by the force's t/R 0.3 two t/R 0.2 skins leave their pinned radius errors.
//!
//! The FE radius the forms are fitted to is not the FE's radius column itself: that column
//! (`a_lin`, the last surface node on the plane, interpolated) moves in node steps, 1.0-1.9 %
//! rms about a smooth curve (up to 5 %), and lags the edge by about half an element face (the
//! contact is resolved per quadratic face). The estimate used is per curve `a_lin` smoothed
//! (`a/sqrt(x)` least squares in powers of `sqrt(x)`) plus half the element edge, 0.485 R/N on a
//! mesh R/N. Re-runs on R/80 and R/120 (`tests/data/fe/{flat,core}/radius_mesh_*.csv`) show
//! `a_lin` converging at first order in the element, and the R/40 estimate within 0.71 % of the
//! fine-mesh limit (the smoothed columns alone move by 0.7-2.4 % from R/40 to R/120).
//!
//! Constants (`tools/calibration/fit_radius_pressure.py`, least squares on the fitted cases,
//! 0.05 <= x <= min(reach, 0.45)): q0 = 0.648666, q1 = -0.706160, q2 = -0.954134 (flat nu =
//! 0.3, 0.4, 0.48, 0.499); s0 = 0.958112, w = 0.695966, c = 0.679698, k = 2.279033 (the 14
//! fitted core curves). Residuals for 0.1 <= x <= min(0.4, x_max) against that FE radius
//! (`cargo test -p softgrip-law --test radius_pressure`): flat within 1.37 % (held out: 1.15 %
//! at nu = 0.35, 1.16 % at 0.45); core within 2.23 % (nu 0.48 t/R 0.2; t/R 0.2 at nu 0.3 / 0.4:
//! 2.02 / 1.00 %; to x_max = 0.8 t/R since session 10, 1.68 % / 0.73 % to 0.6 t/R before;
//! held out: 0.83 % at (nu, t/R) = (0.4, 0.3), 1.40 % (0.49, 0.3), 1.29 % (0.45, 0.5), 0.82 %
//! (0.35, 0.7)); nu 0.499 at t/R 0.2 reaches x = 0.09 only: 2.46 % at
//! 0.05 <= x <= 0.09. The previous core form (`S = s0 + s1 eps`) was within 2.04 % on the 12
//! curves it was fitted to but 2.87 % at (0.4, 0.2); refitted on all 14 it is 4.11 %. Against
//! the raw column step noise and lag add up to 7.5 %. Before the a* estimate: 4.4 % (flat) and
//! 6.4 % (core) off the raw column, 4.3 % and 8.0 % off the estimate.
//!
//! ## Pressure
//!
//! `p = p0 (1 - r^2/a^2)^m (1 + b r^2/a^2)` ([`crate::ContactPatch`], force-conserving:
//! `p0 = (m + 1)(m + 2) F / (pi a^2 (m + 2 + b))`) with
//!
//! ```text
//! flat: m = 1/2 + (a0 + a1 eps) sqrt(x) + a2 x + a3 x^2,   b = 0
//! core: m = m_flat + (1 - m_flat) v^20,   b = -v,   v = w / (w + 1)
//!       w = u (rc^k / (cb (1 - s)))^n,  u = sqrt(x) / tau = a_H / t,  s = x / tau = delta / t
//! ```
//!
//! - `m_flat`: Hertz's ellipse at x -> 0; the patch of a bonded hemisphere is flatter than
//!   Hertz's at moderate x, fuller at large x.
//! - core: `v` is how much of a thin bonded layer the skin under the patch is. A thin bonded
//!   incompressible layer squeezed by a sphere carries `p ~ (1 - r^2/a^2)^2` (a squeeze film:
//!   its material can only flow outwards); the layer over the core's pole is the thinnest
//!   (`(t - delta) + r^2/(2 R)` locally), so the patch's centre carries more than any single
//!   power gives: the taper `b = -v`, with m staying flat's until the layer's end (`v^20`:
//!   within 0.001 of m_flat inside the validity; at v = 1, `(1 - rho^2)^1 (1 - rho^2)`).
//!   `u = a_H / t`: the patch over the skin, to the first power, so the taper vanishes at first
//!   order in `a/t` as the patch shrinks (as every correction of a contact on a bonded layer,
//!   Dimitriadis' series among them): b = -2.6e-5 at x = 1e-10 for t/R = 0.05; it also makes a
//!   thinner skin at the same squeeze more of a layer (v -> 1 as t/R -> 0). `1 / (1 - s)`: the
//!   layer left over the pole, `t - delta`, against t; `rc^k`: a thick skin (rc -> 0) is flat's
//!   shape. No compressibility term: with the right sign (a compressible layer flatter) the fit
//!   puts it at 0 in every variant tried. The previous form, `z = rc^k s^al / ((1 - s)
//!   tau^gam)`, `v = sig(z / cb, n)`, had two more constants the fitted profiles do not
//!   determine (with `al` anywhere in 0.02-0.5 the fitted worst is the same 4.48 %, the held-out
//!   worst moves between 4.9 and 6.0 %), and its fit put `al` near its bound: the taper at x ->
//!   0 faded as `x^0.11`.
//!
//! Constants: a0 = -0.399773, a1 = 0.189139, a2 = 1.031300, a3 = -0.688498 (flat:
//! `tools/calibration/fit_radius_pressure.py`, per FE profile the exponent that best matches it
//! over r <= 0.8 a with the FE's own force and the law's radius, then least squares of
//! `(m + 1)/(m_best + 1)`); k = 0.309476, n = 3.979639, cb = 1.638825 (core: least squares of
//! the profile and peak errors over r <= 0.8 a on the 19 fitted profiles inside the validity
//! x <= 0.6 t/R, with the FE's force and the law's radius, then of their 4th power, then the
//! smallest largest error; `fit_radius_pressure.py --write` writes them and the test's
//! tolerances; `tools/calibration/CORE_PRESSURE.md`).
//!
//! Residuals as fractions of FE's peak, peak / profile over r <= 0.8 a, inside the validity
//! (`cargo test -p softgrip-law --test radius_pressure` asserts each profile), with the FE's
//! force (the shape and radius alone) and [with the law's force]:
//! - flat: 3.1 % / 4.8 % [3.0 % / 4.7 %]; held out (nu 0.35, 0.45): 2.5 % / 2.6 % [2.8 % / 2.9 %];
//! - core, fitted (19 profiles at x <= 0.6 t/R): within 4.25 % / 4.48 % [4.9 % / 5.7 % with
//!   session 10's force]; held out (13, eight of them the second set, run after the forms were
//!   chosen): within 5.28 % / 5.94 % [5.4 % / 5.8 %], over 5 % at (nu, t/R) = (0.46, 0.25) and (0.4, 0.3) x 0.1 [and (0.49, 0.3),
//!   (0.495, 0.35) x 0.1]. Core nu 0.44 t/R 0.8 x 0.3 is in neither fit nor test: its FE profile
//!   integrates to 1.076 F (every other to 0.93-1.03 F), a contact-edge node entering contact
//!   carrying a penalty spike twice the centre's pressure.
//!   Before the radius's crossover and this form: 4.65 % / 5.35 % fitted, 5.36 % held out (3 of
//!   19 and 3 of 6 profiles over 5 %); before the taper (one exponent m): 7.7 % / 8.3 % fitted,
//!   10.1 % / 10.4 % [12.9 %] held out.
//!
//! **The core meets the 5 % target on every fitted profile and misses it by up to 0.9 % on two
//! held-out ones** (t/R 0.25 and 0.3; at t/R 0.3 between the fitted 0.2 and 0.4, x 0.1: the FE wants b = -0.42 there, the form
//! gives -0.32 while matching both neighbours). The floor at t/R 0.2 (the best (m, b) linear in
//! eps on the three t/R 0.2 profiles) is 3.77 %, was 5.35 % with the previous radius. Per
//! profile the best (m, b) leaves 1.2-3.1 % (4.2 % at the held-out (0.45, 0.5) x 0.3). **Past
//! x = 0.6 t/R**, inside the force's validity since session 10 but not in the shape's fit, the
//! three FE profiles there (nu 0.3 t/R 0.4 x 0.3, nu 0.4 t/R 0.4 x 0.3, nu 0.3 t/R 0.8 x 0.5)
//! are 11.2 %, 9.0 % and 9.8 % off (profile, FE force; tested as they are).

use std::sync::Arc;

use super::NormalisedLaw;
use super::shell::{LayerRadius, Shell};
use super::thin_layer::{ThinLayer, flow_share};
use crate::backing::{Backing, MIN_CORE_THICKNESS_RATIO};
use crate::core_map::{CoreOnCounterpart, SqueezeExcess};
use crate::error::{Error, Result};
use crate::level::LevelKind;
use crate::quadrature::integrate;

/// Flat: c0, c1, e0, e1, b, d.
const FLAT: [f64; 6] = [0.681614, -0.341872, 1.754842, -2.984330, 0.791282, 0.329388];
/// Core: e0 (the layer's second order, `e = e0 exp(-m eps)`), l0, l1 (the skin's thinning),
/// k0, k1 (the layer excess under the hemisphere's large-deformation stiffening), m (the
/// confinement's loss with compressibility), lc (the share of the confined skin's large-strain
/// stiffening).
/// Refitted in session 24 with the deviatoric stiffening `CORE_DEVIATORIC` (session 23's
/// variant K, `tools/calibration/try_thin_skin_s23.py --var K`; session 21's, with the
/// thin-layer floor and the small-patch widening: 1.174920, 0.215824, 0.794899, 0.238558,
/// -1.731562, 1.195527, 0.134278).
const CORE: [f64; 7] = [
    1.206147, 0.098330, 1.073688, 0.279726, -1.858645, 1.251425, 0.027101,
];
/// `cd`: the weight of the squeezed skin's deviatoric large-strain stiffening `cd D(s)` at
/// every nu (module docs, session 24), beside the oedometer's `lc (mu/M) D(s)`; fitted with
/// `CORE` (dimensionless).
const CORE_DEVIATORIC: f64 = 0.026678;
/// The thin-skin form SFF (session 29): l0, l1 (the squeeze's slope `l0 + l1 eps`), k0, k1 (the
/// coupling `k0 + k1 eps`), lc (the oedometer's share of the confined skin's stiffening), cf
/// (the squeezed film's weight), fitted on the shell's excess `chi_shell - chi_hemi` on the
/// FITTED set (`tools/calibration/try_deep_squeeze_s29.py --var SFF`). Session 28's SFB0030 had
/// a deviatoric `cd` (0.001603) in place of the film.
const SHELL: [f64; 6] = [0.346016, -0.481405, 0.507177, -1.868559, 0.311041, 0.351796];
/// The t/R by which the thin-skin form has faded into the law (`w = 1 - z^2 (3 - 2 z)`,
/// `z = min(tau / SHELL_FADE, 1)`): chosen among ~15 fades after the held-out, blind and deep
/// sets were seen (CORE_FORM.md, session 28).
const SHELL_FADE: f64 = 0.3;
/// The power of the thin-layer floor `X (1 + (L/X)^p)^(1/p)` (session 20's `U`; not fitted:
/// fitted it is 3.88 and every error moves by less than 0.1 %).
const THIN_POWER: f64 = 4.0;
/// The core's validity: the skin over the core's pole squeezed by at most this fraction of t
/// (the FE's furthest reach, t/R 0.2-0.4 at nu 0.3-0.36).
const CORE_SQUEEZE: f64 = 0.8;
/// Flat radius: q0, q1, q2 of `a_flat = a_free (1 + (q0 + q1 eps) x + q2 x^2)`.
const RADIUS: [f64; 3] = [0.648666, -0.706160, -0.954134];
/// Core radius: s0, w, c, k of `a_core = a_flat (1 + S rc^2 (u / (u + c)) / (1 + k x / rc))`,
/// `S = s0 (1 - w E / (1 + E))`, `E = eps u^2`, `u = sqrt(x) / tau`.
const RADIUS_CORE: [f64; 4] = [0.958112, 0.695966, 0.679698, 2.279033];
/// Flat pressure shape: a0, a1, a2, a3 of `m = 1/2 + (a0 + a1 eps) sqrt(x) + a2 x + a3 x^2`.
const SHAPE: [f64; 4] = [-0.399773, 0.189139, 1.031300, -0.688498];
/// Core pressure shape and taper: k, n, cb of `v = w / (w + 1)`,
/// `w = u (rc^k / (cb (1 - s)))^n`, `u = sqrt(x) / tau`, `s = x / tau`; `b = -v`,
/// `m = m_flat + (1 - m_flat) v^20`.
const SHAPE_CORE: [f64; 3] = [0.309476, 3.979639, 1.638825];
/// The t/R by which the reported radius of a thin skin has faded from the exact layer's into the
/// radius form (`w = 1 - z^2 (3 - 2 z)`, `z = min(tau / RADIUS_FADE, 1)`, the force's fade shape):
/// the thinnest skin the radius form was fitted on (session 30; module docs, Radius). Not fitted.
const RADIUS_FADE: f64 = 0.2;
/// Free sphere's radius excess `1 + g1 x + g3 x^3` (as `calibrated.rs`).
const G: [f64; 2] = [0.042222, 0.109823];

/// The width in x over which `chi_flat`'s continuation past its range (`ChiForm::flat_continued`)
/// blends from the form into its log-tangent: numerical (C2, so that the table's cubic cells
/// follow it), not fitted. Against the FE of a core on balls 0.02, 0.05 and 0.15 give the same
/// largest errors but on two curves (t/R 0.6 on 2R 2.00 / 2.08 / 2.37 %, t/R 0.3 on 3R 2.22 /
/// 2.28 / 2.49 %); the table follows the form in stiffness to 2.5e-4 / 1.3e-4 / 6.5e-5
/// (`table_follows_the_form`).
const FLAT_END_BLEND: f64 = 0.15;
/// Cells of the flat construction's tabulation over `0 <= sqrt(x) <= sqrt(x_max)` (see
/// [`ChiTable`]).
const FLAT_CELLS: usize = 128;
/// Cells of the core's tabulation: twice the flat's, for the confined skin's steep stiffening
/// near `delta/t = 0.8` (`lam^(-5/3)` at lam = 0.2; on 128 cells the table would be 7.8e-7 off
/// the form in force and 4.1e-5 in stiffness there); 320 since session 21's thin-layer floor
/// (on 256 the plane core's table was 6.9e-8 off in force and 1.12e-5 in stiffness, past the
/// test's 1e-5).
const CORE_CELLS: usize = 320;
/// Cells of a core's tabulation on a curved counterpart (`crate::core_map`): 1.5 times the
/// plane's, for the confined skin's tangent stiffening at the ball's true squeeze (`lam^(-8/3)`
/// at lam = 0.2; on 256 cells the table was 3.4e-7 off the form in force and 2.1e-5 in
/// stiffness there, on a ball of R/10; on 384 within the plane core's bounds, 1e-7, 1e-5 and
/// 1e-8 with energy, `table_follows_the_form`; since session 17's continuation of `chi_flat`
/// in the squeeze excess, 2e-7 in force and 6.5e-5 in stiffness, the test's bounds for a core on
/// a counterpart 3e-7 and 1e-4: the law's stiffness and energy stay the table's exact derivative
/// and integral). Binding builds one table of 1.5 times the knots; the hot path is the same
/// lookup.
const CORE_ON_CELLS: usize = 384;

/// A backed construction's `chi` tabulated at construction: a cubic Hermite interpolant in
/// `s = sqrt(x)` on equal cells (`FLAT_CELLS`, `CORE_CELLS`), through the exact form's value and
/// `d chi/ds` at every knot. `chi` is a smooth function of `s` (the form is analytic in `s`, with
/// no pole on `[0, x_max]`), so the interpolant follows the form to 5.3e-8 in force, 5.4e-6 in
/// stiffness and 5.2e-9 in energy (relative; worst at nu 0.3 and t/R 0.05 or 0.2 near x_max,
/// where the confined skin stiffens fastest; `cargo test -p softgrip-law --lib table_follows --
/// --nocapture`), and costs, per
/// evaluation, the square root the force needs anyway, one cell lookup and a cubic: no division.
/// The stiffness is the interpolant's exact derivative and the energy its exact integral (the
/// integrand `(8/3) chi s^4` is a polynomial of degree 7 on a cell: 8-point Gauss-Legendre is
/// exact).
#[derive(Debug)]
struct ChiTable {
    /// `1 / h`.
    inv_h: f64,
    /// The cells' width in `s`, `sqrt(x_max) / n`.
    h: f64,
    /// The last cell's index, `n - 1`.
    last: u32,
    /// Per cell, `chi = c0 + t (c1 + t (c2 + t c3))` in the local `t = s/h - i`, in [0, 1].
    cells: Box<[[f64; 4]]>,
    /// Per cell, `x chi' / s = (1/2) d chi/ds = d0 + t (d1 + t d2)`.
    slopes: Box<[[f64; 3]]>,
    /// Energy `(8/3) ∫ chi s^4 ds` from 0 to the start of each cell.
    energy0: Box<[f64]>,
}

impl ChiTable {
    /// Tabulates `chi` over `[0, x_max]` on `n` cells from `knot(s)` = (`chi`, `d chi/ds`) at
    /// `s = sqrt(x)`.
    fn new(x_max: f64, n: usize, knot: impl Fn(f64) -> (f64, f64)) -> Self {
        let h = x_max.sqrt() / n as f64;
        let knot = |i: usize| knot(h * i as f64);
        let mut cells = vec![[0.0; 4]; n].into_boxed_slice();
        let mut energy0 = vec![0.0; n].into_boxed_slice();
        let mut slopes = vec![[0.0; 3]; n].into_boxed_slice();
        let mut energy = 0.0;
        let mut k0 = knot(0);
        for i in 0..n {
            let k1 = knot(i + 1);
            let (f0, f1, d0, d1) = (k0.0, k1.0, k0.1 * h, k1.1 * h);
            cells[i] = [
                f0,
                d0,
                3.0 * (f1 - f0) - 2.0 * d0 - d1,
                2.0 * (f0 - f1) + d0 + d1,
            ];
            let [_, c1, c2, c3] = cells[i];
            let half = 0.5 / h;
            slopes[i] = [half * c1, half * 2.0 * c2, half * 3.0 * c3];
            energy0[i] = energy;
            energy += cell_energy(cells[i], h, i, 1.0);
            k0 = k1;
        }
        Self {
            inv_h: 1.0 / h,
            h,
            last: u32::try_from(n - 1).expect("invariant: a table has a few hundred cells"),
            cells,
            slopes,
            energy0,
        }
    }

    /// The cell of `s` and the local coordinate in it (the last cell continues past its end).
    #[inline(always)]
    fn locate(&self, s: f64) -> (usize, f64) {
        let t = s * self.inv_h;
        // Through u32 (s >= 0 and t <= n on the validity range): a cheaper conversion than to
        // usize.
        let i = (t as u32).min(self.last);
        (i as usize, t - f64::from(i))
    }

    /// `chi` and `x chi' = (s/2) d chi/ds` at `s = sqrt(x)`.
    #[inline(always)]
    fn chi(&self, s: f64) -> (f64, f64) {
        let (i, t) = self.locate(s);
        let [c0, c1, c2, c3] = self.cells[i];
        let [d0, d1, d2] = self.slopes[i];
        (
            c0 + t * (c1 + t * (c2 + t * c3)),
            s * (d0 + t * (d1 + t * d2)),
        )
    }

    /// The normalised energy at `x`.
    fn energy(&self, x: f64) -> f64 {
        let (i, t) = self.locate(x.sqrt());
        self.energy0[i] + cell_energy(self.cells[i], self.h, i, t)
    }
}

/// `(8/3) ∫ chi s^4 ds` over cell `i` (coefficients `cell`, width `h`) from its start to the
/// local coordinate `t`.
fn cell_energy(cell: [f64; 4], h: f64, i: usize, t: f64) -> f64 {
    let [c0, c1, c2, c3] = cell;
    let s0 = h * i as f64;
    let width = h * t;
    integrate(0.0, 1.0, 1, |w| {
        let tw = t * w;
        let s = s0 + width * w;
        8.0 / 3.0 * (c0 + tw * (c1 + tw * (c2 + tw * c3))) * s * s * s * s
    }) * width
}

/// The contact radius forms (the module docs, Radius) of one construction at one Poisson ratio.
#[derive(Debug, Clone, Copy)]
struct RadiusForm {
    /// `eps / 4` (`eps = mu/kappa`).
    eps4: f64,
    /// `q0 + q1 eps`, the flat base's linear restraint.
    rad_x: f64,
    /// `s0 rc^2`, the core's layer excess at saturation for an incompressible skin (0 for flat).
    rad_core: f64,
    /// `k / rc`, the rigid core holding back the large-x expansion (core).
    rad_thick: f64,
    /// `1 / (t/R)` (core), 0 for flat.
    inv_tau: f64,
}

impl RadiusForm {
    /// `(a_flat / R, a / R)` at `s = sqrt(x)`: the flat hemisphere's radius and this
    /// construction's (the same for flat). Analytic in `s` on `(-0.9, 0.9)`: `s < 0` only for
    /// the slope stencil at `s = 0`.
    fn radii(&self, s: f64) -> (f64, f64) {
        let x = s * s;
        let w = 1.0 - x;
        let [g1, g3] = G;
        let free = s.atanh() * (1.0 + (g1 + g3 * x * x) * x) * w / (w + self.eps4 * x);
        let flat = free * (1.0 + (self.rad_x + RADIUS[2] * x) * x);
        if self.rad_core == 0.0 {
            return (flat, flat);
        }
        // u = a_H / t: Hertz's radius over the skin's thickness; the layer's widening saturates
        // in u and is held back by the rigid core as the squeeze grows. E = eps u^2 = (a_H / l)^2,
        // the patch over the confinement length l = t sqrt(kappa / mu): beyond it a compressible
        // skin widens the patch less, 1 - w E / (1 + E) = (1 + (1 - w) E) / (1 + E).
        let u = s * self.inv_tau;
        let e = 4.0 * self.eps4 * u * u;
        let widen = self.rad_core * (1.0 + (1.0 - RADIUS_CORE[1]) * e) / (1.0 + e);
        let own = flat * (1.0 + widen * u / ((u + RADIUS_CORE[2]) * (1.0 + self.rad_thick * x)));
        (flat, own)
    }
}

/// A thin skin's reported radius (session 30, the module docs, Radius): `w a_H A_lin(a_H/t) + (1 -
/// w) a_core`, the exact small-strain bonded layer's patch faded into the radius form by
/// `RADIUS_FADE`. Only the reported patch: the force's layer term keeps the radius form.
#[derive(Debug)]
struct ThinRadius {
    layer: LayerRadius,
    /// `w = 1 - z^2 (3 - 2 z)`, `z = tau / RADIUS_FADE`, in (0, 1].
    weight: f64,
    /// `1 / tau`.
    inv_tau: f64,
}

/// The thin-skin form (session 28, the module docs): the exact shell on its core in place of the
/// law's layer excess, the law's squeeze and coupling (refitted, [`SHELL`]) on top, weighted by
/// `weight` against the law.
#[derive(Debug, Clone)]
struct ShellForce {
    shell: Shell,
    /// `w = 1 - z^2 (3 - 2 z)`, `z = tau / SHELL_FADE`, in (0, 1].
    weight: f64,
    /// `(l0 + l1 eps) / tau`: the squeeze's linear part `lambda x/tau`.
    thinning: f64,
    /// `lc eps / (1 + 4 eps/3)`.
    confined: f64,
    /// `cf`: the squeezed film's weight (session 29).
    film: f64,
    /// `sqrt(3 mu/M) / tau`: the patch over the skin's crossover length, `z = a_H/lambda`, per
    /// `sqrt(x)` (0 for an incompressible skin).
    inv_l: f64,
    /// `2 / (1 - tau)`: the gap's opening over the core's sphere, `b = bend s / (1 - s)`.
    bend: f64,
    /// `k0 + k1 eps`.
    k: f64,
}

/// The core's layer excess (the module docs, Core): everything that is not chi_flat.
#[derive(Debug, Clone)]
struct CoreForce {
    /// Dimitriadis' first order `d1(nu)`.
    d1: f64,
    /// The second order `e0 exp(-m eps)`.
    e: f64,
    /// `eps = mu/kappa`: the crossover `1 + eps x/tau^2` (skin), `1 + eps x` (hemisphere).
    eps: f64,
    /// `1 / tau^2`.
    inv_tau2: f64,
    /// `1 / h` and `1 / (tau h)`: the flat hemisphere's depth R and the skin's mean depth
    /// `t h`, over R.
    inv_h: f64,
    inv_tau_h: f64,
    /// `(l0 + l1 eps) / tau`: the thinning's linear part `lambda x/tau`.
    thinning: f64,
    /// `1 / tau`: the squeeze `s = delta/t = x/tau` of the skin over the core's pole.
    inv_tau: f64,
    /// `lc mu/M + cd = lc eps / (1 + 4 eps/3) + cd`: the share of the confined skin's
    /// large-strain stiffening [`confined`], the oedometer's (0 for an incompressible skin)
    /// and the deviatoric one at every nu (session 24).
    confined: f64,
    /// `k0 + k1 eps`.
    k: f64,
    /// `d1 / (3 tau h)`: the bonded layer's first-order widening of the patch, over `a_H/R`
    /// (the small-patch widening).
    widening: f64,
    /// Matthewson's thin bonded layer at this skin (the thin-layer floor).
    thin: ThinLayer,
    /// The thin-skin form, for `t/R < SHELL_FADE` (session 28).
    shell: Option<ShellForce>,
}

impl CoreForce {
    /// `B(v, E) = v (d1 + e v / (1 + E))`: a contact of radius `v h` on a layer of depth h
    /// bonded to a rigid base; `E = (a_H / l)^2`, Hertz's patch over the layer's confinement
    /// length `l = h sqrt(kappa/mu)`.
    fn layer(&self, v: f64, conf: f64) -> f64 {
        v * (self.d1 + self.e * v / (1.0 + conf))
    }
}

/// `D(s) = (2/3) lam^(-5/3) (2 - s) - 4/3`, `lam = 1 - s`: how much more than linearly a
/// neo-Hookean layer confined laterally (an oedometer, the skin over the core's pole) resists a
/// squeeze `s = delta/t`, over mu. Its nominal stress is `P = (2/3) mu lam^(-5/3) (lam^2 - 1) +
/// kappa (lam - 1)` against the linear `-M s`, `M = kappa + 4 mu/3`: the volumetric part is
/// linear in lam and cancels, so `P / (-M s) = 1 + (mu/M) D(s)`, `D = (14/9) s + O(s^2)`,
/// growing without bound as the layer collapses (lam -> 0). Theory, no fitted constant; finite
/// and increasing for `s < 1` (the validity keeps `s <= 0.8`).
fn confined(s: f64) -> f64 {
    let lam = 1.0 - s;
    2.0 / 3.0 * lam.powf(-5.0 / 3.0) * (2.0 - s) - 4.0 / 3.0
}

/// `Phi_c(s) = 6 int_0^1 v (1 - v) / h(v)^3 dv`, `h = 1 - s + bend s v`, `bend = 2/(1 - tau)`:
/// the incompressible film between the plane and the core's sphere, squeezed by `s = delta/t`
/// under Matthewson's patch (`a^2 = 4 R delta`, `v = (r/a)^2`; the gap `t - delta + r^2/(2 (R -
/// t))`), over its small-strain force: its lubrication stiffness goes as `h^-3` (session 27's
/// `Phi_c`). With `A = 1 - s`, `b = bend s/A`, `Phi_c = 6 J(b)/A^3`, `J(b) = ((b^2 + 2 b)/(2 (1
/// + b)) - ln(1 + b))/b^3`, below `b = 0.1` its series `sum (-1)^n (n + 1) b^n/(2 (n + 3))`
/// (16 terms; the closed form cancels 3 digits at 0.1). `1 - 3 s tau/(1 - tau) + O(s^2)`;
/// theory, no fitted constant; finite for `s < 1` (the validity keeps `s <= 0.8`).
fn squeezed_film(s: f64, bend: f64) -> f64 {
    let a = 1.0 - s;
    let b = bend * s / a;
    let j = if b.abs() < 0.1 {
        let mut sum = 0.0;
        let mut bn = 1.0;
        for n in 0..16 {
            let n = f64::from(n);
            sum += (n + 1.0) / (2.0 * (n + 3.0)) * bn;
            bn *= -b;
        }
        sum
    } else {
        ((b * b + 2.0 * b) / (2.0 * (1.0 + b)) - b.ln_1p()) / (b * b * b)
    };
    6.0 * j / (a * a * a)
}

/// The force form `chi` of one backed construction at one Poisson ratio (the module docs),
/// evaluated only to build the [`ChiTable`] the hot path uses.
#[derive(Debug, Clone)]
struct ChiForm {
    c: f64,
    d: f64,
    e: f64,
    b2: f64,
    /// Core only.
    core: Option<CoreForce>,
    radius: RadiusForm,
    /// On a curved counterpart (`crate::core_map`), a core only: the plane's compression that
    /// makes the same patch (`rho_H`, Hertz's), at which the whole plane form is evaluated,
    /// and the squeeze of the skin beyond it (`SqueezeExcess`). 1 and `None` on a plane.
    x_plane: f64,
    squeeze: Option<SqueezeExcess>,
    /// `chi_flat`'s own range (`flat_x_max`), `ln chi_flat` and its slope `d ln chi_flat / dx`
    /// there: the squeeze excess continues `chi_flat` past its range by that exponential
    /// (`ChiForm::flat_continued`; session 17). Set with `squeeze`.
    flat_end: [f64; 3],
}

impl ChiForm {
    /// `chi` at `s = sqrt(x)`: analytic in `s` on `(-0.9, 0.9)` (`s < 0` only for the slope
    /// stencil at `s = 0`).
    fn chi(&self, s_true: f64) -> f64 {
        let s_patch = s_true * self.x_plane.sqrt();
        let (flat, plane) = self.plane_chi(s_patch);
        let Some(squeeze) = &self.squeeze else {
            return plane;
        };
        // The layer's part of the plane form at the patch, its confined skin squeezed to the
        // true delta/t (crate::core_map, the confined skin), pressed over the ball's cap
        // (the wrapped cap).
        let x_true = s_true * s_true;
        let layer_extra = (plane - flat) * (squeeze.confined(x_true) + squeeze.wrapped(x_true));
        (plane + layer_extra) * squeeze.factor(s_true, |s| self.flat_continued(s))
    }

    /// `chi_flat` at `s = sqrt(x)` for the squeeze excess (`crate::core_map`, `Phi`): the flat
    /// hemisphere's form on its own range `x <= x_l = flat_x_max` (where the bonded
    /// hemisphere's FE stops), past it its log-tangent there, `ln chi = ln chi_flat(x_l) + d (x -
    /// x_l)` (an exponential, increasing), reached by a quintic smoothstep in `ln chi` over
    /// `FLAT_END_BLEND` (so that the table's cubic cells follow it: C2). `Phi` takes it at
    /// `rho delta/t`, up to 0.66 on balls of 2-4 R, where the form's denominator `(1 - x)^2 +
    /// b^2 eps x^2` (the hemisphere's own collapse) steepens: with it the thick skins on balls
    /// of 2R and 4R were up to 5.6 % too stiff (session 17, `tools/calibration/CORE_FORM.md`).
    fn flat_continued(&self, s: f64) -> f64 {
        let [x_l, ln_l, slope] = self.flat_end;
        let x = s * s;
        if x <= x_l {
            return self.flat(s);
        }
        let tangent = ln_l + slope * (x - x_l);
        let u = (x - x_l) / FLAT_END_BLEND;
        if u >= 1.0 {
            return tangent.exp();
        }
        let step = u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
        ((1.0 - step) * self.flat(s).ln() + step * tangent).exp()
    }

    /// `chi_flat` at `s = sqrt(x)`: the bonded hemisphere (the module docs, Flat).
    fn flat(&self, s: f64) -> f64 {
        let x = s * s;
        let w = 1.0 - x;
        let n = w + x * x / 3.0;
        let sf = 1.0 - self.d * x + self.c * s + self.e * x * x;
        n * sf / (w * w + self.b2 * x * x)
    }

    /// `(chi_flat, chi)` of the plane at `s = sqrt(x)`: the flat hemisphere, and with a core its
    /// layer excess added.
    fn plane_chi(&self, s: f64) -> (f64, f64) {
        let flat = self.flat(s);
        let Some(core) = &self.core else {
            return (flat, flat);
        };
        let x = s * s;
        // The layer of depth t h under the patch of the core's radius, less the layer of depth
        // R under the flat hemisphere's patch that chi_flat already carries.
        let (a_flat, a_law) = self.radius.radii(s);
        // The small-patch widening: the layer sees the law's widening of the patch over the
        // flat one, but no more than the bonded layer's first order `(d1/3) a_H/(t h)` while
        // the patch is small against the skin (`w t1 / sqrt(w^2 + t1^2)`: odd in s, as the
        // patch is, so the table's slope at s = 0 is the form's).
        let wide = a_law / a_flat - 1.0;
        let first = core.widening * s;
        let norm = (wide * wide + first * first).sqrt();
        let a = if norm > 0.0 {
            a_flat * (1.0 + first * wide / norm)
        } else {
            a_flat
        };
        // Each confined over lengths beyond l = depth sqrt(kappa/mu): E = eps (a_H/t)^2 for
        // the skin (the radius's E), eps (a_H/R)^2 = eps x for the hemisphere.
        let conf = core.eps * x;
        let series = core.layer(a * core.inv_tau_h, conf * core.inv_tau2)
            - core.layer(a_flat * core.inv_h, conf);
        // The thin-layer floor: at least Matthewson's thin bonded layer, `L = chi_thin - 1`,
        // joined by a p-norm `(X^p + L^p)^(1/p)` written so that it keeps X's sign (s < 0 only
        // in the slope stencil at s = 0, where L vanishes as |s|^3).
        let thin = core.thin.excess(x);
        let excess = if thin > 0.0 && series != 0.0 {
            series * (1.0 + (thin / series).powf(THIN_POWER)).powf(1.0 / THIN_POWER)
        } else {
            series
        };
        let squeeze = x * core.inv_tau;
        let thinning = 1.0 + core.thinning * x + core.confined * confined(squeeze);
        let law = flat + excess * thinning * (-core.k * (flat - 1.0)).exp();
        let Some(sh) = &core.shell else {
            return (flat, law);
        };
        // The thin-skin form: the exact shell on its core less the hemisphere's own first order
        // `1 + c sqrt(x)` (chi_flat's; odd in s, as the shell's excess is, for the slope stencil
        // at s = 0), the squeeze and coupling on top.
        let excess = sh.shell.chi(s * core.inv_tau) - (1.0 + self.c * s);
        // The squeezed film (session 29): the gap's lubrication stiffness `h^-3` over the
        // patch, weighted by the thinned film's flow share (even in s).
        let film = sh.film
            * flow_share(sh.inv_l * s / (1.0 - squeeze))
            * (squeezed_film(squeeze, sh.bend) - 1.0);
        let thinning = 1.0 + sh.thinning * x + sh.confined * confined(squeeze) + film;
        let shell = flat + excess * thinning * (-sh.k * (flat - 1.0)).exp();
        (flat, sh.weight * shell + (1.0 - sh.weight) * law)
    }

    /// `(chi, d chi/ds)` at `s`: the slope by the 5-point central difference with step
    /// `1e-4` in `s` (truncation and rounding below 1e-11 on the forms' scales, the smallest
    /// `0.35 t/R` in `s`; the unit test checks the table against the form), or within `2e-4` of
    /// the table's end `s_end` by the 5-point backward difference (truncation and rounding below
    /// 1e-10): the form is the law only up to its `x_max`, and past it the thin-skin form's shell
    /// table is held (session 28: at t/R 0.05 its u range ends at the plane's `x_max`, where a
    /// central stencil put the last knot's slope 1e-3 off).
    fn knot(&self, s: f64, s_end: f64) -> (f64, f64) {
        const STEP: f64 = 1e-4;
        let f = |k: f64| self.chi(s + k * STEP);
        let slope = if s + 2.0 * STEP <= s_end {
            (8.0 * (f(1.0) - f(-1.0)) - (f(2.0) - f(-2.0))) / (12.0 * STEP)
        } else {
            (25.0 * f(0.0) - 48.0 * f(-1.0) + 36.0 * f(-2.0) - 16.0 * f(-3.0) + 3.0 * f(-4.0))
                / (12.0 * STEP)
        };
        (self.chi(s), slope)
    }
}

/// The calibrated level of one backed construction at one Poisson ratio.
#[derive(Debug, Clone)]
pub(crate) struct Backed {
    /// `chi` tabulated at construction from the form.
    table: Arc<ChiTable>,
    /// The form itself (the unit test checks the table against it; boxed, so that `auto`'s
    /// candidates stay small in test builds too).
    #[cfg(test)]
    form: Box<ChiForm>,
    radius: RadiusForm,
    /// The reported radius below t/R `RADIUS_FADE` (a core only), `None` above.
    thin_radius: Option<Arc<ThinRadius>>,
    /// Shape: `eps`.
    eps: f64,
    /// Shape: `tau = t/R` (core), 0 for flat.
    tau: f64,
    x_max: f64,
    /// The plane's compression whose patch (radius, pressure shape) this law's `x` makes:
    /// `rho` on a curved counterpart (`crate::core_map`), 1 on a plane.
    x_patch: f64,
}

/// `x_max` of a flat-backed hemisphere at `nu`: where the FE stops.
fn flat_x_max(nu: f64) -> f64 {
    const KNOTS: [(f64, f64); 3] = [(0.3, 0.53), (0.4, 0.46), (0.48, 0.44)];
    if nu <= KNOTS[0].0 {
        return KNOTS[0].1;
    }
    for w in KNOTS.windows(2) {
        let ((n0, x0), (n1, x1)) = (w[0], w[1]);
        if nu <= n1 {
            return x0 + (x1 - x0) * (nu - n0) / (n1 - n0);
        }
    }
    KNOTS[2].1
}

impl Backed {
    /// `backing` is `Flat` or `Core` (with `tau = t/R` in (0, 1)), `0.3 <= nu <= 0.5`.
    pub(crate) fn try_new(backing: Backing, tau: Option<f64>, nu: f64) -> Result<Self> {
        Self::try_new_on(backing, tau, nu, None)
    }

    /// [`Backed::try_new`] on a curved counterpart (a core only, `crate::core_map`): the plane
    /// form at the compression `rho_H x` that makes the same patch, times the skin's squeeze
    /// beyond it (`None`: the plane).
    pub(crate) fn try_new_on(
        backing: Backing,
        tau: Option<f64>,
        nu: f64,
        on: Option<&CoreOnCounterpart>,
    ) -> Result<Self> {
        Self::try_new_capped(backing, tau, nu, on, 1.0)
    }

    /// [`Backed::try_new_on`] with the compressible cap (the denominator's `b^2 eps x^2`)
    /// scaled by `cap` in (0, 1]: for the flat pad on a curved counterpart the area it presses
    /// over the plane's, `rho_H` (`crate::cap_map`); 1 on a plane.
    pub(crate) fn try_new_capped(
        backing: Backing,
        tau: Option<f64>,
        nu: f64,
        on: Option<&CoreOnCounterpart>,
        cap: f64,
    ) -> Result<Self> {
        if !(0.3..=0.5).contains(&nu) {
            return Err(Error::IncompatibleLevel {
                level: LevelKind::Calibrated,
                nu,
                reason: "the calibrated level of a backed fingertip is fitted and validated for 0.3 <= nu <= 0.5 (below, its form is not monotone at nu = 0); use a `tabulated` curve of your fingertip",
            });
        }
        let eps = 3.0 * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
        let [c0, c1, e0, e1, b, d] = FLAT;
        let [q0, q1, _] = RADIUS;
        let [s0, _, _, k_thick] = RADIUS_CORE;
        let tau = match backing {
            Backing::Core { .. } => tau,
            _ => None,
        };
        let (radius, core, x_max) = match tau {
            Some(tau) if !(MIN_CORE_THICKNESS_RATIO..1.0).contains(&tau) => {
                return Err(Error::InvalidParameter {
                    field: "thickness_ratio",
                    value: tau,
                    range: "in [0.05, 1) for the calibrated level of a `core` fingertip (t/R, MIN_CORE_THICKNESS_RATIO: where its form is validated; a thinner skin needs a `tabulated` curve)",
                });
            }
            Some(tau) => {
                let rc = 1.0 - tau;
                let radius = RadiusForm {
                    eps4: 0.25 * eps,
                    rad_x: q0 + q1 * eps,
                    rad_core: s0 * rc * rc,
                    rad_thick: k_thick / rc,
                    inv_tau: 1.0 / tau,
                };
                let [ce0, l0, l1, k0, k1, cm, lc] = CORE;
                // The skin's mean depth over r <= 2t over the core's sphere, over t.
                let h = 1.0 + tau * tau / rc;
                // Dimitriadis' bonded-layer series to first order: chi = 1 + d1 a/h + ...
                let d1 = 2.0 * (1.2876 - 1.4678 * nu + 1.3442 * nu * nu)
                    / ((1.0 - nu) * std::f64::consts::PI);
                let core = CoreForce {
                    d1,
                    e: ce0 * (-cm * eps).exp(),
                    eps,
                    inv_tau2: 1.0 / (tau * tau),
                    inv_h: 1.0 / h,
                    inv_tau_h: 1.0 / (tau * h),
                    thinning: (l0 + l1 * eps) / tau,
                    inv_tau: 1.0 / tau,
                    confined: lc * eps / (1.0 + 4.0 * eps / 3.0) + CORE_DEVIATORIC,
                    k: k0 + k1 * eps,
                    widening: d1 / (3.0 * tau * h),
                    thin: ThinLayer::new(tau, nu),
                    shell: {
                        let z = (tau / SHELL_FADE).min(1.0);
                        let weight = 1.0 - z * z * (3.0 - 2.0 * z);
                        let [l0, l1, k0, k1, lc, cf] = SHELL;
                        (weight > 0.0).then(|| ShellForce {
                            shell: Shell::new(tau, nu, eps),
                            weight,
                            thinning: (l0 + l1 * eps) / tau,
                            confined: lc * eps / (1.0 + 4.0 * eps / 3.0),
                            film: cf,
                            inv_l: (3.0 * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu)))
                                .max(0.0)
                                .sqrt()
                                / tau,
                            bend: 2.0 / rc,
                            k: k0 + k1 * eps,
                        })
                    },
                };
                (
                    radius,
                    Some(core),
                    match on {
                        Some(on) => on.x_max(flat_x_max(nu), CORE_SQUEEZE, tau),
                        None => flat_x_max(nu).min(CORE_SQUEEZE * tau),
                    },
                )
            }
            None => {
                let radius = RadiusForm {
                    eps4: 0.25 * eps,
                    rad_x: q0 + q1 * eps,
                    rad_core: 0.0,
                    rad_thick: 0.0,
                    inv_tau: 0.0,
                };
                (radius, None, flat_x_max(nu))
            }
        };
        let form = ChiForm {
            c: c0 + c1 * eps,
            d,
            e: e0 + e1 * eps,
            b2: cap * b * b * eps,
            core,
            radius,
            x_plane: on.map_or(1.0, |on| on.patch),
            squeeze: on.map(|on| on.squeeze(tau.unwrap_or(1.0), eps)),
            flat_end: [f64::INFINITY, 0.0, 0.0],
        };
        let form = if form.squeeze.is_some() {
            // chi_flat's range and its log-slope there (5-point stencil in x, step 1e-4: the
            // form is analytic there, truncation below 1e-12).
            let x_l = flat_x_max(nu);
            let ln = |x: f64| form.flat(x.sqrt()).ln();
            const STEP: f64 = 1e-4;
            let slope = (8.0 * (ln(x_l + STEP) - ln(x_l - STEP))
                - (ln(x_l + 2.0 * STEP) - ln(x_l - 2.0 * STEP)))
                / (12.0 * STEP);
            ChiForm {
                flat_end: [x_l, ln(x_l), slope],
                ..form
            }
        } else {
            form
        };
        Ok(Self {
            table: Arc::new(ChiTable::new(
                x_max,
                match (&form.core, &form.squeeze) {
                    (Some(_), Some(_)) => CORE_ON_CELLS,
                    (Some(_), None) => CORE_CELLS,
                    _ => FLAT_CELLS,
                },
                |s| form.knot(s, x_max.sqrt()),
            )),
            #[cfg(test)]
            form: Box::new(form),
            radius,
            thin_radius: tau.and_then(|tau| {
                let z = tau / RADIUS_FADE;
                (z < 1.0).then(|| {
                    Arc::new(ThinRadius {
                        layer: LayerRadius::new(eps),
                        weight: 1.0 - z * z * (3.0 - 2.0 * z),
                        inv_tau: 1.0 / tau,
                    })
                })
            }),
            eps,
            tau: tau.unwrap_or(0.0),
            x_max,
            x_patch: on.map_or(1.0, |on| on.rho),
        })
    }
}

impl NormalisedLaw for Backed {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        // f = (4/3) chi x sqrt(x), df/dx = (4/3) sqrt(x) (3/2 chi + x chi').
        let s = x.sqrt();
        let (chi, x_chi) = self.table.chi(s);
        let h = 4.0 / 3.0 * s;
        (h * chi * x, h * (1.5 * chi + x_chi))
    }

    fn energy(&self, x: f64) -> f64 {
        self.table.energy(x)
    }

    fn radius(&self, x: f64) -> f64 {
        let s = (self.x_patch * x).sqrt();
        let form = self.radius.radii(s).1;
        match &self.thin_radius {
            // a_H = sqrt(x) R, u = a_H/t.
            Some(thin) => {
                thin.weight * s * thin.layer.ratio(s * thin.inv_tau) + (1.0 - thin.weight) * form
            }
            None => form,
        }
    }

    fn x_max(&self) -> f64 {
        self.x_max
    }

    fn pressure_shape(&self, x: f64) -> f64 {
        self.pressure_profile(x).0
    }

    fn pressure_taper(&self, x: f64) -> f64 {
        self.pressure_profile(x).1
    }

    /// `(m, b)` with the core's layer share computed once (it costs four `ln` and an `exp`).
    fn pressure_profile(&self, x_true: f64) -> (f64, f64) {
        let x = self.x_patch * x_true;
        let [a0, a1, a2, a3] = SHAPE;
        let flat = 0.5 + (a0 + a1 * self.eps) * x.sqrt() + (a2 + a3 * x) * x;
        if self.tau == 0.0 {
            return (flat, 0.0);
        }
        // m leaves flat's only at the thin layer's end: (1 - rho^2)^1 (1 - rho^2) at v = 1.
        let v = self.layer_share(x);
        (flat + (1.0 - flat) * v.powi(20), -v)
    }
}

impl Backed {
    /// Core: `v` in [0, 1], how much of a thin bonded layer the skin under the patch is (the
    /// module docs, Pressure); 0 at x = 0, 1 once the core's pole would reach the plane.
    fn layer_share(&self, x: f64) -> f64 {
        if x <= 0.0 {
            return 0.0;
        }
        let s = x / self.tau;
        if s >= 1.0 {
            return 1.0;
        }
        let [k, n, cb] = SHAPE_CORE;
        // w = u (rc^k / (cb (1 - s)))^n, u = sqrt(x) / tau: ln w = ln u + n (k ln rc - ln cb -
        // ln(1 - s)).
        let ln_w = 0.5 * x.ln() - self.tau.ln()
            + n * (k * (1.0 - self.tau).ln() - cb.ln() - (1.0 - s).ln());
        let w = ln_w.exp();
        if w.is_infinite() { 1.0 } else { w / (w + 1.0) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plane core's thin-skin form against Python's (`tools/calibration/gen_shell_table_rs.py`
    /// dumps the law, `try_thin_skin_s25.form("K")`, and the thin-skin form,
    /// `try_deep_squeeze_s29.form("SFF")` since session 29, at nu 0.3-0.5 x t/R 0.05-0.3 x 12 x in (0, x_max]). The port is `w shell + (1 - w) law`:
    /// its shell part, blended with Python's own law value, must be Python's form to 1e-6; the
    /// law part is today's law, whose Python and Rust differ by themselves (printed: up to
    /// 3.7e-6 at nu 0.499 and 4.7e-3 at nu 0.5, where Python's thin-layer floor clips nu to
    /// 0.4999 and Rust's is exact).
    #[test]
    fn thin_skin_form_follows_python() {
        let mut worst = [(0.0f64, [0.0; 3]); 3];
        for [nu, tau, x, _, chi_law, chi_form] in super::super::shell::reference() {
            let law = Backed::try_new(Backing::Core { thickness: tau }, Some(tau), nu)
                .expect("core builds");
            let form = &*law.form;
            let core = form.core.as_ref().expect("a core");
            let w = core.shell.as_ref().map_or(0.0, |sh| sh.weight);
            let mut shell_only = form.clone();
            let mut law_only = form.clone();
            if let Some(sh) = shell_only.core.as_mut().and_then(|c| c.shell.as_mut()) {
                sh.weight = 1.0;
            }
            law_only.core.as_mut().expect("a core").shell = None;
            let s = x.sqrt();
            let port = if w > 0.0 {
                w * shell_only.plane_chi(s).1 + (1.0 - w) * chi_law
            } else {
                chi_law
            };
            for (k, (rust, python)) in [
                (port, chi_form),
                (law_only.plane_chi(s).1, chi_law),
                (form.plane_chi(s).1, chi_form),
            ]
            .into_iter()
            .enumerate()
            {
                let r = (rust / python - 1.0).abs();
                if r > worst[k].0 {
                    worst[k] = (r, [nu, tau, x]);
                }
            }
        }
        eprintln!(
            "against Python, largest relative difference (at nu, t/R, x): the port {:?}; \
             today's law (Rust's against Python's) {:?}; the whole form {:?}",
            worst[0], worst[1], worst[2]
        );
        assert!(worst[0].0 < 1e-6, "{worst:?}");
    }

    /// The reported radius of a thin skin (session 30) against Python's
    /// (`tools/calibration/gen_layer_radius_rs.py`: `try_thin_skin_radius_s30.radius(.., "F0.2")`
    /// and the radius form, `fit_core.radius`): the form itself (which the force's layer term
    /// takes) to 1e-9, the reported radius to 1e-6; at t/R 0.2 the two are the same.
    #[test]
    fn thin_skin_radius_follows_python() {
        let mut worst = [(0.0f64, [0.0; 3]); 2];
        for [nu, tau, x, _, a_law, a_form] in super::super::shell::radius_reference() {
            let law = Backed::try_new(Backing::Core { thickness: tau }, Some(tau), nu)
                .expect("core builds");
            let own = law.radius.radii(x.sqrt()).1;
            let reported = law.radius(x);
            if tau >= RADIUS_FADE {
                assert!(law.thin_radius.is_none() && reported == own, "t/R {tau}");
            }
            for (k, (rust, python)) in [(own, a_law), (reported, a_form)].into_iter().enumerate() {
                let r = (rust / python - 1.0).abs();
                if r > worst[k].0 {
                    worst[k] = (r, [nu, tau, x]);
                }
            }
        }
        eprintln!(
            "against Python, largest relative difference (at nu, t/R, x): the radius form {:?}, \
             the reported radius {:?}",
            worst[0], worst[1]
        );
        assert!(worst[0].0 < 1e-9, "{worst:?}");
        assert!(worst[1].0 < 1e-6, "{worst:?}");
    }

    /// The table against the form: force, stiffness and energy over the validity range, for
    /// flat and across the thicknesses and Poisson ratios the level accepts.
    #[test]
    fn table_follows_the_form() {
        let mut worst = [0.0f64; 3];
        let mut worst_on = [0.0f64; 3];
        let mut worst_thin = [0.0f64; 3];
        for nu in [0.3, 0.37, 0.45, 0.49, 0.4999, 0.5] {
            let mut cases = vec![Backed::try_new(Backing::Flat, None, nu).expect("flat builds")];
            for tau in [0.05, 0.07, 0.12, 0.2, 0.33, 0.5, 0.71, 0.8, 0.95] {
                let core = Backed::try_new(Backing::Core { thickness: tau }, Some(tau), nu);
                cases.push(core.expect("core builds"));
                // On balls of R/10, R and 3R, and a bowl of 2R (`core_map`).
                // wrap = rho_H/K^2 on a ball of K R (0.5 on the bowl: the term is off there).
                for (patch, rho, wrap) in [
                    (0.091, 0.2, 9.09),
                    (0.5, 0.556, 0.5),
                    (0.75, 0.789, 0.0833),
                    (2.0, 1.6, 0.5),
                ] {
                    let on = CoreOnCounterpart {
                        patch,
                        rho,
                        wrap,
                        ridge: false,
                    };
                    let core = Backed::try_new_on(
                        Backing::Core { thickness: tau },
                        Some(tau),
                        nu,
                        Some(&on),
                    );
                    cases.push(core.expect("core on a counterpart builds"));
                }
            }
            for law in cases {
                let form = &*law.form;
                // A core on a counterpart: its squeeze excess continues chi_flat past its range
                // (`ChiForm::flat_continued`, session 17), whose blend the cells follow less
                // closely in stiffness (6.5e-5 at its worst, a 3R ball at nu 0.3 and the bowl of
                // 2R near their ends); its own bounds, below. A thin skin (t/R < SHELL_FADE,
                // session 28's shell form, plane or counterpart): its own bounds too, below.
                let thin = form.core.as_ref().is_some_and(|c| c.shell.is_some());
                let worst = if thin {
                    &mut worst_thin
                } else if form.squeeze.is_some() {
                    &mut worst_on
                } else {
                    &mut worst
                };
                // f = (4/3) chi s^3, df/dx = (4/3) s (3/2 chi + (s/2) d chi/ds).
                let exact = |x: f64| {
                    let s = x.sqrt();
                    let (chi, slope) = form.knot(s, law.x_max.sqrt());
                    let h = 4.0 / 3.0 * s;
                    (h * chi * x, h * (1.5 * chi + 0.5 * s * slope))
                };
                // A thin skin also on 997 points uniform in sqrt(x) (the shell's kink at u = 0.1
                // is at x = 0.01 (t/R)^2, below the first uniform x on a plane).
                let xs = (1..=997).map(|k| law.x_max * f64::from(k) / 997.0);
                let extra = (1..=997)
                    .filter(|_| thin)
                    .map(|k| law.x_max * (f64::from(k) / 997.0).powi(2));
                for x in xs.chain(extra) {
                    let (a, b) = (law.force_stiffness(x), exact(x));
                    worst[0] = worst[0].max((a.0 / b.0 - 1.0).abs());
                    worst[1] = worst[1].max((a.1 / b.1 - 1.0).abs());
                    // The form's energy by 64 panels of 8-point Gauss-Legendre in sqrt(x).
                    let e = integrate(0.0, x.sqrt(), 64, |u| 8.0 / 3.0 * form.chi(u) * u.powi(4));
                    worst[2] = worst[2].max((law.energy(x) / e - 1.0).abs());
                }
            }
        }
        eprintln!("table vs form, largest relative difference: force, stiffness, energy {worst:?}");
        eprintln!("the same on a counterpart (a core): {worst_on:?}");
        eprintln!("the same for a thin skin (t/R < 0.3, plane and counterpart): {worst_thin:?}");
        assert!(
            worst[0] < 1e-7 && worst[1] < 1e-5 && worst[2] < 1e-8,
            "{worst:?}"
        );
        assert!(
            worst_on[0] < 3e-7 && worst_on[1] < 1e-4 && worst_on[2] < 1e-8,
            "{worst_on:?}"
        );
        // The thin-skin form is C0 only in u = a_H/t, as its Python reference is
        // (`try_shell_table_s28.G_of`): each t/R node's G is continued linearly to 0 below u 0.1
        // and held past its last u, so chi's slope jumps there (at u 0.1 on every skin, at the
        // thicker nodes' ends u 1.26-2.83 where t/R is between nodes). The table, C1, rounds
        // each kink over a cell: measured 5.9e-6 in force, 9.2e-4 in stiffness, 2.9e-6 in energy
        // (near u 0.1 at t/R 0.05-0.2, u 2.83 at t/R 0.07: a scratch scan in sqrt(x) found
        // 1.1e-3 in stiffness there); elsewhere it follows as the law's.
        assert!(
            worst_thin[0] < 1e-5 && worst_thin[1] < 2e-3 && worst_thin[2] < 5e-6,
            "{worst_thin:?}"
        );
    }
}
