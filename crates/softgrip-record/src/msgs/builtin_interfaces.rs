//! `builtin_interfaces`: [`Time`] and [`Duration`].

use crate::message::ros_message;

ros_message! {
    /// A ROS time point (here: simulation time since the start of the run).
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
    pub struct Time {
        name = "builtin_interfaces/msg/Time", file = "msg/builtin_interfaces/Time.msg", deps = [];
        /// Whole seconds \[s\].
        pub sec: i32,
        /// Nanoseconds \[ns\], in [0, 1e9).
        pub nanosec: u32,
    }
}

ros_message! {
    /// A ROS duration.
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
    pub struct Duration {
        name = "builtin_interfaces/msg/Duration", file = "msg/builtin_interfaces/Duration.msg", deps = [];
        /// Whole seconds \[s\].
        pub sec: i32,
        /// Nanoseconds \[ns\], in [0, 1e9).
        pub nanosec: u32,
    }
}

const NS_PER_S: u64 = 1_000_000_000;

impl Time {
    /// The time `nanos` \[ns\] after the epoch (the start of the simulation). Saturates at
    /// `i32::MAX` seconds (year 2038 of a wall clock; 68 years of simulation).
    ///
    /// ```
    /// use softgrip_record::msgs::builtin_interfaces::Time;
    /// let t = Time::from_nanos(1_500_000_001);
    /// assert_eq!((t.sec, t.nanosec), (1, 500_000_001));
    /// assert_eq!(t.as_nanos(), 1_500_000_001);
    /// ```
    pub fn from_nanos(nanos: u64) -> Self {
        let sec = nanos / NS_PER_S;
        match i32::try_from(sec) {
            Ok(sec) => Self {
                sec,
                nanosec: (nanos % NS_PER_S) as u32,
            },
            Err(_) => Self {
                sec: i32::MAX,
                nanosec: (NS_PER_S - 1) as u32,
            },
        }
    }

    /// Nanoseconds since the epoch; 0 for negative times.
    pub fn as_nanos(&self) -> u64 {
        if self.sec < 0 {
            return 0;
        }
        self.sec as u64 * NS_PER_S + u64::from(self.nanosec)
    }
}
