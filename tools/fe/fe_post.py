"""Post-processing of one softgrip FE run (job.inp, job.dat, job.frd in a run directory).

Per output time point (step time = x = delta / R):
  force_N              -180 x total RF_y of the pushed node set NPUSH (CalculiX reports
                       axisymmetric reaction forces per 2-degree segment)
  contact_radius_mm    a_lin: curved-surface nodes in order from the pole, the last one on or inside
                       the counterpart (signed gap <= 0: the height above a plane, the distance
                       to a ball's surface), then linear interpolation of the signed gap to zero
                       towards the next node, reported as the deformed radius r there (the
                       patch's radius seen along the axis); resolved to about one surface node
  min_element_J        smallest element volume ratio (A r_centroid)_deformed / (A r_centroid)_ref
  V_over_V0            body volume ratio
  max_copen_over_delta largest penalty penetration / delta
  max_lift_mm          highest deformed curved-surface node above the pushed face's plane
                       (y - (R - delta)); > 0 means the free surface folds over the bonded edge
Pressure profiles: nodal CPRESS of the curved-surface nodes against the deformed radius, to a_lin.
"""
from __future__ import annotations

import json
import os
import re

import numpy as np

from fe_counterpart import Counterpart

R = 1.0
# nodes of the curved surface counted from the pole that are dropped from pressure profiles:
# the tied first face (pole, its midside node) and the two nodes beside it (spurious peaks)
N_DROP_PRESSURE = 4


def read_inp(path, element="CAX", dim=2):
    """Nodes of NBODY {number: (x, y[, z])} (the first `dim` coordinates), the connectivity of
    the `*ELEMENT` blocks whose type contains `element` (CAX: the axisymmetric body; C3D10: the
    3D one), every `*NSET` {name: [numbers]} and the contact penalty (None without one)."""
    X, E, sets, kpen, mode, cur = {}, [], {}, None, None, None
    for line in open(path):
        line = line.rstrip("\n")
        if line.startswith("*"):
            u = line.upper().replace(" ", "")
            mode = None
            if u.startswith("*NODE,NSET=NBODY"):
                mode = "n"
            elif u.startswith("*ELEMENT") and element in u:
                mode = "e"
            elif u.startswith("*NSET,NSET="):
                cur = u.split("=")[1]
                sets[cur] = []
                mode = "s"
            elif u.startswith("*SURFACEBEHAVIOR"):
                mode = "k"
            continue
        if mode == "n":
            p = line.split(",")
            X[int(p[0])] = tuple(float(v) for v in p[1:1 + dim])
        elif mode == "e":
            E.append([int(v) for v in line.split(",")][1:])
        elif mode == "s":
            sets[cur] += [int(v) for v in line.split(",") if v.strip()]
        elif mode == "k":
            kpen = float(line.split(",")[0])
            mode = None
    return X, E, sets, kpen


def read_dat_force(path, nset="NPUSH", scale=-180.0):
    """Total RF_y of `nset` per output time, times `scale` (axisymmetric: -180, the 2-degree
    segment to the whole ring, sign to a compressive force > 0; quarter model: -4)."""
    F = {}
    L = open(path).read().split("\n")
    pat = re.compile(rf"\s*total force \(fx,fy,fz\) for set {nset} and time\s+(\S+)")
    for i, line in enumerate(L):
        m = pat.match(line)
        if m:
            F[round(float(m.group(1)), 6)] = scale * float(L[i + 2].split()[1])
    return F


def read_frd(path, nodes, dim=2):
    """DISP (the first `dim` components: u_r, u_y; or u_x, u_y, u_z) of `nodes` and CONTACT
    (COPEN, CPRESS) per output time."""
    pos = {n: i for i, n in enumerate(nodes)}
    U, C = {}, {}
    t = blk = cur = None
    with open(path) as fh:
        for line in fh:
            if line.startswith("  100CL"):
                t = round(float(line[12:24]), 6)
            elif line.startswith(" -4"):
                blk = line.split()[1]
                if blk == "DISP":
                    cur = np.zeros((len(nodes), dim))
                elif blk == "CONTACT":
                    cur = np.zeros((len(nodes), 2))
            elif line.startswith(" -3"):
                if blk == "DISP":
                    U[t] = cur
                elif blk == "CONTACT":
                    C[t] = cur
                blk = None
            elif line.startswith(" -1") and blk in ("DISP", "CONTACT"):
                i = pos.get(int(line[3:13]))
                if i is None:
                    continue
                if blk == "DISP":
                    cur[i] = [float(line[13 + 12 * j:25 + 12 * j]) for j in range(dim)]
                else:  # COPEN, CSLIP1, CSLIP2, CPRESS, ...
                    cur[i] = (-float(line[13:25]), float(line[49:61]))
    return U, C


