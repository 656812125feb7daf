//! Elastic material of a soft body, and the contact parameters of a fingertip (material and
//! radius, or two soft bodies combined).

use crate::backing::Backing;
use crate::error::{Error, Result, positive};

/// An isotropic elastic material: Young's modulus `E` and Poisson ratio `nu`.
///
/// Validated at construction; the fields are private so an invalid material cannot exist.
///
/// ```
/// use softgrip_law::Material;
/// let m = Material::try_from_shear_modulus(1.0e6, 0.49).unwrap();
/// // E = 2 mu (1 + nu), E* = E / (1 - nu^2)
/// assert!((m.youngs_modulus() - 2.98e6).abs() < 1e-3);
/// assert!((m.effective_modulus() - 2.98e6 / (1.0 - 0.49 * 0.49)).abs() < 1e-3);
/// assert!(Material::try_new(-3.0e6, 0.3).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    youngs_modulus: f64,
    poisson_ratio: f64,
}

impl Material {
    /// Material from Young's modulus `youngs_modulus` E \[Pa\] (finite, > 0) and Poisson ratio
    /// `poisson_ratio` nu [-] (in (-1, 0.5]).
    pub fn try_new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        positive("youngs_modulus", youngs_modulus, "finite and > 0 Pa")?;
        check_nu(poisson_ratio)?;
        Ok(Self {
            youngs_modulus,
            poisson_ratio,
        })
    }

    /// Material from the shear modulus `shear_modulus` mu \[Pa\] (finite, > 0) and Poisson ratio
    /// nu [-] (in (-1, 0.5]): `E = 2 mu (1 + nu)`.
    pub fn try_from_shear_modulus(shear_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        positive("shear_modulus", shear_modulus, "finite and > 0 Pa")?;
        check_nu(poisson_ratio)?;
        Self::try_new(2.0 * shear_modulus * (1.0 + poisson_ratio), poisson_ratio)
    }

    /// Material from the effective (plane-strain) modulus `effective_modulus`
    /// E* = E / (1 - nu^2) \[Pa\] (finite, > 0), as measured by a Hertz fit, and the Poisson
    /// ratio nu [-] (in (-1, 0.5]; use 0.5 for rubbers and cells when it is unknown).
    pub fn try_from_effective_modulus(effective_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        positive("effective_modulus", effective_modulus, "finite and > 0 Pa")?;
        check_nu(poisson_ratio)?;
        Self::try_new(
            effective_modulus * (1.0 - poisson_ratio * poisson_ratio),
            poisson_ratio,
        )
    }

    /// Young's modulus E \[Pa\].
    pub fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Poisson ratio nu [-].
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// Shear modulus mu = E / (2 (1 + nu)) \[Pa\].
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Effective modulus E* = E / (1 - nu^2) \[Pa\] against a rigid body.
    pub fn effective_modulus(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }

    /// Compliance (1 - nu^2) / E [1/Pa], the quantity that adds for two soft bodies.
    pub fn compliance(&self) -> f64 {
        1.0 / self.effective_modulus()
    }
}

fn check_nu(nu: f64) -> Result<f64> {
    if nu.is_finite() && nu > -1.0 && nu <= 0.5 {
        Ok(nu)
    } else {
        Err(Error::InvalidParameter {
            field: "poisson_ratio",
            value: nu,
            range: "finite and in (-1, 0.5]",
        })
    }
}

/// Validated inputs of a contact law: effective modulus, effective radius and the Poisson
/// ratio that the large-deformation levels use.
///
/// For a fingertip on a rigid body these are the fingertip's own E*, R and nu
/// ([`ContactParams::try_new`]); for two soft spheres they are combined
/// ([`ContactParams::try_combine`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactParams {
    effective_modulus: f64,
    radius: f64,
    poisson_ratio: f64,
    backing: Backing,
}

impl ContactParams {
    /// A soft sphere of radius `radius` R \[m\] (finite, > 0) made of `material`, pressed on a
    /// rigid flat body.
    ///
    /// ```
    /// use softgrip_law::{ContactParams, Material};
    /// let m = Material::try_new(3.0e6, 0.49).unwrap();
    /// assert!(ContactParams::try_new(m, 0.01).is_ok());
    /// let err = ContactParams::try_new(m, -0.01).unwrap_err();
    /// assert!(err.to_string().contains("`radius` must be finite and > 0 m"));
    /// ```
    pub fn try_new(material: Material, radius: f64) -> Result<Self> {
        positive("radius", radius, "finite and > 0 m")?;
        scales(material.effective_modulus(), radius)?;
        Ok(Self {
            effective_modulus: material.effective_modulus(),
            radius,
            poisson_ratio: material.poisson_ratio(),
            backing: Backing::Free,
        })
    }

