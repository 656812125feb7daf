//! [`FingertipLaw`]: a fingertip's law parameters, as written in the recording's metadata (and
//! read back by `softgrip inspect` and `softgrip plot`).

use std::fmt;

use serde::{Deserialize, Serialize};
use softgrip_law::{
    Backing, ContactLaw, ContactParams, Level, LevelData, Material, TabulatedCurve,
};

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
///     curve: None,
///     custom_name: None,
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
    /// The curve of a level that its name and the parameters above do not rebuild
    /// ([`ContactLaw::recorded_curve`]): a `tabulated` level's measured curve, a `custom`
    /// level's sampled one; `None` for the others (JSON `curve`: `{"delta_m": [...],
    /// "force_n": [...]}` in m and N, absent when `None`; recordings made before it was
    /// written have none, and their `tabulated` law then reads as parameters without a law).
    #[serde(default, with = "curve_json", skip_serializing_if = "Option::is_none")]
    pub curve: Option<TabulatedCurve>,
    /// A `custom` level's own name ([`softgrip_law::NormalisedLaw::name`]; JSON
    /// `custom_name`, absent for other levels).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub custom_name: Option<String>,
}

impl FingertipLaw {
    /// The law as recorded: a level that the parameters rebuild, or the recorded
    /// [`curve`](Self::curve) of a `tabulated` or `custom` level (a custom law reads back as
    /// the `tabulated` law of its sampled curve). Fails for parameters no scene could have
    /// had, and for a `tabulated` or `custom` level without a curve (a recording made before
    /// curves were recorded: [`softgrip_law::Error::LevelNeedsData`]).
    pub fn law(&self) -> Result<ContactLaw, softgrip_law::Error> {
        match (self.level.info().data, &self.curve) {
            (LevelData::None, _) => self.law_at(self.level),
            (_, Some(curve)) => ContactLaw::tabulated(self.params()?, curve.clone()),
            (_, None) => ContactLaw::try_new(self.params()?, self.level),
        }
    }

    /// The same fingertip with another level that its parameters build (for overlays:
    /// Hertz, Tatara, ...).
    pub fn law_at(&self, level: Level) -> Result<ContactLaw, softgrip_law::Error> {
        ContactLaw::try_new(self.params()?, level)
    }

    /// The contact parameters: material, radius and construction.
    pub fn params(&self) -> Result<ContactParams, softgrip_law::Error> {
        let material = Material::try_new(self.youngs_modulus, self.poisson_ratio)?;
        ContactParams::try_new(material, self.radius)?.with_backing(self.backing)
    }
}

impl fmt::Display for FingertipLaw {
    /// One line for people: `NAME: level=auto tolerance=0.01 youngs_modulus=590000 ...`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: level={}", self.name, self.level.name())?;
        for setting in self.level.info().settings {
            if let Some(value) = (setting.get)(&self.level) {
                write!(f, " {}={value}", setting.key)?;
            }
        }
        if let Some(name) = &self.custom_name {
            write!(f, " custom_name={name}")?;
        }
        if let Some(curve) = &self.curve {
            write!(
                f,
                " curve_samples={} curve_delta_max={} curve_force_max={}",
                curve.delta_m().len(),
                curve.delta_max(),
                curve.force_max()
            )?;
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
/// object; a missing `backing` is `free`), through the law's one parser
/// ([`Backing::try_from_parts`], the table `softgrip_law::BACKINGS`).
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
        Backing::try_from_parts(&json.backing, json.core_thickness).map_err(D::Error::custom)
    }
}

/// A [`Level`] as `{"name": "auto", "tolerance": 0.01}`: the level's name and its settings,
/// each under its key of `softgrip_law::LEVELS` (`match_x`, `k`, `tolerance`). A level's
/// every setting is written; one missing on reading is an error (every recording has written
/// them since levels had settings).
mod level_json {
    use std::collections::BTreeMap;

    use serde::de::Error as _;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};
    use softgrip_law::Level;

    #[derive(Serialize, Deserialize)]
    struct LevelJson {
        name: String,
        #[serde(flatten)]
        settings: BTreeMap<String, f64>,
    }

    pub(super) fn serialize<S: Serializer>(level: &Level, s: S) -> Result<S::Ok, S::Error> {
        let settings = level
            .info()
            .settings
            .iter()
            .filter_map(|setting| (setting.get)(level).map(|v| (setting.key.to_owned(), v)))
            .collect();
        LevelJson {
            name: level.name().to_owned(),
            settings,
        }
        .serialize(s)
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Level, D::Error> {
        let json = LevelJson::deserialize(d)?;
        let mut level = Level::from_name(&json.name).map_err(D::Error::custom)?;
        for (key, value) in &json.settings {
            level = level.with_setting(key, *value).map_err(D::Error::custom)?;
        }
        match level
            .info()
            .settings
            .iter()
            .find(|s| !json.settings.contains_key(s.key))
        {
            Some(missing) => Err(D::Error::custom(format!(
                "level `{}` needs `{}`",
                json.name, missing.key
            ))),
            None => Ok(level),
        }
    }
}

/// A [`TabulatedCurve`] as `{"delta_m": [...], "force_n": [...]}` (the samples as
/// [`TabulatedCurve::try_new`] takes them: without the origin it adds).
mod curve_json {
    use serde::de::Error as _;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};
    use softgrip_law::TabulatedCurve;

    #[derive(Serialize, Deserialize)]
    struct CurveJson {
        delta_m: Vec<f64>,
        force_n: Vec<f64>,
    }

    pub(super) fn serialize<S: Serializer>(
        curve: &Option<TabulatedCurve>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        curve
            .as_ref()
            .map(|c| CurveJson {
                delta_m: c.delta_m().to_vec(),
                force_n: c.force_n().to_vec(),
            })
            .serialize(s)
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<Option<TabulatedCurve>, D::Error> {
        Option::<CurveJson>::deserialize(d)?
            .map(|c| TabulatedCurve::try_new(c.delta_m, c.force_n).map_err(D::Error::custom))
            .transpose()
    }
}
