"""The rigid counterpart a fingertip is pressed on: its master mesh, its signed gap, its faceting.

  plane    : the half-space y <= 0 (today's model).
  ball     : a ball of radius R2 = k R, centre (0, -R2, 0), touching the fingertip's pole at the
             origin (axisymmetric, or 3D for the check of the 3D pipeline).
  cylinder : a cylinder of radius R2 = k R, axis along z through (0, -R2, 0) (3D only).
  edge     : a right-angle edge along z, its faces at 45 degrees to the contact plane, pressed
             along its bisector (3D only). Its ridge is rounded with a radius r_e = k R
             (EDGE_RIDGE by default, 0.01 R), centre (0, -r_e), so that first contact is at the
             origin: CalculiX's face-to-face contact pairs a slave face with a master face only if
             their normals are within 45.6 degrees of opposite (slavintpoints.f: anglesm < -0.7),
             and a sharp 90-degree ridge meets the fingertip's pole at exactly 45 degrees: no
             contact is ever made (measured: a plane tilted by 44 degrees is found, by 45 or 46
             not). The flanks are y = -|x| + r_e (sqrt 2 - 1).

The counterpart is a set of fixed 3D elements (C3D8, C3D6 at the ball's pole) whose outer faces
are the contact's master surface: CalculiX has no analytical rigid surfaces, and it forbids
axisymmetric master faces with a node on the axis. Every master node lies exactly on the curved
surface; the flat faces between them sit inside it by at most the faceting sag
R2 (1 - cos(d_alpha / 2)) (meridian or circumferential direction; a straight generator has
none). The facet size is chosen from the sag: `SAG_MAX` below.

Axisymmetric models (CalculiX expands CAX elements into a +-1 degree wedge about the y axis): the
ball's master is a wedge strip of the ball's surface over +-2 degrees, three node rows (-2, 0,
+2 degrees), from the pole (wedge elements C3D6 there) to `alpha_max` along the meridian. The
circumferential facets sit inside the sphere by r (1 - cos 1 deg) x slope, i.e. (1.5e-4 r^2 / R2)
at radius r: at the contact edge that is below 3e-4 of delta for every R2 (a^2 ~ 2 R_eff delta).

Units mm, R = 1 mm.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

R = 1.0
KINDS = ("plane", "ball", "cylinder", "edge")
AXISYMMETRIC = ("plane", "ball")
# largest faceting sag of a curved master [mm]: 1e-3 of the compression at x = 0.01 (delta =
# 0.01 mm): a uniform shift of the surface by that much changes the force by <= 1.5e-3 there
# (F ~ delta^1.5) and by 10x less at x = 0.1
SAG_MAX = 1e-5
# the edge's ridge radius over R (see the module's doc)
EDGE_RIDGE = 0.01
# how far the master reaches from the first contact point [mm]: beyond the largest contact
# radius of any run (a / R <= 1.2 at x = 0.7 on a plane)
REACH = 1.6 * R


@dataclass(frozen=True)
class Counterpart:
    kind: str = "plane"
    k: float = 0.0  # R2 / R (ball, cylinder); 0 for plane and edge
    sag_max: float = SAG_MAX  # largest faceting sag [mm] (the faceting check uses a finer one)

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"counterpart kind {self.kind!r}, expected one of {KINDS}")
        if self.kind in ("ball", "cylinder") and not (self.k > 0 and math.isfinite(self.k)):
            raise ValueError(f"{self.kind}: k = R2/R must be finite and > 0, got {self.k}")
        if self.kind == "edge" and self.k == 0.0:
            object.__setattr__(self, "k", EDGE_RIDGE)

    @property
    def r2(self) -> float:
        return self.k * R

    @property
    def tag(self) -> str:
        """The counterpart's part of a case name: '' for the plane (names as before), 'ball_k2_',
        'cylinder_k1_', 'edge_'."""
        if self.kind == "plane":
            return ""
        if self.kind == "edge":
            return "edge_" if self.k == EDGE_RIDGE else f"edge_r{self.k:g}_"
        s = f"{self.kind}_k{self.k:g}_"
        if self.sag_max != SAG_MAX:
            s += f"sag{self.sag_max:g}_"
        return s

    def describe(self) -> str:
        return {"plane": "a rigid plane",
                "ball": f"a rigid ball of radius R2 = {self.k:g} R",
                "cylinder": f"a rigid cylinder of radius R2 = {self.k:g} R (axis along z, in the "
                            f"contact plane)",
                "edge": f"a rigid right-angle edge (faces at 45 degrees, along z; ridge rounded "
                        f"with radius {self.k:g} R), pressed along its bisector"}[self.kind]

    def gap(self, P):
        """Signed distance [mm] of points P (n, 2) axisymmetric (r, y) or (n, 3) (x, y, z) to the
        counterpart's true (unfaceted) surface: > 0 outside, <= 0 in contact or penetrating."""
        P = np.asarray(P, dtype=float)
        y = P[:, 1]
        if self.kind == "plane":
            return y
        if self.kind == "ball":
            rr = P[:, 0] ** 2 + (P[:, 2] ** 2 if P.shape[1] == 3 else 0.0)
            return np.sqrt(rr + (y + self.r2) ** 2) - self.r2
        if self.kind == "cylinder":
            return np.hypot(P[:, 0], y + self.r2) - self.r2
        # edge: the ridge's arc (centre (0, -r_e)) within 45 degrees of the bisector, the flanks
        # beyond
        re_ = self.r2
        ax = np.abs(P[:, 0])
        on_arc = ax <= (y + re_)  # angle from the centre below 45 degrees
        d_arc = np.hypot(ax, y + re_) - re_
        d_flank = (ax + y - re_ * (math.sqrt(2) - 1)) / math.sqrt(2)
        return np.where(on_arc, d_arc, d_flank)

    def alpha_max(self) -> float:
        """Angle about the ball's or cylinder's centre [rad] the master covers from the first
        contact point: horizontal reach REACH, or 120 degrees on a counterpart smaller than
        that (a fingertip wraps around a small ball at large x)."""
        if self.r2 > REACH:
            return math.asin(REACH / self.r2)
        return 2 * math.pi / 3

    def facet_angle(self) -> float:
        """Angle one facet spans [rad], from sag_max: R2 (1 - cos(d/2)) <= sag_max (the edge: its
        ridge arc, 45 degrees each side)."""
        d = 2 * math.acos(1 - self.sag_max / self.r2)
        amax = math.pi / 4 if self.kind == "edge" else self.alpha_max()
        n = math.ceil(amax / d)
        return amax / n

    def sag(self) -> float:
        """Largest faceting sag of the master [mm] (0 for the plane; the edge's ridge arc)."""
        if self.kind == "plane":
            return 0.0
        return self.r2 * (1 - math.cos(self.facet_angle() / 2))

    # ---- master meshes -------------------------------------------------------------------
    def master_axisym(self) -> "Master":
        if self.kind == "plane":
            return _slab_plane(x0=-0.1, x1=2.6, nx=54, z0=-0.1, z1=0.1, nz=1)
        if self.kind == "ball":
            return _ball_wedge(self.r2, self.alpha_max(), self.facet_angle(), math.radians(2.0))
        raise ValueError(f"{self.kind} has no axisymmetric model (3D only)")

    def master_3d(self) -> "Master":
        """The master of a quarter model (x >= 0, z >= 0), reaching a little past both symmetry
        planes so that the fingertip's nodes on them project inside it."""
        if self.kind == "plane":
            return _slab((0, 0, 0), (1, 0, 0), (0, 1, 0), (-0.1, 2.0, 8), (-0.1, 2.0, 8))
        zr = (-0.1, 2.0, 8)
        da = self.facet_angle()
        if self.kind == "edge":
            # the ridge's arc from 2 facets before its top (x < 0: the fingertip's nodes on x = 0
            # meet the top from both sides) to 45 degrees, then the flank to x = 2.0 in 16 facets
            re_ = self.r2
            n = int(round(math.pi / 4 / da))
            arc = [(re_ * math.sin(a), -re_ + re_ * math.cos(a)) for a in da * np.arange(-2, n + 1)]
            x0, y0 = arc[-1]
            flank = [(x0 + t, y0 - t) for t in np.linspace(0, 2.0 - x0, 17)[1:]]
            return _extrude(arc + flank, zr, 0.1, down=True, about=
                            f"ridge arc radius {re_:g} mm in {n} facets of "
                            f"{math.degrees(da):.3g} deg, flank in 16")
        if self.kind == "cylinder":
            na = int(round(self.alpha_max() / da))
            r2 = self.r2
            prof = [(r2 * math.sin(a), -r2 + r2 * math.cos(a)) for a in da * np.arange(-2, na + 1)]
            return _extrude(prof, zr, 0.2 * r2,
                            f"{na + 2} facets of {math.degrees(da):.4g} deg around its axis to "
                            f"{math.degrees(self.alpha_max()):.4g} deg")
        raise ValueError(f"{self.kind}: no 3D master (a 3D ball is not part of the campaign)")


