//! Tracking the balls in a video of the experiment: frames
//! in colour (`frame`, with their luma as `gray`), every threshold in one
//! `params::Params`, the bench's background learned from the clip (`background`),
//! a coarse look for what differs from it in ball-shaped blobs (`detect`), each
//! ball's outline fitted to sub-pixel accuracy on its visible edge (`circle`), its
//! mark (`mark`), both followed through the frames (`tracker`), marks that do not
//! turn with their ball left out (`mark_check`), turned into metres
//! and seconds along the groove (`tracks`) and written as a Tracker-style file
//! (`write`), with small pictures of the frames for the app (`thumbs`), and drawn
//! over the frames for a user to check (`overlay`); the rows of the groove's band,
//! found from the first frames, the only ones decoded and tracked (`band`); the
//! near rail's edges, found once per background, which no ball's outline takes in
//! (`rail`). Pure:
//! the frames come from `input::video`; the synthetic films that test it are test
//! support (`tests/support/film`). How it works and when it refuses:
//! docs/tracking.md.

// Bad frames never panic the tracker: no unchecked index, unwrap or panic here (a
// short `allow` with its reason where an index is provably in range). Tests may.
#![deny(
    clippy::indexing_slicing,
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic
)]
#![cfg_attr(
    test,
    allow(
        clippy::indexing_slicing,
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic
    )
)]

/// The tracker's own version: raised whenever a change makes it find other numbers
/// in the same video, or write other words with them (cached tracks are keyed by it,
/// not by the program's version: 65 refuses tracks whose radius more clear
/// outlines than fits kept put elsewhere, and tracks the clip again from theirs).
pub const VERSION: u32 = 65;

pub mod background;
pub mod band;
pub mod circle;
pub mod detect;
pub mod frame;
pub mod gray;
pub mod hough;
pub mod mark;
pub mod mark_check;
pub mod mark_fit;
pub mod overlay;
pub mod params;
pub mod prepared;
pub mod rail;
pub mod repeats;
pub mod select;
pub mod stack;
pub mod thumbs;
pub mod tracker;
pub mod tracks;
pub mod write;

pub use frame::Frame;
pub use gray::Gray;
pub use params::{Params, Roi};
pub use tracker::{Tracker, track};
pub use tracks::{Handles, Tracks, TracksError, tracks};
