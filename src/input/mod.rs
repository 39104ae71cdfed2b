//! Text to SI at the edge: the scene parameter table and its settings layers
//! (`params`), quantities with units (`units`), presets (`preset`) and measured
//! series from files (`data`: velocity files and position tracks),
//! and the safe reading of a user's file (`file`).

pub mod data;
pub mod file;
pub use file::{FileError, MAX_FILE_BYTES, read_user_file};
pub mod params;
pub mod preset;
mod spec;
pub mod units;
