//! The video as the app shows it: small pictures of its frames (made while tracking,
//! each a box average of its frame; memory bounded by [`BUDGET`] whatever the video's
//! length: a long video keeps every k-th frame), the tracked centres and marks in
//! the video's pixels, and how the tracks' metres map back to those pixels (the
//! scale, the groove's angle and the origin the tracker found). Kept with the
//! tracks in the cache ([`VideoView::to_bytes`]), so a second open is instant.

use serde::{Deserialize, Serialize};

use super::gray::Gray;
use super::tracks::Tracks;

/// Most bytes of pictures kept for one video (a 3 s clip at 100 frames/s: 300
/// pictures of 79 × 44).
pub const BUDGET: usize = 1 << 20;

/// Widest picture kept, px (wider than the Scene panel of a 200-column terminal).
const MAX_WIDTH: usize = 160;

/// Small pictures of a video's frames, row by row, 8-bit luma.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Thumbs {
    pub width: usize,
    pub height: usize,
    /// The video's own size, px.
    pub video: (usize, usize),
    /// Every `every`-th frame is kept (1: all).
    pub every: usize,
    #[serde(skip)]
    pub pictures: Vec<Vec<u8>>,
}

impl Thumbs {
    /// Pictures of a `w × h` video of about `frames` frames, sized so that all of
    /// them fit in [`BUDGET`] (at least 32 px wide; a longer video keeps fewer).
    pub fn sized(w: usize, h: usize, frames: u64) -> Thumbs {
        let (w, h) = (w.max(1), h.max(1));
        let n = frames.max(1) as f64;
        let aspect = w as f64 / h as f64;
        let area = BUDGET as f64 / n;
        let tw = ((area * aspect).sqrt() as usize)
            .clamp(32, MAX_WIDTH)
            .min(w);
        let th = ((tw as f64 / aspect).round() as usize).clamp(1, h);
        let every = ((n * (tw * th) as f64 / BUDGET as f64).ceil() as usize).max(1);
        Thumbs {
            width: tw,
            height: th,
            video: (w, h),
            every,
            pictures: Vec::new(),
        }
    }

    /// These pictures' first alone (the first frame's), the sizes kept: no copy of
    /// the others.
    pub fn first(&self) -> Thumbs {
        Thumbs {
            every: 1,
            pictures: self.pictures.first().cloned().into_iter().collect(),
            ..*self
        }
    }

    /// Takes frame `index` (counted from 0) if it is one kept.
    pub fn push(&mut self, index: usize, img: &Gray) {
        if index.is_multiple_of(self.every) {
            self.pictures.push(self.reduce(img));
        }
    }

    /// `img` reduced to a picture: each pixel the mean of its box of the frame.
    fn reduce(&self, img: &Gray) -> Vec<u8> {
        let (tw, th) = (self.width, self.height);
        let mut out = Vec::with_capacity(tw * th);
        let cols: Vec<(usize, usize)> = (0..tw).map(|x| span(x, tw, img.width)).collect::<Vec<_>>();
        // A box row's lines summed per column first (one vectorised add per byte),
        // then each box's columns; in 16 bits while a box's rows of 255 fit (twice
        // the adds per instruction): the same whole sums.
        let tall = (0..th)
            .map(|y| span(y, th, img.height))
            .map(|(a, b)| b - a)
            .max();
        if tall.unwrap_or(0) * 255 <= usize::from(u16::MAX) {
            self.reduce_in::<u16>(img, &cols, &mut out);
        } else {
            self.reduce_in::<u32>(img, &cols, &mut out);
        }
        out
    }

    /// [`Thumbs::reduce`]'s box means into `out`, the columns summed in `C`.
    #[allow(clippy::indexing_slicing)] // whole boxes inside the frame
    fn reduce_in<C>(&self, img: &Gray, cols: &[(usize, usize)], out: &mut Vec<u8>)
    where
        C: Copy + Default + std::ops::AddAssign + From<u8> + Into<u32>,
    {
        let th = self.height;
        let mut columns = vec![C::default(); img.width];
        for y in 0..th {
            let (y0, y1) = span(y, th, img.height);
            columns.iter_mut().for_each(|c| *c = C::default());
            for row in y0..y1 {
                let line = &img.data[row * img.width..(row + 1) * img.width];
                for (c, &v) in columns.iter_mut().zip(line) {
                    *c += C::from(v);
                }
            }
            for &(x0, x1) in cols {
                let sum: u32 = columns[x0..x1].iter().map(|&c| c.into()).sum();
                let n = ((y1 - y0) * (x1 - x0)).max(1) as u32;
                out.push((sum / n) as u8);
            }
        }
    }

