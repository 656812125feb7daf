#![doc = include_str!("../README.md")]

pub mod icosphere;
pub mod impact;
pub mod resting;
pub mod scenes;
