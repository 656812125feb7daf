#![doc = include_str!("../README.md")]

pub mod icosphere;
pub mod impact;
pub mod scenes;