    /// The picture of frame `index` (the nearest kept one), if any.
    pub fn picture(&self, index: usize) -> Option<&[u8]> {
        let k = ((index + self.every / 2) / self.every).min(self.pictures.len().checked_sub(1)?);
        self.pictures.get(k).map(Vec::as_slice)
    }

    /// Bytes held by the pictures.
    pub fn bytes(&self) -> usize {
        self.pictures.iter().map(Vec::len).sum()
    }
}

/// The source rows (or columns) `[lo, hi)` that pixel `i` of `n` covers in `len`.
fn span(i: usize, n: usize, len: usize) -> (usize, usize) {
    let lo = i * len / n;
    let hi = ((i + 1) * len / n).max(lo + 1).min(len);
    (lo, hi)
}

/// One ball's tracked points in the video's pixels, frame by frame (`None` where
/// left out).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BallPixels {
    pub name: String,
    pub centre: Vec<Option<(f32, f32)>>,
    pub mark: Vec<Option<(f32, f32)>>,
}

/// A tracked video as the app draws it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VideoView {
    pub thumbs: Thumbs,
    /// Each frame's time, s, from the first frame (the tracks' t).
    pub t: Vec<f64>,
    /// Pixels per metre; the groove's angle in the picture, rad (positive: the
    /// right end lower); the pixel of the tracks' x = y = 0.
    pub px_per_m: f64,
    pub groove: f64,
    pub origin: (f64, f64),
    /// The balls' fitted radius, px.
    pub radius_px: f64,
    pub balls: Vec<BallPixels>,
    /// The pictures' dark and bright luma (their 10th and 90th percentiles) and the
    /// level halfway between, for a drawing in few tones.
    pub levels: [u8; 3],
    /// The first frame shown alone, for a click on a ball in it (a seed is a point in
    /// the first frame), with this note beside it: why the video was not tracked, or
    /// how to go back ([`VideoView::first_frame`], [`VideoView::first_only`]); `None`
    /// for a tracked video's view.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub first_only: Option<String>,
}

/// Why cached bytes are no [`VideoView`].
#[derive(Debug, thiserror::Error)]
pub enum Damaged {
    #[error("the cached pictures are damaged (no header)")]
    NoHeader,
    #[error("the cached pictures are damaged ({0})")]
    Header(serde_json::Error),
    /// `bytes` of pictures, not a whole number of pictures of `size` bytes (or too many).
    #[error("the cached pictures are damaged ({bytes} bytes of pictures of {size})")]
    Pictures { bytes: usize, size: usize },
}

impl VideoView {
    /// The view of `tracks` with `thumbs` made from the same frames.
    pub fn new(thumbs: Thumbs, tracks: &Tracks) -> VideoView {
        let c = &tracks.calibration;
        let groove = c.groove_deg.to_radians();
        let mut view = VideoView {
            thumbs,
            t: tracks.t.clone(),
            px_per_m: c.px_per_m,
            groove,
            origin: c.origin_px,
            radius_px: c.radius_px,
            balls: Vec::new(),
            levels: [0, 128, 255],
            first_only: None,
        };
        let px = |x: f64, y: f64| {
            let p = view.pixel(x, y);
            (x.is_finite() && y.is_finite()).then_some((p.0 as f32, p.1 as f32))
        };
        let balls = tracks
            .balls
            .iter()
            .map(|b| BallPixels {
                name: b.name.to_string(),
                centre: b.x.iter().zip(&b.y).map(|(&x, &y)| px(x, y)).collect(),
                mark: b
                    .mark_x
                    .iter()
                    .zip(&b.mark_y)
                    .map(|(&x, &y)| px(x, y))
                    .collect(),
            })
            .collect();
        view.balls = balls;
        view.levels = levels(&view.thumbs.pictures);
        view
    }