    /// Two soft spheres in contact: `1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2`,
    /// `R = R1 R2 / (R1 + R2)`. A radius of `f64::INFINITY` stands for a flat body.
    ///
    /// The large-deformation levels also need one Poisson ratio: the compliance-weighted mean
    /// `nu = (c1 nu1 + c2 nu2) / (c1 + c2)`, `ci = (1 - nui^2)/Ei`, which is exact when one body
    /// is rigid or both are of one material. This is an approximation of the model, which is
    /// derived for one sphere on a rigid plate: treat the large-deformation part of a
    /// soft-on-soft contact as an estimate.
    ///
    /// ```
    /// use softgrip_law::{ContactParams, Material};
    /// let m = Material::try_new(1.0e6, 0.5).unwrap();
    /// let p = ContactParams::try_combine(m, 0.01, m, 0.01).unwrap();
    /// assert!((p.radius() - 0.005).abs() < 1e-15);
    /// assert!((p.effective_modulus() - 0.5 * m.effective_modulus()).abs() < 1e-6);
    /// ```
    pub fn try_combine(
        material1: Material,
        radius1: f64,
        material2: Material,
        radius2: f64,
    ) -> Result<Self> {
        for (field, r) in [("radius1", radius1), ("radius2", radius2)] {
            if r.is_nan() || r <= 0.0 {
                return Err(Error::InvalidParameter {
                    field,
                    value: r,
                    range: "> 0 m (infinite for a flat body)",
                });
            }
        }
        if radius1.is_infinite() && radius2.is_infinite() {
            return Err(Error::InvalidParameter {
                field: "radius1",
                value: radius1,
                range: "finite for at least one of the two bodies",
            });
        }
        // 1/R = 1/R1 + 1/R2, with 1/inf = 0 for a flat body.
        let radius = 1.0 / (1.0 / radius1 + 1.0 / radius2);
        // A subnormal radius (5e-324) has 1/R = inf: the combined R would be 0 (found by
        // tests/fuzz_law.rs).
        positive("radius", radius, "finite and > 0 m (1/R = 1/R1 + 1/R2)")?;
        let (c1, c2) = (material1.compliance(), material2.compliance());
        positive(
            "effective_modulus",
            1.0 / (c1 + c2),
            "finite and > 0 Pa (1/E* = sum of (1 - nu^2)/E)",
        )?;
        scales(1.0 / (c1 + c2), radius)?;
        Ok(Self {
            effective_modulus: 1.0 / (c1 + c2),
            radius,
            poisson_ratio: (c1 * material1.poisson_ratio() + c2 * material2.poisson_ratio())
                / (c1 + c2),
            backing: Backing::Free,
        })
    }

    /// Two soft bodies given by their own parameters (each a body on a rigid plane), combined as
    /// [`try_combine`](Self::try_combine) does (`1/E* = 1/E1* + 1/E2*`, `1/R = 1/R1 + 1/R2`,
    /// compliance-weighted nu). Only free spheres combine: the combined law is the free sphere's,
    /// and no law exists for a bonded pad pressed on another soft body, so a backed one is
    /// [`Error::IncompatibleBacking`].
    ///
    /// ```
    /// use softgrip_law::{Backing, ContactParams, Error, Material};
    /// let m = Material::try_new(1.0e6, 0.49).unwrap();
    /// let free = ContactParams::try_new(m, 0.01).unwrap();
    /// assert!(ContactParams::try_combine_params(&free, &free).is_ok());
    /// let flat = free.with_backing(Backing::Flat).unwrap();
    /// let err = ContactParams::try_combine_params(&free, &flat).unwrap_err();
    /// assert!(matches!(err, Error::IncompatibleBacking { second: "flat", .. }));
    /// ```
    pub fn try_combine_params(first: &ContactParams, second: &ContactParams) -> Result<Self> {
        if !(first.backing.is_free() && second.backing.is_free()) {
            return Err(Error::IncompatibleBacking {
                first: first.backing.name(),
                second: second.backing.name(),
            });
        }
        let m = |p: &ContactParams| {
            Material::try_from_effective_modulus(p.effective_modulus, p.poisson_ratio)
        };
        Self::try_combine(m(first)?, first.radius, m(second)?, second.radius)
    }

