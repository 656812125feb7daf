"""The parts of a softgrip CalculiX deck that the axisymmetric model (fe_model) and the 3D
quarter model (fe_model3d) share: the material constants, node sets, element surfaces, the rigid
counterpart's elements, the materials and sections, the frictionless penalty contact, and the
load steps with their output requests.

Every writer appends lines to a deck through `w` (a list's `append`); nothing here knows the
mesh's dimension. Units mm, N, MPa.
"""
from __future__ import annotations

R = 1.0  # mm, the fingertip's radius (fe_model.R, fe_model3d.R)


def neo_hooke(mu: float, nu: float) -> tuple[float, float]:
    """CalculiX's compressible neo-Hookean constants (C10 [MPa], D1 [1/MPa]) of the shear
    modulus `mu` [MPa] and the small-strain Poisson ratio `nu` (0 < nu < 0.5): C10 = mu / 2,
    D1 = 2 / kappa with the bulk modulus kappa = 2 mu (1 + nu) / (3 (1 - 2 nu))."""
    kappa = 2 * mu * (1 + nu) / (3 * (1 - 2 * nu))
    return mu / 2, 2 / kappa


def write_nset(w, name: str, ids) -> None:
    """`*NSET` of the 1-based node numbers `ids`, 12 a line, each line closed by a comma."""
    w(f"*NSET, NSET={name}")
    ids = [int(v) for v in ids]
    for i in range(0, len(ids), 12):
        w(", ".join(str(v) for v in ids[i:i + 12]) + ",")


def write_surface(w, name: str, faces) -> None:
    """Element-face `*SURFACE` of (1-based element number, face number) pairs."""
    w(f"*SURFACE, NAME={name}, TYPE=ELEMENT")
    for e, j in faces:
        w(f"{e}, S{j}")


def write_master_elements(w, master, base: int, elsets: dict) -> None:
    """The counterpart's fixed elements (fe_counterpart's `master.elements`, (type, 0-based node
    indices)), numbered base + index + 1 with their nodes base + index + 1, one `*ELEMENT` block
    per type present, in the order of `elsets` (element type -> element set name). A type not
    in `elsets` is an error."""
    other = {t for t, _ in master.elements} - set(elsets)
    if other:
        raise ValueError(f"counterpart element types {sorted(other)}: this deck takes {list(elsets)}")
    for typ, elset in elsets.items():
        els = [(k, ids) for k, (t, ids) in enumerate(master.elements) if t == typ]
        if els:
            w(f"*ELEMENT, TYPE={typ}, ELSET={elset}")
            for k, ids in els:
                w(f"{base + k + 1}, " + ", ".join(str(base + v + 1) for v in ids))


def write_materials(w, c10: float, d1: float, master, elsets: dict) -> None:
    """The neo-Hookean RUBBER of the body (element set EBODY) and the stiff elastic RIGID of the
    counterpart's element sets present (`elsets` as in write_master_elements)."""
    w("*MATERIAL, NAME=RUBBER")
    w("*HYPERELASTIC, NEO HOOKE")
    w(f"{c10:.10g}, {d1:.10g}")
    w("*MATERIAL, NAME=RIGID")
    w("*ELASTIC")
    w("1e6, 0.3")
    w("*SOLID SECTION, ELSET=EBODY, MATERIAL=RUBBER")
    for typ, elset in elsets.items():
        if any(t == typ for t, _ in master.elements):
            w(f"*SOLID SECTION, ELSET={elset}, MATERIAL=RIGID")


def write_contact(w, kpen: float) -> None:
    """Frictionless surface-to-surface contact of SSLAVE (the body) on SMASTER (the
    counterpart), linear pressure-overclosure penalty `kpen` [MPa/mm]."""
    w("*SURFACE INTERACTION, NAME=SI")
    w("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR")
    w(f"{kpen:g}")
    w("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE")
    w("SSLAVE, SMASTER")


def write_steps(w, case, tp_per_increment: bool) -> None:
    """Time points (all before the first *STEP, relative to their step: every case.tp in x, or,
    with `tp_per_increment`, every increment where the step's largest increment is longer) and
    the load steps of case.steps ((x at the step's end, largest increment)): u_y = -x R of the
    node set NPUSH, step time = x; the force totals of NPUSH, the displacements and the contact
    fields at each point."""
    x0 = 0.0
    for s, (x1, dtmax) in enumerate(case.steps):
        tp = max(case.tp, dtmax) if tp_per_increment else case.tp
        n0, n1 = int(round(x0 / tp)), int(round(x1 / tp))
        pts = [n * tp - x0 for n in range(n0 + 1, n1 + 1)]
        w(f"*TIME POINTS, NAME=T{s + 1}")
        for i in range(0, len(pts), 8):
            w(", ".join(f"{p:.6f}" for p in pts[i:i + 8]) + ",")
        x0 = x1
    x0 = 0.0
    for s, (x1, dtmax) in enumerate(case.steps):
        w("*STEP, NLGEOM, INC=1000000")
        w("*STATIC")
        w(f"{dtmax / 2:g}, {x1 - x0:.6g}, {case.dtmin:g}, {dtmax:g}")
        # more iterations before a cutback, more cutbacks (nearly incompressible, late x)
        w("*CONTROLS, PARAMETERS=TIME INCREMENTATION")
        w("4,8,9,40,10,4,,10")
        w("*BOUNDARY")
        w(f"NPUSH, 2, 2, {-x1 * R:.6g}")
        w(f"*NODE PRINT, NSET=NPUSH, TOTALS=ONLY, TIME POINTS=T{s + 1}")
        w("RF")
        w(f"*NODE FILE, TIME POINTS=T{s + 1}")
        w("U")
        w(f"*CONTACT FILE, TIME POINTS=T{s + 1}")
        w("CDIS, CSTR")
        w("*END STEP")
        x0 = x1
