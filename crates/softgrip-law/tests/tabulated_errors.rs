//! Every invalid measured curve gets an `Error::InvalidTable` naming the column, the sample,
//! the value and the valid range.

use softgrip_law::{ContactLaw, ContactParams, Error, Level, LevelKind, TabulatedCurve};

/// Asserts an `InvalidTable` for `field[index]` with `value`, whose message names the range.
fn invalid(
    r: Result<impl std::fmt::Debug, Error>,
    field: &str,
    index: Option<usize>,
    value: f64,
    range: &str,
) {
    match r {
        Err(e @ Error::InvalidTable { .. }) => {
            let Error::InvalidTable {
                field: f,
                index: i,
                value: v,
                range: rg,
            } = &e
            else {
                unreachable!()
            };
            assert_eq!((*f, *i), (field, index), "{e}");
            assert!(v == &value || (v.is_nan() && value.is_nan()), "{e}");
            assert!(rg.contains(range), "{e}");
            let name = match index {
                Some(i) => format!("`{field}[{i}]`"),
                None => format!("`{field}`"),
            };
            assert!(e.to_string().starts_with(&name), "{e}");
        }
        other => panic!("expected InvalidTable({field}), got {other:?}"),
    }
}

fn curve(delta: &[f64], force: &[f64]) -> Result<TabulatedCurve, Error> {
    TabulatedCurve::try_new(delta.to_vec(), force.to_vec())
}

#[test]
fn non_finite_and_negative_values() {
    let finite = "finite, >= 0";
    invalid(
        curve(&[1e-3, f64::NAN], &[1.0, 2.0]),
        "delta_m",
        Some(1),
        f64::NAN,
        finite,
    );
    invalid(
        curve(&[1e-3, 2e-3], &[1.0, f64::NAN]),
        "force_n",
        Some(1),
        f64::NAN,
        finite,
    );
    invalid(
        curve(&[1e-3, 2e-3], &[f64::INFINITY, 2.0]),
        "force_n",
        Some(0),
        f64::INFINITY,
        finite,
    );
    invalid(
        curve(&[-1e-3, 2e-3], &[1.0, 2.0]),
        "delta_m",
        Some(0),
        -1e-3,
        "finite, >= 0 m",
    );
    invalid(
        curve(&[1e-3, 2e-3], &[-1.0, 2.0]),
        "force_n",
        Some(0),
        -1.0,
        "finite, >= 0 N",
    );
}

#[test]
fn values_not_representable_in_f32() {
    invalid(
        curve(&[1e-3, 2e-3], &[1.0, 1e39]),
        "force_n",
        Some(1),
        1e39,
        "f32",
    );
    invalid(
        curve(&[1e-40, 2e-3], &[1.0, 2.0]),
        "delta_m",
        Some(0),
        1e-40,
        "f32",
    );
}

#[test]
fn non_monotone_tables() {
    invalid(
        curve(&[1e-3, 2e-3, 2e-3], &[1.0, 2.0, 3.0]),
        "delta_m",
        Some(2),
        2e-3,
        "strictly increasing",
    );
    invalid(
        curve(&[1e-3, 3e-3, 2e-3], &[1.0, 2.0, 3.0]),
        "delta_m",
        Some(2),
        2e-3,
        "> delta_m[1] = 0.003 m",
    );
    invalid(
        curve(&[1e-3, 2e-3, 3e-3], &[1.0, 2.0, 1.5]),
        "force_n",
        Some(2),
        1.5,
        ">= force_n[1] = 2 N (non-decreasing",
    );
    // A plateau is allowed (non-decreasing).
    assert!(curve(&[1e-3, 2e-3, 3e-3], &[1.0, 2.0, 2.0]).is_ok());
}

#[test]
fn too_short_or_mismatched_tables() {
    invalid(
        curve(&[], &[]),
        "delta_m",
        None,
        0.0,
        "at least 2 samples with delta > 0",
    );
    invalid(curve(&[1e-3], &[1.0]), "delta_m", None, 1.0, "at least 2");
    // The origin does not count.
    invalid(
        curve(&[0.0, 1e-3], &[0.0, 1.0]),
        "delta_m",
        None,
        1.0,
        "at least 2",
    );
    invalid(
        curve(&[1e-3, 2e-3], &[1.0]),
        "force_n",
        None,
        1.0,
        "as many samples as `delta_m` (2)",
    );
}

#[test]
fn the_origin() {
    // F(0) = 0 is required at delta = 0 ...
    invalid(
        curve(&[0.0, 1e-3, 2e-3], &[0.1, 1.0, 2.0]),
        "force_n",
        Some(0),
        0.1,
        "0 N at delta = 0",
    );
    // ... and prepended otherwise.
    let c = curve(&[1e-3, 2e-3], &[1.0, 2.0]).expect("valid");
    assert_eq!(
        (c.delta_m(), c.force_n()),
        (&[0.0, 1e-3, 2e-3][..], &[0.0, 1.0, 2.0][..])
    );
    let c = curve(&[0.0, 1e-3, 2e-3], &[0.0, 1.0, 2.0]).expect("valid");
    assert_eq!(c.delta_m().len(), 3);
    // A curve that never loads is no contact law.
    invalid(
        curve(&[1e-3, 2e-3], &[0.0, 0.0]),
        "force_n",
        Some(2),
        0.0,
        "> 0 N at the last",
    );
}

#[test]
fn tables_past_four_radii_and_level_without_data() {
    let p = ContactParams::try_from_parts(1e6, 1e-3, 0.49).expect("valid");
    let c = curve(&[1e-3, 5e-3], &[1.0, 2.0]).expect("valid");
    invalid(
        ContactLaw::tabulated(p, c),
        "delta_m",
        Some(2),
        5e-3,
        "<= 4 R = 0.004 m",
    );
    for (level, kind) in [
        (Level::Tabulated, LevelKind::Tabulated),
        (Level::Custom, LevelKind::Custom),
    ] {
        match ContactLaw::try_new(p, level) {
            Err(Error::LevelNeedsData { level, hint }) => {
                assert_eq!(level, kind);
                assert!(hint.contains("ContactLaw::"), "{hint}");
            }
            other => panic!("expected LevelNeedsData, got {other:?}"),
        }
    }
    // The name parses (the table has the row); what it needs is the row's `data`.
    assert_eq!("tabulated".parse::<Level>(), Ok(Level::Tabulated));
    assert_eq!(
        Level::Tabulated.info().data,
        softgrip_law::LevelData::MeasuredCurve
    );
    assert_eq!(Level::Tabulated.to_string(), "tabulated");
}
