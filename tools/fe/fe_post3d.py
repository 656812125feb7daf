"""Post-processing of one 3D softgrip FE run (fe_model3d: a quarter model, x >= 0, z >= 0).

Per output time point (step time = x = delta / R):
  force_N              -4 x total RF_y of the pushed face NPUSH (the quarter model)
  semi_axis_across_mm  a: the patch's extent along x (across the cylinder's axis or the edge),
                       from the sphere's surface nodes on the symmetry plane z = 0 in order from
                       the pole, with their signed gap to the counterpart: the crossing of the
                       Hertzian edge shape g ~ (s - a)^(3/2) through the first two nodes outside
                       (fe_post.edge_crossing's a_32; a_lin, the last node in contact, is
                       resolved to one node spacing only), as the deformed x there (the patch
                       seen along the pressing direction)
  semi_axis_along_mm   b: the same along z, from the nodes on the symmetry plane x = 0
  min_element_J        smallest volume ratio of an element's corner tetrahedron
  V_over_V0            body volume ratio (corner tetrahedra)
  max_copen_over_delta largest penalty penetration / delta
  max_lift_mm          highest deformed surface node above the pushed face's plane
Pressure maps: nodal CPRESS of the surface nodes in contact (gap <= 0) with their deformed (x, z).
"""
from __future__ import annotations

import numpy as np

from fe_post import counterpart_of, edge_crossing, read_dat_force, read_frd, read_inp

R = 1.0


class Run3D:
    def __init__(self, rundir, job="job"):
        base = f"{rundir}/{job}"
        self.cp = counterpart_of(rundir)
        X, T, sets, _ = read_inp(base + ".inp", element="C3D10", dim=3)
        self.ids = sorted(X)
        pos = {n: i for i, n in enumerate(self.ids)}
        self.X0 = np.array([X[n] for n in self.ids])
        self.tets = np.array([[pos[n] for n in e[:4]] for e in T])
        self.surf = np.array([pos[n] for n in sets["NSURF"]])
        Xs = self.X0[self.surf]
        # the surface's lines on the two symmetry planes, ordered from the pole
        on_z0 = self.surf[np.abs(Xs[:, 2]) < 1e-12]
        on_x0 = self.surf[np.abs(Xs[:, 0]) < 1e-12]
        self.line_x = on_z0[np.argsort(np.arctan2(self.X0[on_z0, 0], R - self.X0[on_z0, 1]))]
        self.line_z = on_x0[np.argsort(np.arctan2(self.X0[on_x0, 2], R - self.X0[on_x0, 1]))]
        self.V0 = self._vol(self.X0)
        self.F = read_dat_force(base + ".dat", scale=-4.0)
        self.U, self.C = read_frd(base + ".frd", self.ids, dim=3)
        self.times = sorted(set(self.F) & set(self.U))

    def _vol(self, P):
        p = P[self.tets]
        return np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]),
                         p[:, 3] - p[:, 0]) / 6.0

    def _extent(self, P, line, axis):
        """(a_lin, a_32) of the deformed coordinate `axis` along `line` (fe_post.edge_crossing)."""
        return edge_crossing(P[line, axis], self.cp.gap(P[line]))

    def row(self, t):
        P = self.X0 + self.U[t]
        V = self._vol(P)
        c = self.C.get(t)
        copen = float(c[self.surf, 0].max()) / t if c is not None else np.nan
        lift = float(P[self.surf, 1].max() - (R - t * R))
        a_lin, a32 = self._extent(P, self.line_x, 0)
        b_lin, b32 = self._extent(P, self.line_z, 2)
        return dict(x=t, F=self.F[t], a=a_lin, a32=a32, b=b_lin, b32=b32, minJ=float((V / self.V0).min()),
                    VV0=float(V.sum() / self.V0.sum()), copen=copen, lift=lift)

    def pressure(self, t):
        """(x, z, CPRESS, gap) of the surface nodes with CPRESS > 0, deformed. The nodal CPRESS
        is extrapolated from the faces' integration points and stays positive up to a face
        beyond the contact edge: gap <= 0 (or the penalty's penetration) marks contact."""
        c = self.C.get(t)
        if c is None:
            return None
        P = self.X0[self.surf] + self.U[t][self.surf]
        p = c[self.surf, 1]
        keep = p > 0
        return P[keep, 0], P[keep, 2], p[keep], self.cp.gap(P[keep])
