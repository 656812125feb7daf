//! `--counterpart`: what the fingertip is pressed on, relative to its radius R (as
//! `--thickness` is t/R): `plane`, `ball:K`, `cylinder:K` (K = R2/R, the counterpart's radius
//! over the fingertip's) or `edge`.

use std::fmt;
use std::str::FromStr;

use softgrip_law::{Counterpart, CounterpartKind};

/// The forms `--counterpart` takes.
pub const FORMS: &str = "plane, ball:K, cylinder:K (K = R2/R > 0) or edge";

/// A counterpart relative to the fingertip's radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CounterpartArg {
    /// A flat body (the default).
    Plane,
    /// A rigid ball of radius K R.
    Ball(f64),
    /// A rigid cylinder's side of radius K R (its axis the patch's first direction).
    Cylinder(f64),
    /// A sharp edge.
    Edge,
}

impl CounterpartArg {
    /// The law's counterpart for a fingertip of radius `radius` \[m\] (curvatures `1/(K R)`).
    pub fn counterpart(self, radius: f64) -> Result<Counterpart, softgrip_law::Error> {
        match self {
            Self::Plane => Ok(Counterpart::PLANE),
            Self::Edge => Ok(Counterpart::EDGE),
            Self::Ball(k) => Counterpart::try_ball(k * radius),
            Self::Cylinder(k) => Counterpart::try_cylinder(k * radius),
        }
    }

    /// `true` for [`CounterpartArg::Plane`].
    pub fn is_plane(self) -> bool {
        self == Self::Plane
    }
}

impl fmt::Display for CounterpartArg {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Plane => f.write_str(CounterpartKind::Plane.name()),
            Self::Edge => f.write_str(CounterpartKind::Edge.name()),
            Self::Ball(k) => write!(f, "ball:{k}"),
            Self::Cylinder(k) => write!(f, "cylinder:{k}"),
        }
    }
}

impl FromStr for CounterpartArg {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let radius = |name: &str, k: &str| -> Result<f64, String> {
            let v: f64 = k
                .parse()
                .map_err(|_| format!("`{name}:K` needs a number K = R2/R, got `{k}`"))?;
            if v.is_finite() && v > 0.0 {
                Ok(v)
            } else {
                Err(format!(
                    "`{name}:K`: K = R2/R must be finite and > 0, got {v}"
                ))
            }
        };
        match s.split_once(':') {
            None if s == "plane" => Ok(Self::Plane),
            None if s == "edge" => Ok(Self::Edge),
            Some(("ball", k)) => radius("ball", k).map(Self::Ball),
            Some(("cylinder", k)) => radius("cylinder", k).map(Self::Cylinder),
            None if s == "ball" || s == "cylinder" => Err(format!(
                "`{s}` needs its radius over the fingertip's: `{s}:K`"
            )),
            _ => Err(format!(
                "unknown counterpart `{s}`; expected one of: {FORMS}"
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_every_form_and_refuses_the_rest() {
        assert_eq!("plane".parse(), Ok(CounterpartArg::Plane));
        assert_eq!("edge".parse(), Ok(CounterpartArg::Edge));
        assert_eq!("ball:3".parse(), Ok(CounterpartArg::Ball(3.0)));
        assert_eq!("cylinder:0.5".parse(), Ok(CounterpartArg::Cylinder(0.5)));
        for bad in [
            "ball",
            "ball:",
            "ball:0",
            "ball:-1",
            "cylinder:inf",
            "cone:1",
            "edge:2",
            "",
        ] {
            assert!(bad.parse::<CounterpartArg>().is_err(), "{bad}");
        }
        let c = CounterpartArg::Ball(2.0).counterpart(0.01).unwrap();
        assert!((c.curvatures()[0] - 50.0).abs() < 1e-12);
        assert_eq!(CounterpartArg::Cylinder(1.0).to_string(), "cylinder:1");
    }
}