@dataclass
class Master:
    """Fixed elements of the counterpart: nodes (n, 3), elements as (type, 0-based node tuple),
    and the master faces as (element index, face number)."""
    nodes: np.ndarray
    elements: list
    faces: list
    about: str


def _slab_plane(x0, x1, nx, z0, z1, nz, depth=0.1):
    """A slab of C3D8 under y = 0 over [x0, x1] x [z0, z1]; master = top faces (S2)."""
    xs, zs = np.linspace(x0, x1, nx + 1), np.linspace(z0, z1, nz + 1)
    idx = {}
    nodes = []
    for i, x in enumerate(xs):  # node order as the slab of the first campaigns (same decks)
        for L, y in enumerate((-depth, 0.0)):
            for j, z in enumerate(zs):
                idx[(i, j, L)] = len(nodes)
                nodes.append((x, y, z))
    el = []
    for i in range(nx):
        for j in range(nz):
            q = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)]
            el.append(("C3D8", tuple(idx[(a, b, 0)] for a, b in q) + tuple(idx[(a, b, 1)] for a, b in q)))
    return Master(np.array(nodes), el, [(e, 2) for e in range(len(el))],
                  f"fixed C3D8 slab, {len(el)} elements, top faces y = 0")


def _slab(origin, eu, normal, urange, zrange, depth=0.1):
    """A slab of C3D8 whose top face is the plane through `origin` with unit `normal`, spanning
    u in urange along `eu` and z in zrange (each (lo, hi, n)); master = top faces (S2)."""
    o, eu, en = (np.asarray(v, float) for v in (origin, eu, normal))
    us = np.linspace(*urange[:2], urange[2] + 1)
    zs = np.linspace(*zrange[:2], zrange[2] + 1)
    idx, nodes = {}, []
    for i, u in enumerate(us):
        for j, z in enumerate(zs):
            for L, off in enumerate((-depth, 0.0)):
                idx[(i, j, L)] = len(nodes)
                nodes.append(tuple(o + u * eu + off * en + (0, 0, z)))
    el = []
    for i in range(len(us) - 1):
        for j in range(len(zs) - 1):
            q = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)]
            el.append(("C3D8", tuple(idx[(a, b, 0)] for a, b in q) + tuple(idx[(a, b, 1)] for a, b in q)))
    return Master(np.array(nodes), el, [(e, 2) for e in range(len(el))],
                  f"fixed C3D8 slab, {len(el)} elements")


