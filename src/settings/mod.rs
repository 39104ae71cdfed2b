//! The settings model, below everything that studies a scene: the one table of scene
//! parameters (`params`), the layers of settings and their resolution into a checked
//! SI scene (`spec`), and physical quantities with their units, read and shown
//! (`units`: the one display-unit table). Pure: no files, no flags, no terminal.

pub mod params;
pub mod quote;
pub mod spec;
pub mod units;
