//! [`FingertipLaw`]: a fingertip's law parameters, as written in the recording's metadata (and
//! read back by `softgrip inspect` and `softgrip plot`).

use std::fmt;

use serde::{Deserialize, Serialize};
use softgrip_law::{Backing, ContactLaw, ContactParams, Level, Material};

/// A fingertip's law, as recorded (JSON in the `law` value of the `softgrip` metadata):
/// `{"name":"left_tip","level":{"name":"auto","tolerance":0.01},"youngs_modulus":590000.0,...,
/// "backing":"core","core_thickness":0.004}` (`backing` absent in recordings made before
/// issue 10: read as `free`; `core_thickness` only for `core`).
///
/// ```
/// use softgrip_law::{Backing, Level};
/// use softgrip_record::FingertipLaw;
/// let law = FingertipLaw {
///     name: "thumb".into(),
///     level: Level::auto(),
///     youngs_modulus: 5.9e5,
///     poisson_ratio: 0.49,
///     radius: 0.01,
///     friction: 0.8,
///     restitution: 0.5,
///     backing: Backing::Core { thickness: 0.004 },
/// };
/// let json = serde_json::to_string(&law).unwrap();
/// assert!(json.ends_with(r#""backing":"core","core_thickness":0.004}"#), "{json}");
/// assert_eq!(serde_json::from_str::<FingertipLaw>(&json).unwrap(), law);
/// assert_eq!(law.law().unwrap().params().backing(), law.backing);
/// assert!(law.law().unwrap().response(1e-3).force > 0.0); // N at 1 mm
/// // Before issue 10 the metadata had no backing: a free sphere.
/// let old = json.replace(r#","backing":"core","core_thickness":0.004"#, "");
/// assert_eq!(serde_json::from_str::<FingertipLaw>(&old).unwrap().backing, Backing::Free);
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FingertipLaw {
    /// Fingertip name.
    pub name: String,
    /// The level as configured (with its setting: `k`, `tolerance` or `match_x`).
    #[serde(with = "level_json")]
    pub level: Level,
    /// Young's modulus E \[Pa\], > 0.
    pub youngs_modulus: f64,
    /// Poisson ratio nu [-], in (-1, 0.5].
    pub poisson_ratio: f64,
    /// Radius R \[m\], > 0.
    pub radius: f64,
    /// Coulomb friction coefficient [-], >= 0.
    pub friction: f64,
    /// Coefficient of restitution e [-], in [0, 1].
    pub restitution: f64,
    /// How the fingertip is built (JSON `backing` = `free` | `flat` | `core`, and
    /// `core_thickness` \[m\] for `core`); its law is that construction's.
    #[serde(flatten, with = "backing_json")]
    pub backing: Backing,
}

impl FingertipLaw {
    /// The law (fails only for parameters no scene could have had).
    pub fn law(&self) -> Result<ContactLaw, softgrip_law::Error> {
        self.law_at(self.level)
    }

    /// The same fingertip with another level (for overlays: Hertz, Tatara, ...).
    pub fn law_at(&self, level: Level) -> Result<ContactLaw, softgrip_law::Error> {
        let material = Material::try_new(self.youngs_modulus, self.poisson_ratio)?;
        let params = ContactParams::try_new(material, self.radius)?.with_backing(self.backing)?;
        ContactLaw::try_new(params, level)
    }
}

impl fmt::Display for FingertipLaw {
    /// One line for people: `NAME: level=auto tolerance=0.01 youngs_modulus=590000 ...`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: level={}", self.name, self.level.name())?;
        match self.level {
            Level::Fit { k } => write!(f, " k={k}")?,
            Level::Auto { tolerance } => write!(f, " tolerance={tolerance}")?,
            Level::Linear { match_x } => write!(f, " match_x={match_x}")?,
            _ => {}
        }
        write!(
            f,
            " youngs_modulus={} poisson_ratio={} radius={} friction={} restitution={}",
            self.youngs_modulus, self.poisson_ratio, self.radius, self.friction, self.restitution
        )?;
        write!(f, " backing={}", self.backing.name())?;
        match self.backing.thickness() {
            Some(t) => write!(f, " core_thickness={t}"),
            None => Ok(()),
        }
    }
}

/// A [`Backing`] as `"backing": "core", "core_thickness": 0.004` (flattened into the law's
/// object; a missing `backing` is `free`).
mod backing_json {
    use serde::de::Error as _;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};
    use softgrip_law::Backing;

    #[derive(Serialize, Deserialize)]
    struct BackingJson {
        #[serde(default = "free")]
        backing: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        core_thickness: Option<f64>,
    }

    fn free() -> String {
        Backing::Free.name().to_owned()
    }

    pub(super) fn serialize<S: Serializer>(backing: &Backing, s: S) -> Result<S::Ok, S::Error> {
        BackingJson {
            backing: backing.name().to_owned(),
            core_thickness: backing.thickness(),
        }
        .serialize(s)
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Backing, D::Error> {
        let json = BackingJson::deserialize(d)?;
        match (json.backing.as_str(), json.core_thickness) {
            ("core", Some(thickness)) => Ok(Backing::Core { thickness }),
            ("core", None) => Err(D::Error::custom("backing `core` needs `core_thickness`")),
            (name, None) => name.parse().map_err(D::Error::custom),
            (name, Some(_)) => Err(D::Error::custom(format!(
                "`core_thickness` applies only to backing `core`, not `{name}`"
            ))),
        }
    }
}

/// A [`Level`] as `{"name": "auto", "tolerance": 0.01}` (the level's name and its setting, if
/// it has one).
mod level_json {
    use serde::de::Error as _;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};
    use softgrip_law::Level;

    #[derive(Serialize, Deserialize)]
    struct LevelJson {
        name: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        k: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        tolerance: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        match_x: Option<f64>,
    }

    pub(super) fn serialize<S: Serializer>(level: &Level, s: S) -> Result<S::Ok, S::Error> {
        let mut json = LevelJson {
            name: level.name().to_owned(),
            k: None,
            tolerance: None,
            match_x: None,
        };
        match *level {
            Level::Fit { k } => json.k = Some(k),
            Level::Auto { tolerance } => json.tolerance = Some(tolerance),
            Level::Linear { match_x } => json.match_x = Some(match_x),
            _ => {}
        }
        json.serialize(s)
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Level, D::Error> {
        let json = LevelJson::deserialize(d)?;
        let mut level: Level = json.name.parse().map_err(D::Error::custom)?;
        let setting = |v: Option<f64>, key: &str| {
            v.ok_or_else(|| D::Error::custom(format!("level `{}` needs `{key}`", json.name)))
        };
        match &mut level {
            Level::Fit { k } => *k = setting(json.k, "k")?,
            Level::Auto { tolerance } => *tolerance = setting(json.tolerance, "tolerance")?,
            Level::Linear { match_x } => *match_x = setting(json.match_x, "match_x")?,
            _ => {}
        }
        Ok(level)
    }
}