def _extrude(profile, zrange, depth, about, down=False):
    """A strip of C3D8 whose top faces are the polyline `profile` [(x, y), x increasing, the
    body above it] extruded along z over zrange = (lo, hi, n); the inner layer sits `depth`
    below, along the vertex normals (or straight down, -y, with `down`: a ridge radius below
    `depth` would turn normal offsets inside out). Master = top faces (S2)."""
    P = np.asarray(profile, float)
    t = np.gradient(P, axis=0)
    nrm = np.stack([-t[:, 1], t[:, 0]], axis=1)
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    if down:
        nrm[:] = (0.0, 1.0)
    zs = np.linspace(*zrange[:2], zrange[2] + 1)
    idx, nodes = {}, []
    for i, (p, q) in enumerate(zip(P, nrm)):
        for j, z in enumerate(zs):
            for L, off in enumerate((-depth, 0.0)):
                idx[(i, j, L)] = len(nodes)
                nodes.append((p[0] + off * q[0], p[1] + off * q[1], z))
    el = []
    for i in range(len(P) - 1):
        for j in range(len(zs) - 1):
            q = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)]
            el.append(("C3D8", tuple(idx[(a, b, 0)] for a, b in q) + tuple(idx[(a, b, 1)] for a, b in q)))
    return Master(np.array(nodes), el, [(e, 2) for e in range(len(el))],
                  f"fixed C3D8 strip: {about}; {len(zs) - 1} along z ({len(el)} elements)")


