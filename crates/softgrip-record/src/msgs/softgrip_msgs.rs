//! `softgrip_msgs` (the interface package in `ros2/softgrip_msgs/`): [`SoftContactMsg`] and
//! [`SoftContactArrayMsg`].

use softgrip_law::{
    Backing, BackingKind, ContactReading, Counterpart, CounterpartKind, LevelKind, Regime,
};

use super::geometry_msgs::{Point, Vector3};
use super::std_msgs::Header;
use crate::message::ros_message;

ros_message! {
    /// One soft fingertip contact over a step. Fields, units and conventions are those of
    /// `ros2/softgrip_msgs/msg/SoftContact.msg`, which is embedded verbatim as the schema.
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct SoftContactMsg {
        name = "softgrip_msgs/msg/SoftContact", file = "../../ros2/softgrip_msgs/msg/SoftContact.msg",
        deps = [Header, Point, Vector3];
        /// Stamp: simulation time at the end of the step; frame: the world frame.
        pub header: Header,
        /// Name of the fingertip (its `/tf` frame).
        pub fingertip: String,
        /// Name of the other body.
        pub other: String,
        /// Contact point, world \[m\].
        pub point: Point,
        /// Unit normal, world, from the other body to the fingertip [-].
        pub normal: Vector3,
        /// Compression delta \[m\], >= 0.
        pub compression: f64,
        /// Compression ratio x = delta / R [-].
        pub ratio_x: f64,
        /// Normal force on the fingertip \[N\], >= 0 (step average).
        pub normal_force: f64,
        /// Friction force on the fingertip, world \[N\] (step average).
        pub friction_force: Vector3,
        /// Torsional friction moment about the normal [N m] (step average).
        pub torsional_moment: f64,
        /// Contact radius a \[m\], >= 0 (of an elliptical patch, its semi-axis along
        /// `patch_direction`).
        pub contact_radius: f64,
        /// Mean pressure F / (pi a b) \[Pa\].
        pub mean_pressure: f64,
        /// Peak pressure at the patch centre: (m + 1) times the mean for the law's pressure
        /// shape m (3/2 for Hertz's) \[Pa\].
        pub peak_pressure: f64,
        /// Stiffness K = dF/d delta [N/m], >= 0.
        pub stiffness: f64,
        /// Law level code ([`LevelKind::code`]).
        pub level: u8,
        /// Law level name ([`LevelKind::name`]).
        pub level_name: String,
        /// The compression is past the level's validity range (tangent extension used).
        pub validity_exceeded: bool,
        /// Friction saturated in some substep.
        pub sliding: bool,
        /// Largest normal force of any substep \[N\].
        pub peak_normal_force: f64,
        /// Largest compression of any substep, the end of the step included \[m\] (>= `compression`).
        pub max_compression: f64,
        /// Time in contact during the step \[s\].
        pub contact_duration: f64,
        /// The fingertip's construction ([`Backing::code`]: 0 free, 1 flat, 2 core).
        pub backing: u8,
        /// Skin thickness t of a `core` fingertip \[m\]; 0 for the others.
        pub core_thickness: f64,
        /// The patch's second semi-axis b \[m\] (`contact_radius` for a disc; recordings made
        /// before patches were ellipses read as discs).
        pub contact_radius2: f64,
        /// Unit vector, world, along the patch's first semi-axis [-] (zero in recordings made
        /// before it was recorded).
        pub patch_direction: Vector3,
        /// What the fingertip touched ([`CounterpartKind::code`]: 0 plane, 1 curved, 2 edge).
        pub counterpart: u8,
        /// The counterpart's principal curvature along `patch_direction` \[1/m\].
        pub counterpart_curvature1: f64,
        /// The counterpart's principal curvature across `patch_direction` \[1/m\].
        pub counterpart_curvature2: f64,
    }
}

ros_message! {
    /// Every soft contact of one step (`/softgrip/contacts`).
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct SoftContactArrayMsg {
        name = "softgrip_msgs/msg/SoftContactArray", file = "../../ros2/softgrip_msgs/msg/SoftContactArray.msg",
        deps = [Header, SoftContactMsg];
        /// Stamp: simulation time at the end of the step; frame: the world frame.
        pub header: Header,
        /// The contacts (may be empty).
        pub contacts: Vec<SoftContactMsg>,
    }
}

