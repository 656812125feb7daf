#![doc = include_str!("../README.md")]

pub mod bounce;
pub mod fe;
pub mod fem_ball;
pub mod overhead;
pub mod squeeze;
