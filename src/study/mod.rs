//! Slow, pure analyses of a scene: methods against the exact solution (`compare`),
//! the model against measured data (`fit`), regime maps (`sweep`), and the SVG
//! figures of all three and of a run (`figures`), a run as CSV (`export`), presets' text
//! form (`preset`), the story of a run in words (`story`), measured series for a scene (`measured`: a position
//! track's velocities, the rest band, the ghost ball) and synthetic tracked videos to test them against truth (`video`).

pub mod compare;
pub mod export;
pub mod figures;
pub mod fit;
pub mod measured;
pub mod preset;
pub mod story;
pub mod sweep;
pub mod video;

use std::sync::atomic::{AtomicBool, Ordering};

/// How a long analysis reports how far it is and learns that it should stop: the
/// command line's progress bar and Ctrl-C, the app's worker and its `q`. Both
/// methods are called from the analysis' own thread, often (cheap checks only).
pub trait Progress: Sync {
    /// `done` of `total` units of work are finished (`total` 0: not known ahead).
    fn tick(&self, _done: u64, _total: u64) {}
    /// True once the work should be abandoned; the analysis then returns
    /// [`Cancelled`] soon and leaves no partial result.
    fn cancelled(&self) -> bool {
        false
    }
}

/// Reports nothing and never stops: for callers that wait for the result.
pub struct Quiet;

impl Progress for Quiet {}

/// A stop flag (set by a signal handler or another thread) is a `Progress` too.
impl Progress for AtomicBool {
    fn cancelled(&self) -> bool {
        self.load(Ordering::Relaxed)
    }
}

/// The work was abandoned because [`Progress::cancelled`] said so.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("cancelled")]
pub struct Cancelled;
