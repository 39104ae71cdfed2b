//! The scene's background learned from the clip itself (the balls move, the bench
//! does not): frames reduced to the coarse look's size, a bounded sample of them
//! kept while the clip streams by (every k-th, k doubling when the sample is full),
//! and per coarse pixel and plane (Y, U, V) their median; then the median again with
//! each kept frame's differing pixels (the balls, their shadows) masked out, so a
//! ball that rests in one place for part of the clip weighs less. What differs
//! from it in a frame, in brightness or colour but not as a shadow, is a ball
//! candidate (`detect`).

use super::frame::Frame;
use super::params::Params;
use super::select;
use rayon::prelude::*;
use std::sync::Arc;

/// A frame reduced to the coarse size: Y, U and V per coarse pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Small {
    pub width: usize,
    pub height: usize,
    /// Full-frame pixels per coarse pixel, each way.
    pub factor: usize,
    /// Block means of luma.
    pub y: Vec<f32>,
    /// The colour planes' samples, whole levels (their bytes, not widened to f32:
    /// a third of the memory the learner's sample holds and gathers).
    pub u: Vec<u8>,
    pub v: Vec<u8>,
}

/// The reduction factor that brings a frame `width` wide to about `coarse` px.
pub fn factor(width: usize, coarse: usize) -> usize {
    (width / coarse.max(16)).max(1)
}

impl Small {
    /// `frame` reduced `factor` times: luma as block means, colour sampled at each
    /// block's middle (the colour planes are smooth already: half size, and what an
    /// encoder keeps least of).
    pub fn of(frame: &Frame, factor: usize) -> Small {
        let f = factor.max(1);
        let luma = frame.luma.reduced(f);
        let (w, h) = (luma.width, luma.height);
        let (cw, ch) = (frame.chroma_width, frame.chroma_height);
        let mut u = Vec::with_capacity(w * h);
        let mut v = Vec::with_capacity(w * h);
        // Each block's colour column once, not per row.
        let cxs: Vec<usize> = (0..w)
            .map(|bx| ((bx * f + f / 2) / 2).min(cw.saturating_sub(1)))
            .collect();
        // Each plane from its row's start on (a short plane: its missing samples
        // grey), a row's samples in one extend, without a check of room per sample.
        let sample = |plane: &[u8], cx: usize| plane.get(cx).copied().unwrap_or(128);
        for by in 0..h {
            let cy = ((by * f + f / 2) / 2).min(ch.saturating_sub(1));
            let ur = frame.u.get(cy * cw..).unwrap_or_default();
            let vr = frame.v.get(cy * cw..).unwrap_or_default();
            u.extend(cxs.iter().map(|&cx| sample(ur, cx)));
            v.extend(cxs.iter().map(|&cx| sample(vr, cx)));
        }
        Small {
            width: w,
            height: h,
            factor: f,
            y: luma.data,
            u,
            v,
        }
    }
}

/// The background: per coarse pixel, Y, U and V (see [`Small`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Background {
    pub image: Small,
}

/// Gathers the sample of frames the background is learned from.
#[derive(Clone, Debug)]
pub struct Learner {
    params: Params,
    every: usize,
    seen: usize,
    /// The sample, shared with the frames' looks (`PreparedLook::small`): a kept
    /// frame is the reduction the look uses, not a copy of it.
    kept: Vec<Arc<Small>>,
}

impl Learner {
    pub fn new(params: Params) -> Learner {
        Learner {
            params,
            every: 1,
            seen: 0,
            kept: Vec::new(),
        }
    }

    /// Frames offered so far.
    pub fn seen(&self) -> usize {
        self.seen
    }

    /// Offers one more frame (in the clip's order).
    pub fn push(&mut self, frame: &Frame) {
        let f = factor(frame.width(), self.params.coarse_width);
        self.offer(|| Arc::new(Small::of(frame, f)));
    }

    /// As [`Learner::push`], the frame already reduced by [`factor`] of its width
    /// and `coarse_width` (reduced once, for the learner and the tracker's look),
    /// kept shared, not copied (0.7 MB a 1080p frame).
    pub fn push_small(&mut self, small: &Arc<Small>) {
        self.offer(|| Arc::clone(small));
    }

