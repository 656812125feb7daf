"""Writes crates/softgrip-fe/src/counterpart_files.rs: the loader's table of every FE file on a
counterpart other than the plane (tests/data/fe/{ball,cylinder,edge}/<geometry>/*.csv), so that
they load through softgrip_fe's API keyed by counterpart, construction, nu (and x); and
crates/softgrip-fe/src/core_counterpart_files.rs, the same for the skin on a core
(tests/data/fe/{ball,cylinder,edge}/core/, keyed by t/R too; a table of its own since session
11, the cylinder and the edge since session 18). Run by
`fe_campaign.py export`; the crate's tests fail if a file has no row.
"""
from __future__ import annotations

import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
OUT = os.path.join(REPO, "tests", "data", "fe")
TABLE = os.path.join(REPO, "crates", "softgrip-fe", "src", "counterpart_files.rs")
CORE_TABLE = os.path.join(REPO, "crates", "softgrip-fe", "src", "core_counterpart_files.rs")
CORE_NAME = re.compile(r"(force|pressure)_nu([\d.]+)_t([\d.]+)(?:_k([\d.]+))?(?:_d([\d.]+))?\.csv$")
KINDS = ("ball", "cylinder", "edge")
# fe_campaign.py's semi-axes checks on a finer 3D mesh (cylinder/<geometry>/axes_*.csv, session
# 20): read by softgrip-law's tests through include_str!, not by the loader (no row here; the
# softgrip-fe test that every file has a row skips them as it skips convergence.csv)
AXES_PREFIX = "axes_"
NAME = re.compile(r"(force|pressure)_nu([\d.]+)(?:_k([\d.]+))?(?:_d([\d.]+))?\.csv$")


def about_of(what, prov, head, x):
    """A row's description: `head`, the force file's reach or the pressure file's x, and
    whether the run is held out of every fit (from its provenance line `prov`)."""
    reached = re.search(r"reached x = ([\d.]+)", prov)
    about = head
    if what == "force":
        about += f", x = 0.01..{reached.group(1) if reached else '?'}"
    else:
        about += f", pressure at x = {x}"
    if "held out of every fit" in prov:
        about = "held out of every fit: " + about
    return about


def rows():
    """(path, schema, nu, geometry, counterpart literal, about) of every file, sorted."""
    out = []
    for kind in KINDS:
        for geometry in ("free", "flat"):
            d = os.path.join(OUT, kind, geometry)
            if not os.path.isdir(d):
                continue
            for f in sorted(os.listdir(d)):
                if f.startswith(AXES_PREFIX):
                    continue
                m = NAME.match(f)
                if not m:
                    raise SystemExit(f"{kind}/{geometry}/{f}: not a force or pressure file name")
                what, nu, k, x = m.groups()
                three_d = kind in ("cylinder", "edge")
                schema = {("force", False): "Force", ("force", True): "Force3d",
                          ("pressure", False): "Pressure", ("pressure", True): "PressureMap"}[
                    (what, three_d)]
                # Only the row's own kind is formatted: an edge file has no k.
                cp = ("Counterpart::Edge" if kind == "edge" else
                      f"Counterpart::{kind.capitalize()} {{ k: {float(k)!r} }}")
                prov = open(os.path.join(d, f)).readline()
                head = f"{kind}" + (f" k = {float(k):g}" if k else "") + f", {geometry}, nu = {nu}"
                out.append((f"{kind}/{geometry}/{f}", schema, f"{float(nu)!r}", f'"{geometry}"',
                            cp, about_of(what, prov, head, x)))
    return out


