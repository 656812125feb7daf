"""Mesh and CalculiX deck for softgrip's axisymmetric fingertip-flattening problem.

One generator, the geometry is a parameter:

  free : a full sphere between two plates, modelled as the hemisphere below its equator (a
         symmetry plane): flat face y = R gets u_y = -delta, u_r free.
  flat : a soft hemisphere whose flat face is bonded to a rigid backing: u = (0, -delta) there.
  core : a soft hemispherical shell between radii R - t and R, bonded on its inner surface to a
         rigid core and on its flat annulus to the finger: both get u = (0, -delta).

Coordinates (axisymmetric, CalculiX's x = radius r, y = axial): sphere centre C = (0, R), pole
(first contact point) at (0, 0), rigid plane y = 0. Units mm, N, MPa.

The rigid plane is a slab of fixed 3D C3D8 elements under y = 0, wide enough in z to cover the
+-1 degree wedge CalculiX expands axisymmetric elements into: CalculiX forbids axisymmetric
master faces with a node on the axis. Contact: surface to surface, frictionless, linear penalty.

The load is the vertical displacement of the pushed face, ramped with step time: step time = x.
The load is split in steps (x_end, dt_max): small increments where the contact front moves fast
relative to the element size (small x), larger ones later.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from fe_counterpart import SAG_MAX, Counterpart
from fe_deck import (neo_hooke, write_contact, write_master_elements, write_materials,
                     write_nset, write_steps, write_surface)

R = 1.0  # mm
GEOMETRIES = ("free", "flat", "core")
# the body's element: CAX8R (8-node quadratic, reduced integration, 2x2 points: the campaign's
# default since session 1) or CAX8 (full integration, 3x3 points; session 23: a skin squeezed
# against the core converges further with it, see README "Where runs stop")
ELEMENTS = ("CAX8R", "CAX8")


@dataclass
class Case:
    geometry: str  # free | flat | core
    nu: float
    t: float = 0.0  # shell thickness / R (core only)
    h: float = 1 / 60  # element size on the curved contact surface [mm]
    g: float = 0.12  # size growth rate into the interior
    hmax: float = 0.05
    hpole: float = 0.25  # size at the pole as a fraction of h
    gpole: float = 0.2  # growth rate away from the pole
    mu: float = 1.0  # MPa
    kpen: float = 1e5  # MPa/mm, linear pressure-overclosure penalty
    # load steps: (x at the end of the step, max increment); first increment = dt_max / 2
    steps: list = field(default_factory=lambda: [(0.1, 0.0025), (0.2, 0.005), (0.75, 0.01)])
    tp: float = 0.01  # output every tp in x
    dtmin: float = 1e-7
    tie: bool = True  # tie the on-axis slave face (see README)
    counterpart: str = "plane"  # plane | ball (axisymmetric); see fe_counterpart
    k: float = 0.0  # counterpart radius over R (ball)
    facet_sag: float = SAG_MAX  # largest faceting sag of a curved counterpart [mm]
    element: str = "CAX8R"  # the body's element type, one of ELEMENTS

    def __post_init__(self):
        if self.element not in ELEMENTS:
            raise ValueError(f"element {self.element!r} is not one of {ELEMENTS}")

    @property
    def cp(self) -> Counterpart:
        return Counterpart(self.counterpart, self.k, self.facet_sag)

    @property
    def name(self) -> str:
        s = f"{self.cp.tag}{self.geometry}_nu{self.nu:g}"
        if self.geometry == "core":
            s += f"_t{self.t:g}"
        s += f"_h{1 / self.h:.0f}"
        # the default element keeps every earlier run's name (its run directory)
        return s if self.element == "CAX8R" else s + "_" + self.element.lower()

    @property
    def tend(self) -> float:
        return self.steps[-1][0]

    def material(self):
        return neo_hooke(self.mu, self.nu)


def mesh(case: Case):
    """gmsh quad mesh, 8-node serendipity quads. Returns nodes X (n, 2), elements E (m, 8)
    1-based, counter-clockwise, plus the curve tags needed for node sets."""
    import gmsh

    gmsh.initialize(interruptible=False)  # callable from a worker thread
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("tip")
        geo = gmsh.model.geo
        pC = geo.addPoint(0, R, 0)
        pP = geo.addPoint(0, 0, 0)
        pE = geo.addPoint(R, R, 0)
        arc = geo.addCircleArc(pP, pC, pE)
        if case.geometry == "core":
            ri = R - case.t * R
            pI = geo.addPoint(0, R - ri, 0)  # inner pole
            pIE = geo.addPoint(ri, R, 0)
            loop = [geo.addLine(pI, pP), arc, geo.addLine(pE, pIE), -geo.addCircleArc(pI, pC, pIE)]
        else:
            loop = [geo.addLine(pC, pP), arc, geo.addLine(pE, pC)]
        geo.addPlaneSurface([geo.addCurveLoop(loop)])
        geo.synchronize()
        f = gmsh.model.mesh.field
        fd = f.add("Distance")
        f.setNumbers(fd, "CurvesList", [arc])
        f.setNumber(fd, "Sampling", 2000)
        ft = f.add("MathEval")
        f.setString(ft, "F", f"Min({case.h} + {case.g}*Max(F{fd}-{4 * case.h},0), {case.hmax})")
        fp = f.add("Distance")
        f.setNumbers(fp, "PointsList", [pP])
        fq = f.add("MathEval")
        f.setString(fq, "F", f"{case.hpole * case.h} + {case.gpole}*F{fp}")
        fm = f.add("Min")
        f.setNumbers(fm, "FieldsList", [ft, fq])
        f.setAsBackgroundMesh(fm)
        for k, v in [("MeshSizeExtendFromBoundary", 0), ("MeshSizeFromPoints", 0),
                     ("MeshSizeFromCurvature", 0), ("Algorithm", 8), ("RecombineAll", 1),
                     ("RecombinationAlgorithm", 1), ("SecondOrderIncomplete", 1)]:
            gmsh.option.setNumber("Mesh." + k, v)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.optimize("Laplace2D")
        gmsh.model.mesh.setOrder(2)
        ntags, ncoord, _ = gmsh.model.mesh.getNodes()
        etypes, _, enodes = gmsh.model.mesh.getElements(2)
        version = gmsh.__version__
    finally:
        gmsh.finalize()
    if list(etypes) != [16]:
        raise RuntimeError(f"mesh has element types {list(etypes)}, expected only 8-node quads (16)")
    quads = enodes[0].reshape(-1, 8)
    ncoord = ncoord.reshape(-1, 3)[:, :2]
    used = np.unique(quads)
    pos = {int(t): i for i, t in enumerate(ntags)}
    new = {int(t): i + 1 for i, t in enumerate(used)}
    X = np.array([ncoord[pos[int(t)]] for t in used])
    X[np.abs(X[:, 0]) < 1e-12, 0] = 0.0
    X[np.abs(X[:, 1] - R) < 1e-12, 1] = R
    E = np.vectorize(lambda t: new[int(t)])(quads)
    for k in range(len(E)):
        p = X[E[k, :4] - 1]
        area = 0.5 * np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])
        if area < 0:
            c = E[k].copy()
            E[k] = [c[0], c[3], c[2], c[1], c[7], c[6], c[5], c[4]]
    return X, E, version


ELSETS = {"C3D8": "EPLATE", "C3D6": "EPLATE6"}  # the counterpart's element sets
EDGES = [(0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)]  # corner, corner, midside (CAX8 faces S1..S4)


def deck(case: Case, path: str) -> dict:
    """Write the CalculiX deck to `path` (.inp). Returns a summary (sizes, versions)."""
    X, E, gmsh_version = mesh(case)
    nn = len(X)
    dist = np.hypot(X[:, 0], X[:, 1] - R)
    on_arc = np.abs(dist - R) < 1e-8
    on_axis = X[:, 0] == 0.0
    on_top = X[:, 1] == R
    push = on_top.copy()
    if case.geometry == "core":
        push |= np.abs(dist - (R - case.t * R)) < 1e-8
    slave = [(k + 1, j + 1) for k in range(len(E)) for j, ed in enumerate(EDGES)
             if all(on_arc[E[k, i] - 1] for i in ed)]
    ipole = int(np.where(on_arc & on_axis)[0][0]) + 1
    arcn = np.where(on_arc)[0]
    th = np.sort(np.arctan2(X[arcn, 0], R - X[arcn, 1]))
    h_surf = float(np.diff(th[:40]).max() * 2 * R)  # element edge near the pole region

    # the rigid counterpart: fixed 3D elements whose outer faces are the master surface
    master = case.cp.master_axisym()
    base = 10 ** (len(str(nn)) + 1)
    pn = master.nodes

    c10, d1 = case.material()
    o = []
    w = o.append
    w("*HEADING")
    w(f"softgrip FE {case.name}: geometry={case.geometry} nu={case.nu} t/R={case.t} mu={case.mu} "
      f"C10={c10:.8g} D1={d1:.8g} h={case.h:.5g} kpen={case.kpen:g} {case.element} gmsh {gmsh_version}"
      + (f" counterpart={case.counterpart} k={case.k:g}" if case.counterpart != "plane" else ""))
    w("*NODE, NSET=NBODY")
    for i, (x, y) in enumerate(X):
        w(f"{i + 1}, {x:.15g}, {y:.15g}, 0")
    w("*NODE, NSET=NPLATE")
    for i, (x, y, z) in enumerate(pn):
        w(f"{base + i + 1}, {x:.10g}, {y:.10g}, {z:.10g}")
    w(f"*ELEMENT, TYPE={case.element}, ELSET=EBODY")
    for k, c in enumerate(E):
        w(f"{k + 1}, " + ", ".join(str(int(v)) for v in c))
    write_master_elements(w, master, base, ELSETS)
    write_nset(w, "NAXIS", np.where(on_axis)[0] + 1)
    write_nset(w, "NPUSH", np.where(push)[0] + 1)
    write_nset(w, "NARC", np.where(on_arc)[0] + 1)
    write_nset(w, "NPOLE", [ipole])
    write_surface(w, "SSLAVE", slave)
    write_surface(w, "SMASTER", [(base + k + 1, j) for k, j in master.faces])
    write_materials(w, c10, d1, master, ELSETS)
    write_contact(w, case.kpen)
    w("*BOUNDARY")
    w("NPLATE, 1, 3, 0.")
    w("NAXIS, 1, 1, 0.")
    if case.geometry in ("flat", "core"):
        w("NPUSH, 1, 1, 0.")  # bonded: no slip, no radial expansion
    if case.tie:
        # CalculiX's face-to-face contact ignores the first slave face (it collapses onto the
        # axis when CAX elements are expanded) and that face sags into the plane. Make it move
        # rigidly in y with its outer corner node, which is held by the neighbouring face.
        for k, j in slave:
            ed = [int(E[k - 1, i]) for i in EDGES[j - 1]]
            if ipole in ed[:2]:
                nm = ed[2]
                nc = ed[1] if ed[0] == ipole else ed[0]
                for n in (ipole, nm):
                    w("*EQUATION")
                    w("2")
                    w(f"{n}, 2, 1.0, {nc}, 2, -1.0")
    write_steps(w, case, tp_per_increment=False)
    with open(path, "w") as fh:
        fh.write("\n".join(o) + "\n")
    return dict(elements=len(E), nodes=nn, slave_faces=len(slave), h_surface=h_surf,
                gmsh=gmsh_version, master=master.about, master_elements=len(master.elements),
                facet_sag_mm=case.cp.sag())