    /// Offers one more frame, reduced by `small` only when it is one kept.
    fn offer(&mut self, small: impl FnOnce() -> Arc<Small>) {
        if self.seen.is_multiple_of(self.every) {
            let small = small();
            // Frames of another size than the first are not of this clip's bench.
            if self
                .kept
                .first()
                .is_none_or(|k| (k.width, k.height) == (small.width, small.height))
            {
                self.kept.push(small);
            }
            let cap = self.params.background_frames.max(3);
            if self.kept.len() >= 2 * cap {
                // Full: keep every other, and take every other frame from now on.
                let mut i = 0;
                self.kept.retain(|_| {
                    i += 1;
                    i % 2 == 1
                });
                self.every *= 2;
            }
        }
        self.seen += 1;
    }

    /// The background, `None` before any frame.
    pub fn finish(self) -> Option<Background> {
        self.background()
    }

    /// The background of the frames offered so far, `None` before any frame.
    pub fn background(&self) -> Option<Background> {
        let first = self.kept.first()?;
        let (w, h, f) = (first.width, first.height, first.factor);
        let n = w * h;
        let [y_pass, u_pass, v_pass] = [
            median_plane(&self.kept, n, |s| &s.y, None),
            median_plane(&self.kept, n, |s| &s.u, None),
            median_plane(&self.kept, n, |s| &s.v, None),
        ];
        let first_bg = Small {
            width: w,
            height: h,
            factor: f,
            y: y_pass,
            u: bytes(&u_pass),
            v: bytes(&v_pass),
        };
        // Again, each frame's differing pixels (and their neighbours) left out.
        let masks = differing(&self.kept, &first_bg, &self.params);
        let any_mask = touched(&masks, n);
        let again = |first_pass| {
            Some(Again {
                masks: &masks,
                touched: &any_mask,
                first_pass,
            })
        };
        let y = median_plane(&self.kept, n, |s| &s.y, again(&first_bg.y));
        let u = bytes(&median_plane(&self.kept, n, |s| &s.u, again(&u_pass)));
        let v = bytes(&median_plane(&self.kept, n, |s| &s.v, again(&v_pass)));
        Some(Background {
            image: Small {
                y,
                u,
                v,
                ..first_bg
            },
        })
    }
}

/// Medians of byte planes as bytes: each is one of the values, a whole level.
fn bytes(levels: &[f32]) -> Vec<u8> {
    levels.iter().map(|&l| l as u8).collect()
}

/// The second pass of a plane's medians: each frame's mask (its differing pixels
/// left out), which pixels any mask touches, and the plane's first-pass medians. A
/// pixel no mask touches has all its values again, so its median is the first
/// pass's (bit for bit): only the tiles the balls (and whatever else moved) touched,
/// a band along the groove, are counted again.
#[derive(Clone, Copy)]
struct Again<'a> {
    masks: &'a [Vec<bool>],
    touched: &'a [bool],
    first_pass: &'a [f32],
}

/// Each frame's pixels that differ from the background `bg` (over its
/// [`threshold`]), and their neighbours: what the second pass leaves out.
fn differing(frames: &[Arc<Small>], bg: &Small, p: &Params) -> Vec<Vec<bool>> {
    frames
        .par_iter()
        .map(|s| {
            let d = differences(s, bg, p);
            let thr = threshold(&d, p);
            dilate(
                &d.iter().map(|&v| v > thr).collect::<Vec<_>>(),
                bg.width,
                bg.height,
            )
        })
        .collect()
}

/// Per pixel, whether any of `masks` leaves it out.
fn touched(masks: &[Vec<bool>], n: usize) -> Vec<bool> {
    let mut any = vec![false; n];
    for m in masks {
        for (a, &b) in any.iter_mut().zip(m) {
            *a |= b;
        }
    }
    any
}

/// A plane's value: a byte (the colour planes: a whole level, counted per
/// level) or an f32 (luma's block means: by selection, unless whole levels).
trait Sample: Copy + Send + Sync {
    /// The level `self` is, when it is exactly one.
    fn level(self) -> Option<u8>;
    fn value(self) -> f32;
    /// Worth counting per level: every value is a whole level.
    const LEVELS: bool;
}

