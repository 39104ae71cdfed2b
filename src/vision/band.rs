//! The groove's band: the rows of the frame the balls roll through, found from the
//! clip's first frames, so that only they are decoded and tracked (issue 34's speed:
//! a quarter of a 1080p frame's bytes through ffmpeg's pipe, and a quarter of every
//! pass over the pixels). The balls roll along one line, the groove (tilted as the
//! phone was); the band holds that line across the whole width and
//! [`Band::MARGIN_RADII`] radii above and below it. Where the first frames leave the
//! line in doubt, there is no band: the whole frame is tracked, as before. A band
//! is a speed-up, never a new refusal: `input::video::tracked` tracks the whole
//! frame again when the banded tracking is refused or a ball came near the band's
//! edge ([`Band::holds`]). How it is found: docs/tracking.md.

use super::background::factor;
use super::frame::{Frame, chroma_size};
use super::gray::Gray;
use super::params::Params;
use super::tracker::{FrameFixes, Tracker};
use std::borrow::Borrow;

/// Rows `y .. y + height` of frames `height_of` high, full width: where the tracker
/// looks. `y` and `height` are multiples of twice the coarse reductions, so the
/// band's coarse pixels (and its colour rows) are the whole frame's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    pub y: usize,
    pub height: usize,
    /// The whole frame's height, px.
    pub frame_height: usize,
    /// The whole frame's pixel noise in the first frames (`prepared::pixel_noise`,
    /// luma levels), which the band's frames are given: the band's own sample of
    /// pixels gives another (a median of whole levels: 1.05 or 2.10), and the marks'
    /// threshold is a multiple of it.
    pub noise: f64,
}

/// Frames of the clip's start looked at for the balls' line, evenly over the first
/// [`first_frames`] (the first and the last of them among them).
pub const FIRST_FRAMES: usize = 3;
/// Fewest frames from the first looked-at to the last: a passing blob does not
/// agree with itself.
pub const LEAST_SPAN: usize = 12;
/// Seconds from the first looked-at frame to the last, where the rate allows more
/// than [`LEAST_SPAN`] frames: the background is learned from these frames, and a
/// ball stands out of it only where it covered a pixel in less than half of them
/// (rolling its own width, 5.5 cm, in under half the span: faster than 0.75 m/s,
/// the paper's clip's approach; at 240 frames/s a span of 12 frames, 0.05 s, kept
/// most balls in the background).
pub const SPAN_S: f64 = 0.15;
/// Most frames from the first looked-at to the last (the first frames are kept
/// whole until the band is found: 48 of 1080p are 150 MB).
pub const MOST_SPAN: usize = 48;
/// Largest relative spread of the first frames' pixel noise for a band (else the
/// clip's noise may change, and the band, given the first frames', could not follow
/// it): a textured wall's noise is its grain, which an encoder renders a level or
/// so differently frame to frame (8.4 and 9.4 levels); a plain wall's, a level or
/// two, steps from 1.05 to 2.10 and gives no band.
pub const NOISE_SPREAD: f64 = 0.15;

/// The most of the clip's first frames, counted from the first, that the band is
/// found from for a clip of `fps` frames/s: [`SPAN_S`] of them, at least
/// [`LEAST_SPAN`] + 1 and at most [`MOST_SPAN`] + 1. (`input::video::tracked`
/// tries the first [`LEAST_SPAN`] + 1 first, and reads on only where they leave
/// the line in doubt.)
pub fn first_frames(fps: f64) -> usize {
    let span = (SPAN_S * fps).round();
    let span = if span.is_finite() && span > 0.0 {
        (span as usize).clamp(LEAST_SPAN, MOST_SPAN)
    } else {
        LEAST_SPAN
    };
    span + 1
}

impl Band {
    /// Radii kept above and below the balls' line: the outline's outermost edge is
    /// sought out to 2.2 radii from the centre (`Params::outer_reach`), and the line
    /// from the first frames may be off a little at the far end of a tilted groove
    /// (a ball that strays further is tracked whole again, [`Band::KEEP_RADII`]).
    /// Tracker 56: 3, was 4 — every pass over a band's pixels, and the pipe, a
    /// quarter less (look 85's 1080p band 558 → 420 rows, 0.93 of its time), the
    /// looks tables' verdicts and band count as with 4.
    pub const MARGIN_RADII: f64 = 3.0;
    /// Radii a fit's centre must keep from a band's edge (not the frame's) for the
    /// banded tracking to stand ([`Band::holds`]): the outermost-edge check's reach
    /// (2.2) and a tenth more, so that no check of a banded fit reads past the band.
    pub const KEEP_RADII: f64 = 2.3;
    /// Largest share of the frame a band may take: more, and the whole frame is
    /// tracked (little to gain, and the look's statistics drift from the whole's).
    pub const MOST_SHARE: f64 = 0.6;