/// The `.msg` constants of the level, construction and counterpart codes, as
/// `SoftContact.msg` must list them: `uint8 LEVEL_<NAME>=<code>` for every concrete level of
/// `softgrip_law::LEVELS`, `uint8 BACKING_<NAME>=<code>` for every construction of
/// `softgrip_law::BACKINGS` and `uint8 COUNTERPART_<NAME>=<code>` for every kind of
/// `softgrip_law::CounterpartKind::ALL`, in table order (a test checks the `.msg` file against
/// it: the file is read by ROS 2 tools, so it is written out, but from these tables only).
///
/// ```
/// use softgrip_record::msgs::softgrip_msgs::code_constants;
/// let lines = code_constants();
/// assert!(lines.contains(&"uint8 LEVEL_TABULATED=8".to_owned()));
/// assert!(lines.contains(&"uint8 BACKING_CORE=2".to_owned()));
/// assert!(lines.contains(&"uint8 COUNTERPART_EDGE=2".to_owned()));
/// ```
pub fn code_constants() -> Vec<String> {
    let constant = |prefix: &str, name: &str, code: u8| {
        format!(
            "uint8 {prefix}_{}={code}",
            name.to_uppercase().replace('-', "_")
        )
    };
    let levels = softgrip_law::LEVELS
        .iter()
        .filter_map(|row| row.code.map(|code| constant("LEVEL", row.name, code)));
    let backings = softgrip_law::BACKINGS
        .iter()
        .map(|row| constant("BACKING", row.name, row.code));
    let counterparts = CounterpartKind::ALL
        .iter()
        .map(|(_, code, name)| constant("COUNTERPART", name, *code));
    levels.chain(backings).chain(counterparts).collect()
}

impl SoftContactMsg {
    /// Sets `level` and `level_name` from the law level that computed the force.
    pub fn set_level(&mut self, level: LevelKind) {
        self.level = level.code();
        self.level_name.clear();
        self.level_name.push_str(level.name());
    }

    /// Sets `validity_exceeded` from the law's regime (true for [`Regime::Extended`]).
    pub fn set_regime(&mut self, regime: Regime) {
        self.validity_exceeded = regime == Regime::Extended;
    }

    /// Sets `backing` and `core_thickness` from the fingertip's construction.
    pub fn set_backing(&mut self, backing: Backing) {
        self.backing = backing.code();
        self.core_thickness = backing.thickness().unwrap_or(0.0);
    }

    /// The fingertip's construction, if `backing` is a known code (a `core` with its
    /// `core_thickness`).
    ///
    /// ```
    /// use softgrip_law::Backing;
    /// use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
    /// let mut m = SoftContactMsg::default();
    /// assert_eq!(m.backing(), Some(Backing::Free));
    /// m.set_backing(Backing::Core { thickness: 0.004 });
    /// assert_eq!((m.backing, m.core_thickness), (2, 0.004));
    /// assert_eq!(m.backing(), Some(Backing::Core { thickness: 0.004 }));
    /// ```
    pub fn backing(&self) -> Option<Backing> {
        BackingKind::from_code(self.backing).map(|kind| kind.with_parameter(self.core_thickness))
    }

    /// Sets `counterpart`, its curvatures and `patch_direction` (world, unit).
    pub fn set_counterpart(&mut self, counterpart: Counterpart, patch_direction: [f64; 3]) {
        self.counterpart = counterpart.kind().code();
        [self.counterpart_curvature1, self.counterpart_curvature2] = counterpart.curvatures();
        self.patch_direction = Vector3::from_array(patch_direction);
    }

