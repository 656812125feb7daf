//! Fingertip checks: every `[[fingertip]]` built into the plugin's [`SoftFingertip`], its
//! material from a preset or constants, its law from a level name or a measured curve.

use std::collections::{HashMap, HashSet};
use std::path::Path;

use softgrip_law::{
    Backing, ContactLaw, ContactParams, Level, LevelData, MIN_CORE_THICKNESS_RATIO, Material,
    Shortest, TabulatedCurve,
};
use softgrip_rapier::{Preset, SoftFingertip, SoftFingertipBuilder};

use crate::control::Carrier;
use crate::curve::{MeasuredCurve, read_curve};
use crate::error::SceneError;
use crate::format::{FingertipSpec, SceneFile};
use crate::level::LevelSpec;
use crate::limits::{MAX_DENSITY, MIN_DENSITY};
use crate::robot::Robot;
use crate::validate::Checker;

/// Builds every fingertip (the plugin validates radius, restitution, friction and material)
/// and finds what carries it: a body, or a robot's link.
pub(crate) fn check_fingertips(
    c: &Checker,
    file: &SceneFile,
    robots: &[Robot],
    base: &Path,
) -> Result<(Vec<SoftFingertip>, Vec<Carrier>), SceneError> {
    let mut names = HashSet::new();
    // By name, so that N fingertips on N bodies check in O(N).
    let bodies: HashMap<&str, usize> = (file.bodies.iter().enumerate())
        .map(|(i, b)| (b.name.as_str(), i))
        .collect();
    let mut tips = Vec::new();
    let mut carriers = Vec::new();
    for (i, t) in file.fingertips.iter().enumerate() {
        let f = |s: &str| format!("fingertip[{i}].{s}");
        if t.name.is_empty() || !names.insert(t.name.as_str()) {
            return Err(c.name(f("name"), format!("`{}` is empty or used twice", t.name)));
        }
        carriers.push(carrier(c, t, &bodies, robots, &f)?);
        c.coords(f("offset"), t.offset)?;
        c.range(
            f("density"),
            t.density,
            (MIN_DENSITY, MAX_DENSITY),
            "kg/m^3",
        )?;
        let material = material(c, t, &f)?;
        let law = law(c, t, &f, base)?;
        let backing = backing(c, t, &f)?;
        check_core_ratio(c, t, &f, backing, &law)?;
        let builder = SoftFingertip::builder(t.radius)
            .name(t.name.clone())
            .material(material)
            .restitution(t.restitution)
            .friction(t.friction)
            .backing(backing);
        let builder = match t.facing {
            Some(d) => builder.facing(d),
            None => builder,
        };
        let builder = match &t.tactile {
            Some(pad) => builder.tactile(pad.pad()),
            None => builder,
        };
        let builder = match law {
            TipLaw::Level(level) => builder.level(level),
            TipLaw::Tabulated(curve) => {
                tabulated_law(c, &f("level"), builder, material, t.radius, backing, curve)?
            }
        };
        let tip = builder.build().map_err(|e| SceneError::Fingertip {
            origin: c.origin.to_string(),
            // A pad's error names its key: `fingertip[0].tactile.rows`.
            field: match &e {
                softgrip_rapier::Error::InvalidTactilePad { field, .. } => f(field),
                softgrip_rapier::Error::MissingFacing(_) => f("facing"),
                softgrip_rapier::Error::InvalidParameter { field, .. } if *field == "facing" => {
                    f("facing")
                }
                _ => format!("fingertip[{i}]"),
            },
            source: e,
        })?;
        tips.push(tip);
    }
    Ok((tips, carriers))
}

