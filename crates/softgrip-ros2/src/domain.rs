//! The ROS domain id: `ROS_DOMAIN_ID`, validated (ros2-client's default context ignores it).

use crate::error::{Error, Result};

/// The environment variable ROS 2 reads the domain id from.
pub const ROS_DOMAIN_ID: &str = "ROS_DOMAIN_ID";

/// The largest valid domain id. DDS derives UDP ports from it
/// (`7400 + 250·domain + ...`, RTPS 9.6.1.1): above 232 they pass 65535.
pub const MAX_DOMAIN_ID: u16 = 232;

/// Parses a domain id as ROS 2 does: an unsigned decimal integer in `0..=232` (surrounding
/// whitespace allowed); an empty value means "unset", i.e. domain 0.
///
/// ```
/// use softgrip_ros2::parse_domain_id;
/// assert_eq!(parse_domain_id("42").unwrap(), 42);
/// assert_eq!(parse_domain_id("").unwrap(), 0);
/// assert!(parse_domain_id("233").is_err());
/// assert!(parse_domain_id("-1").is_err());
/// ```
pub fn parse_domain_id(value: &str) -> Result<u16> {
    let v = value.trim();
    if v.is_empty() {
        return Ok(0);
    }
    let err = || Error::DomainId {
        value: value.to_owned(),
    };
    if !v.bytes().all(|b| b.is_ascii_digit()) {
        return Err(err());
    }
    match v.parse::<u16>() {
        Ok(id) if id <= MAX_DOMAIN_ID => Ok(id),
        _ => Err(err()),
    }
}

/// The domain id from `ROS_DOMAIN_ID`: 0 if it is unset or empty, an [`Error::DomainId`] if it
/// is not an integer in `0..=232` (or not Unicode).
pub fn domain_id_from_env() -> Result<u16> {
    match std::env::var(ROS_DOMAIN_ID) {
        Ok(v) => parse_domain_id(&v),
        Err(std::env::VarError::NotPresent) => Ok(0),
        Err(std::env::VarError::NotUnicode(v)) => Err(Error::DomainId {
            value: v.to_string_lossy().into_owned(),
        }),
    }
}
