//! Files at the edge: presets by name or path and the user's preset folder
//! (`preset`), measured series from files (`data`: velocity files and position
//! tracks), and the safe reading of a user's file (`file`). The parameter table and
//! units they read through are `settings`'.

#![deny(
    clippy::indexing_slicing,
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic
)]

pub mod data;
pub mod file;
pub mod video;
pub use file::{FileError, FileRole, MAX_FILE_BYTES, read_user_file};
pub mod preset;