    /// What the fingertip touched, if `counterpart` is a known code and its curvatures are
    /// finite.
    ///
    /// ```
    /// use softgrip_law::Counterpart;
    /// use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
    /// let mut m = SoftContactMsg::default();
    /// assert_eq!(m.counterpart(), Some(Counterpart::PLANE)); // and every old recording
    /// m.set_counterpart(Counterpart::try_cylinder(0.02).unwrap(), [0.0, 0.0, 1.0]);
    /// assert_eq!((m.counterpart, m.counterpart_curvature2), (1, 50.0));
    /// assert_eq!(m.counterpart(), Some(Counterpart::try_cylinder(0.02).unwrap()));
    /// ```
    pub fn counterpart(&self) -> Option<Counterpart> {
        let kind = CounterpartKind::from_code(self.counterpart)?;
        Counterpart::try_from_parts(
            kind,
            [self.counterpart_curvature1, self.counterpart_curvature2],
        )
        .ok()
    }

    /// The law level, if `level` is a known code.
    pub fn level_kind(&self) -> Option<LevelKind> {
        LevelKind::from_code(self.level)
    }

    /// The message as the law's plain [`ContactReading`], its vectors as recorded: the one
    /// conversion back from a recording (the inverse of
    /// [`soft_contact_msg`](crate::soft_contact_msg)). Every number the message and
    /// the reading share is copied as it is. What the message does not hold:
    /// - `regime`: `Separated` at zero compression, else `Extended` when `validity_exceeded`,
    ///   else `Valid` (`validity_exceeded` also flags an excursion within the step);
    /// - `max_x`: `max_compression x / compression` (the radius from the message's own ratio),
    ///   `ratio_x` at zero compression;
    /// - `patch`: `None` (the recorded patch is the message's `contact_radius`,
    ///   `contact_radius2` and pressures; the law's pressure shape is not recorded).
    ///
    /// A code this version does not know (another writer's, or a newer softgrip's) reads as
    /// [`ContactReading::default`]'s level, construction or counterpart (`hertz`, `free`, a
    /// plane): [`level_kind`](Self::level_kind), [`backing`](Self::backing) and
    /// [`counterpart`](Self::counterpart) tell them apart.
    ///
    /// ```
    /// use softgrip_law::{Backing, ContactReading, Counterpart, LevelKind, Regime};
    /// use softgrip_record::{ContactSample, soft_contact_msg};
    /// let reading = ContactReading {
    ///     delta: 0.002,
    ///     x: 0.2,
    ///     normal_force: 5.0,
    ///     level: LevelKind::Tabulated,
    ///     regime: Regime::Valid,
    ///     backing: Backing::Core { thickness: 0.004 },
    ///     counterpart: Counterpart::try_cylinder(0.02).unwrap(),
    ///     patch_direction: [0.0, 0.0, 1.0],
    ///     ..ContactReading::default()
    /// };
    /// let sample = ContactSample { fingertip: "tip".into(), other: "box".into(), contact: reading.clone() };
    /// assert_eq!(soft_contact_msg(&sample).reading(), reading);
    /// ```
    pub fn reading(&self) -> ContactReading {
        let unknown = ContactReading::default();
        let regime = match (self.compression > 0.0, self.validity_exceeded) {
            (false, _) => Regime::Separated,
            (true, true) => Regime::Extended,
            (true, false) => Regime::Valid,
        };
        ContactReading {
            point: self.point.to_array(),
            normal: self.normal.to_array(),
            delta: self.compression,
            x: self.ratio_x,
            normal_force: self.normal_force,
            friction_force: self.friction_force.to_array(),
            torsional_moment: self.torsional_moment,
            stiffness: self.stiffness,
            level: self.level_kind().unwrap_or(unknown.level),
            regime,
            validity_exceeded: self.validity_exceeded,
            sliding: self.sliding,
            peak_normal_force: self.peak_normal_force,
            max_delta: self.max_compression,
            max_x: if self.compression > 0.0 && self.ratio_x > 0.0 {
                self.max_compression * (self.ratio_x / self.compression)
            } else {
                self.ratio_x
            },
            contact_duration: self.contact_duration,
            backing: self.backing().unwrap_or(unknown.backing),
            counterpart: self.counterpart().unwrap_or(unknown.counterpart),
            patch_direction: self.patch_direction.to_array(),
            patch: None,
        }
    }
}
