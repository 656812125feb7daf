"""Writes crates/softgrip-fe/src/counterpart_files.rs: the loader's table of every FE file on a
counterpart other than the plane (tests/data/fe/{ball,cylinder,edge}/<geometry>/*.csv), so that
they load through softgrip_fe's API keyed by counterpart, construction, nu (and x); and
crates/softgrip-fe/src/core_counterpart_files.rs, the same for the skin on a core
(tests/data/fe/ball/core/, keyed by t/R too; a table of its own since session 11). Run by
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
CORE_NAME = re.compile(r"(force|pressure)_nu([\d.]+)_t([\d.]+)_k([\d.]+)(?:_d([\d.]+))?\.csv$")
KINDS = ("ball", "cylinder", "edge")
NAME = re.compile(r"(force|pressure)_nu([\d.]+)(?:_k([\d.]+))?(?:_d([\d.]+))?\.csv$")


def rows():
    """(path, schema, nu, geometry, counterpart literal, about) of every file, sorted."""
    out = []
    for kind in KINDS:
        for geometry in ("free", "flat"):
            d = os.path.join(OUT, kind, geometry)
            if not os.path.isdir(d):
                continue
            for f in sorted(os.listdir(d)):
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
                text = open(os.path.join(d, f)).read()
                prov = text.splitlines()[0]
                reached = re.search(r"reached x = ([\d.]+)", prov)
                about = f"{kind}" + (f" k = {float(k):g}" if k else "") + f", {geometry}, nu = {nu}"
                if what == "force":
                    about += f", x = 0.01..{reached.group(1) if reached else '?'}"
                else:
                    about += f", pressure at x = {x}"
                if "held out of every fit" in prov:
                    about = "held out of every fit: " + about
                out.append((f"{kind}/{geometry}/{f}", schema, nu, geometry, cp, about))
    return out


def write():
    rs = ["//! [`COUNTERPART_FILES`]: every embedded FE file on a ball, a cylinder or an edge.",
          "//!",
          "//! Written by `tools/fe/fe_campaign.py export` (tools/fe/fe_table.py) from the files of",
          "//! `tests/data/fe/{ball,cylinder,edge}/`; do not edit by hand.",
          "",
          "use crate::counterpart::Counterpart;",
          "use crate::fe_file::{FeFile, Schema};",
          "",
          "/// One row: path (relative to `tests/data/fe/`), schema, nu, construction, counterpart,",
          "/// description.",
          "macro_rules! counterpart_file {",
          "    ($path:literal, $schema:ident, $nu:expr, $geometry:literal, $cp:expr, $about:literal) => {",
          "        FeFile {",
          "            path: $path,",
          "            schema: Schema::$schema,",
          "            nu: Some($nu),",
          "            about: $about,",
          "            geometry: $geometry,",
          "            thickness_ratio: None,",
          "            counterpart: $cp,",
          "            text: include_str!(concat!(\"../../../tests/data/fe/\", $path)),",
          "        }",
          "    };",
          "}",
          "",
          "/// Every embedded file on a counterpart other than the plane (tools/fe: CalculiX 2.20, gmsh",
          "/// 4.15.2; each file's provenance line says how it was made).",
          "#[rustfmt::skip]",
          "pub const COUNTERPART_FILES: &[FeFile] = &["]
    for path, schema, nu, geometry, cp, about in rows():
        rs.append(f"    counterpart_file!(\"{path}\", {schema}, {float(nu)!r}, \"{geometry}\", {cp}, "
                  f"\"{about}\"),")
    rs.append("];")
    with open(TABLE, "w") as f:
        f.write("\n".join(rs) + "\n")
    return f"{TABLE}, {write_core()}"


def core_rows():
    """(path, schema, nu, t/R, counterpart literal, about) of every skin-on-core file on a ball."""
    out = []
    d = os.path.join(OUT, "ball", "core")
    for f in sorted(os.listdir(d)) if os.path.isdir(d) else []:
        m = CORE_NAME.match(f)
        if not m:
            raise SystemExit(f"ball/core/{f}: not a force or pressure file name")
        what, nu, t, k, x = m.groups()
        prov = open(os.path.join(d, f)).readline()
        reached = re.search(r"reached x = ([\d.]+)", prov)
        about = f"ball k = {float(k):g}, core t/R = {float(t):g}, nu = {nu}"
        if what == "force":
            about += f", x = 0.01..{reached.group(1) if reached else '?'}"
        else:
            about += f", pressure at x = {x}"
        if "held out of every fit" in prov:
            about = "held out of every fit: " + about
        out.append((f"ball/core/{f}", what.capitalize(), nu, t,
                    f"Counterpart::Ball {{ k: {float(k)!r} }}", about))
    return out


def write_core():
    rs = ["//! [`CORE_COUNTERPART_FILES`]: every embedded FE file of a skin on a core pressed on a",
          "//! ball.",
          "//!",
          "//! Written by `tools/fe/fe_campaign.py export` (tools/fe/fe_table.py) from the files of",
          "//! `tests/data/fe/ball/core/`; do not edit by hand.",
          "",
          "use crate::counterpart::Counterpart;",
          "use crate::fe_file::{FeFile, Schema};",
          "",
          "/// One row: path (relative to `tests/data/fe/`), schema, nu, t/R, counterpart, description.",
          "macro_rules! core_counterpart_file {",
          "    ($path:literal, $schema:ident, $nu:expr, $t:expr, $cp:expr, $about:literal) => {",
          "        FeFile {",
          "            path: $path,",
          "            schema: Schema::$schema,",
          "            nu: Some($nu),",
          "            about: $about,",
          "            geometry: \"core\",",
          "            thickness_ratio: Some($t),",
          "            counterpart: $cp,",
          "            text: include_str!(concat!(\"../../../tests/data/fe/\", $path)),",
          "        }",
          "    };",
          "}",
          "",
          "/// Every embedded file of a skin on a rigid core pressed on a rigid ball (tools/fe:",
          "/// CalculiX 2.20, gmsh 4.15.2; each file's provenance line says how it was made).",
          "#[rustfmt::skip]",
          "pub const CORE_COUNTERPART_FILES: &[FeFile] = &["]
    for path, schema, nu, t, cp, about in core_rows():
        rs.append(f"    core_counterpart_file!(\"{path}\", {schema}, {float(nu)!r}, {float(t)!r}, {cp}, "
                  f"\"{about}\"),")
    rs.append("];")
    with open(CORE_TABLE, "w") as f:
        f.write("\n".join(rs) + "\n")
    return CORE_TABLE


if __name__ == "__main__":
    print(write())
