//! [`TipContact`]: what one soft contact did over the last step, and its assembly from the
//! substeps' impulses.

use std::collections::HashMap;
use std::sync::Arc;

use nalgebra::Vector3;
use rapier3d::prelude::ColliderHandle;
use softgrip_law::{
    Backing, ContactLaw, ContactPatch, ContactReading, Counterpart, LevelKind, Regime,
};

use crate::detect::{Model, Series, raw};
use crate::solve::Row;

/// One soft contact after a step. Cheap to produce: the contact radius and pressure are only
/// computed when [`patch`](Self::patch) is called.
///
/// Forces are step averages (total impulse over the step / dt); the geometry (`point`,
/// `normal`, `delta`) is that of the last (sub)step, with `delta` predicted to the end of it
/// (`delta - h v_n`, what rapier's position update produces), so `normal_force` and
/// `law(delta)` agree for a quasi-static contact.
///
/// A contact of two fingertips is reported **twice**, once per fingertip: `fingertip` and
/// `other` swapped, each with its own normal (from the other fingertip to it), the force and
/// friction vectors exactly opposite. Two free fingertips are one pair with one combined law
/// (`ContactParams::try_combine`): `delta` is the approach of the two surfaces and
/// `x = delta / R_eff` (R_eff the combined radius) in both rows. When either is backed, the two
/// are pressed in series on their rigid mid-surface: each row is its own fingertip's, `delta`
/// its share of the approach (the shares add up to the approach, their forces are equal),
/// `x = delta / R` with its own radius, and its own law's stiffness, level, regime and patch.
/// Sum `normal_force` per fingertip, not over all contacts, to avoid counting such a pair
/// twice.
#[derive(Debug, Clone)]
pub struct TipContact {
    /// The fingertip's collider.
    pub fingertip: ColliderHandle,
    /// The other collider (a rigid body, or a second fingertip).
    pub other: ColliderHandle,
    /// Contact point, world \[m\].
    pub point: [f64; 3],
    /// Unit normal, world, from the other body to the fingertip.
    pub normal: [f64; 3],
    /// Compression delta \[m\] (> 0 in contact; of two fingertips: the approach of their
    /// surfaces).
    pub delta: f64,
    /// Compression ratio x = delta / R [-] (of two fingertips: R = the combined radius).
    pub x: f64,
    /// Normal force on the fingertip \[N\], >= 0 (step average; includes the dissipative part).
    pub normal_force: f64,
    /// Friction force on the fingertip, world \[N\] (step average, tangent to the contact).
    pub friction_force: [f64; 3],
    /// Torsional friction moment on the fingertip about `normal` [N m] (step average).
    pub torsional_moment: f64,
    /// Law stiffness K = dF/d delta at `delta` \[N/m\].
    pub stiffness: f64,
    /// The level that computed the force.
    pub level: LevelKind,
    /// Valid, extended (validity excursion) or separated, at `delta` (the end of the step).
    pub regime: Regime,
    /// The compression was past the law's validity range in some substep of the step, or is
    /// at its end (an impact can pass `x_max` and rebound within one step).
    pub validity_exceeded: bool,
    /// Friction was saturated (the contact slid) in some substep of the step.
    pub sliding: bool,
    /// Largest normal force of any substep of the step \[N\] (an impact's peak; equals
    /// `normal_force` for an unsplit step).
    pub peak_normal_force: f64,
    /// Largest compression of the step \[m\]: the maximum over the start of every substep and
    /// the end of the step, so `max_delta >= delta` always.
    pub max_delta: f64,
    /// Largest compression ratio of the step, `max_delta / R` [-] (`>= x`).
    pub max_x: f64,
    /// Time in contact (compression > 0) during the step \[s\].
    pub contact_duration: f64,
    /// The fingertip's construction (`SoftFingertip::backing`; `Free` for a combined pair of
    /// two free fingertips).
    pub backing: Backing,
    pub(crate) model: Arc<Model>,
}

impl TipContact {
    /// The contact's numbers as the law crate's plain [`ContactReading`], the one shape that
    /// the recorder, the ROS 2 publisher and the ECS take (the conversion is here, once; the
    /// patch is `None`: [`patch`](Self::patch) computes it when wanted).
    pub fn reading(&self) -> ContactReading {
        ContactReading {
            point: self.point,
            normal: self.normal,
            delta: self.delta,
            x: self.x,
            normal_force: self.normal_force,
            friction_force: self.friction_force,
            torsional_moment: self.torsional_moment,
            stiffness: self.stiffness,
            level: self.level,
            regime: self.regime,
            validity_exceeded: self.validity_exceeded,
            sliding: self.sliding,
            peak_normal_force: self.peak_normal_force,
            max_delta: self.max_delta,
            max_x: self.max_x,
            contact_duration: self.contact_duration,
            backing: self.backing,
            counterpart: self.counterpart(),
            patch_direction: self.patch_direction(),
            patch: None,
        }
    }

