//! What of the tracker's look at a frame depends on the frame alone, made once and
//! ahead of the frame's turn, off the tracker's thread (`input::video` makes it on
//! the thread that reads the frames, while the tracker works on earlier ones): the
//! frame reduced to the coarse size, which the learner keeps and the look compares
//! with the background; the look against a smooth surface of luma; the pixel
//! noise. The very numbers the tracker would make from the frame itself.

use super::background::{self, Small};
use super::detect::{self, Coarse};
use super::frame::Frame;
use super::gray::Levels;
use super::params::Params;
use super::tracker::pixel_noise;

/// A frame's own part of its look (see the module's note).
#[derive(Clone, Debug)]
pub struct Prepared {
    /// The parameters it was made for: a tracker with others makes its own.
    pub params: Params,
    /// The frame reduced by the learner's factor (`background::factor`).
    pub small: Small,
    /// The look against a smooth surface of luma (`detect::coarse`).
    pub luma_look: Coarse,
    /// The frame's pixel noise (`tracker::pixel_noise`).
    pub noise: f64,
}

impl Prepared {
    /// The part of `frame`'s look that is the frame's alone, for a tracker of
    /// `params`.
    pub fn of(frame: &Frame, params: &Params) -> Prepared {
        let f = background::factor(frame.width(), params.coarse_width);
        let mut small = Small::of(frame, f);
        Prepared {
            params: *params,
            luma_look: luma_look(frame, &mut small, params.min_radius),
            small,
            noise: pixel_noise(&frame.luma),
        }
    }
}

/// `detect::coarse` of `frame`'s luma: from `small`'s luma where `small` is the
/// frame reduced alike (one reduction serves the learner and both looks), lent to
/// the look and given back (not copied: a quarter of a megabyte a 1080p frame).
pub fn luma_look(frame: &Frame, small: &mut Small, min_radius: f64) -> Coarse {
    if small.factor == detect::factor(frame.luma.width) {
        let levels = Levels {
            width: small.width,
            height: small.height,
            data: std::mem::take(&mut small.y),
        };
        let look = detect::coarse_reduced(&levels, small.factor, min_radius);
        small.y = levels.data;
        look
    } else {
        detect::coarse(&frame.luma, min_radius)
    }
}
