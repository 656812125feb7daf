"""3D mesh and CalculiX deck: the fingertip on a counterpart that is not axisymmetric.

The fingertip (sphere of radius R, centre (0, R, 0), pole at the origin) is pressed along -y on
a rigid counterpart (fe_counterpart: a cylinder with its axis along z, a right-angle edge along
z, or the plane, which checks this 3D model against the axisymmetric one). Both symmetry planes
of the problem (x = 0, across the cylinder or edge; z = 0, along it) bound a quarter model:
x >= 0, z >= 0, u_x = 0 on x = 0, u_z = 0 on z = 0; force = 4 x RF_y of the pushed face.

  free : the quarter of the hemisphere below the equator; the equator face y = R gets
         u_y = -delta, u_x and u_z free (a symmetry plane: the sphere between two identical
         counterparts, each contact compressed by delta).
  flat : the same quarter bonded at y = R to a rigid backing: u = (0, -delta, 0) there.
  core : the quarter of a hemispherical shell R - t <= rho <= R (rho the distance from the
         centre), bonded on its inner surface rho = R - t to a rigid core and on its flat
         annulus y = R, R - t <= r <= R, to the finger: both get u = (0, -delta, 0), exactly as
         the axisymmetric `core` (fe_model); force = 4 x RF_y of both. Only the outer surface
         rho = R is the contact's slave surface.

Elements: C3D10 (10-node quadratic tetrahedra, full integration) from gmsh (OpenCASCADE sphere
cut by a box, Delaunay, second order with the midside nodes on the sphere). Element edge at the
pole R/n, growing linearly with the distance d from the pole, h(d) = (R/n) (1 + beta d / R),
up to hmax: the contact patch of every x is covered by about the same number of elements
(a self-similar mesh). For `core`, the skin of thickness t is meshed by the same field: at the
pole the element edge grows from R/n to (R/n)(1 + beta t/R) across the skin (R/20, beta 2,
t/R 0.4: 0.05 to 0.09 mm, about 6 quadratic elements through the skin there), and away from the
pole at most min(hmax, t / core_across) (at least core_across = 3.5 elements through it). The edge adds a band along the ridge (the line x = 0 of the sphere's
surface), h = (R / (ridge n)) (1 + beta d / R) + g_ridge x: the patch across a sharp edge is
narrow (about delta wide at small x), and a coarse face bridges the ridge without wrapping it.

Contact, material, penalty and load steps as the axisymmetric model (fe_model), with
`*NODE PRINT` totals of the pushed face. Units mm, N, MPa.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from fe_counterpart import SAG_MAX, Counterpart
from fe_deck import (neo_hooke, write_contact, write_master_elements, write_materials,
                     write_nset, write_steps, write_surface)

R = 1.0
GEOMETRIES = ("free", "flat", "core")
# C3D10 faces (CalculiX = Abaqus numbering), 0-based corner indices
TET_FACES = {1: (0, 1, 2), 2: (0, 3, 1), 3: (1, 3, 2), 4: (2, 3, 0)}
# gmsh's 10-node tetrahedron -> CalculiX's: gmsh midsides 4:(0,1) 5:(1,2) 6:(2,0) 7:(3,0)
# 8:(3,2) 9:(3,1); CalculiX 5:(1,2) 6:(2,3) 7:(3,1) 8:(1,4) 9:(2,4) 10:(3,4) (1-based)
GMSH_TO_CCX_TET10 = (0, 1, 2, 3, 4, 5, 6, 7, 9, 8)
ELSETS = {"C3D8": "EPLATE8"}  # the counterpart's element set (fe_counterpart.master_3d: hexahedra)


@dataclass
class Case3D:
    geometry: str  # free | flat | core
    nu: float
    t: float = 0.0  # core only: the skin's thickness / R
    counterpart: str = "cylinder"
    k: float = 0.0
    n: float = 40  # element edge at the pole R/n
    beta: float = 2.0  # growth of the element edge with the distance from the pole
    hmax: float = 0.12
    core_across: float = 3.5  # core only: elements through the skin at least (hmax <= t / this)
    g_ridge: float = 0.15  # edge only: growth away from the ridge line
    ridge: float = 3.0  # edge only: the element edge along the ridge is 1/ridge of the pole's
    mu: float = 1.0
    kpen: float = 1e5
    steps: list = field(default_factory=lambda: [(0.1, 0.005), (0.2, 0.01), (0.6, 0.02)])
    tp: float = 0.01
    dtmin: float = 1e-7
    facet_sag: float = SAG_MAX
    dim: int = 3

    @property
    def cp(self) -> Counterpart:
        return Counterpart(self.counterpart, self.k, self.facet_sag)

    @property
    def name(self) -> str:
        s = f"3d_{self.cp.tag}{self.geometry}_nu{self.nu:g}"
        if self.geometry == "core":
            s += f"_t{self.t:g}"
        return s + f"_n{self.n:g}"

    @property
    def h(self) -> float:  # the campaign's convention: element edge at the contact's start
        return R / self.n

    def material(self):
        return neo_hooke(self.mu, self.nu)


def mesh(case: Case3D):
    """gmsh quarter hemisphere (core: the quarter of the shell R - t <= rho <= R), C3D10.
    Returns nodes X (n, 3), tets T (m, 10) 0-based in CalculiX's order, the outer sphere
    surface's triangles (corner triples, 0-based) and gmsh's version."""
    import gmsh

    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("tip3d")
        occ = gmsh.model.occ
        s = occ.addSphere(0, R, 0, R)
        if case.geometry == "core":
            inner = occ.addSphere(0, R, 0, R - case.t * R)
            shell, _ = occ.cut([(3, s)], [(3, inner)])
            s = shell[0][1]
        b = occ.addBox(0, 0, 0, R, R, R)
        vol, _ = occ.intersect([(3, s)], [(3, b)])
        occ.synchronize()
        curved = [tag for dim, tag in gmsh.model.getBoundary(vol, oriented=False)
                  if not _on_plane(gmsh.model.occ.getCenterOfMass(dim, tag))
                  and _on_outer_sphere(gmsh, tag)]
        if len(curved) != 1:
            raise RuntimeError(f"expected one curved surface, got {curved}")
        pole = [t for d, t in gmsh.model.getEntities(0)
                if np.allclose(gmsh.model.getValue(0, t, []), (0, 0, 0), atol=1e-9)]
        f = gmsh.model.mesh.field
        fd = f.add("Distance")
        if pole:
            f.setNumbers(fd, "PointsList", pole)
        else:
            raise RuntimeError("no geometry point at the pole")
        fs = f.add("MathEval")
        hmax = case.hmax
        if case.geometry == "core":
            hmax = min(hmax, case.t * R / case.core_across)
        f.setString(fs, "F", f"Min({R / case.n}*(1+{case.beta}*F{fd}/{R}), {hmax})")
        fields = [fs]
        if case.counterpart == "edge":
            ridge = [t for d, t in gmsh.model.getEntities(1) if _is_ridge(gmsh, t)]
            fr = f.add("Distance")
            f.setNumbers(fr, "CurvesList", ridge)
            f.setNumber(fr, "Sampling", 400)
            fe = f.add("MathEval")
            f.setString(fe, "F", f"{R / (case.ridge * case.n)}*(1+{case.beta}*F{fd}/{R})"
                                 f" + {case.g_ridge}*F{fr}")
            fields.append(fe)
        fm = f.add("Min")
        f.setNumbers(fm, "FieldsList", fields)
        f.setAsBackgroundMesh(fm)
        for key, v in [("MeshSizeExtendFromBoundary", 0), ("MeshSizeFromPoints", 0),
                       ("MeshSizeFromCurvature", 0), ("Algorithm", 6), ("Algorithm3D", 1),
                       ("ElementOrder", 2), ("SecondOrderLinear", 0), ("Optimize", 1),
                       ("OptimizeNetgen", 1)]:
            gmsh.option.setNumber("Mesh." + key, v)
        gmsh.model.mesh.generate(3)
        ntags, ncoord, _ = gmsh.model.mesh.getNodes()
        etypes, _, enodes = gmsh.model.mesh.getElements(3)
        tris = []
        for tag in curved:
            et, _, en = gmsh.model.mesh.getElements(2, tag)
            for t, e in zip(et, en):
                if t == 9:  # 6-node triangle
                    tris.append(e.reshape(-1, 6)[:, :3])
        version = gmsh.__version__
    finally:
        gmsh.finalize()
    if list(etypes) != [11]:
        raise RuntimeError(f"mesh has element types {list(etypes)}, expected only 10-node tets (11)")
    pos = {int(t): i for i, t in enumerate(ntags)}
    X = ncoord.reshape(-1, 3)
    T = np.vectorize(lambda t: pos[int(t)])(enodes[0].reshape(-1, 10))[:, GMSH_TO_CCX_TET10]
    tris = np.vectorize(lambda t: pos[int(t)])(np.concatenate(tris))
    # snap the symmetry planes and the pushed face exactly
    for j, v in ((0, 0.0), (2, 0.0), (1, R)):
        X[np.abs(X[:, j] - v) < 1e-10, j] = v
    T = _orient(X, T)
    _check_midsides(X, T)
    return X, T, tris, version


def _on_plane(c):
    return abs(c[0]) < 1e-9 or abs(c[2]) < 1e-9 or abs(c[1] - R) < 1e-9


def _on_outer_sphere(gmsh, tag):
    """Whether surface `tag` lies on the outer sphere rho = R (not the core's rho = R - t)."""
    lo, hi = gmsh.model.getParametrizationBounds(2, tag)
    p = gmsh.model.getValue(2, tag, [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2])
    return abs(math.dist(p, (0, R, 0)) - R) < 1e-6


def _is_ridge(gmsh, tag):
    """The curve where the sphere meets x = 0 (the line of the fingertip over the edge)."""
    lo, hi = gmsh.model.getParametrizationBounds(1, tag)
    pts = [gmsh.model.getValue(1, tag, [lo[0] + (hi[0] - lo[0]) * s]) for s in (0.2, 0.5, 0.8)]
    return all(abs(p[0]) < 1e-9 and abs(math.dist(p, (0, R, 0)) - R) < 1e-6 for p in pts)


def _orient(X, T):
    """CalculiX wants ((2-1) x (3-1)) . (4-1) > 0; swap corners 2, 3 (and midsides) if not."""
    P = X[T[:, :4]]
    v = np.einsum("ij,ij->i", np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]), P[:, 3] - P[:, 0])
    bad = v < 0
    if bad.any():
        # swap corners 1 <-> 2 (0-based): midsides (0,1)<->(0,2): 4<->6, (1,3)<->(2,3): 8<->9
        T = T.copy()
        T[bad] = T[bad][:, [0, 2, 1, 3, 6, 5, 4, 7, 9, 8]]
    return T


