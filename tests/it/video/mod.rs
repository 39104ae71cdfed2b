//! Videos: tracking balls against truth, random looks, the overlay, and a video given
//! as `--data` everywhere.

pub(crate) mod app;
mod follow_gap;
pub(crate) mod found_frames;
pub(crate) mod looks;
mod mark_highlight;
mod mark_place;
mod marks_stay;
mod marks_turn;
mod outer_lock;
pub(crate) mod overlay;
mod ragged_fringe;
pub(crate) mod seed;
mod sharp_arc;
pub(crate) mod tracker_looks;
pub(crate) mod tracking;
mod unfit;