    /// The first frame of a video the tracker refused (`why`), its whole height, with
    /// the outlines it found there (`found`: centre and mark, video px): the app shows
    /// it so that a click on a ball seeds the tracking again (`--ball-at` is a point
    /// in the first frame). No scale: nothing turns metres into its pixels.
    pub fn first_frame(
        mut thumbs: Thumbs,
        found: &[super::overlay::Drawn],
        why: String,
    ) -> VideoView {
        thumbs.pictures.truncate(1);
        thumbs.every = 1;
        let balls = found
            .iter()
            .enumerate()
            .map(|(i, b)| BallPixels {
                name: format!("found {}", i + 1),
                centre: vec![Some((b.centre.0 as f32, b.centre.1 as f32))],
                mark: vec![b.mark.map(|m| (m.0 as f32, m.1 as f32))],
            })
            .collect();
        let levels = levels(&thumbs.pictures);
        VideoView {
            thumbs,
            t: vec![0.0],
            px_per_m: f64::NAN,
            groove: 0.0,
            origin: (f64::NAN, f64::NAN),
            radius_px: f64::NAN,
            balls,
            levels,
            first_only: Some(why),
        }
    }

    /// This view's first frame alone, with its tracked centres and marks there and
    /// `note` beside it.
    pub fn first_only(&self, note: String) -> VideoView {
        let found: Vec<super::overlay::Drawn> = self
            .balls
            .iter()
            .filter_map(|b| {
                let (x, y) = b.centre.first().copied().flatten()?;
                Some(super::overlay::Drawn {
                    centre: (f64::from(x), f64::from(y)),
                    radius: self.radius_px,
                    mark: b
                        .mark
                        .first()
                        .copied()
                        .flatten()
                        .map(|(x, y)| (f64::from(x), f64::from(y))),
                })
            })
            .collect();
        VideoView::first_frame(self.thumbs.first(), &found, note)
    }

    /// The video's pixel of the tracks' point (x along the groove, y up), m.
    pub fn pixel(&self, x: f64, y: f64) -> (f64, f64) {
        let (c, s) = (self.groove.cos(), self.groove.sin());
        let k = self.px_per_m;
        (
            self.origin.0 + k * (x * c + y * s),
            self.origin.1 + k * (x * s - y * c),
        )
    }

    /// The frame shown at time `t` (s from the first frame): the nearest.
    #[allow(clippy::indexing_slicing)] // j comes from a search of self.t
    pub fn frame_at(&self, t: f64) -> Option<usize> {
        if self.t.is_empty() || !t.is_finite() {
            return None;
        }
        let i = self.t.partition_point(|&s| s < t);
        let best = match (i.checked_sub(1), self.t.get(i)) {
            (Some(j), Some(&b)) if t - self.t[j] <= b - t => j,
            (Some(j), None) => j,
            _ => i,
        };
        Some(best)
    }

    /// The view as bytes: a JSON line, then the pictures.
    #[allow(clippy::expect_used)] // plain data (numbers and byte vectors) always serializes
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = serde_json::to_vec(self).expect("plain data serializes");
        out.push(b'\n');
        for p in &self.thumbs.pictures {
            out.extend_from_slice(p);
        }
        out
    }

    /// The view from [`VideoView::to_bytes`].
    #[allow(clippy::indexing_slicing)] // lengths checked before each slice
    pub fn from_bytes(bytes: &[u8]) -> Result<VideoView, Damaged> {
        let nl = bytes
            .iter()
            .position(|&b| b == b'\n')
            .ok_or(Damaged::NoHeader)?;
        let mut view: VideoView = serde_json::from_slice(&bytes[..nl]).map_err(Damaged::Header)?;
        let size = view.thumbs.width * view.thumbs.height;
        let rest = &bytes[nl + 1..];
        if size == 0 || !rest.len().is_multiple_of(size) || rest.len() > 4 * BUDGET {
            return Err(Damaged::Pictures {
                bytes: rest.len(),
                size,
            });
        }
        view.thumbs.pictures = rest.chunks_exact(size).map(<[u8]>::to_vec).collect();
        Ok(view)
    }
}

