//! Literature materials for fingertips and cells.

use softgrip_law::Material;

/// A material from the literature. The values are typical, not a calibration of your batch:
/// fit your own (see `softgrip_law::fitting`) when accuracy matters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Preset {
    /// Smooth-On Ecoflex 00-30: shear modulus mu = 40.7 kPa, nu = 0.5 (the paper's Hertz fit
    /// of a 10 mm sphere on x <= 0.1; MODEL.md). E = 3 mu = 122.1 kPa.
    Ecoflex0030,
    /// Smooth-On Dragon Skin 10: E ~ 0.15 MPa (approximate; the 100 % tensile modulus in the
    /// manufacturer's data sheet is 0.15 MPa), nu = 0.49.
    DragonSkin10,
    /// Smooth-On Dragon Skin 20: E ~ 0.34 MPa (approximate; 100 % modulus 0.34 MPa, data
    /// sheet), nu = 0.49.
    DragonSkin20,
    /// Smooth-On Dragon Skin 30: E ~ 0.59 MPa (approximate; 100 % modulus 0.59 MPa, data
    /// sheet), nu = 0.49.
    DragonSkin30,
    /// Dow Sylgard 184 (10:1, cured at room temperature to 100 C): E ~ 1.5 MPa (approximate;
    /// Johnston et al. 2014, J. Micromech. Microeng. 24 035017, report 1.32-2.97 MPa depending
    /// on the cure), nu = 0.49.
    Sylgard184,
    /// Live human mesenchymal stem cell (Tartibi et al. 2015, via MODEL.md): E* = 20.8 kPa,
    /// nu = 0.5 (assumed), measured radius R = 14.2 um.
    LiveCell,
    /// Fixed (stained) human mesenchymal stem cell (Tartibi et al. 2015, via MODEL.md):
    /// E* = 42.2 MPa, nu = 0.5 (assumed), measured radius R = 15.4 um.
    FixedCell,
}

impl Preset {
    /// Every preset.
    pub const ALL: [Preset; 7] = [
        Preset::Ecoflex0030,
        Preset::DragonSkin10,
        Preset::DragonSkin20,
        Preset::DragonSkin30,
        Preset::Sylgard184,
        Preset::LiveCell,
        Preset::FixedCell,
    ];

    /// The preset's material.
    pub fn material(self) -> Material {
        let m = match self {
            Preset::Ecoflex0030 => Material::try_from_shear_modulus(40.7e3, 0.5),
            Preset::DragonSkin10 => Material::try_new(0.15e6, 0.49),
            Preset::DragonSkin20 => Material::try_new(0.34e6, 0.49),
            Preset::DragonSkin30 => Material::try_new(0.59e6, 0.49),
            Preset::Sylgard184 => Material::try_new(1.5e6, 0.49),
            Preset::LiveCell => Material::try_from_effective_modulus(20.8e3, 0.5),
            Preset::FixedCell => Material::try_from_effective_modulus(42.2e6, 0.5),
        };
        m.expect("invariant: preset values are finite, positive, and nu is in (-1, 0.5]")
    }

    /// The radius measured with the material, for the cell presets \[m\]; `None` for rubbers.
    pub fn measured_radius(self) -> Option<f64> {
        match self {
            Preset::LiveCell => Some(14.2e-6),
            Preset::FixedCell => Some(15.4e-6),
            _ => None,
        }
    }

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Preset::Ecoflex0030 => "ecoflex-00-30",
            Preset::DragonSkin10 => "dragon-skin-10",
            Preset::DragonSkin20 => "dragon-skin-20",
            Preset::DragonSkin30 => "dragon-skin-30",
            Preset::Sylgard184 => "sylgard-184",
            Preset::LiveCell => "live-cell",
            Preset::FixedCell => "fixed-cell",
        }
    }
}