    /// The band's rows of `frame` (which is the whole frame): a frame of its own.
    pub fn cut(&self, frame: &Frame) -> Frame {
        let w = frame.width();
        let (cw, _) = chroma_size(w, self.height);
        let rows = |data: &[u8], width: usize, y: usize, h: usize| -> Vec<u8> {
            data.get(y * width..(y + h) * width)
                .map(<[u8]>::to_vec)
                .unwrap_or_else(|| vec![128; width * h])
        };
        let ch = self.height.div_ceil(2);
        Frame {
            luma: Gray {
                width: w,
                height: self.height,
                data: rows(&frame.luma.data, w, self.y, self.height),
            },
            chroma_width: cw,
            chroma_height: ch,
            u: rows(&frame.u, cw, self.y / 2, ch),
            v: rows(&frame.v, cw, self.y / 2, ch),
        }
    }

    /// `params` for frames of this band: the rectangle and the seed moved up by its top.
    pub fn params(&self, params: &Params) -> Params {
        let dy = self.y as f64;
        Params {
            roi: params.roi.map(|r| super::Roi { y: r.y - dy, ..r }),
            ball_at: params.ball_at.map(|(x, y)| (x, y - dy)),
            ..*params
        }
    }

    /// True when every fit of `frames` (the whole frame's pixels) keeps
    /// [`Band::KEEP_RADII`] of `radius` from the band's edges that are not the
    /// frame's: the balls stayed well inside it.
    pub fn holds(&self, frames: &[FrameFixes], radius: f64) -> bool {
        let keep = Self::KEEP_RADII * radius;
        let top = if self.y == 0 {
            f64::NEG_INFINITY
        } else {
            self.y as f64 + keep
        };
        let bottom_edge = self.y + self.height;
        let bottom = if bottom_edge >= self.frame_height {
            f64::INFINITY
        } else {
            bottom_edge as f64 - keep
        };
        radius.is_finite()
            && frames
                .iter()
                .flatten()
                .flatten()
                .all(|fix| (top..=bottom).contains(&fix.outline.circle.y))
    }
}

/// Every fit, mark and spot of `frames` moved down by `dy` px: from a band's pixels
/// to the whole frame's.
pub fn shift(frames: &mut [FrameFixes], dy: f64) {
    for fix in frames.iter_mut().flatten().flatten() {
        fix.outline.circle.y += dy;
        fix.outline.lowest += dy;
        if let Some(m) = &mut fix.mark {
            m.y += dy;
        }
        for (_, y, _) in fix.spots.iter_mut().flatten() {
            *y += dy;
        }
    }
}

/// The band around the balls' line in `first` (the clip's first frames, whole and
/// in order, [`first_frames`] of them; [`FIRST_FRAMES`] looked at, evenly from the
/// first to the last), or
/// `None` when the line is in doubt: not exactly two balls of one radius in each
/// looked-at frame, more than one of them crowded (a third thing seen: as a clip
/// crowded in under half its frames is tracked, one such frame of three is no doubt
/// where the three agree on the line), balls too close to tell the line's tilt,
/// frames that disagree on it, a band of most of the frame, a seed (`--ball-at`) off
/// its rows, or a pixel noise that changes between the first frames by more than
/// [`NOISE_SPREAD`].
pub fn find<F: Borrow<Frame>>(first: &[F], params: &Params) -> Option<Band> {
    let frames: Vec<&Frame> = first.iter().map(Borrow::borrow).collect();
    let first = frames.as_slice();
    let (w, h) = (first.first()?.width(), first.first()?.height());
    if first.iter().any(|f| (f.width(), f.height()) != (w, h)) {
        return None;
    }
    // The tracker with a background learned from these frames (balls that moved
    // past their own width stand out of it, on any wall), else with none (the look
    // against a smooth surface of luma, which sees a ball at rest on a plain wall).
    let (lines, radius) = lines(first, params, true).or_else(|| lines(first, params, false))?;
    let noise = steady_noise(first)?;
    band_about(&lines, radius, (w, h), params).map(|b| Band { noise, ..b })
}

