//! What of the tracker's look at a frame depends on the frame alone, made once and
//! ahead of the frame's turn, off the tracker's thread (`input::video` makes it on
//! the thread that reads the frames, while the tracker works on earlier ones): the
//! frame reduced to the coarse size, which the learner keeps and the look compares
//! with the background; the look against a smooth surface of luma; the pixel
//! noise. The very numbers the tracker would make from the frame itself.

use super::background::{self, Small};
use super::detect::{self, Coarse};
use super::frame::Frame;
use super::gray::{Gray, Levels};
use super::params::Params;
use std::sync::Arc;

/// A frame's own part of its look (see the module's note).
#[derive(Clone, Debug)]
pub struct PreparedLook {
    /// The parameters it was made for: a tracker with others makes its own.
    pub params: Params,
    /// The frame reduced by the learner's factor (`background::factor`), shared
    /// by the learner's sample and the tracker's look.
    pub small: Arc<Small>,
    /// The look against a smooth surface of luma (`detect::coarse`).
    pub luma_look: Coarse,
    /// The frame's pixel noise ([`pixel_noise`]).
    pub noise: f64,
}

impl PreparedLook {
    /// The part of `frame`'s look that is the frame's alone, for a tracker of
    /// `params`.
    pub fn of(frame: &Frame, params: &Params) -> PreparedLook {
        let f = background::factor(frame.width(), params.coarse_width);
        let mut small = Small::of(frame, f);
        let luma_look = luma_look(frame, &mut small, params.min_radius);
        PreparedLook {
            params: *params,
            luma_look,
            small: Arc::new(small),
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

/// The pixel noise of a frame, luma levels: from neighbouring pixels' differences
/// over a sparse sample (their median, so edges do not count).
#[allow(clippy::indexing_slicing)] // i + 1 < len checked by the loop
pub fn pixel_noise(img: &Gray) -> f64 {
    let mut d = Vec::with_capacity(4096);
    let step = ((img.width * img.height) / 4096).max(1);
    let mut i = 0;
    while i + 1 < img.data.len() {
        if (i + 1) % img.width != 0 {
            d.push((f64::from(img.data[i + 1]) - f64::from(img.data[i])).abs());
        }
        i += step;
    }
    // Whole levels: the median counted by level (`select`), the sort's middle.
    super::select::median(&mut d).map_or(1.0, |m| m * 1.4826 / std::f64::consts::SQRT_2)
}