/// The pictures' dark and bright ends (their 1st and 99th percentiles: the balls
/// are a small share of a frame) and the level that best parts them in two (Otsu's:
/// the most variance between the two parts).
#[allow(clippy::indexing_slicing)] // a 256-bin histogram indexed by a byte
fn levels(pictures: &[Vec<u8>]) -> [u8; 3] {
    let mut hist = [0u64; 256];
    for p in pictures {
        for &v in p {
            hist[usize::from(v)] += 1;
        }
    }
    let total: u64 = hist.iter().sum();
    let level = |share: f64| {
        let want = (share * total as f64) as u64;
        let mut seen = 0;
        for (v, &n) in hist.iter().enumerate() {
            seen += n;
            if seen > want {
                return v as u8;
            }
        }
        255
    };
    let (n, sum) = hist.iter().enumerate().fold((0.0, 0.0), |(n, s), (v, &c)| {
        (n + c as f64, s + (v as f64) * c as f64)
    });
    let (mut best, mut split) = (-1.0, 128u8);
    let (mut n0, mut s0) = (0.0, 0.0);
    for (v, &c) in hist.iter().enumerate().take(255) {
        n0 += c as f64;
        s0 += v as f64 * c as f64;
        let n1 = n - n0;
        if n0 == 0.0 || n1 == 0.0 {
            continue;
        }
        let between = n0 * n1 * (s0 / n0 - (sum - s0) / n1).powi(2);
        if between > best {
            (best, split) = (between, v as u8);
        }
    }
    [level(0.01), split, level(0.99)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pictures_stay_within_the_budget_however_long_the_video() {
        for frames in [10u64, 300, 720, 24_000, 1_000_000] {
            let mut t = Thumbs::sized(1920, 1080, frames);
            let img = Gray::filled(1920, 1080, 7);
            // Only the size matters: push the kept ones as empty frames would be.
            let kept = frames.div_ceil(t.every as u64) as usize;
            // Within the budget but for the last picture's rounding.
            assert!(
                kept * t.width * t.height <= BUDGET + t.width * t.height,
                "{frames}: {t:?}"
            );
            assert!(t.width >= 32 && t.width <= MAX_WIDTH);
            t.push(0, &img);
            assert_eq!(t.picture(0).unwrap(), vec![7; t.width * t.height]);
        }
    }

    #[test]
    fn a_picture_is_the_mean_of_its_box() {
        let mut img = Gray::filled(4, 2, 0);
        img.data[0] = 40; // box (0, 0) of 2×2 in a 2×1 picture: (40 + 0 + 0 + 0) / 4
        let mut t = Thumbs {
            width: 2,
            height: 1,
            video: (4, 2),
            every: 1,
            pictures: Vec::new(),
        };
        t.push(0, &img);
        assert_eq!(t.picture(0), Some(&[10u8, 0][..]));
    }

    fn view() -> VideoView {
        let mut thumbs = Thumbs::sized(64, 36, 3);
        for k in 0..3 {
            let mut img = Gray::filled(64, 36, 40);
            img.data[k * 70] = 250;
            thumbs.push(k, &img);
        }
        VideoView {
            thumbs,
            t: vec![0.0, 0.01, 0.02],
            px_per_m: 1234.5,
            groove: 0.05,
            origin: (31.5, 17.25),
            radius_px: 13.6,
            balls: vec![BallPixels {
                name: "left".into(),
                centre: vec![Some((1.0, 2.0)), None, Some((3.5, 4.25))],
                mark: vec![None, Some((5.0, 6.0)), None],
            }],
            levels: [40, 100, 250],
            first_only: None,
        }
    }

    #[test]
    fn metres_go_back_to_the_pixels_they_came_from() {
        // The tracks' metres of pixel p, as `tracks::tracks` makes them (x along the
        // groove turned by its angle, y up, about the origin, over the scale).
        let v = view();
        let (c, s) = (v.groove.cos(), v.groove.sin());
        for p in [(0.0, 0.0), (10.0, 30.0), (63.0, 1.5)] {
            let (dx, dy) = (p.0 - v.origin.0, p.1 - v.origin.1);
            let m = (
                (dx * c + dy * s) / v.px_per_m,
                (dx * s - dy * c) / v.px_per_m,
            );
            let back = v.pixel(m.0, m.1);
            assert!((back.0 - p.0).abs() < 1e-9 && (back.1 - p.1).abs() < 1e-9);
        }
    }

    #[test]
    fn a_view_survives_its_bytes_and_damaged_bytes_are_refused() {
        let v = view();
        let bytes = v.to_bytes();
        assert_eq!(VideoView::from_bytes(&bytes).unwrap(), v);
        assert!(VideoView::from_bytes(&bytes[..bytes.len() - 1]).is_err());
        assert!(VideoView::from_bytes(b"garbage").is_err());
    }

    #[test]
    fn the_frame_at_a_time_is_the_nearest() {
        let v = view();
        assert_eq!(v.frame_at(-1.0), Some(0));
        assert_eq!(v.frame_at(0.004), Some(0));
        assert_eq!(v.frame_at(0.006), Some(1));
        assert_eq!(v.frame_at(9.0), Some(2));
        assert_eq!(v.frame_at(f64::NAN), None);
    }
}