/// The whole frame's pixel noise over `first` (their median), or `None` when it
/// spreads by more than [`NOISE_SPREAD`] of it.
fn steady_noise(first: &[&Frame]) -> Option<f64> {
    steady(
        first
            .iter()
            .map(|f| super::prepared::pixel_noise(&f.luma))
            .collect(),
    )
}

/// The median of `noises`, or `None` when they spread by more than
/// [`NOISE_SPREAD`] of it.
fn steady(mut noises: Vec<f64>) -> Option<f64> {
    noises.sort_by(f64::total_cmp);
    let (lo, hi) = (*noises.first()?, *noises.last()?);
    let noise = *noises.get(noises.len() / 2)?;
    (hi - lo <= NOISE_SPREAD * noise).then_some(noise)
}

/// Each looked-at frame's line through its two balls (its height at the middle of
/// the width, its slope) and the balls' radius, or `None` when any frame does not
/// show exactly two balls of one radius 4 radii apart or more, or the frames'
/// lines disagree. `learned`: the background learned from all of `first` first.
fn lines(first: &[&Frame], params: &Params, learned: bool) -> Option<(Vec<(f64, f64)>, f64)> {
    let mut t = Tracker::new(*params);
    if learned {
        first.iter().for_each(|f| t.learn(f));
    }
    let every = (first.len().saturating_sub(1) / (FIRST_FRAMES - 1)).max(1);
    first
        .iter()
        .step_by(every)
        .take(FIRST_FRAMES)
        .for_each(|f| t.push(f));
    if t.counts.mostly_crowded() || t.frames.len() < FIRST_FRAMES {
        return None;
    }
    let half = 0.5 * first.first()?.width() as f64;
    let mut lines = Vec::new();
    let mut radius: f64 = 0.0;
    for f in &t.frames {
        let [Ok(a), Ok(b)] = f else { return None };
        let (a, b) = (a.outline.circle, b.outline.circle);
        let r = 0.5 * (a.r + b.r);
        let dx = b.x - a.x;
        if (a.r - b.r).abs() > 0.1 * r || dx.abs() < 4.0 * r {
            return None;
        }
        let slope = (b.y - a.y) / dx;
        lines.push((a.y + slope * (half - a.x), slope));
        radius = radius.max(r);
    }
    let (first_line, _) = lines.split_first()?;
    let agree = lines.iter().all(|(mid, slope)| {
        (mid - first_line.0).abs() < 0.25 * radius && (slope - first_line.1).abs() < 0.02
    });
    (agree && radius.is_finite()).then_some((lines, radius))
}

/// The band about `lines` (see [`lines`]) for balls of `radius` in frames `w × h`.
fn band_about(
    lines: &[(f64, f64)],
    radius: f64,
    (w, h): (usize, usize),
    params: &Params,
) -> Option<Band> {
    // The line's highest and lowest rows across the width, and the margin.
    let half = 0.5 * w as f64;
    let ends = lines
        .iter()
        .flat_map(|(mid, slope)| [mid - slope * half, mid + slope * half]);
    let (lo, hi) = ends.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| {
        (lo.min(y), hi.max(y))
    });
    let margin = Band::MARGIN_RADII * radius;
    let step = alignment(w, params);
    let top = ((lo - margin).floor().max(0.0) as usize) / step * step;
    let bottom = (((hi + margin).ceil().max(0.0) as usize).div_ceil(step) * step).min(h);
    let height = bottom.checked_sub(top)?;
    if height == 0 || height as f64 > Band::MOST_SHARE * h as f64 {
        return None;
    }
    // A seed off the band's rows: the whole frame, where the user pointed.
    if params
        .ball_at
        .is_some_and(|(_, y)| !(y >= top as f64 && y < bottom as f64))
    {
        return None;
    }
    Some(Band {
        y: top,
        height,
        frame_height: h,
        noise: 1.0,
    })
}

