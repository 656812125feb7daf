#![doc = include_str!("../README.md")]

pub mod impact;
pub mod scenes;
