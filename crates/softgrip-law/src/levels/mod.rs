//! The levels of the law, each as a normalised curve `f(x) = F / (E* R^2)` of the compression
//! ratio `x = delta / R`, implementing [`crate::NormalisedLaw`]. One level per file.

pub(crate) mod auto;
pub(crate) mod backed;
pub(crate) mod calibrated;
pub(crate) mod fit;
pub(crate) mod hertz;
pub(crate) mod incompressible;
pub(crate) mod linear;
pub(crate) mod neo_hookean;
pub(crate) mod nh_table;
pub(crate) mod shell;
pub(crate) mod tabulated;
pub(crate) mod tatara;
pub(crate) mod thin_layer;

pub(crate) use crate::normalised::NormalisedLaw;
pub(crate) use hertz::{hertz, scale_by_chi};