def _ball_wedge(r2, amax, da, phiw, depth_frac=0.2):
    """The ball's surface over a +-phiw wedge about the y axis, from the pole to amax, facets of
    da along the meridian, three rows (-phiw, 0, +phiw); C3D6 wedges at the pole, C3D8 beyond.
    Outer layer on the sphere, inner layer at radius (1 - depth_frac) R2."""
    na = int(round(amax / da))
    phis = (-phiw, 0.0, phiw)
    c = np.array([0.0, -r2, 0.0])
    nodes, idx = [], {}
    for L, rad in enumerate(((1 - depth_frac) * r2, r2)):
        idx[(0, 0, L)] = idx[(0, 1, L)] = idx[(0, 2, L)] = len(nodes)
        nodes.append(tuple(c + (0.0, rad, 0.0)))
        for i in range(1, na + 1):
            a = i * da
            for j, ph in enumerate(phis):
                rho = rad * math.sin(a)
                idx[(i, j, L)] = len(nodes)
                nodes.append((rho * math.cos(ph), c[1] + rad * math.cos(a), rho * math.sin(ph)))
    el = []
    for i in range(na):
        for j in range(2):
            q = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)]
            ids = [idx[(a, b, 0)] for a, b in q] + [idx[(a, b, 1)] for a, b in q]
            if i == 0:  # the pole: nodes 1 and 2 (and 5, 6) coincide -> a wedge
                el.append(("C3D6", (ids[0], ids[2], ids[3], ids[4], ids[6], ids[7])))
            else:
                el.append(("C3D8", tuple(ids)))
    faces = [(e, 2) for e in range(len(el))]  # S2: the outer face of both C3D8 and C3D6
    return Master(np.array(nodes), el, faces,
                  f"fixed wedge strip of the ball's surface, +-{math.degrees(phiw):g} deg, "
                  f"{na} facets of {math.degrees(da):.4g} deg along the meridian to "
                  f"{math.degrees(amax):.4g} deg ({len(el)} elements)")


def element_volumes(m: Master):
    """Signed volumes of the master's elements (positive = CalculiX's node order)."""
    out = []
    for typ, ids in m.elements:
        P = m.nodes[list(ids)]
        if typ == "C3D8":
            tets = [(0, 1, 3, 4), (1, 2, 3, 6), (1, 3, 4, 6), (3, 4, 6, 7), (1, 4, 5, 6)]
        else:
            tets = [(0, 1, 2, 3), (1, 2, 3, 4), (2, 3, 4, 5)]
        out.append(sum(np.dot(np.cross(P[b] - P[a], P[c] - P[a]), P[d] - P[a]) / 6
                       for a, b, c, d in tets))
    return np.array(out)