def core_rows():
    """(path, schema, nu, t/R, counterpart literal, about) of every skin-on-core file on a ball
    (axisymmetric), a cylinder or an edge (3D quarter models, session 18)."""
    out = []
    for kind in KINDS:
        d = os.path.join(OUT, kind, "core")
        for f in sorted(os.listdir(d)) if os.path.isdir(d) else []:
            if f.startswith(AXES_PREFIX):
                continue
            m = CORE_NAME.match(f)
            if not m or (kind == "edge") != (m.group(4) is None):
                raise SystemExit(f"{kind}/core/{f}: not a force or pressure file name")
            what, nu, t, k, x = m.groups()
            three_d = kind in ("cylinder", "edge")
            schema = {("force", False): "Force", ("force", True): "Force3d",
                      ("pressure", False): "Pressure", ("pressure", True): "PressureMap"}[
                (what, three_d)]
            cp = ("Counterpart::Edge" if kind == "edge" else
                  f"Counterpart::{kind.capitalize()} {{ k: {float(k)!r} }}")
            prov = open(os.path.join(d, f)).readline()
            head = (f"{kind}" + (f" k = {float(k):g}" if k else "") +
                    f", core t/R = {float(t):g}, nu = {nu}")
            out.append((f"{kind}/core/{f}", schema, f"{float(nu)!r}", f"{float(t)!r}", cp,
                        about_of(what, prov, head, x)))
    return out


# The two tables, one format: (file, module doc, macro, its fourth argument (name, the field
# it fills, how), the row doc, the list's doc, const, rows). The counterpart table's rows carry
# the construction (`geometry`), the core's the skin's t/R (its construction is "core").
TABLES = [
    (TABLE,
     ["//! [`COUNTERPART_FILES`]: every embedded FE file on a ball, a cylinder or an edge.",
      "//!",
      "//! Written by `tools/fe/fe_campaign.py export` (tools/fe/fe_table.py) from the files of",
      "//! `tests/data/fe/{ball,cylinder,edge}/`; do not edit by hand."],
     "counterpart_file", "$geometry:literal",
     ["            geometry: $geometry,", "            thickness_ratio: None,"],
     ["/// One row: path (relative to `tests/data/fe/`), schema, nu, construction, counterpart,",
      "/// description."],
     ["/// Every embedded file on a counterpart other than the plane (tools/fe: CalculiX 2.20, gmsh",
      "/// 4.15.2; each file's provenance line says how it was made)."],
     "COUNTERPART_FILES", rows),
    (CORE_TABLE,
     ["//! [`CORE_COUNTERPART_FILES`]: every embedded FE file of a skin on a core pressed on a",
      "//! ball, a cylinder or an edge.",
      "//!",
      "//! Written by `tools/fe/fe_campaign.py export` (tools/fe/fe_table.py) from the files of",
      "//! `tests/data/fe/{ball,cylinder,edge}/core/`; do not edit by hand."],
     "core_counterpart_file", "$t:expr",
     ["            geometry: \"core\",", "            thickness_ratio: Some($t),"],
     ["/// One row: path (relative to `tests/data/fe/`), schema, nu, t/R, counterpart, description."],
     ["/// Every embedded file of a skin on a rigid core pressed on a rigid ball, cylinder or edge",
      "/// (tools/fe: CalculiX 2.20, gmsh 4.15.2; each file's provenance line says how it was",
      "/// made)."],
     "CORE_COUNTERPART_FILES", core_rows),
]


def write_table(out, doc, macro, arg, fields, row_doc, list_doc, const, rows_of):
    """One table's Rust file: the loader's rows, each through the table's macro."""
    rs = doc + [
        "",
        "use crate::counterpart::Counterpart;",
        "use crate::fe_file::{FeFile, Schema};",
        "",
    ] + row_doc + [
        f"macro_rules! {macro} {{",
        f"    ($path:literal, $schema:ident, $nu:expr, {arg}, $cp:expr, $about:literal) => {{",
        "        FeFile {",
        "            path: $path,",
        "            schema: Schema::$schema,",
        "            nu: Some($nu),",
        "            about: $about,",
    ] + fields + [
        "            counterpart: $cp,",
        "            text: include_str!(concat!(\"../../../tests/data/fe/\", $path)),",
        "        }",
        "    };",
        "}",
        "",
    ] + list_doc + [
        "#[rustfmt::skip]",
        f"pub const {const}: &[FeFile] = &[",
    ]
    for path, schema, nu, key, cp, about in rows_of():
        rs.append(f"    {macro}!(\"{path}\", {schema}, {nu}, {key}, {cp}, \"{about}\"),")
    rs.append("];")
    with open(out, "w") as f:
        f.write("\n".join(rs) + "\n")
    return out


def write():
    """Both tables; their paths."""
    return ", ".join(write_table(*t) for t in TABLES)


if __name__ == "__main__":
    print(write())