impl Sample for u8 {
    #[inline]
    fn level(self) -> Option<u8> {
        Some(self)
    }
    #[inline]
    fn value(self) -> f32 {
        f32::from(self)
    }
    const LEVELS: bool = true;
}

impl Sample for f32 {
    #[inline]
    fn level(self) -> Option<u8> {
        select::Level::level(self)
    }
    #[inline]
    fn value(self) -> f32 {
        self
    }
    const LEVELS: bool = false;
}

/// Pixels whose medians are taken together: each frame's run of them gathered at
/// once (half a kilobyte of each of some hundred frames: long enough runs for the
/// memory to stream them).
const TILE: usize = 128;

/// Per pixel, the median of `plane` over `frames`; with `again` (the second pass),
/// leaving out its masked samples (but taking them all when fewer than a quarter
/// are left), a tile no mask touches keeping the first pass's medians. The colour
/// planes' bytes are counted per level; luma's block means go by selection.
fn median_plane<T: Sample>(
    frames: &[Arc<Small>],
    n: usize,
    plane: impl Fn(&Small) -> &Vec<T>,
    again: Option<Again>,
) -> Vec<f32> {
    let planes: Vec<&[T]> = frames.iter().map(|s| plane(s).as_slice()).collect();
    let masks: Vec<&[bool]> =
        again.map_or_else(Vec::new, |a| a.masks.iter().map(Vec::as_slice).collect());
    // The first pass's medians of a tile no mask touches.
    let untouched = |start: usize, t: usize| {
        let a = again?;
        let end = start + t;
        if a.touched.get(start..end)?.iter().any(|&b| b) {
            return None;
        }
        a.first_pass.get(start..end)
    };
    let nf = frames.len();
    // Runs of pixels spread over the cores, each worker with lists and counts of
    // its own: each pixel's median is its own, the same numbers in any order. (A
    // new background stops the tracker for a tenth of a second of 1080p, while
    // ffmpeg soon waits on a full read-ahead: the other core is free.)
    const RUN: usize = 64 * TILE;
    let runs: Vec<Vec<f32>> = (0..n.div_ceil(RUN))
        .into_par_iter()
        .map_init(
            || (Lists::new(nf), LevelCounts::new()),
            |(lists, counts), r| {
                let end = ((r + 1) * RUN).min(n);
                let mut out = Vec::with_capacity(RUN);
                for start in (r * RUN..end).step_by(TILE) {
                    if let Some(first_pass) = untouched(start, TILE.min(end - start)) {
                        out.extend_from_slice(first_pass);
                        continue;
                    }
                    let tile = Tile {
                        planes: &planes,
                        masks: &masks,
                        start,
                        t: TILE.min(end - start),
                    };
                    // Counted, unless a value is not a whole level after all.
                    if !(T::LEVELS && counts.medians(&tile, &mut out)) {
                        lists.medians(&tile, &mut out);
                    }
                }
                out
            },
        )
        .collect();
    runs.concat()
}

/// Pixels `start … start + t` of every frame's plane (`planes`) and mask.
struct Tile<'a, T> {
    planes: &'a [&'a [T]],
    masks: &'a [&'a [bool]],
    start: usize,
    t: usize,
}

impl<T> Tile<'_, T> {
    /// True when pixel `j`'s median is over all its values, masked or not: fewer
    /// than a quarter of the frames left unmasked (`kept` of them).
    fn takes_all(&self, kept: usize) -> bool {
        kept * 4 < self.planes.len()
    }
}

/// Each pixel's list of values, kept (unmasked) and all, `planes.len()` long.
struct Lists {
    kept: Vec<f32>,
    all: Vec<f32>,
}

impl Lists {
    /// Room for a tile's lists over `nf` frames.
    fn new(nf: usize) -> Lists {
        Lists {
            kept: vec![0.0f32; TILE * nf],
            all: vec![0.0f32; TILE * nf],
        }
    }

