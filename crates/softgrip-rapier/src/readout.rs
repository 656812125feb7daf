//! The assembly of a step's [`TipContact`]s (what one soft contact did over the last step)
//! from the substeps' impulses.

use std::sync::Arc;

use nalgebra::Vector3;
use rapier3d::prelude::ColliderHandle;
use softgrip_law::{ContactReading, Regime};

use crate::boundary::raw;
use crate::detect::{Detected, owner};
use crate::fast_hash::FastMap;
use crate::model::{Model, Series};
use crate::problem::Row;
use crate::tip_contact::TipContact;
use crate::tip_record::TipRecord;

/// Per-contact sums over the substeps of a step.
#[derive(Debug, Clone)]
pub(crate) struct Accum {
    jn: f64,
    jt: Vector3<f64>,
    jtw: f64,
    sliding: bool,
    extended: bool,
    peak_force: f64,
    max_delta: f64,
    duration: f64,
    point: Vector3<f64>,
    normal: Vector3<f64>,
    delta_end: f64,
    model: Arc<Model>,
}

/// Key of a contact: (fingertip, other).
type Key = (ColliderHandle, ColliderHandle);

/// The sums of every contact of a step, in the order of their first substep. The first
/// substep's contacts are unique and are pushed without any lookup; a key index (a hash map)
/// is only built and used from the second substep of a split step on.
#[derive(Debug, Clone, Default)]
pub(crate) struct Accums {
    list: Vec<(Key, Accum)>,
    index: FastMap<Key, usize>,
    /// Contacts of the current substep are looked up in `index` (not the first substep).
    indexed: bool,
}

impl Accums {
    /// Empties the sums (buffers kept), before the first substep of a step.
    pub(crate) fn clear(&mut self) {
        self.list.clear();
        self.index.clear();
        self.indexed = false;
    }

    /// Starts a substep: from the second one on, contacts are merged by key.
    pub(crate) fn begin_substep(&mut self) {
        if !self.list.is_empty() && !self.indexed {
            self.index.clear();
            self.index
                .extend(self.list.iter().enumerate().map(|(i, (k, _))| (*k, i)));
            self.indexed = true;
        }
    }
}

/// Adds one substep of `h` seconds of a contact: its solved `row`, its `model`, its
/// compression at the start of the substep `delta` and at its end `delta_end` \[m\]. Within a
/// substep each key comes at most once.
pub(crate) fn accumulate(
    acc: &mut Accums,
    key: Key,
    row: &Row,
    model: Arc<Model>,
    delta: f64,
    delta_end: f64,
    h: f64,
) {
    let slot = if acc.indexed {
        acc.index.get(&key).copied()
    } else {
        None
    };
    let i = match slot {
        Some(i) => i,
        None => {
            let i = acc.list.len();
            if acc.indexed {
                acc.index.insert(key, i);
            }
            acc.list.push((
                key,
                Accum {
                    jn: 0.0,
                    jt: Vector3::zeros(),
                    jtw: 0.0,
                    sliding: false,
                    extended: false,
                    peak_force: 0.0,
                    max_delta: 0.0,
                    duration: 0.0,
                    point: row.p,
                    normal: row.n,
                    delta_end,
                    model,
                },
            ));
            let e = &mut acc.list[i].1;
            add(e, row, delta, delta_end, h);
            return;
        }
    };
    let e = &mut acc.list[i].1;
    add(e, row, delta, delta_end, h);
    e.model = model;
}

fn add(e: &mut Accum, row: &Row, delta: f64, delta_end: f64, h: f64) {
    e.jn += row.jn;
    e.jt += row.jt;
    e.jtw += row.jtw;
    e.sliding |= row.sliding;
    e.extended |= row.extended;
    e.peak_force = e.peak_force.max(row.jn / h);
    // The end of the substep too: the last substep's end is the step's `delta`.
    e.max_delta = e.max_delta.max(delta).max(delta_end);
    if delta > 0.0 {
        e.duration += h;
    }
    e.point = row.p;
    e.normal = row.n;
    e.delta_end = delta_end;
}

