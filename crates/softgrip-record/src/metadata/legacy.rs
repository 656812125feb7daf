//! The metadata records of every softgrip version, read as today's types: recordings made
//! before the records were typed JSON (softgrip before 2026-12-01, `git show
//! 2974346:recordings/default.mcap` and `12ba9ad:...`) stored the fingertips' laws as text
//! lines (`left_tip: level=auto tolerance=0.01 youngs_modulus=590000 poisson_ratio=0.49
//! radius=0.01 friction=0.8 restitution=0.5`, one per fingertip: [`FingertipLaw`]'s `Display`
//! of the time) and the run summary as flat keys (`left_tip.peak_force = 11.82`).
//! [`MetadataRecord::from_metadata`] refuses both; [`recording_info`] and [`run_summary`]
//! read today's records and those.

use std::collections::BTreeMap;

use serde::de::Error as _;

use super::law::FingertipLaw;
use super::records::{MetadataError, MetadataRecord, RecordingInfo, RunSummary, TipRunSummary};

/// A [`MetadataError`] of record `R` saying `message`.
fn error<R: MetadataRecord>(message: String) -> MetadataError {
    MetadataError {
        name: R::NAME,
        source: serde_json::Error::custom(message),
    }
}

/// The `softgrip` record of any version: today's typed record, or the text-law record of
/// recordings made before 2026-12-01 (a value that does not parse is an error naming it).
///
/// ```
/// use std::collections::BTreeMap;
/// use softgrip_law::{Backing, Level};
/// use softgrip_record::metadata::legacy::recording_info;
/// let map: BTreeMap<String, String> = [
///     ("dt", "0.016666666666666666"),
///     ("every_n_steps", "4"),
///     ("law", "left_tip: level=auto tolerance=0.01 youngs_modulus=590000 poisson_ratio=0.49 radius=0.01 friction=0.8 restitution=0.5"),
///     ("origin", "scenes/default.toml"),
///     ("scene", "dt = 0.016666666666666666"),
///     ("softgrip_version", "0.1.0"),
///     ("steps", "300"),
/// ].into_iter().map(|(k, v)| (k.to_owned(), v.to_owned())).collect();
/// let info = recording_info(&map).unwrap();
/// assert_eq!((info.every_n_steps, info.steps), (4, 300));
/// assert_eq!(info.law[0].name, "left_tip");
/// assert_eq!(info.law[0].level, Level::Auto { tolerance: 0.01 });
/// assert_eq!((info.law[0].youngs_modulus, info.law[0].backing), (590000.0, Backing::Free));
/// ```
pub fn recording_info(map: &BTreeMap<String, String>) -> Result<RecordingInfo, MetadataError> {
    if let Ok(info) = RecordingInfo::from_metadata(map) {
        return Ok(info);
    }
    let mut info = RecordingInfo::default();
    let number = |key: &str| -> Result<Option<f64>, MetadataError> {
        map.get(key)
            .map(|v| {
                v.trim()
                    .parse::<f64>()
                    .map_err(|_| error::<RecordingInfo>(format!("`{key}` is not a number: {v:?}")))
            })
            .transpose()
    };
    let count = |key: &str| -> Result<Option<u64>, MetadataError> {
        map.get(key)
            .map(|v| {
                v.trim()
                    .parse::<u64>()
                    .map_err(|_| error::<RecordingInfo>(format!("`{key}` is not a count: {v:?}")))
            })
            .transpose()
    };
    for (key, field) in [
        ("scene", &mut info.scene),
        ("softgrip_version", &mut info.softgrip_version),
        ("origin", &mut info.origin),
    ] {
        if let Some(v) = map.get(key) {
            v.clone_into(field);
        }
    }
    info.dt = number("dt")?.unwrap_or(0.0);
    info.every_n_steps = count("every_n_steps")?.unwrap_or(0);
    info.steps = count("steps")?.unwrap_or(0);
    if let Some(g) = map.get("gravity") {
        info.gravity = serde_json::from_str(g).map_err(|source| MetadataError {
            name: RecordingInfo::NAME,
            source,
        })?;
    }
    if let Some(law) = map.get("law") {
        info.law = match serde_json::from_str(law) {
            Ok(laws) => laws,
            Err(_) => (law.lines())
                .filter(|l| !l.trim().is_empty())
                .map(law_line)
                .collect::<Result<_, _>>()?,
        };
    }
    Ok(info)
}

