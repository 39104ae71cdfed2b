//! Slow, pure analyses of a scene: methods against the exact solution (`compare`),
//! the model against measured data (`fit`), regime maps (`sweep`), and the SVG
//! figures of all three (`figures`).

pub mod compare;
pub mod figures;
pub mod fit;
pub mod sweep;