    /// The tile's medians by selection (`select::median`: the sort's middle).
    #[allow(clippy::indexing_slicing)] // j < t ≤ TILE; a pixel's counts ≤ nf, its list j·nf … (j + 1)·nf
    fn medians<T: Sample>(&mut self, tile: &Tile<T>, out: &mut Vec<f32>) {
        let nf = tile.planes.len();
        let (mut nk, mut na) = ([0usize; TILE], [0usize; TILE]);
        for (k, p) in tile.planes.iter().enumerate() {
            let m = tile.masks.get(k).copied().unwrap_or(&[]);
            for j in 0..tile.t {
                let i = tile.start + j;
                let Some(v) = p.get(i).map(|&v| v.value()) else {
                    continue;
                };
                self.all[j * nf + na[j]] = v;
                na[j] += 1;
                if !m.get(i).copied().unwrap_or(false) {
                    self.kept[j * nf + nk[j]] = v;
                    nk[j] += 1;
                }
            }
        }
        for j in 0..tile.t {
            let vals = if tile.takes_all(nk[j]) {
                &mut self.all[j * nf..j * nf + na[j]]
            } else {
                &mut self.kept[j * nf..j * nf + nk[j]]
            };
            out.push(select::median(vals).unwrap_or(0.0));
        }
    }
}

/// Each pixel's values counted per level, unmasked and masked: zero between tiles.
struct LevelCounts {
    kept: Vec<[u16; 256]>,
    masked: Vec<[u16; 256]>,
}

impl LevelCounts {
    /// A tile's counts, all zero.
    fn new() -> LevelCounts {
        LevelCounts {
            kept: vec![[0; 256]; TILE],
            masked: vec![[0; 256]; TILE],
        }
    }

    /// The tile's medians read off counts per level, the value a sort puts at the
    /// middle (`select::median`'s, bit for bit: whole levels are equal bits, and
    /// order as their levels). Counted as gathered, each pixel's counts apart from
    /// its neighbour's: no increment waits on the last, as one pixel's run of equal
    /// levels counted in a row would make it. False, nothing pushed, when a value
    /// is not a whole level (or the frames are too many to count in 16 bits).
    #[allow(clippy::indexing_slicing)] // j < t ≤ TILE; a level indexes 256 counts
    fn medians<T: Sample>(&mut self, tile: &Tile<T>, out: &mut Vec<f32>) -> bool {
        if tile.planes.len() > usize::from(u16::MAX) {
            return false;
        }
        let (mut lo, mut hi) = ([u8::MAX; TILE], [0u8; TILE]);
        let (mut nk, mut nm) = ([0usize; TILE], [0usize; TILE]);
        let mut whole = true;
        'frames: for (k, p) in tile.planes.iter().enumerate() {
            let m = tile.masks.get(k).copied().unwrap_or(&[]);
            for j in 0..tile.t {
                let i = tile.start + j;
                let Some(&v) = p.get(i) else { continue };
                let Some(l) = v.level() else {
                    whole = false;
                    break 'frames;
                };
                if m.get(i).copied().unwrap_or(false) {
                    self.masked[j][usize::from(l)] += 1;
                    nm[j] += 1;
                } else {
                    self.kept[j][usize::from(l)] += 1;
                    nk[j] += 1;
                }
                lo[j] = lo[j].min(l);
                hi[j] = hi[j].max(l);
            }
        }
        for j in 0..tile.t {
            let all = tile.takes_all(nk[j]);
            let levels = usize::from(lo[j])..=usize::from(hi[j]);
            if whole {
                let len = if all { nk[j] + nm[j] } else { nk[j] };
                let mut below = 0usize;
                let median = levels.clone().find(|&l| {
                    below += usize::from(self.kept[j][l]);
                    if all {
                        below += usize::from(self.masked[j][l]);
                    }
                    below > len / 2
                });
                out.push(median.map_or(0.0, |l| l as f32));
            }
            // Back to zero where counted (every count lies within lo … hi).
            if lo[j] <= hi[j] {
                self.kept[j][levels.clone()].fill(0);
                self.masked[j][levels].fill(0);
            }
        }
        whole
    }
}

