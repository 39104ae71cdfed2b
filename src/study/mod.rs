//! Slow, pure analyses of a scene: methods against the exact solution (`compare`),
//! the model against measured data (`fit`), regime maps (`sweep`), and the SVG
//! figures of all three and of a run (`figures`), a run as CSV (`export`), position tracks to velocities (`track`) and
//! synthetic tracked videos to test them against truth (`video`).

pub mod compare;
pub mod export;
pub mod figures;
pub mod fit;
pub mod sweep;
pub mod track;
pub mod video;
