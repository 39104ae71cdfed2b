//! groovelab: two balls colliding in a groove (Gröber & Sniatecki), solved exactly.
//!
//! Layers, each using only those above it: `physics` (the model and the exact engine,
//! no flags, no I/O) → `settings` (the parameter table, settings layers and units) →
//! `methods` (time-stepping methods) → `vision` (finding the balls in video frames) →
//! `study` (compare, fit, sweep, figures, presets' text form) → `lab` (one scene under
//! study with its cached analyses) → the edges: `input` (files and their text to SI),
//! `output` (the one atomic file writer), `signals` (the one stop mechanism), `cli` and
//! `tui`.

pub mod cli;
pub mod input;
pub mod lab;
pub mod methods;
pub mod output;
pub mod physics;
pub mod settings;
pub mod signals;
pub mod study;
pub mod tui;
pub mod vision;