    /// Contact patch and pressure at `delta` (computed now): a disc on a plane or a ball, an
    /// ellipse on a cylinder or an edge, its first semi-axis (`radius`) along
    /// [`patch_direction`](Self::patch_direction).
    pub fn patch(&self) -> ContactPatch {
        self.model.law.patch(self.delta)
    }

    /// What the fingertip touched (read from the other collider's shape at the contact, see
    /// the crate's README): a plane, a curved surface or an edge. A plane for two fingertips
    /// (their combined law already has both curvatures).
    pub fn counterpart(&self) -> Counterpart {
        self.model.law.counterpart()
    }

    /// Unit vector, world, along the patch's first semi-axis (the counterpart's first
    /// principal direction: along a cylinder's axis, along an edge); tangent to the contact.
    /// For a disc (a plane, a ball, two fingertips) any tangent: the one nearest the world's x
    /// axis (z when the normal is nearly x).
    pub fn patch_direction(&self) -> [f64; 3] {
        let d = self.model.patch_direction;
        if d.norm() > 0.0 {
            return d.into();
        }
        let n = Vector3::from(self.normal);
        let seed = if n.x.abs() < 0.9 {
            Vector3::x()
        } else {
            Vector3::z()
        };
        let t = seed - n * n.dot(&seed);
        (t / t.norm()).into()
    }

    /// Whether the compression was past the law's validity range during the step
    /// ([`validity_exceeded`](Self::validity_exceeded)).
    pub fn validity_excursion(&self) -> bool {
        self.validity_exceeded
    }

    /// Magnitude of the friction force \[N\].
    pub fn friction_magnitude(&self) -> f64 {
        let [a, b, c] = self.friction_force;
        (a * a + b * b + c * c).sqrt()
    }

    /// The contact's law (for a fingertip on a rigid body, the fingertip's own).
    pub fn law(&self) -> &ContactLaw {
        &self.model.law
    }

    /// Force and torque the contact puts on the fingertip, the torque about `center` (world
    /// \[m\], e.g. the fingertip's centre): normal plus friction force, `r x f` plus the
    /// torsional moment about the normal. Summed over a fingertip's contacts this is its
    /// contact wrench \[N\], [N m].
    pub fn wrench_about(&self, center: [f64; 3]) -> ([f64; 3], [f64; 3]) {
        let (n, p) = (self.normal, self.point);
        let f: [f64; 3] =
            std::array::from_fn(|i| n[i] * self.normal_force + self.friction_force[i]);
        let r: [f64; 3] = std::array::from_fn(|i| p[i] - center[i]);
        let rxf = [
            r[1] * f[2] - r[2] * f[1],
            r[2] * f[0] - r[0] * f[2],
            r[0] * f[1] - r[1] * f[0],
        ];
        let torque = std::array::from_fn(|i| rxf[i] + n[i] * self.torsional_moment);
        (f, torque)
    }
}

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
    index: HashMap<Key, usize>,
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
/// `out`; `acc` is emptied (its buffer kept).
pub(crate) fn assemble(acc: &mut Accums, dt: f64, out: &mut Vec<TipContact>) {
    out.clear();
    for ((tip, other), a) in acc.list.drain(..) {
        if a.jn <= 0.0 && a.delta_end <= 0.0 {
            continue;
        }
        let resp = a.model.law.response(a.delta_end);
        out.push(TipContact {
            fingertip: tip,
            other,
            point: a.point.into(),
            normal: a.normal.into(),
            delta: a.delta_end,
            x: a.delta_end / a.model.radius,
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
        row.delta = delta;
        row.x = delta / model.radius;
        row.max_delta = max_delta;
        row.max_x = max_delta / model.radius;
        row.stiffness = resp.stiffness;
        row.level = resp.level;
        row.validity_exceeded |= resp.regime == Regime::Extended;
        row.regime = resp.regime;
        row.backing = model.backing;
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
        normal: neg(c.normal),
        friction_force: neg(c.friction_force),
        ..c.clone()
    }
}