/// Whether brightness and colour `(y, u, v)` (video levels) are the background's
/// `(by, bu, bv)` dimmed alike, as a shadow dims it: at least `1 − darkest` of its
/// light (`Params::shadow_darkest`, above black at 16), its colour the background's
/// scaled by as much within `hue` levels (`Params::shadow_hue_levels`). Whether it
/// is darker at all is the caller's test. Without branches (`&`, not `&&`), so the
/// loop over a frame ([`differences`]) vectorises.
#[inline(always)]
pub fn dimmed_alike(
    (y, u, v): (f32, f32, f32),
    (by, bu, bv): (f32, f32, f32),
    darkest: f32,
    hue: f32,
) -> bool {
    let a = (y - 16.0) / (by - 16.0).max(1.0);
    (a >= 1.0 - darkest)
        & (((u - 128.0) - a * (bu - 128.0)).abs() <= hue)
        & (((v - 128.0) - a * (bv - 128.0)).abs() <= hue)
}

/// How much each coarse pixel of `s` differs from the background `bg` (levels:
/// the larger of the brightness difference and the weighted colour differences; 0
/// for a shadow: darker by at most [`Params::shadow_darkest`] and of the same hue).
pub fn differences(s: &Small, bg: &Small, p: &Params) -> Vec<f32> {
    let cw = p.colour_weight as f32;
    let darkest = p.shadow_darkest as f32;
    let hue = p.shadow_hue_levels as f32;
    // Without branches or a count in the loop (the shadow test and the difference
    // both computed, one taken: a background pixel is darker than its median half
    // the time, a branch on it mispredicted as often), so the loop vectorises.
    s.y.iter()
        .zip(&s.u)
        .zip(&s.v)
        .zip(bg.y.iter().zip(&bg.u).zip(&bg.v))
        .map(|(((&y, &u), &v), ((&by, &bu), &bv))| {
            let (u, v, bu, bv) = (f32::from(u), f32::from(v), f32::from(bu), f32::from(bv));
            let dy = y - by;
            let shadow = (dy < 0.0) & dimmed_alike((y, u, v), (by, bu, bv), darkest, hue);
            let differ = dy.abs().max(cw * (u - bu).abs()).max(cw * (v - bv).abs());
            if shadow { 0.0 } else { differ }
        })
        .collect()
}

/// The level above which a difference marks a pixel: [`Params::differ_sigmas`]
/// times the differences' robust scatter (their median absolute value, most pixels
/// being background), at least [`Params::differ_levels`].
pub fn threshold(d: &[f32], p: &Params) -> f32 {
    let step = (d.len() / 4096).max(1);
    let mut s: Vec<f32> = d.iter().step_by(step).copied().collect();
    let med = select::median(&mut s).unwrap_or(0.0);
    (p.differ_sigmas as f32 * 1.4826 * med).max(p.differ_levels as f32)
}