def _check_midsides(X, T):
    """Every midside node lies between its two corners (within the curved surface's bulge)."""
    edges = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
    for m, (a, b) in enumerate(edges):
        mid = 0.5 * (X[T[:, a]] + X[T[:, b]])
        d = np.linalg.norm(X[T[:, 4 + m]] - mid, axis=1)
        L = np.linalg.norm(X[T[:, a]] - X[T[:, b]], axis=1)
        if (d > 0.3 * L).any():
            raise RuntimeError(f"C3D10 midside node {5 + m} is not between its corners")


def slave_faces(T, tris):
    """(element, face number) of every tet face on the sphere surface."""
    want = {tuple(sorted(t)) for t in tris.tolist()}
    out = []
    for e, c in enumerate(T[:, :4].tolist()):
        for j, f in TET_FACES.items():
            if tuple(sorted(c[i] for i in f)) in want:
                out.append((e, j))
    if len(out) != len(want):
        raise RuntimeError(f"{len(out)} slave faces for {len(want)} surface triangles")
    return out


def deck(case: Case3D, path: str) -> dict:
    """Write the CalculiX deck to `path` (.inp). Returns a summary (sizes, versions, master)."""
    X, T, tris, gmsh_version = mesh(case)
    nn = len(X)
    slave = slave_faces(T, tris)
    on_sphere = np.abs(np.linalg.norm(X - (0, R, 0), axis=1) - R) < 1e-7
    master = case.cp.master_3d()
    base = 10 ** (len(str(nn)) + 1)
    c10, d1 = case.material()
    o = []
    w = o.append
    w("*HEADING")
    w(f"softgrip FE 3D {case.name}: geometry={case.geometry} nu={case.nu} mu={case.mu} "
      f"C10={c10:.8g} D1={d1:.8g} t/R={case.t:g} n={case.n:g} beta={case.beta:g} kpen={case.kpen:g} C3D10 "
      f"gmsh {gmsh_version} counterpart={case.counterpart} k={case.k:g}")
    # CalculiX reads at most 20 characters of a number: "-3.97144573136554e-05" (21) was
    # read as -3.97 and turned a master element inside out; 12 digits fit every value
    w("*NODE, NSET=NBODY")
    for i, (x, y, z) in enumerate(X):
        w(f"{i + 1}, {x:.12g}, {y:.12g}, {z:.12g}")
    w("*NODE, NSET=NPLATE")
    for i, (x, y, z) in enumerate(master.nodes):
        w(f"{base + i + 1}, {x:.12g}, {y:.12g}, {z:.12g}")
    w("*ELEMENT, TYPE=C3D10, ELSET=EBODY")
    for e, c in enumerate(T):
        w(f"{e + 1}, " + ", ".join(str(int(v) + 1) for v in c))
    write_master_elements(w, master, base, ELSETS)
    write_nset(w, "NSYMX", np.where(X[:, 0] == 0.0)[0] + 1)
    write_nset(w, "NSYMZ", np.where(X[:, 2] == 0.0)[0] + 1)
    push = X[:, 1] == R
    if case.geometry == "core":  # the inner surface, bonded to the rigid core
        push |= np.abs(np.linalg.norm(X - (0, R, 0), axis=1) - (R - case.t * R)) < 1e-7
    write_nset(w, "NPUSH", np.where(push)[0] + 1)
    write_nset(w, "NSURF", np.where(on_sphere)[0] + 1)
    write_surface(w, "SSLAVE", [(e + 1, j) for e, j in slave])
    write_surface(w, "SMASTER", [(base + e + 1, j) for e, j in master.faces])
    write_materials(w, c10, d1, master, ELSETS)
    write_contact(w, case.kpen)
    w("*BOUNDARY")
    w("NPLATE, 1, 3, 0.")
    w("NSYMX, 1, 1, 0.")
    w("NSYMZ, 3, 3, 0.")
    if case.geometry in ("flat", "core"):
        w("NPUSH, 1, 1, 0.")
        w("NPUSH, 3, 3, 0.")
    write_steps(w, case, tp_per_increment=True)  # an output point per increment at most
    with open(path, "w") as fh:
        fh.write("\n".join(o) + "\n")
    return dict(elements=len(T), nodes=nn, slave_faces=len(slave), h_surface=R / case.n,
                gmsh=gmsh_version, master=master.about, master_elements=len(master.elements),
                facet_sag_mm=case.cp.sag())