/// What carries fingertip `t`: exactly one of `body` (a body's name) and `link`
/// (`<robot>/<link>`).
fn carrier(
    c: &Checker,
    t: &FingertipSpec,
    bodies: &HashMap<&str, usize>,
    robots: &[Robot],
    f: &dyn Fn(&str) -> String,
) -> Result<Carrier, SceneError> {
    match (&t.body, &t.link) {
        (Some(body), None) => (bodies.get(body.as_str()))
            .map(|&i| Carrier::Body(i))
            .ok_or_else(|| c.name(f("body"), format!("no body is named `{body}`"))),
        (None, Some(link)) => {
            let (robot, name) = link
                .split_once('/')
                .ok_or_else(|| c.name(f("link"), format!("`{link}`: expected `<robot>/<link>`")))?;
            let r = (robots.iter().position(|r| r.name() == robot)).ok_or_else(|| {
                c.name(
                    f("link"),
                    format!(
                        "no robot is named `{robot}` (robots: {})",
                        crate::control::robot_names(robots)
                    ),
                )
            })?;
            let l = robots[r].link_index(name).ok_or_else(|| {
                c.name(
                    f("link"),
                    format!(
                        "robot `{robot}` has no link `{name}` (links without collision, visual or inertial are merged into their parent)"
                    ),
                )
            })?;
            Ok(Carrier::Link { robot: r, link: l })
        }
        _ => Err(c.name(f("body"), "give exactly one of `body` and `link`")),
    }
}

/// The material of a fingertip: a preset by name, or the constants.
fn material(
    c: &Checker,
    t: &FingertipSpec,
    f: &dyn Fn(&str) -> String,
) -> Result<Material, SceneError> {
    match (&t.preset, &t.material) {
        (Some(p), None) => Preset::ALL
            .iter()
            .find(|q| q.name() == p)
            .map(|q| q.material())
            .ok_or_else(|| {
                let all: Vec<_> = Preset::ALL.iter().map(|q| q.name()).collect();
                c.invalid(f("preset"), p, &format!("one of {}", all.join(", ")))
            }),
        // The law names the constant at fault: `fingertip[0].material.poisson_ratio` must be
        // in (-1, 0.5], got -1 (was "`fingertip[0].material` must be `poisson_ratio` must be").
        (None, Some(m)) => {
            Material::try_new(m.youngs_modulus, m.poisson_ratio).map_err(|e| match e {
                softgrip_law::Error::InvalidParameter {
                    field,
                    value,
                    range,
                } => c.invalid(f(&format!("material.{field}")), value, range),
                e => c.name(f("material"), e.to_string()),
            })
        }
        _ => Err(c.name(f("preset"), "give exactly one of `preset` and `material`")),
    }
}

/// The fingertip's construction: `backing` and `core_thickness` through the law's one parser
/// ([`Backing::try_from_parts`], the table `softgrip_law::BACKINGS`), the thickness then
/// against the radius (in (0, radius)).
fn backing(
    c: &Checker,
    t: &FingertipSpec,
    f: &dyn Fn(&str) -> String,
) -> Result<Backing, SceneError> {
    let name = t.backing.as_deref().unwrap_or(Backing::Free.name());
    let range = |key: &str| {
        format!(
            "finite and in (0, radius) m, radius = {} m (the skin's thickness `{key}`)",
            Shortest(t.radius)
        )
    };
    let backing = Backing::try_from_parts(name, t.core_thickness).map_err(|e| match e {
        softgrip_law::Error::InvalidParameter { field, value, .. } => {
            c.invalid(f(field), value, &range(field))
        }
        e => kind_error(c, f, e),
    })?;
    match (backing.thickness(), backing.info().parameter) {
        (Some(thickness), Some(p)) if thickness >= t.radius => {
            Err(c.invalid(f(p.key), thickness, &range(p.key)))
        }
        _ => Ok(backing),
    }
}

/// A `core` skin thinner than the calibrated level's form holds
/// ([`MIN_CORE_THICKNESS_RATIO`] R): an error naming `core_thickness` for the levels that use
/// the form (`calibrated`, `auto`); a measured curve holds any thickness.
fn check_core_ratio(
    c: &Checker,
    t: &FingertipSpec,
    f: &dyn Fn(&str) -> String,
    backing: Backing,
    law: &TipLaw,
) -> Result<(), SceneError> {
    let (Backing::Core { thickness }, TipLaw::Level(level)) = (backing, law) else {
        return Ok(());
    };
    if !matches!(level, Level::Calibrated | Level::Auto { .. }) {
        return Ok(());
    }
    let min = MIN_CORE_THICKNESS_RATIO * t.radius;
    if thickness >= min {
        return Ok(());
    }
    let range = format!(
        "in [{} m, radius) for level `{}` (t/R >= {MIN_CORE_THICKNESS_RATIO}, radius = {} m: the calibrated core form is validated down to there; a thinner skin needs `level = {{ tabulated = \"curve.csv\" }}`)",
        Shortest(min),
        level.name(),
        Shortest(t.radius)
    );
    Err(c.invalid(f("core_thickness"), thickness, &range))
}