/// The readout of a step of `dt` seconds (impulses / dt), in a deterministic order, written to
/// `out`; `acc` is emptied (its buffer kept). The contacts of the fingertips the detection held
/// (`detected`: asleep, not looked at) keep their rows of `out` as they were; with every
/// fingertip held, `out` is left untouched.
pub(crate) fn assemble(
    acc: &mut Accums,
    dt: f64,
    detected: &Detected,
    tips: &FastMap<ColliderHandle, TipRecord>,
    out: &mut Vec<TipContact>,
) {
    if !detected.all && detected.tips.is_empty() && acc.list.is_empty() {
        return;
    }
    let held = !detected.all;
    if held {
        out.retain(|c| detected.held(owner(tips, c.fingertip, c.other)));
    } else {
        out.clear();
    }
    for ((tip, other), a) in acc.list.drain(..) {
        if a.jn <= 0.0 && a.delta_end <= 0.0 {
            continue;
        }
        // A contact that carried an impulse but opened within the step reads its end-of-step
        // compression as 0 (separated), never the gap: `delta >= 0` (ContactReading), its force
        // the step's average (a three-finger hand's pad read -0.51 mm with 3.5e-5 N).
        let delta = a.delta_end.max(0.0);
        let resp = a.model.law.response(delta);
        out.push(TipContact {
            fingertip: tip,
            other,
            reading: ContactReading {
                point: a.point.into(),
                normal: a.normal.into(),
                delta,
                x: delta / a.model.radius,
                normal_force: a.jn / dt,
                friction_force: (a.jt / dt).into(),
                torsional_moment: a.jtw / dt,
                stiffness: resp.stiffness,
                level: resp.level,
                regime: resp.regime,
                sliding: a.sliding,
                validity_exceeded: a.extended || resp.regime == Regime::Extended,
                peak_normal_force: a.peak_force,
                max_delta: a.max_delta,
                max_x: a.max_delta / a.model.radius,
                contact_duration: a.duration,
                backing: a.model.backing,
                // Set below, from the row's final model.
                ..ContactReading::default()
            },
            model: a.model,
        });
        if let Some(last) = out.last_mut()
            && last.model.soft_pair
        {
            if let Some(series) = &last.model.series {
                let series = series.clone();
                let mirror = in_series(last, &series);
                out.push(mirror);
            } else {
                let mirror = mirrored(last);
                out.push(mirror);
            }
        }
    }
    acc.clear();
    // Already sorted unless a split step found new contacts after its first substep.
    out.sort_by_key(|c| (raw(c.fingertip), raw(c.other)));
    for c in out.iter_mut() {
        c.set_counterpart();
    }
}

/// A pair in series (`detect::Series`): rewrites `c` as its first fingertip's own contact
/// with the rigid mid-surface (its share `delta_1` of the approach, `x = delta_1 / R_1`, its
/// own law's stiffness, level and regime, its own model, so `patch()` is its own patch) and
/// returns the second fingertip's (`delta_2`, its law, normal and force vectors negated). The
/// forces are the pair's (equal and opposite, Newton's third law).
fn in_series(c: &mut TipContact, series: &Series) -> TipContact {
    let (d1, d2) = series.law.split(c.delta);
    let (m1, m2) = series.law.split(c.max_delta);
    let mut second = mirrored(c);
    for (row, model, delta, max_delta) in [
        (c, &series.first, d1, m1),
        (&mut second, &series.second, d2, m2),
    ] {
        let resp = model.law.response(delta);
        let r = &mut row.reading;
        r.delta = delta;
        r.x = delta / model.radius;
        r.max_delta = max_delta;
        r.max_x = max_delta / model.radius;
        r.stiffness = resp.stiffness;
        r.level = resp.level;
        r.validity_exceeded |= resp.regime == Regime::Extended;
        r.regime = resp.regime;
        r.backing = model.backing;
        row.model = model.clone();
    }
    second
}

/// The contact `c` of two fingertips as the second fingertip sees it: the same pair, point,
/// compression and law; normal, normal force vector and friction force negated (so the two
/// readouts are exactly equal and opposite, Newton's third law), and the same torsional
/// moment about the negated normal (the moment vector negated).
fn mirrored(c: &TipContact) -> TipContact {
    let neg = |v: [f64; 3]| v.map(|x| -x);
    TipContact {
        fingertip: c.other,
        other: c.fingertip,
        reading: ContactReading {
            normal: neg(c.normal),
            friction_force: neg(c.friction_force),
            ..c.reading.clone()
        },
        model: c.model.clone(),
    }
}