def edge_crossing(c, g):
    """Where a contact ends along a line of surface nodes ordered from the first contact point:
    c their deformed coordinate along the line, g their signed gap to the counterpart. Returns
    (a_lin, a_32): a_lin = from the last node with g <= 0, linear interpolation of g to zero
    towards the next node (inside the contact g is ~0, so a_lin sits at that node: resolved to
    one node spacing); a_32 = the crossing of g = C (s - a)^(3/2) through the first two nodes
    outside, the gap's shape at the edge of a smooth frictionless contact (Hertz), kept between
    the last node in and the first node out (a_lin where it does not apply)."""
    inside = np.where(g <= 0)[0]
    if len(inside) == 0 or inside.max() >= len(c) - 1:
        return np.nan, np.nan
    j = int(inside.max())
    a_lin = c[j] + (c[j + 1] - c[j]) * (0 - g[j]) / (g[j + 1] - g[j])
    a_32 = a_lin
    if j + 2 < len(c) and 0 < g[j + 1] < g[j + 2]:
        q = (g[j + 1] / g[j + 2]) ** (2 / 3)
        a = (c[j + 1] - q * c[j + 2]) / (1 - q)
        lo, hi = sorted((c[j], c[j + 1]))
        a_32 = float(min(max(a, lo), hi))
    return float(a_lin), a_32


def counterpart_of(rundir):
    """The run's counterpart, from its meta.json (runs made before counterparts: the plane)."""
    path = os.path.join(rundir, "meta.json")
    c = json.load(open(path))["case"] if os.path.exists(path) else {}
    if "facet_sag" in c:
        return Counterpart(c.get("counterpart", "plane"), c.get("k", 0.0), c["facet_sag"])
    return Counterpart(c.get("counterpart", "plane"), c.get("k", 0.0))


class Run:
    def __init__(self, rundir, job="job"):
        base = f"{rundir}/{job}"
        self.cp = counterpart_of(rundir)
        X, E, sets, self.kpen = read_inp(base + ".inp")
        self.ids = sorted(X)
        pos = {n: i for i, n in enumerate(self.ids)}
        self.X0 = np.array([X[n] for n in self.ids])
        arc = np.array(sets["NARC"])
        xa = np.array([X[n] for n in arc])
        o = np.argsort(np.arctan2(xa[:, 0], R - xa[:, 1]))
        self.arc = np.array([pos[n] for n in arc[o]])  # positions in X0, from the pole
        self.seq = np.array([[pos[e[i]] for i in (0, 4, 1, 5, 2, 6, 3, 7)] for e in E])
        self.V0 = self._vol(self.X0)
        self.F = read_dat_force(base + ".dat")
        self.U, self.C = read_frd(base + ".frd", self.ids)
        self.times = sorted(set(self.F) & set(self.U))

    def _vol(self, P):
        x, y = P[self.seq, 0], P[self.seq, 1]
        x1, y1 = np.roll(x, -1, 1), np.roll(y, -1, 1)
        cr = x * y1 - x1 * y
        return ((x + x1) * cr).sum(1) / 6.0  # = area * centroid radius (2 pi omitted)

    def row(self, t):
        u = self.U[t]
        P = self.X0 + u
        r, z = P[self.arc, 0], P[self.arc, 1]
        a, a32 = edge_crossing(r, self.cp.gap(P[self.arc]))
        V = self._vol(P)
        J = V / self.V0
        c = self.C.get(t)
        copen = float(c[self.arc, 0].max()) / t if c is not None else np.nan
        lift = float(z.max() - (R - t * R))
        return dict(x=t, F=self.F[t], a=a, a32=a32, minJ=float(J.min()), VV0=float(V.sum() / self.V0.sum()),
                    copen=copen, lift=lift)

    def pressure(self, t):
        """(r_deformed, CPRESS) of the curved-surface nodes inside the contact radius a_lin, from
        the pole outwards, closed by (a_lin, 0). CalculiX's nodal CPRESS is extrapolated from the
        face integration points and stays positive up to a face beyond the contact edge, so the
        profile is cut at a_lin (where the penalty pressure -K z crosses zero)."""
        c = self.C.get(t)
        if c is None:
            return None
        a = self.row(t)["a"]
        P = self.X0 + self.U[t]
        r = P[self.arc, 0]
        p = c[self.arc, 1]
        keep = (np.arange(len(r)) >= N_DROP_PRESSURE) & (r < a)
        return np.append(r[keep], a), np.append(p[keep], 0.0)