/// A law error about a fingertip's kinds (a level or backing name, a setting given to the
/// wrong one or missing) as the scene's error naming the fingertip's key.
fn kind_error(c: &Checker, f: &dyn Fn(&str) -> String, e: softgrip_law::Error) -> SceneError {
    use softgrip_law::Error as E;
    match e {
        E::UnknownName {
            field,
            value,
            expected,
        } => c.invalid(f(field), value, &format!("one of {expected}")),
        E::UnexpectedSetting {
            field, kind, name, ..
        } => c.name(
            f(field),
            format!(
                "applies only to `{kind} = \"{}\"`, the {kind} is `{name}`",
                e.takes().join("\" | \"")
            ),
        ),
        E::MissingSetting {
            field,
            kind,
            name,
            range,
        } => c.name(
            f(field),
            format!("required with `{kind} = \"{name}\"`: {range}"),
        ),
        E::InvalidParameter {
            field,
            value,
            range,
        } => c.invalid(f(field), value, range),
        e => c.name(f("level"), e.to_string()),
    }
}

/// What a fingertip's `level` (and its settings) ask for.
enum TipLaw {
    /// A built-in level.
    Level(Level),
    /// A measured curve, read from its file.
    Tabulated(MeasuredCurve),
}

/// The law of a fingertip: a level by name with its settings (`tolerance`, `k`, `match_x`:
/// each only for the level whose row of `softgrip_law::LEVELS` has it), or a measured curve
/// read from its CSV file (relative to `base`, the scene file's folder).
fn law(
    c: &Checker,
    t: &FingertipSpec,
    f: &dyn Fn(&str) -> String,
    base: &Path,
) -> Result<TipLaw, SceneError> {
    let mut level = match &t.level {
        LevelSpec::Named(name) => Level::from_name(name).map_err(|e| kind_error(c, f, e))?,
        LevelSpec::Tabulated(_) => Level::Tabulated,
    };
    for (key, value) in t.settings() {
        if let Some(value) = value {
            level = level
                .with_setting(key, value)
                .map_err(|e| kind_error(c, f, e))?;
        }
    }
    match (&t.level, level.info().data) {
        (LevelSpec::Tabulated(path), _) => Ok(TipLaw::Tabulated(read_curve(&base.join(path))?)),
        (LevelSpec::Named(_), LevelData::None) => Ok(TipLaw::Level(level)),
        (LevelSpec::Named(name), LevelData::MeasuredCurve) => Err(c.name(
            f("level"),
            format!(
                "`{name}` needs a measured curve: write `level = {{ tabulated = \"tip.csv\" }}`"
            ),
        )),
        (LevelSpec::Named(name), LevelData::UserLaw) => Err(c.name(
            f("level"),
            format!("`{name}` is a user's own law, from Rust only (`ContactLaw::custom`)"),
        )),
    }
}

/// The fingertip's law from its measured curve: `softgrip_law::TabulatedCurve` (monotone C1
/// interpolation of the samples, checked) bound with the fingertip's material, radius and
/// backing.
fn tabulated_law(
    c: &Checker,
    field: &str,
    builder: SoftFingertipBuilder,
    material: Material,
    radius: f64,
    backing: Backing,
    curve: MeasuredCurve,
) -> Result<SoftFingertipBuilder, SceneError> {
    let path = curve.path.clone();
    let law_error = |source: softgrip_law::Error| SceneError::Law {
        origin: c.origin.to_string(),
        field: field.to_string(),
        path: path.clone(),
        source: Box::new(source),
    };
    // The measured curve is the construction's own: its params carry the backing.
    let params = ContactParams::try_new(material, radius)
        .and_then(|p| p.with_backing(backing))
        .map_err(law_error)?;
    let table = TabulatedCurve::try_new(curve.delta_m, curve.force_n).map_err(law_error)?;
    let law = ContactLaw::tabulated(params, table).map_err(law_error)?;
    Ok(builder.law(law))
}