/// One fingertip's law as a text line: `NAME: level=L [k=|tolerance=|match_x=V] key=value...`
/// (`backing` and `core_thickness` optional: absent, the fingertip is `free`).
fn law_line(line: &str) -> Result<FingertipLaw, MetadataError> {
    let bad = |why: &str| error::<RecordingInfo>(format!("law line {line:?}: {why}"));
    let (name, rest) = line
        .rsplit_once(": level=")
        .ok_or_else(|| bad("no `: level=`"))?;
    let mut words = rest.split_whitespace();
    let level_name = words.next().ok_or_else(|| bad("no level"))?;
    let mut values: BTreeMap<&str, &str> = BTreeMap::new();
    for word in words {
        let (k, v) = word
            .split_once('=')
            .ok_or_else(|| bad("a word without `=`"))?;
        values.insert(k, v);
    }
    // The typed JSON form of the same law, so that the level, its setting and the backing are
    // checked by the one deserializer there is.
    let mut json = serde_json::Map::new();
    json.insert("name".into(), name.into());
    let mut level = serde_json::Map::new();
    level.insert("name".into(), level_name.into());
    for (key, value) in &values {
        let v: serde_json::Value = match value.parse::<f64>() {
            Ok(x) => x.into(),
            Err(_) => (*value).into(),
        };
        match *key {
            k if softgrip_law::setting_keys().contains(&k) => level.insert((*key).into(), v),
            _ => json.insert((*key).into(), v),
        };
    }
    json.insert("level".into(), level.into());
    serde_json::from_value(json.into()).map_err(|source| MetadataError {
        name: RecordingInfo::NAME,
        source,
    })
}

/// The `softgrip_run_summary` record of any version: today's typed record, or the flat keys
/// (`NAME.peak_force`, `NAME.peak_x`, `NAME.slips`, `NAME.validity_excursions`, `steps`) of
/// recordings made before 2026-12-01 (told by a key with a dot), fingertips in name order.
///
/// ```
/// use std::collections::BTreeMap;
/// use softgrip_record::metadata::legacy::run_summary;
/// let map: BTreeMap<String, String> = [
///     ("left_tip.peak_force", "11.82"), ("left_tip.peak_x", "0.2"),
///     ("left_tip.slips", "2"), ("left_tip.validity_excursions", "0"), ("steps", "300"),
/// ].into_iter().map(|(k, v)| (k.to_owned(), v.to_owned())).collect();
/// let s = run_summary(&map).unwrap();
/// assert_eq!(s.steps, 300);
/// let tip = s.tip("left_tip").unwrap();
/// assert_eq!((tip.peak_force, tip.slips), (11.82, 2));
/// ```
pub fn run_summary(map: &BTreeMap<String, String>) -> Result<RunSummary, MetadataError> {
    // Today's record ignores keys it does not know, so the flat keys are told by their dot.
    if !map.keys().any(|k| k.contains('.')) {
        return RunSummary::from_metadata(map);
    }
    let bad = |key: &str, v: &str| error::<RunSummary>(format!("`{key}` = {v:?} does not parse"));
    let mut summary = RunSummary::default();
    let mut tips: BTreeMap<&str, TipRunSummary> = BTreeMap::new();
    for (key, v) in map {
        if key == "steps" {
            summary.steps = v.trim().parse().map_err(|_| bad(key, v))?;
            continue;
        }
        let Some((name, field)) = key.rsplit_once('.') else {
            return Err(bad(key, v));
        };
        let tip = tips.entry(name).or_insert_with(|| TipRunSummary {
            name: name.to_owned(),
            ..Default::default()
        });
        let v = v.trim();
        match field {
            "peak_force" => tip.peak_force = v.parse().map_err(|_| bad(key, v))?,
            "peak_x" => tip.peak_x = v.parse().map_err(|_| bad(key, v))?,
            "slips" => tip.slips = v.parse().map_err(|_| bad(key, v))?,
            "validity_excursions" => {
                tip.validity_excursions = v.parse().map_err(|_| bad(key, v))?;
            }
            _ => return Err(bad(key, v)),
        }
    }
    summary.fingertips = tips.into_values().collect();
    Ok(summary)
}
