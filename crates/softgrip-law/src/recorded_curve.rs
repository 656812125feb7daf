//! [`ContactLaw::recorded_curve`]: the curve that stands for a law that its parameters alone
//! do not rebuild (`tabulated`, `custom`), so that a recording carries every law it used.

use crate::error::Result;
use crate::law::ContactLaw;
use crate::level_table::LevelData;
use crate::tabulated::TabulatedCurve;

/// Samples of a custom law's recorded curve ([`ContactLaw::recorded_curve`]). With 256 the
/// curve read back is within 1.6e-5 (relative) of the law's force from `x_max/100` to `x_max`
/// for laws shaped like the built-in levels (hertz, fit, incompressible, calibrated at nu 0.3,
/// 0.45, 0.49: `cargo test -p softgrip-law --test recorded_curve -- --nocapture` prints it),
/// and the metadata holds about 10 kB of numbers per custom fingertip.
pub const CUSTOM_CURVE_SAMPLES: usize = 256;

impl ContactLaw {
    /// The curve a recording stores for this law, or `None` for a level that its name,
    /// settings and the contact's parameters rebuild:
    /// - `tabulated`: the measured curve itself (a law rebuilt from it is the same, bit for
    ///   bit);
    /// - `custom`: a sample of the user's law ([`sampled_curve`](Self::sampled_curve) with
    ///   [`CUSTOM_CURVE_SAMPLES`] points), which reads back as a `tabulated` law under the
    ///   custom law's [`name`](crate::NormalisedLaw::name): the same force at every sample
    ///   and a monotone cubic between them (the radius and pressure become Hertz's of that
    ///   force, as for every measured curve).
    ///
    /// ```
    /// use std::sync::Arc;
    /// use softgrip_law::{ContactLaw, ContactParams, Level, NormalisedLaw};
    /// #[derive(Debug)]
    /// struct DoubleHertz;
    /// impl NormalisedLaw for DoubleHertz {
    ///     fn force_stiffness(&self, x: f64) -> (f64, f64) { (8.0 / 3.0 * x * x.sqrt(), 4.0 * x.sqrt()) }
    ///     fn energy(&self, x: f64) -> f64 { 16.0 / 15.0 * x * x * x.sqrt() }
    ///     fn radius(&self, x: f64) -> f64 { x.sqrt() }
    ///     fn x_max(&self) -> f64 { 0.5 }
    ///     fn name(&self) -> &str { "double-hertz" }
    /// }
    /// let params = ContactParams::try_from_parts(1.0e6, 0.010, 0.5)?;
    /// let custom = ContactLaw::custom(params, Arc::new(DoubleHertz))?;
    /// let curve = custom.recorded_curve()?.expect("a custom law is recorded as a curve");
    /// let back = ContactLaw::tabulated(params, curve)?;
    /// let (a, b) = (custom.response(0.003).force, back.response(0.003).force);
    /// assert!((b / a - 1.0).abs() < 1e-5, "{a} {b}");
    /// assert_eq!(custom.custom_name(), Some("double-hertz"));
    /// let hertz = ContactLaw::try_new(params, Level::Hertz)?;
    /// assert!(hertz.recorded_curve()?.is_none()); // its name rebuilds it
    /// # Ok::<(), softgrip_law::Error>(())
    /// ```
    pub fn recorded_curve(&self) -> Result<Option<TabulatedCurve>> {
        match self.level().info().data {
            LevelData::None => Ok(None),
            LevelData::MeasuredCurve => Ok(self.tabulated_curve().cloned()),
            LevelData::UserLaw => self.sampled_curve(CUSTOM_CURVE_SAMPLES).map(Some),
        }
    }

    /// The law's force at `samples` compressions over its validity range, as a measured
    /// curve would hold it: `delta_i = delta_max (1 - cos(pi i/N))/2` for i = 1..N, dense near
    /// 0 (where the force grows like `delta^1.5`) and near `delta_max` (where a law's
    /// stiffness grows fastest); the last is `delta_max`. A sample that a
    /// [`TabulatedCurve`] cannot hold is left out: a compression or a force that is not 0 or
    /// a normal `f32` (a force below 1.2e-38 N), or a force below the previous one (a user's
    /// law that dips between the points its checks looked at). Fails
    /// ([`Error::InvalidTable`](crate::Error::InvalidTable)) if fewer than two samples remain.
    pub fn sampled_curve(&self, samples: usize) -> Result<TabulatedCurve> {
        let delta_max = self.delta_max();
        let n = samples as f64;
        let (mut delta_m, mut force_n) = (Vec::with_capacity(samples), Vec::with_capacity(samples));
        let (mut d_prev, mut f_prev) = (0.0, 0.0);
        for i in 1..=samples {
            let s = i as f64 / n;
            let delta = if i == samples {
                delta_max
            } else {
                delta_max * 0.5 * (1.0 - (std::f64::consts::PI * s).cos())
            };
            let force = self.response(delta).force;
            let holds = |v: f64| v == 0.0 || (v as f32).is_normal();
            if delta > d_prev && force >= f_prev && holds(delta) && holds(force) {
                delta_m.push(delta);
                force_n.push(force);
                (d_prev, f_prev) = (delta, force);
            }
        }
        TabulatedCurve::try_new(delta_m, force_n)
    }
}