    /// The same contact with the fingertip built as `backing`. A [`Backing::Core`] needs a
    /// finite skin thickness `0 < t < R` \[m\] ([`Error::InvalidParameter`] naming `thickness`
    /// otherwise).
    ///
    /// ```
    /// use softgrip_law::{Backing, ContactParams, Material};
    /// let p = ContactParams::try_new(Material::try_new(1.0e6, 0.49).unwrap(), 0.01).unwrap();
    /// let core = p.with_backing(Backing::Core { thickness: 0.004 }).unwrap();
    /// assert_eq!(core.thickness_ratio(), Some(0.4));
    /// let err = p.with_backing(Backing::Core { thickness: 0.01 }).unwrap_err();
    /// assert!(err.to_string().contains("`thickness` must be"));
    /// ```
    pub fn with_backing(self, backing: Backing) -> Result<Self> {
        if let Backing::Core { thickness } = backing {
            if !(thickness > 0.0 && thickness < self.radius && thickness.is_finite()) {
                return Err(Error::InvalidParameter {
                    field: "thickness",
                    value: thickness,
                    range: "finite and in (0, R) m, R the fingertip's outer radius",
                });
            }
            // t/R must be representable away from 0 and 1 (the law is a function of t/R).
            let ratio = thickness / self.radius;
            if !(ratio > 0.0 && ratio < 1.0) {
                return Err(Error::InvalidParameter {
                    field: "thickness",
                    value: thickness,
                    range: "in (0, R) m with t/R strictly between 0 and 1",
                });
            }
        }
        Ok(Self { backing, ..self })
    }

    /// How the fingertip is built ([`Backing::Free`] unless set by
    /// [`with_backing`](Self::with_backing)).
    pub fn backing(&self) -> Backing {
        self.backing
    }

    /// Skin thickness over outer radius t/R [-] of a [`Backing::Core`], else `None`.
    pub fn thickness_ratio(&self) -> Option<f64> {
        self.backing.thickness().map(|t| t / self.radius)
    }

    /// Parameters given directly: E* \[Pa\] (finite, > 0), R \[m\] (finite, > 0), nu [-]
    /// (in (-1, 0.5]).
    pub fn try_from_parts(effective_modulus: f64, radius: f64, poisson_ratio: f64) -> Result<Self> {
        let m = Material::try_from_effective_modulus(effective_modulus, poisson_ratio)?;
        Self::try_new(m, radius)
    }

    /// Effective modulus E* \[Pa\].
    pub fn effective_modulus(&self) -> f64 {
        self.effective_modulus
    }

    /// Effective radius R \[m\].
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Poisson ratio nu [-] used by the large-deformation levels.
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }
}

/// Room the law's scales keep below `f64::MAX` (see `scales`).
const SCALE_HEADROOM: f64 = 1e12;

/// The law's scales stay finite and non-zero: the force `E* R^2`, the energy `E* R^3` and
/// `1/R` (found by tests/fuzz_law.rs: R = 1e308 gave an infinite force scale and `response`
/// returned inf; R = 1e-200 a zero one and `compression_for_force(0)` returned NaN).
///
/// Each scale keeps [`SCALE_HEADROOM`] of room below `f64::MAX`: the normalised law multiplies
/// them by up to ~1e3 (force, stiffness past the validity range), and E* = 1.3e308 with
/// R = 0.19 m passed an `E* R^3` check yet gave an infinite stiffness (tests/fuzz_law.rs).
fn scales(effective_modulus: f64, radius: f64) -> Result<()> {
    let energy = effective_modulus * radius * radius * radius;
    let force = effective_modulus * radius * radius;
    let stiffness = effective_modulus * radius;
    let room = |v: f64| (v * SCALE_HEADROOM).is_finite();
    // force > 0: a scale that underflows to 0 made `compression_for_force(0)` NaN (0/0).
    if !room(effective_modulus) {
        return Err(Error::InvalidParameter {
            field: "effective_modulus",
            value: effective_modulus,
            range: "small enough that 1e12 E* [Pa] is finite",
        });
    }
    if room(energy) && room(force) && room(stiffness) && force > 0.0 && (1.0 / radius).is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            field: "radius",
            value: radius,
            range: "small enough that 1e12 E* R^3 [J] and 1e12 E* R [N/m] are finite, large enough that E* R^2 [N] > 0",
        })
    }
}