/// Rows a band's top and height are multiples of, for frames `width` wide: twice
/// each coarse reduction (the background's and the luma look's), so the band's
/// coarse pixels and colour rows are the whole frame's.
fn alignment(width: usize, params: &Params) -> usize {
    let gcd = |mut a: usize, mut b: usize| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let lcm = |a: usize, b: usize| a / gcd(a, b).max(1) * b;
    let (f1, f2) = (
        factor(width, params.coarse_width),
        super::detect::factor(width),
    );
    lcm(2, lcm(f1.max(1), f2.max(1)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_frames_span_a_time_and_their_noise_may_spread_a_little() {
        // 0.15 s at 240 and 100 frames/s; 12 frames' span at least, 48 at most.
        assert_eq!(first_frames(240.0), 37);
        assert_eq!(first_frames(100.0), 16);
        assert_eq!(first_frames(30.0), 13);
        assert_eq!(first_frames(1000.0), 49);
        assert_eq!(first_frames(f64::NAN), 13);
        // A grainy wall's noise, a level apart in some frames: their median.
        assert_eq!(steady(vec![9.44, 8.39, 8.39]), Some(8.39));
        assert_eq!(steady(vec![8.39, 9.44, 9.44]), Some(9.44));
        // A plain wall's steps by 100 %; a noiseless frame's is none.
        assert_eq!(steady(vec![1.05, 2.10, 1.05]), None);
        assert_eq!(steady(vec![0.0, 0.0, 0.0]), Some(0.0));
        assert_eq!(steady(Vec::new()), None);
    }

    #[test]
    fn a_band_is_aligned_to_the_coarse_pixels_and_cut_alike() {
        let p = Params::default();
        assert_eq!(alignment(1920, &p), 6);
        assert_eq!(alignment(1280, &p), 4);
        assert_eq!(alignment(1000, &p), 6);
        let mut luma = Gray::filled(8, 8, 0);
        for (i, v) in luma.data.iter_mut().enumerate() {
            *v = i as u8;
        }
        let mut frame = Frame::from_gray(luma);
        frame.u = (0..16).collect();
        let band = Band {
            y: 2,
            height: 4,
            frame_height: 8,
            noise: 1.0,
        };
        let cut = band.cut(&frame);
        assert_eq!(cut.luma.data, (16..48).collect::<Vec<u8>>());
        assert_eq!(cut.u, (4..12).collect::<Vec<u8>>());
        assert_eq!((cut.chroma_width, cut.chroma_height), (4, 2));
    }

    /// A fit at height `y` (px), radius 10.
    fn fit_at(y: f64) -> FrameFixes {
        let outline = crate::vision::circle::Outline {
            lowest: y + 5.0,
            ..crate::vision::circle::Outline::upper_half(50.0, y, 10.0)
        };
        let fix = crate::vision::tracker::Fix {
            outline,
            sigma: 0.1,
            mark: None,
            spots: {
                let mut spots = [None; crate::vision::mark::SPOTS];
                spots[0] = Some((50.0, y - 3.0, 20.0));
                spots
            },
            colour: None,
        };
        [Ok(fix), Err(crate::vision::tracker::LeftOut::Unseen)]
    }

    #[test]
    fn fits_are_moved_to_the_whole_frame_and_must_keep_off_the_bands_edges() {
        let band = Band {
            y: 100,
            height: 120,
            frame_height: 400,
            noise: 1.0,
        };
        let mut frames = vec![fit_at(60.0)];
        shift(&mut frames, 100.0);
        let [Ok(f), _] = &frames[0] else { panic!() };
        assert_eq!((f.outline.circle.y, f.outline.lowest), (160.0, 165.0));
        assert_eq!(f.spots[0], Some((50.0, 157.0, 20.0)));
        // `KEEP_RADII` (2.3) radii from either edge that is not the frame's: rows
        // 123 to 197 of the band's 100 to 220 for a radius of 10.
        assert!(band.holds(&frames, 10.0));
        assert!(!band.holds(&[fit_at(122.9)], 10.0));
        assert!(!band.holds(&[fit_at(197.1)], 10.0));
        assert!(band.holds(&[fit_at(123.0), fit_at(197.0)], 10.0));
        // The frame's own edge bounds nothing.
        let top = Band { y: 0, ..band };
        assert!(top.holds(&[fit_at(5.0)], 10.0));
        assert!(!band.holds(&frames, f64::NAN));
    }
}
