//! Tracking the balls in a video of the experiment: frames as luma (`gray`), a coarse
//! look for ball-shaped blobs (`detect`), each ball's outline fitted to sub-pixel
//! accuracy on its visible edge (`circle`), its mark (`mark`), both followed through
//! the frames (`tracker`), turned into metres and seconds along the groove (`tracks`)
//! and written as a Tracker-style file (`write`), with small pictures of the frames
//! for the app (`thumbs`), and drawn over the frames for a user to check
//! (`overlay`). Pure: the frames come from `input::video`. The synthetic
//! films that test it are test support (`tests/support/film`).

/// The tracker's own version: raised whenever a change makes it find other numbers
/// in the same video (cached tracks are keyed by it, not by the program's version).
pub const VERSION: u32 = 2;

pub mod background;
pub mod circle;
pub mod detect;
pub mod frame;
pub mod gray;
pub mod mark;
pub mod overlay;
pub mod params;
pub mod thumbs;
pub mod tracker;
pub mod tracks;
pub mod write;

pub use frame::Frame;
pub use gray::Gray;
pub use params::{Params, Roi};
pub use tracker::{Tracker, track};
pub use tracks::{Tracks, TracksError, tracks};