/// The mask grown by one pixel each way (8-neighbours).
fn dilate(m: &[bool], w: usize, h: usize) -> Vec<bool> {
    let mut out = vec![false; m.len()];
    for y in 0..h {
        for x in 0..w {
            if !m.get(y * w + x).copied().unwrap_or(false) {
                continue;
            }
            for yy in y.saturating_sub(1)..(y + 2).min(h) {
                for xx in x.saturating_sub(1)..(x + 2).min(w) {
                    if let Some(o) = out.get_mut(yy * w + xx) {
                        *o = true;
                    }
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vision::gray::Gray;

    /// The shadows among [`differences`] `d` of `s` from `bg`, counted: a darker
    /// pixel's difference is at least its brightness step, so 0 for a darker pixel
    /// means a shadow.
    fn shadows(d: &[f32], s: &Small, bg: &Small) -> usize {
        d.iter()
            .zip(s.y.iter().zip(&bg.y))
            .filter(|&(&d, (&y, &by))| d == 0.0 && y - by < 0.0)
            .count()
    }

    fn flat(w: usize, h: usize, level: u8) -> Frame {
        Frame::from_gray(Gray::filled(w, h, level))
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// A tile's medians counted per level are the ones selection gives, bit for
        /// bit: over any frames' bytes, masks that leave a pixel many values, few
        /// (under a quarter: all are taken) or none, and planes shorter than the tile.
        #[test]
        fn counted_medians_are_the_selected_ones(
            nf in 1usize..100,
            t in 1usize..=TILE,
            seed in proptest::prelude::any::<u64>(),
            masked_share in 0.0f64..1.0,
            short in proptest::prelude::any::<bool>(),
        ) {
            // Proptest's own generator, seeded: levels bunched (a wall) or spread,
            // masks at the share.
            use proptest::prelude::Rng;
            use proptest::test_runner::{RngAlgorithm, TestRng};
            let mut rng = TestRng::from_seed(RngAlgorithm::ChaCha, &seed.to_le_bytes().repeat(4));
            let mut next = move || rng.next_u64();
            let planes: Vec<Vec<u8>> = (0..nf)
                .map(|k| {
                    let len = if short && k % 3 == 0 { t / 2 } else { t };
                    (0..len).map(|_| (next() % 256) as u8 / if k % 2 == 0 { 1 } else { 8 }).collect()
                })
                .collect();
            let masks: Vec<Vec<bool>> = (0..nf)
                .map(|_| (0..t).map(|_| (next() % 1000) as f64 / 1000.0 < masked_share).collect())
                .collect();
            let planes: Vec<&[u8]> = planes.iter().map(Vec::as_slice).collect();
            let masks: Vec<&[bool]> = masks.iter().map(Vec::as_slice).collect();
            for with_masks in [false, true] {
                let tile = Tile {
                    planes: &planes,
                    masks: if with_masks { &masks } else { &[] },
                    start: 0,
                    t,
                };
                let (mut counted, mut selected) = (Vec::new(), Vec::new());
                proptest::prop_assert!(LevelCounts::new().medians(&tile, &mut counted));
                Lists::new(nf).medians(&tile, &mut selected);
                let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                proptest::prop_assert_eq!(bits(&counted), bits(&selected));
            }
        }
    }

    /// A plane's second pass over `frames` with `masks`, as bits: the tiles no mask
    /// touches kept from the first pass, and every tile counted again (no first
    /// pass given: `untouched` finds none).
    fn second_passes<T: Sample>(
        frames: &[Arc<Small>],
        n: usize,
        plane: impl Fn(&Small) -> &Vec<T> + Copy,
        masks: &[Vec<bool>],
    ) -> [Vec<u32>; 2] {
        let first_pass = median_plane(frames, n, plane, None);
        let any_mask = touched(masks, n);
        let second = |touched, first_pass| Again {
            masks,
            touched,
            first_pass,
        };
        [
            median_plane(frames, n, plane, Some(second(&any_mask, &first_pass))),
            median_plane(frames, n, plane, Some(second(&[], &[]))),
        ]
        .map(|v| v.iter().map(|x| x.to_bits()).collect())
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(8))]
        /// The second pass's medians with the tiles no mask touches taken from the
        /// first pass are those counted again everywhere (no first pass given), bit
        /// for bit: frames of more than one run of tiles, masks in a band of rows
        /// (the balls' path) with stray pixels anywhere, in any frame but the first.
        #[test]
        fn untouched_tiles_keep_the_first_medians(
            nf in 2usize..8,
            (w, h) in (100usize..150, 84usize..100),
            seed in proptest::prelude::any::<u64>(),
            band in 0usize..100,
            strays in 0usize..6,
        ) {
            use proptest::prelude::Rng;
            use proptest::test_runner::{RngAlgorithm, TestRng};
            let mut rng = TestRng::from_seed(RngAlgorithm::ChaCha, &seed.to_le_bytes().repeat(4));
            let n = w * h;
            let frames: Vec<Arc<Small>> = (0..nf)
                .map(|_| {
                    let mut level = || (rng.next_u64() % 256) as u8;
                    // Luma in quarter levels, as 2 × 2 block means are.
                    let y = (0..n).map(|_| f32::from(level()) * 0.25).collect();
                    let u = (0..n).map(|_| level()).collect();
                    let v = (0..n).map(|_| level()).collect();
                    Arc::new(Small { width: w, height: h, factor: 2, y, u, v })
                })
                .collect();
            let masks: Vec<Vec<bool>> = (0..nf)
                .map(|k| {
                    let mut m = vec![false; n];
                    if k > 0 {
                        for (i, b) in m.iter_mut().enumerate() {
                            let in_band = (band..band + 3).contains(&(i / w));
                            *b = in_band && rng.next_u64().is_multiple_of(3);
                        }
                        for _ in 0..strays {
                            if let Some(b) = m.get_mut((rng.next_u64() % n as u64) as usize) {
                                *b = true;
                            }
                        }
                    }
                    m
                })
                .collect();
            let [skipping, recounted] = second_passes(&frames, n, |s| &s.y, &masks);
            proptest::prop_assert_eq!(skipping, recounted, "luma");
            let [skipping, recounted] = second_passes(&frames, n, |s| &s.u, &masks);
            proptest::prop_assert_eq!(skipping, recounted, "u");
            let [skipping, recounted] = second_passes(&frames, n, |s| &s.v, &masks);
            proptest::prop_assert_eq!(skipping, recounted, "v");
        }
    }

    /// The learner's background is each plane's second pass against its own first
    /// pass: the same as every tile counted again, for a square that crosses a
    /// wall whose planes differ (a first pass taken from another plane shows).
    #[test]
    fn each_plane_is_learned_against_its_own_first_pass() {
        let (w, h) = (150, 60);
        let p = Params::default();
        let mut l = Learner::new(p);
        for k in 0..20 {
            let at = |i: usize| (i % w).abs_diff(7 * k) < 6 && (i / w).abs_diff(30) < 6;
            let wobble = |i: usize| ((i * 7 + k * 3) % 5) as u8;
            let plane = |base: u8, square: u8| -> Vec<u8> {
                (0..w * h)
                    .map(|i| if at(i) { square } else { base + wobble(i) })
                    .collect()
            };
            let small = Small {
                width: w,
                height: h,
                factor: 1,
                y: plane(100, 250).into_iter().map(f32::from).collect(),
                u: plane(120, 60),
                v: plane(140, 200),
            };
            l.push_small(&Arc::new(small));
        }
        let n = w * h;
        let kept = &l.kept;
        let first = Small {
            width: w,
            height: h,
            factor: 1,
            y: median_plane(kept, n, |s| &s.y, None),
            u: bytes(&median_plane(kept, n, |s| &s.u, None)),
            v: bytes(&median_plane(kept, n, |s| &s.v, None)),
        };
        let masks = differing(kept, &first, &p);
        assert!(
            masks.iter().any(|m| m.iter().any(|&b| b)),
            "the square is masked"
        );
        let everywhere = Some(Again {
            masks: &masks,
            touched: &[],
            first_pass: &[],
        });
        let recounted = Small {
            y: median_plane(kept, n, |s| &s.y, everywhere),
            u: bytes(&median_plane(kept, n, |s| &s.u, everywhere)),
            v: bytes(&median_plane(kept, n, |s| &s.v, everywhere)),
            ..first
        };
        assert_eq!(l.background().unwrap().image, recounted);
    }

    #[test]
    fn the_median_leaves_out_what_passes() {
        // A bright square visits each place in fewer than half the frames.
        let p = Params {
            coarse_width: 16,
            ..Params::default()
        };
        let mut l = Learner::new(p);
        for k in 0..9 {
            let mut f = flat(16, 8, 60);
            for y in 2..6 {
                for x in k..k + 4 {
                    if x < 16 {
                        f.luma.data[y * 16 + x] = 200;
                    }
                }
            }
            l.push(&f);
        }
        let bg = l.finish().unwrap();
        assert!(bg.image.y.iter().all(|&v| v == 60.0), "{:?}", bg.image.y);
    }

    #[test]
    fn a_shadow_is_not_a_difference_but_a_dark_ball_is() {
        let p = Params::default();
        let bg = Small::of(&flat(4, 2, 180), 1);
        let mut s = bg.clone();
        s.y[0] = 16.0 + 0.7 * (180.0 - 16.0); // a shadow: 70 % of the light
        s.y[1] = 16.0 + 0.2 * (180.0 - 16.0); // a black ball
        s.u[2] = 150; // a blue ball of the wall's brightness
        let d = differences(&s, &bg, &p);
        assert_eq!(shadows(&d, &s, &bg), 1);
        assert_eq!(d[0], 0.0);
        assert!(d[1] > 100.0);
        assert_eq!(d[2], 44.0);
        assert_eq!(d[3], 0.0);
    }
}
