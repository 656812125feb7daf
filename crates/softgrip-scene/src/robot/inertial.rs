//! A URDF link's `<inertial>`: its mass and inertia tensor checked against what rapier (f32)
//! can hold and what a body can have (a positive semi-definite tensor).

use rapier3d_urdf::urdf_rs::Inertial;

use crate::limits::MAX_SIZE;

/// Largest mass of a link \[kg\] (rapier is f32; inertias are masses times squared lengths).
pub const MAX_LINK_MASS: f64 = 1.0e6;

/// Relative tolerance on a principal moment of inertia below zero (URDFs exported from CAD
/// round their tensors): a moment may be as low as `-1e-6` times the largest one.
const PSD_TOLERANCE: f64 = 1e-6;

/// `inertial` of the link `at` names: mass finite in \[0, [`MAX_LINK_MASS`]\], tensor entries
/// finite within `MAX_LINK_MASS * MAX_SIZE`, principal moments not negative.
pub(crate) fn check_inertial(at: &str, inertial: &Inertial) -> Result<(), String> {
    let m = inertial.mass.value;
    if !(m.is_finite() && (0.0..=MAX_LINK_MASS).contains(&m)) {
        return Err(format!(
            "{at}: mass must be finite and in [0, {MAX_LINK_MASS:e}] kg, got {m}"
        ));
    }
    let i = &inertial.inertia;
    let bound = MAX_LINK_MASS * MAX_SIZE;
    for (name, v) in [
        ("ixx", i.ixx),
        ("ixy", i.ixy),
        ("ixz", i.ixz),
        ("iyy", i.iyy),
        ("iyz", i.iyz),
        ("izz", i.izz),
    ] {
        if !(v.is_finite() && v.abs() <= bound) {
            return Err(format!(
                "{at}: inertia {name} must be finite and within ±{bound:e} kg m^2, got {v}"
            ));
        }
    }
    for (name, v) in [("ixx", i.ixx), ("iyy", i.iyy), ("izz", i.izz)] {
        if v < 0.0 {
            return Err(format!(
                "{at}: inertia {name} must be >= 0 kg m^2 (a moment of inertia), got {v}"
            ));
        }
    }
    let p = principal_moments([i.ixx, i.iyy, i.izz, i.ixy, i.ixz, i.iyz]);
    let largest = p.iter().fold(0.0_f64, |a, &b| a.max(b.abs()));
    if p.iter().any(|&l| l < -PSD_TOLERANCE * largest) {
        return Err(format!(
            "{at}: inertia (ixx {}, iyy {}, izz {}, ixy {}, ixz {}, iyz {}) has principal moments \
             [{:.4e}, {:.4e}, {:.4e}] kg m^2: each must be >= 0 (the off-diagonal terms are too \
             large for the diagonal ones)",
            i.ixx, i.iyy, i.izz, i.ixy, i.ixz, i.iyz, p[0], p[1], p[2]
        ));
    }
    Ok(())
}

/// Eigenvalues of the symmetric tensor `[xx, yy, zz, xy, xz, yz]`, ascending (the closed form
/// for a symmetric 3x3 matrix).
pub(crate) fn principal_moments([xx, yy, zz, xy, xz, yz]: [f64; 6]) -> [f64; 3] {
    let off = xy * xy + xz * xz + yz * yz;
    if off == 0.0 {
        let mut d = [xx, yy, zz];
        d.sort_by(f64::total_cmp);
        return d;
    }
    let q = (xx + yy + zz) / 3.0;
    let (a, b, c) = (xx - q, yy - q, zz - q);
    let p = ((a * a + b * b + c * c + 2.0 * off) / 6.0).sqrt();
    // det((A - qI) / p) / 2, in [-1, 1] up to rounding.
    let det = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
    let r = (det / (2.0 * p * p * p)).clamp(-1.0, 1.0);
    let phi = r.acos() / 3.0;
    let hi = q + 2.0 * p * phi.cos();
    let lo = q + 2.0 * p * (phi + 2.0 * std::f64::consts::PI / 3.0).cos();
    [lo, 3.0 * q - hi - lo, hi]
}

#[cfg(test)]
mod tests {
    use super::principal_moments;

    #[test]
    fn principal_moments_of_a_rotated_tensor() {
        // diag(1, 2, 3) turned 45 degrees about z: [[1.5, -0.5, 0], [-0.5, 1.5, 0], [0, 0, 3]].
        let p = principal_moments([1.5, 1.5, 3.0, -0.5, 0.0, 0.0]);
        for (got, want) in p.iter().zip([1.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-12, "{p:?}");
        }
        // [[1, 2, 0], [2, 1, 0], [0, 0, 1]]: eigenvalues -1, 1, 3.
        let p = principal_moments([1.0, 1.0, 1.0, 2.0, 0.0, 0.0]);
        for (got, want) in p.iter().zip([-1.0, 1.0, 3.0]) {
            assert!((got - want).abs() < 1e-12, "{p:?}");
        }
    }
}
