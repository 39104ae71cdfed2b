//! Text to SI at the edge: the scene parameter table and its settings layers
//! (`params`), quantities with units (`units`), presets (`preset`) and measured
//! series from files (`data`: velocities; `tracks`: positions from video analysis).

pub mod data;
pub mod params;
pub mod preset;
pub mod tracks;
pub mod units;
