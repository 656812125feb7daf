//! One typed row per file layout ([`crate::Schema`]), with the files' own column names. Units
//! as in the files: force \[N\], radii \[mm\] (R = 1 mm, so a radius in mm is `a/R`).

use serde::Deserialize;

/// A row of `force_nu*.csv` ([`crate::Schema::Force`]).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct ForceRow {
    /// Compression ratio x = delta/R [-].
    #[serde(rename = "delta_over_R")]
    pub delta_over_r: f64,
    /// Force \[N\].
    #[serde(rename = "force_N")]
    pub force_n: f64,
    /// Contact radius \[mm\] (resolved to about one element, R/60).
    pub contact_radius_mm: f64,
}

/// A row of `full_nu*.csv` ([`crate::Schema::Full`]): every converged point with the run's
/// diagnostics.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct FullRow {
    /// Compression ratio x = delta/R [-].
    #[serde(rename = "delta_over_R")]
    pub delta_over_r: f64,
    /// Force \[N\].
    #[serde(rename = "force_N")]
    pub force_n: f64,
    /// Contact radius from the last node in contact, linearly interpolated \[mm\] (the radius
    /// the force files carry).
    #[serde(rename = "a_lin_mm(contact_radius)")]
    pub a_lin_mm: f64,
    /// Contact radius from a fit of the pressure profile \[mm\].
    pub a_fit_mm: f64,
    /// Contact radius where the contact pressure vanishes \[mm\].
    pub a_cpress_mm: f64,
    /// Largest penalty penetration over delta [-].
    #[serde(rename = "max_COPEN_over_delta")]
    pub max_copen_over_delta: f64,
    /// Largest geometric overlap over delta, surface nodes beyond the first face [-].
    #[serde(rename = "max_geometric_overlap_over_delta_surface_nodes_beyond_first_face")]
    pub max_overlap_beyond_first_face: f64,
    /// Largest geometric overlap over delta, first-face nodes [-].
    #[serde(rename = "max_geometric_overlap_over_delta_first_face_nodes")]
    pub max_overlap_first_face: f64,
    /// Smallest element Jacobian J (volume ratio) [-].
    #[serde(rename = "min_element_J")]
    pub min_element_j: f64,
    /// Volume over initial volume [-].
    #[serde(rename = "V_over_V0")]
    pub v_over_v0: f64,
    /// Largest load increment of the run [-].
    pub max_load_increment_of_run: f64,
}

/// A row of `small_x_check.csv` ([`crate::Schema::SmallX`]): x = 0.001..0.01 on two meshes.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct SmallXRow {
    /// Poisson ratio of the run [-].
    pub nu: f64,
    /// 1 on the extra-fine (R/120) mesh, 0 on the fine (R/60) one.
    pub extra_fine_mesh: u8,
    /// Compression ratio x = delta/R [-].
    #[serde(rename = "delta_over_R")]
    pub delta_over_r: f64,
    /// Force \[N\].
    #[serde(rename = "force_N")]
    pub force_n: f64,
    /// Contact radius, linear interpolation \[mm\].
    pub a_lin_mm: f64,
    /// Contact radius, pressure fit \[mm\].
    pub a_fit_mm: f64,
}

/// A row of `mesh_convergence_nu0.49.csv` ([`crate::Schema::MeshConvergence`]): force \[N\] and
/// radius \[mm\] on the R/30, R/60 and R/120 meshes.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct MeshConvergenceRow {
    /// Compression ratio x = delta/R [-].
    #[serde(rename = "delta_over_R")]
    pub delta_over_r: f64,
    /// Force on the coarse (R/30) mesh \[N\].
    #[serde(rename = "F_coarse_R30")]
    pub force_coarse_n: f64,
    /// Force on the fine (R/60) mesh, the mesh of the other files \[N\].
    #[serde(rename = "F_fine_R60")]
    pub force_fine_n: f64,
    /// Force on the extra-fine (R/120) mesh \[N\].
    #[serde(rename = "F_xfine_R120")]
    pub force_xfine_n: f64,
    /// Fine against coarse force [%].
    pub reldiff_fine_coarse_pct: f64,
    /// Extra-fine against fine force [%].
    pub reldiff_xfine_fine_pct: f64,
    /// Radius on the coarse mesh \[mm\].
    pub a_coarse: f64,
    /// Radius on the fine mesh \[mm\].
    pub a_fine: f64,
    /// Radius on the extra-fine mesh \[mm\].
    pub a_xfine: f64,
}

/// A row of a 3D run's `force_nu*.csv` ([`crate::Schema::Force3d`]): a cylinder or an edge.
/// The semi-axes are the patch's extents along the two symmetry planes, seen along the pressing
/// direction: from the last surface node in contact (resolved to one node spacing, like
/// `contact_radius_mm`), and from the Hertzian edge shape of the gap through the first two
/// nodes outside (`*_32_mm`).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct Force3dRow {
    /// Compression ratio x = delta/R [-].
    #[serde(rename = "delta_over_R")]
    pub delta_over_r: f64,
    /// Force (the whole fingertip: 4 x the quarter model's) \[N\].
    #[serde(rename = "force_N")]
    pub force_n: f64,
    /// Semi-axis across the cylinder's axis or the edge \[mm\].
    pub semi_axis_across_mm: f64,
    /// Semi-axis along the cylinder's axis or the edge \[mm\].
    pub semi_axis_along_mm: f64,
    /// Semi-axis across, from the gap's Hertzian edge shape \[mm\].
    pub semi_axis_across_32_mm: f64,
    /// Semi-axis along, from the gap's Hertzian edge shape \[mm\].
    pub semi_axis_along_32_mm: f64,
    /// Smallest element volume ratio J [-].
    #[serde(rename = "min_element_J")]
    pub min_element_j: f64,
    /// Body volume over its initial volume [-].
    #[serde(rename = "V_over_V0")]
    pub v_over_v0: f64,
    /// Largest penalty penetration over delta [-].
    pub max_copen_over_delta: f64,
}

/// A row of a pressure profile `pressure_nu*_d*.csv` ([`crate::Schema::Pressure`]): nodal
/// contact pressure against the deformed radius, to the contact radius (closed by p = 0).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct PressureRow {
    /// Deformed radius of the surface node (seen along the axis) \[mm\].
    pub r_mm: f64,
    /// Contact pressure \[MPa\].
    #[serde(rename = "pressure_MPa")]
    pub pressure_mpa: f64,
}

/// A row of a 3D pressure map `pressure_nu*_d*.csv` ([`crate::Schema::PressureMap`]): one
/// surface node in contact of the quarter model (x >= 0, z >= 0).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
pub struct PressureMapRow {
    /// Deformed x (across the cylinder or edge) \[mm\].
    pub x_mm: f64,
    /// Deformed z (along it) \[mm\].
    pub z_mm: f64,
    /// Nodal contact pressure \[MPa\].
    #[serde(rename = "pressure_MPa")]
    pub pressure_mpa: f64,
    /// Signed gap to the counterpart's true surface (<= 0: in contact) \[mm\].
    pub gap_mm: f64,
}
