//! groovelab: two balls colliding in a groove (Gröber & Sniatecki), solved exactly.
//!
//! The physics and solvers (`scene`, `model`, `closed_form`, `engine`, `solution`,
//! `derived`, `preset`) know nothing of terminals or flags; `tui` draws and `cli` is
//! the edge.

pub mod cli;
pub mod closed_form;
pub mod data;
pub mod derived;
pub mod engine;
pub mod figures;
pub mod fit;
pub mod methods;
pub mod model;
pub mod preset;
pub mod scene;
pub mod solution;
pub mod sweep;
pub mod tui;
pub mod units;
