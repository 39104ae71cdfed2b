//! Videos: tracking balls against truth, and a video given as `--data` everywhere.

pub(crate) mod app;
pub(crate) mod tracking;
