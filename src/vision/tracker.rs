//! Following both balls through a stream of frames, one frame at a time (memory: one
//! frame and the numbers found so far): each frame is looked at coarsely for
//! ball-shaped blobs, each blob's outline is fitted to sub-pixel accuracy near where
//! the ball was last seen, and its mark is found inside it. A ball is left out of a
//! frame, and counted, when it is not seen (hidden or out of the picture), when the
//! two balls touch (at an impact their outlines merge), or when its outline is poor
//! (blurred, or too little of it visible); nothing is filled in.

use super::background::{Background, Learner, Small, differences, factor, threshold};
use super::circle::{self, Circle, Outline, length};
use super::detect;
use super::detect::Blob;
use super::frame::Frame;
use super::gray::Gray;
use super::hough;
use super::mark::{self, Mark};
use super::params::Params;
use super::prepared::PreparedLook;
use super::select;
use super::stack;
use std::sync::Arc;

/// One ball in one frame, in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fix {
    pub outline: Outline,
    /// Standard error of the centre's x and y, px.
    pub sigma: f64,
    pub mark: Option<Mark>,
    /// The strongest spots of its disc, the mark or not (`mark::InDisc::spots`).
    pub spots: mark::Spots,
    /// The mean colour (U, V levels) of its disc's upper half ([`disc_colour`]):
    /// both balls are alike, so a fit far off the clip's other fits in colour is
    /// something else's outline; `None` where too little of it is in the picture.
    pub colour: Option<[f64; 2]>,
}

/// Why a ball has no position in a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LeftOut {
    /// Not seen: hidden, or out of the picture.
    Unseen,
    /// Touching the other ball (their outlines merge).
    Merged,
    /// Its outline is poor: blurred, too little of it visible, or off the circle.
    Poor,
    /// The frame repeats another frame's picture of the moving ball
    /// ([`super::repeats`]): its place is that frame's, not this one's.
    Repeated,
}

/// What one frame gave for the two slots (the balls, in the order first seen).
pub type FrameFixes = [Result<Fix, LeftOut>; 2];

/// How many frames of each kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Counts {
    pub frames: usize,
    /// Frames in which more than two ball-shaped blobs were seen.
    pub crowded: usize,
    /// Frames in which no ball was seen.
    pub empty: usize,
}

impl Counts {
    /// More than half the frames crowded: the clip's balls are in doubt (tracks
    /// refused), as is the line of the first frames' band. Fewer, and the crowded
    /// frames' two balls are taken.
    pub fn mostly_crowded(&self) -> bool {
        self.crowded * 2 > self.frames
    }
}

/// The state of tracking: the background (learned first, from the clip), the balls'
/// last fits and every frame's result.
///
/// Use: [`Tracker::learn`] every frame of the clip (or a sample, in order), then
/// [`Tracker::push`] every frame; or learn each frame as it comes and push it some
/// frames later (one pass: the background is learned anew as it learns more); or
/// [`track`] for frames in memory. Frames pushed
/// with nothing learned are looked at against a smooth surface of luma instead.
#[derive(Clone, Debug, Default)]
pub struct Tracker {
    pub params: Params,
    pub frames: Vec<FrameFixes>,
    pub counts: Counts,
    /// Each slot's last two fits (frame index, circle), newest last.
    last: [Vec<(usize, Circle)>; 2],
    /// Blobs whose own fit was left out in the frames before: see
    /// [`Params::stale_blob`] and [`Stale`].
    stale: Vec<Stale>,
    /// The balls found at rest in contact in the frames before: see [`Contact`].
    contact: Option<Contact>,
    polarity: f64,
    radii: Vec<f64>,
    /// The median of `radii`, renewed while they are few and then every 256; or
    /// the seeded ball's radius (`Params::ball_at`).
    radius: Option<f64>,
    seeded: bool,
    learner: Option<Learner>,
    background: Option<Background>,
    /// The near rail's edges in `background` (`rail::edges`), full-frame px.
    rails: Vec<circle::StraightEdge>,
    /// Frames the learner had seen when `background` was last learned.
    learned_at: usize,
    /// Marks found before their sign is settled (`mark::settled_sign`) …
    mark_votes: Vec<mark::Vote>,
    /// … and that sign once settled (−1 darker than the ball, +1 lighter).
    mark_sign: Option<f64>,
    /// Each fit's edge by other definitions (`circle::edge_offsets`), px.
    edges: Vec<[f64; 2]>,
    /// Each fit's edge in colour, where the ball's colour steps from the wall's
    /// (`circle::colour_offset`), px.
    colour_edges: Vec<f64>,
    /// A lock was found inside a larger circle, or reaching past the ball, and that
    /// circle's outline taken instead: the fits the radius is learned from are
    /// checked likewise (`Tracker::outermost_agrees`).
    outer_taken: bool,
    /// The frame being pushed, reduced to the background's coarse pixels (by `look`,
    /// where a background is learned): what the outermost-edge check compares with
    /// the background, as the looks do.
    small: Option<Arc<Small>>,
    /// The fits of the frame being pushed that were sought at the known radius (a
    /// blob's guess at that radius, the Hough search, the follower): they say little
    /// of the radius, being sought at it.
    sought: Vec<Circle>,
    /// Each ball's radii fitted about its blobs' own guesses (not sought at the
    /// known radius): what confirms the radius ([`confirmed_radius`]).
    found_free: [Vec<f64>; 2],
    /// The radii of clear outlines left out for their radius alone, each circle
    /// once a frame: what contradicts a wrong radius ([`Tracker::radius_contradicted`]).
    other_radii: Vec<f64>,
    /// Those circles of the frame being pushed (one found about several guesses is
    /// counted once).
    other_here: Vec<Circle>,
    /// Each fit's patch of its frame (frame, slot, patch) for the balls' stacked
    /// pictures ([`Tracker::restacked`], [`Tracker::picture_radii`]), while their
    /// bytes stay within `Params::stack_bytes`; past that, every `2^thinned`-th
    /// frame's (thinned at all: no restacking).
    patches: Vec<(usize, usize, stack::Patch)>,
    patch_bytes: usize,
    thinned: u32,
    /// The fits are the stacked pictures' ([`Tracker::restacked`]).
    stacked: bool,
    /// Outlines are sought about the guess given, not where a slot predicts its
    /// ball ([`Tracker::moved_off_rest`]).
    about_guess: bool,
    /// Each ball's radius as its stacked picture shows it, found once
    /// ([`Tracker::picture_radii`]).
    pictures: std::sync::OnceLock<Vec<f64>>,
}

/// Most patches of a ball stacked for its picture's radius
/// ([`Tracker::picture_radii`]), spread over the clip: a bounded cost on a long
/// clip. Of 16–32, small look 5's picture of a ball on a checker came out up to
/// 7 % larger (squares of the wall left in its outline), of 40–64 the same.
const PICTURE_PATCHES: usize = 48;

/// A ball's radius in the pixels of [`Tracker::picture_radii`]'s pictures, at
/// least: their pixels lie ⌊r / 12⌋ px apart (the frames' own below 24 px), so a
/// larger ball's picture costs what a 12–24 px ball's does, its radius to a few
/// per cent where it is checked to 18 % (the bench's 1080p clip, balls of 38 px:
/// 1.3 s for the two pictures at its own pixels, matched three rounds; under
/// 0.1 s so).
const PICTURE_RADIUS: f64 = 12.0;

/// An outline and how it was found.
struct OutlineFound {
    outline: Outline,
    /// In colour (the ball of the wall's brightness), not in brightness.
    colour: bool,
    polarity: f64,
}

/// What the outermost circular edge about a lock says of it.
enum Outer {
    /// The lock is that edge's outline.
    Agrees,
    /// The lock lies inside a larger circle or reaches past the ball; this clear
    /// outline about that edge is the ball's.
    Instead(Outline),
    /// The lock is not the ball's outline, and no clear outline is there instead.
    Poor,
}

/// True when the frame reduced to `small` differs from the background `bg` at
/// `(x, y)` (px, the coarse pixel there): in brightness, or in colour weighed by
/// `colour_weight`, by more than `differ_levels` (the looks' difference before their
/// shadow test, [`super::background::differences`]).
fn differs_at(small: &Small, bg: &Small, x: f64, y: f64, p: &Params) -> bool {
    if !(x >= 0.0 && y >= 0.0) {
        return false;
    }
    let f = bg.factor.max(1);
    let (bx, by) = (x as usize / f, y as usize / f);
    if bx >= bg.width || by >= bg.height {
        return false;
    }
    let i = by * bg.width + bx;
    let (Some(&y0), Some(&u0), Some(&v0)) = (bg.y.get(i), bg.u.get(i), bg.v.get(i)) else {
        return false;
    };
    let (Some(&y1), Some(&u1), Some(&v1)) = (small.y.get(i), small.u.get(i), small.v.get(i)) else {
        return false;
    };
    let dl = (y1 - y0).abs();
    let (u0, v0, u1, v1) = (f32::from(u0), f32::from(v0), f32::from(u1), f32::from(v1));
    let dc = (u1 - u0).abs().max((v1 - v0).abs());
    f64::from(dl.max(p.colour_weight as f32 * dc)) > p.differ_levels
}

/// The share of the coarse pixels in the upper half of `blob` (above the rail) whose
/// difference `d` from the background is over half the threshold `thr`.
fn differing_share(d: &[f32], thr: f32, small: &Small, blob: &Blob) -> f64 {
    let f = small.factor.max(1) as f64;
    let g = blob.guess();
    let x0 = (blob.left / f).floor().max(0.0) as usize;
    let x1 = ((blob.right / f).ceil() as usize).min(small.width);
    let y0 = (blob.top / f).floor().max(0.0) as usize;
    let y1 = ((g.y / f).ceil() as usize).min(small.height);
    let (mut hit, mut n) = (0usize, 0usize);
    for y in y0..y1 {
        for x in x0..x1 {
            if let Some(&v) = d.get(y * small.width + x) {
                n += 1;
                hit += usize::from(v > 0.5 * thr);
            }
        }
    }
    if n == 0 {
        return 0.0;
    }
    hit as f64 / n as f64
}

/// True when the luma look's blob `b` is a part of the difference's blob `m` (coarse
/// pixels `f` px): within its box (give or take a coarse pixel) and narrower than
/// `share` of its width (`Params::part_width`).
fn part_of(b: &Blob, m: &Blob, f: f64, share: f64) -> bool {
    b.left >= m.left - f
        && b.right <= m.right + f
        && b.top >= m.top - f
        && b.bottom <= m.bottom + f
        && b.width() < share * m.width()
}

/// How many things a frame shows: the blobs that differ from the background
/// (`differing`), and the luma look's blobs (`luma`) outside them; luma blobs whose
/// middles lie in one differing blob (give or take a coarse pixel, `f` px) are parts
/// of that one thing. Never fewer than the differing blobs, nor more than the more
/// numerous look's blobs (boxes of differing blobs may overlap, a luma blob's middle
/// then in two): no frame is more crowded than either look alone says. A coloured
/// ball's cast shadow on a plain wall of its brightness is a dark blob of the luma
/// look beside its shaded limb, its middle over the ball's edge (not within the
/// ball's own blob): the blob where ball and shadow differ takes in both (full look
/// 105: 95 of 106 frames crowded by the two balls and their shadows).
pub fn things_seen(luma: &[Blob], differing: &[Blob], f: f64) -> usize {
    let within = |b: &Blob, m: &Blob| {
        let g = b.guess();
        (m.left - f..=m.right + f).contains(&g.x) && (m.top - f..=m.bottom + f).contains(&g.y)
    };
    let holding = differing
        .iter()
        .filter(|m| luma.iter().any(|b| within(b, m)))
        .count();
    let apart = luma
        .iter()
        .filter(|b| !differing.iter().any(|m| within(b, m)))
        .count();
    (holding + apart).clamp(differing.len(), luma.len().max(differing.len()))
}

/// Least standard error of a centre matched to its ball's stacked picture, px:
/// the match's own from the pixels' noise is some 0.02–0.04 px, but its centres
/// lie 0.1–0.5 px from the drawn ones on the looks table (the picture blurred by
/// the matches it is made from).
const MATCH_SIGMA: f64 = 0.15;

/// Tracks frames held in memory: the background learned from all of them, then
/// each one followed.
pub fn track(frames: &[Frame], params: Params) -> Tracker {
    let mut t = Tracker::new(params);
    frames.iter().for_each(|f| t.learn(f));
    frames.iter().for_each(|f| t.push(f));
    t
}

impl Tracker {
    pub fn new(params: Params) -> Tracker {
        Tracker {
            params,
            radius: params.radius_px,
            learner: Some(Learner::new(params)),
            ..Tracker::default()
        }
    }

    /// The radius (px) the clip's clear outlines agree on where they contradict the
    /// one learned: more of them left out for their radius alone than fits kept (and
    /// `Params::min_contradicting` or more), scattering within `max_radius_spread`
    /// of their median, which lies beyond `radius_tolerance` of the radius learned.
    /// A wrong first lock (a circle through a ball's top and the shadow joined to its
    /// blob) sets a radius every clear outline of the ball is then refused by; a
    /// clip refused so is worth tracking again at the radius its outlines show
    /// (`Params::radius_px`), which meets every check of the tracks as before.
    pub fn radius_contradicted(&self) -> Option<f64> {
        contradicting_radius(
            self.radius?,
            self.radii.len(),
            &self.other_radii,
            &self.params,
        )
    }

    /// The radius (px) and count of the clear outlines left out for their radius
    /// alone where they put the radius learned in doubt ([`doubting_radius`]: more
    /// of them than fits kept, however they scatter); `None` where the radius was
    /// given (`Params::radius_px`) or set by a seed.
    pub fn radius_doubted(&self) -> Option<(f64, usize)> {
        if self.params.radius_px.is_some() || self.seeded {
            return None;
        }
        let m = doubting_radius(
            self.radius?,
            self.radii.len(),
            &self.other_radii,
            &self.params,
        )?;
        Some((m, self.other_radii.len()))
    }

    /// The median radius fitted so far, px.
    pub fn radius(&self) -> Option<f64> {
        self.radius
    }

    /// Whether the seed (`Params::ball_at`) found a ball's outline, which set the
    /// radius (false without a seed).
    pub fn seeded(&self) -> bool {
        self.seeded
    }

    /// Every radius fitted, px.
    pub fn radii(&self) -> &[f64] {
        &self.radii
    }

    /// How far each fit's edge moves by other definitions of it
    /// (`circle::edge_offsets`), px.
    pub fn edge_offsets(&self) -> &[[f64; 2]] {
        &self.edges
    }

    /// How far each fit's edge in colour lies from it, for the fits whose ball's
    /// colour steps from the wall's (`circle::colour_offset`), px.
    pub fn colour_offsets(&self) -> &[f64] {
        &self.colour_edges
    }

    /// Offers one frame to learn the background from (before any [`Tracker::push`]).
    pub fn learn(&mut self, frame: &Frame) {
        if let Some(l) = &mut self.learner {
            l.push(frame);
        }
    }

    /// The background learned, if any.
    pub fn background(&self) -> Option<&Background> {
        self.background.as_ref()
    }

    /// Ball-shaped blobs in `frame`, by two looks. The look against a smooth surface
    /// of luma, as before a background: it sees a ball at rest where the background
    /// learned it (a target ball waiting for the impact); the look against the
    /// background adds what differs in colour or against a busy bench. A frame where
    /// either look sees more than two balls is counted crowded.
    /// `made_small`, `coarse`: the frame's reduction and luma look ([`PreparedLook`]).
    fn look(
        &mut self,
        frame: &Frame,
        made_small: Arc<Small>,
        mut coarse: detect::Coarse,
    ) -> detect::Coarse {
        let p = self.params;
        // The frame reduced once for both looks where they reduce it alike.
        let small = self.background.as_ref().map(|bg| {
            if made_small.factor == bg.image.factor {
                made_small
            } else {
                Arc::new(Small::of(frame, bg.image.factor))
            }
        });
        if let Some(roi) = p.roi {
            coarse.balls.retain(|b| {
                let g = b.guess();
                roi.contains(g.x, g.y)
            });
        }
        let mut crowded = coarse.balls.len() > 2;
        if let (Some(bg), Some(small)) = (&self.background, &small) {
            let d = differences(small, &bg.image, &p);
            let thr = threshold(&d, &p);
            let more = detect::against_differences(small, &d, thr, &p);
            // What the luma look sees but does not differ from the background is the
            // bench (a disc of clutter, a stripe's end, a checker's square), unless
            // it lies on the line of a ball that moves, at its size: a ball at rest
            // where the background learned it (a target waiting for the impact).
            let moving: Vec<Circle> = coarse
                .balls
                .iter()
                .filter(|b| differing_share(&d, thr, small, b) >= p.moved_share)
                .chain(&more.balls)
                .map(Blob::guess)
                .chain(self.last.iter().filter_map(|l| l.last().map(|(_, c)| *c)))
                .collect();
            let on_line = |b: &Blob| {
                let g = b.guess();
                moving
                    .iter()
                    .any(|m| (g.y - m.y).abs() < 0.5 * m.r && (g.r - m.r).abs() < 0.35 * m.r)
            };
            // With two balls moving (this frame's difference shows them, within
            // `--roi`), a third thing that stands still is the bench, not a target
            // at rest.
            let at_rest_possible = more.balls.len() < 2;
            coarse.balls.retain(|b| {
                differing_share(&d, thr, small, b) >= p.moved_share
                    || (at_rest_possible && on_line(b))
            });
            coarse
                .pairs
                .retain(|b| differing_share(&d, thr, small, b) >= p.moved_share);
            // A ball of the wall's brightness is, in luma, its lit part brighter
            // than the wall and its shaded part darker: two blobs inside the one
            // blob where the ball differs from the background. Parts of one ball,
            // not balls (`Params::part_width`).
            let f = small.factor as f64;
            let part = |b: &Blob, m: &Blob| part_of(b, m, f, p.part_width);
            let parts = |m: &Blob| coarse.balls.iter().filter(|b| part(b, m)).count();
            let whole: Vec<Blob> = more
                .balls
                .iter()
                .filter(|m| parts(m) >= 2)
                .copied()
                .collect();
            coarse.balls.retain(|b| !whole.iter().any(|m| part(b, m)));
            crowded = things_seen(&coarse.balls, &more.balls, f) > 2;
            coarse.balls.extend(more.balls);
            coarse.pairs.extend(more.pairs);
        }
        if crowded {
            self.counts.crowded += 1;
        }
        self.small = small;
        coarse
    }

    /// The background learned anew when the learner has seen enough frames more
    /// than when it was last learned (twice as many, or 32 more while fewer):
    /// frames learned while frames are pushed (one pass over a long clip, the
    /// learner running ahead of the tracker) keep improving it; all learned first,
    /// it is learned once. Each learning takes a median per pixel over the frames
    /// kept, so it is done a few times per clip, not every few frames (720 frames of
    /// 1080p: 6 times, where a quarter more took 13 and a sixth of the tracking).
    fn relearn(&mut self) {
        let Some(l) = &self.learner else { return };
        let seen = l.seen();
        let due = self.learned_at + self.learned_at.max(32);
        if seen > 0 && (self.background.is_none() || seen >= due) {
            self.background = l.background();
            // The rail's edges only where the background is learned at full
            // resolution (frames under 640 px wide at the default `coarse_width`):
            // from coarse pixels of 2–6 px an edge is placed to a pixel or so, no
            // closer than the clearance above it that a ball's points must keep (on
            // the full looks the refits lost two verdicts and gained none).
            self.rails = self
                .background
                .as_ref()
                .filter(|b| b.image.factor == 1)
                .map(|b| super::rail::edges(&b.image))
                .unwrap_or_default();
            self.learned_at = seen;
        }
    }

    /// Tracks one more frame.
    pub fn push(&mut self, frame: &Frame) {
        self.push_made(frame, PreparedLook::of(frame, &self.params));
    }

    /// As [`Tracker::push`], with the frame's own part of its look made ahead
    /// (`PreparedLook::of` of this frame; made for other parameters, it is made anew).
    pub fn push_prepared(&mut self, frame: &Frame, prep: PreparedLook) {
        let prep = if prep.params == self.params {
            prep
        } else {
            PreparedLook::of(frame, &self.params)
        };
        self.push_made(frame, prep);
    }

    /// As [`Tracker::learn`], the frame already reduced in `prep` (`PreparedLook::of`
    /// of this frame).
    pub fn learn_prepared(&mut self, frame: &Frame, prep: &PreparedLook) {
        let f = factor(frame.width(), self.params.coarse_width);
        if let Some(l) = &mut self.learner {
            if prep.params == self.params && prep.small.factor == f {
                l.push_small(&prep.small);
            } else {
                l.push(frame);
            }
        }
    }

    fn push_made(&mut self, frame: &Frame, prep: PreparedLook) {
        self.relearn();
        let img = &frame.luma;
        let k = self.frames.len();
        self.sought.clear();
        self.other_here.clear();
        self.counts.frames += 1;
        let p = self.params;
        let noise = prep.noise;
        let coarse = self.look(frame, prep.small, prep.luma_look);
        if self.still_in_contact(&coarse.balls) {
            self.frames
                .push([Err(LeftOut::Merged), Err(LeftOut::Merged)]);
            return;
        }
        let f = coarse.balls.first().map_or(1.0, |_| {
            self.background
                .as_ref()
                .map_or(detect::factor(img.width), |b| b.image.factor) as f64
        });
        let (mut fits, stale) = self.fit_blobs(frame, &coarse.balls, f);
        self.search_wide(frame, &coarse, &mut fits, (f, &stale));
        self.follow(frame, &mut fits);
        self.note_stale(&coarse.balls, &fits);
        self.seed(frame, &mut fits);
        self.no_locks_inside_blobs(&coarse.balls, &mut fits);
        let mut fits = one_fit_per_ball(fits);
        self.no_disagreeing_locks(&mut fits);
        let merged = self.merged(&coarse, &fits);
        if fits.is_empty() && !merged {
            self.counts.empty += 1;
        }
        // Two outlines touching: the impact; neither is measured.
        let good: Vec<Outline> = fits.iter().filter_map(|f| f.ok()).collect();
        let touching = match good.as_slice() {
            [a, b] => {
                let (a, b) = (a.circle, b.circle);
                (a.x - b.x).hypot(a.y - b.y) < a.r + b.r + p.touch_gap
            }
            _ => false,
        };
        self.note_contact(touching.then_some(good.as_slice()), &coarse.balls);
        let mut out: FrameFixes = [Err(LeftOut::Unseen), Err(LeftOut::Unseen)];
        if merged || touching {
            out = [Err(LeftOut::Merged), Err(LeftOut::Merged)];
            self.frames.push(out);
            return;
        }
        // Two balls at most: the good fits first.
        fits.truncate(2);
        for (slot, fit) in self.assign(fits) {
            let fix = fit.map(|o| {
                if let Some(l) = self.last.get_mut(slot) {
                    l.push((k, o.circle));
                    if l.len() > 2 {
                        l.remove(0);
                    }
                }
                self.radii.push(o.circle.r);
                if !self.sought.contains(&o.circle)
                    && let Some(free) = self.found_free.get_mut(slot)
                {
                    free.push(o.circle.r);
                }
                if let Some(e) = circle::edge_offsets(img, &o) {
                    self.edges.push(e);
                }
                let steps = (p.colour_edge_step, p.grey_levels, p.colour_weight);
                if let Some(c) = circle::colour_offset(frame, &o, p.colour_edge_reach, steps) {
                    self.colour_edges.push(c);
                }
                if self.radii.len() <= 64 || self.radii.len().is_multiple_of(256) {
                    self.radius = median(&self.radii);
                }
                self.fix((frame, img), o, noise, slot)
            });
            if let Some(o) = out.get_mut(slot) {
                *o = fix;
            }
        }
        self.keep_patches(frame, &out);
        self.frames.push(out);
    }

    /// The tracking again from each ball's stacked picture (`stack`), where its
    /// frames' radii disagree (or their edge in colour lies off them): each fit's
    /// centre matched to its ball's picture, its radius the picture's outline's
    /// (`stack_edge` outside it), the edge's definitions measured on the picture.
    /// `None` where not every frame's patches were kept (past `stack_bytes`),
    /// either ball gives no picture, a picture's outline is unclear
    /// (`min_coverage`, `stack_max_rms`) or the two pictures' radii disagree by more
    /// than `max_radius_spread` (both balls have one radius). A fit its picture
    /// does not match is left out (poor). The patches are used up (taken, not
    /// copied with the tracker).
    pub fn restacked(&mut self) -> Option<(Tracker, [f64; 2])> {
        let patches = std::mem::take(&mut self.patches);
        let p = &self.params;
        let r = median(&self.radii)?;
        if self.thinned > 0 {
            return None;
        }
        let polarity = self.outline_polarity();
        let mut t = self.clone();
        t.stacked = true;
        // Its radius is the pictures': not checked against them.
        t.pictures = std::sync::OnceLock::new();
        t.radii.clear();
        t.edges.clear();
        t.colour_edges.clear();
        let mut radii = [f64::NAN; 2];
        for (slot, radius) in radii.iter_mut().enumerate() {
            let mine = self.fitted_patches(&patches, slot);
            let refs: Vec<&stack::Patch> = mine.iter().map(|(_, patch)| *patch).collect();
            let cw = p.colour_weight as f32;
            let s = stack::stack(&refs, r, polarity, p.rail_moves, cw)?;
            let o = s.outline;
            if o.coverage() < p.min_coverage || o.rms > p.stack_max_rms {
                return None;
            }
            // The outline lies inside the ball's edge by 0–2 stack_edge of it:
            // the radius is the middle of that, its ± the half (`the_radius`).
            let ball_r = o.circle.r * (1.0 + p.stack_edge);
            *radius = ball_r;
            if let Some(e) = circle::edge_offsets(&s.picture.luma(), &o) {
                t.edges.push(e);
            }
            for (i, (k, patch)) in mine.iter().enumerate() {
                let Some(fix) = t.frames.get_mut(*k).and_then(|f| f.get_mut(slot)) else {
                    continue;
                };
                let Some(((x, y), sigma)) = s.centre(patch, i) else {
                    *fix = Err(LeftOut::Poor);
                    continue;
                };
                if let Ok(f) = fix {
                    // The fit's centre moved by what the match moved the cut's:
                    // patches are cut where the frames were pushed (a band's rows).
                    let (dx, dy) = (x - patch.centre.0, y - patch.centre.1);
                    let (cx, cy) = (f.outline.circle.x + dx, f.outline.circle.y + dy);
                    let sig = sigma.max(MATCH_SIGMA);
                    f.outline = Outline {
                        circle: Circle {
                            x: cx,
                            y: cy,
                            r: ball_r,
                        },
                        sigma: [sig, sig, o.sigma[2]],
                        covariance: [
                            [sig * sig, 0.0, 0.0],
                            [0.0, sig * sig, 0.0],
                            [0.0, 0.0, o.sigma[2] * o.sigma[2]],
                        ],
                        lowest: o.lowest - o.circle.y + cy,
                        ..o
                    };
                    f.sigma = sig;
                    t.radii.push(ball_r);
                }
            }
        }
        let mean = 0.5 * (radii[0] + radii[1]);
        ((radii[0] - radii[1]).abs() <= p.max_radius_spread * mean).then_some((t, radii))
    }

    /// Each ball's radius as its stacked picture shows it, px: the outline of
    /// `stack::radius_at_fits` on up to `PICTURE_PATCHES` of its patches spread
    /// over the clip, where that outline is clear (`min_coverage`, `max_rms`). The
    /// wall behind a rolling ball averages out there, so an outline that takes in
    /// the wall's pattern in every frame (a dark ball's limb run into the dark
    /// squares of a checkered wall) does not in the picture. Found once; none
    /// where the fits are the pictures' already.
    pub fn picture_radii(&self) -> &[f64] {
        self.pictures.get_or_init(|| self.pictured_radii())
    }

    fn pictured_radii(&self) -> Vec<f64> {
        let p = &self.params;
        let Some(r) = median(&self.radii) else {
            return Vec::new();
        };
        if self.stacked {
            return Vec::new();
        }
        let step = (r / PICTURE_RADIUS).floor().max(1.0);
        let look = (
            self.outline_polarity(),
            p.rail_moves,
            p.colour_weight as f32,
        );
        let picture = |slot: usize| {
            let mine = self.fitted_patches(&self.patches, slot);
            let every = mine.len().div_ceil(PICTURE_PATCHES).max(1);
            let some: Vec<&stack::Patch> = mine.iter().step_by(every).map(|(_, p)| *p).collect();
            stack::radius_at_fits(&some, (r, step), look, (p.min_coverage, p.max_rms))
        };
        // The two balls' pictures at once: the frames are all tracked by now and
        // the cores free.
        std::thread::scope(|scope| {
            let balls = [0, 1].map(|slot| scope.spawn(move || picture(slot)));
            balls
                .into_iter()
                .filter_map(|b| b.join().ok().flatten())
                .collect()
        })
    }

    /// Of `patches`, those of `slot`'s fits that stand (frame, patch).
    fn fitted_patches<'a>(
        &self,
        patches: &'a [(usize, usize, stack::Patch)],
        slot: usize,
    ) -> Vec<(usize, &'a stack::Patch)> {
        let fitted = |k: usize| {
            self.frames
                .get(k)
                .and_then(|f| f.get(slot))
                .is_some_and(Result::is_ok)
        };
        patches
            .iter()
            .filter(|(k, s, _)| *s == slot && fitted(*k))
            .map(|(k, _, patch)| (*k, patch))
            .collect()
    }

    /// The balls' outline polarity once settled, else either.
    fn outline_polarity(&self) -> f64 {
        if self.polarity == 0.0 {
            circle::EITHER
        } else {
            self.polarity
        }
    }

    /// Whether the fits are the stacked pictures' ([`Tracker::restacked`]).
    pub fn stacked(&self) -> bool {
        self.stacked
    }

    /// Keeps a patch of `frame` about each fit of `fixes` (the frame being pushed)
    /// for the stacked pictures, while the budget allows; past it, every second
    /// frame's of those kept, and of the frames to come (again each time it is
    /// passed): the pictures' radius needs a few dozen a ball, spread over the
    /// clip; the restacking needs every frame's and is not done.
    fn keep_patches(&mut self, frame: &Frame, fixes: &FrameFixes) {
        let k = self.frames.len();
        let every = 1usize << self.thinned;
        if !k.is_multiple_of(every) {
            return;
        }
        for (slot, fix) in fixes.iter().enumerate() {
            let Ok(fix) = fix else { continue };
            let c = fix.outline.circle;
            // Room for a picture of 1.75 radii about a ball whose radius the fits
            // overstate by a quarter, and the match's reach.
            let half = (1.75 * 1.25 * c.r + (0.3 * c.r).max(3.0) + 3.0).ceil() as usize;
            if let Some(p) = stack::Patch::cut(frame, (c.x, c.y), half) {
                self.patch_bytes += p.bytes();
                self.patches.push((k, slot, p));
            }
        }
        if self.patch_bytes > self.params.stack_bytes && self.thinned < 32 {
            self.thinned += 1;
            let every = 1usize << self.thinned;
            self.patches.retain(|(k, _, _)| k.is_multiple_of(every));
            self.patch_bytes = self.patches.iter().map(|(_, _, p)| p.bytes()).sum();
        }
    }

    /// The outline of the blob `b` (coarse pixels `f` px): about its guess, else
    /// about its solid core.
    fn fit_blob(&mut self, frame: &Frame, b: &Blob, f: f64) -> Result<Outline, LeftOut> {
        let p = self.params;
        let band = (1.5 * f).max(4.0);
        let whole = |o: Outline, blob: f64| whole_in_blob(o, blob, &p);
        let guess = b.guess();
        // A coloured ball's blob with a wide ragged fringe, before the balls' radius
        // is known: its solid core first (`Params::core_first`). The fringe (a
        // checker's edges about a moving ball in a compressed clip) closes the
        // ball's top into a circle of the blob's size, which passes as a first lock
        // (full look 1: 41 px for 25.5, every later fit of the ball then refused for
        // its radius). A grey ball's core may be its lit part alone (full look 9: a
        // black ball's, 15 px for 24.4); a coloured ball differs from the wall in
        // colour over its whole disc.
        let core_first = b.core.filter(|c| {
            self.radius.is_none()
                && c.r < p.core_first * guess.r
                && coloured(frame, c, p.grey_levels)
        });
        let fit = match core_first {
            Some(core) => self
                .refine(frame, core, band)
                .and_then(|o| whole(o, core.r))
                .or_else(|_| {
                    self.refine(frame, guess, band)
                        .and_then(|o| whole(o, guess.r))
                }),
            None => self
                .refine(frame, guess, band)
                .and_then(|o| whole(o, guess.r)),
        };
        let fit = self.moved_off_rest(frame, guess, band, fit);
        // A blob with a ragged fringe (`Blob::core`): the ball is its solid core.
        // Once the radius is known, only in a blob wider than a ball: the opened
        // blob of a ball that matches the wall in places (same-brightness wood
        // grain, looks table seed 45) is smaller than the ball, its fits too.
        let fit = match (fit, b.core) {
            (Err(e), Some(core))
                if core_first.is_none()
                    && self
                        .radius
                        .is_none_or(|r| b.width() > p.wide_blob * 2.0 * r) =>
            {
                self.refine(frame, core, band)
                    .map_err(|_| e)
                    .and_then(|o| whole(o, core.r))
            }
            (fit, _) => fit,
        };
        // A blob of about a ball's width whose own guess gave no outline (wider or
        // narrower than the ball: a fringe joined to it, a ball matching the wall in
        // places): once the radius is confirmed by both balls, the ball sought at
        // that radius, its top the blob's (the ball's top shows above the rail), in
        // brightness only (a colour outline at a given radius fits what it is given).
        match (
            fit,
            confirmed_radius(self.radius, &self.found_free, p.confirm_spread),
        ) {
            (Err(e), Some(r)) if b.width() <= p.wide_blob * 2.0 * r => {
                let at = Circle {
                    x: guess.x,
                    y: b.top + r,
                    r,
                };
                let fit = self
                    .refine_with(frame, at, band, false)
                    .map_err(|_| e)
                    .and_then(|o| whole(o, r))
                    .and_then(|o| {
                        if (o.circle.r - r).abs() <= p.confirm_spread * r {
                            Ok(o)
                        } else {
                            Err(LeftOut::Poor)
                        }
                    });
                if let Ok(o) = &fit {
                    self.sought.push(o.circle);
                }
                fit
            }
            (fit, _) => fit,
        }
    }

    /// A first lock inside a larger blob is no ball: before the balls' radius is
    /// known, a frame's good fits whose centre lies inside another blob of the frame
    /// (its guess) and that are smaller than `smallest_in_blob` of it are poor. They
    /// are that blob's mark or highlight, found as a blob of its own (the looks
    /// table's seed 15: a steel ball's dark mark, 11.8 px in colour, inside the
    /// ball's blob of 63–87 px, set a radius of 10.6 px for 53.6 and no ball was
    /// found); a ball's own fit lies inside its blob, which is the ball plus at most
    /// a shadow's fringe (`smallest_in_blob` of it or more).
    fn no_locks_inside_blobs(&self, blobs: &[Blob], fits: &mut [Result<Outline, LeftOut>]) {
        if self.radius.is_some() {
            return;
        }
        let guesses: Vec<Circle> = blobs.iter().map(Blob::guess).collect();
        let share = self.params.smallest_in_blob;
        for fit in fits.iter_mut() {
            if fit
                .as_ref()
                .is_ok_and(|o| inside_a_larger_blob(&o.circle, &guesses, share))
            {
                *fit = Err(LeftOut::Poor);
            }
        }
    }

    /// First locks that disagree set no radius: before it is known, a frame's good
    /// fits whose radii lie over `locks_agree` apart are all poor (of a circle
    /// through a ball's top and the fringe joined to its blob, and the ball, neither
    /// is known to be the ball; the median of two radii is the larger).
    fn no_disagreeing_locks(&self, fits: &mut [Result<Outline, LeftOut>]) {
        let locks: Vec<f64> = fits.iter().flatten().map(|o| o.circle.r).collect();
        if self.radius.is_none() && locks_disagree(&locks, self.params.locks_agree) {
            for f in fits.iter_mut().filter(|f| f.is_ok()) {
                *f = Err(LeftOut::Poor);
            }
        }
    }

    /// The ball `o` with its mark, the spots of its disc and its colour (`frame`
    /// and its brightness `img`).
    fn fix(&mut self, (frame, img): (&Frame, &Gray), o: Outline, noise: f64, slot: usize) -> Fix {
        let found = self.mark(img, &o, noise, slot);
        Fix {
            outline: o,
            sigma: 0.5 * (o.sigma[0] + o.sigma[1]),
            mark: found.mark,
            spots: found.spots,
            colour: disc_colour(frame, &o.circle),
        }
    }

    /// The mark on the ball `o` (of `slot`): of either sign while few are found, then
    /// of the sign most had, those that stayed put in their disc left out.
    fn mark(&mut self, img: &Gray, o: &Outline, noise: f64, slot: usize) -> mark::InDisc {
        if self.mark_sign.is_none() && self.mark_votes.len() >= self.params.mark_votes {
            self.mark_sign = Some(mark::settled_sign(&self.mark_votes));
        }
        let sign = self.mark_sign.unwrap_or(0.0);
        let p = self.params;
        let found = mark::find(
            img,
            o,
            noise,
            sign,
            (p.mark_sigmas, p.mark_levels, p.mark_cut, p.mark_soft),
        );
        if sign == 0.0
            && let Some(m) = found.mark
        {
            self.mark_votes.push(mark::Vote {
                slot,
                x: o.circle.x,
                r: o.circle.r.max(1.0),
                kr: o.rolling_radius(),
                at: o.in_disc((m.x, m.y)),
                sign: m.contrast.signum(),
            });
        }
        found
    }

    /// Balls inside blobs that gave no outline about their middle, or are wider
    /// than a ball (in a compressed clip a moving ball drags a smear of changed
    /// blocks that joins its blob): once the balls' radius is known, the centres of
    /// circles of that radius on the frame's edges inside the blob
    /// (`hough::centres`), each outline fitted about them. Not before the radius is
    /// known: a first lock comes from a blob of a ball's shape.
    fn search_wide(
        &mut self,
        frame: &Frame,
        coarse: &detect::Coarse,
        fits: &mut Vec<Result<Outline, LeftOut>>,
        (f, stale): (f64, &[bool]),
    ) {
        let Some(r) = self.radius() else { return };
        let p = self.params;
        let gave: Vec<bool> = fits.iter().map(Result::is_ok).collect();
        let blobs = coarse
            .balls
            .iter()
            .take(6)
            .zip(gave.iter().copied().chain(std::iter::repeat(true)))
            .zip(stale.iter().copied().chain(std::iter::repeat(false)))
            .filter(|((b, ok), skip)| !skip && (!ok || b.width() > p.wide_blob * 2.0 * r))
            .map(|((b, _), _)| b)
            .chain(coarse.pairs.iter().take(2));
        let mut guesses: Vec<Circle> = Vec::new();
        for b in blobs {
            let area = hough::HoughArea {
                left: b.left,
                right: b.right,
                top: b.top + 0.5 * r,
                bottom: (b.top + 1.5 * r).min(b.bottom + 0.5 * r),
            };
            let polarity = if self.polarity.abs() == 1.0 {
                self.polarity
            } else {
                0.0
            };
            guesses.extend(hough::centres(
                &frame.luma,
                area,
                r,
                polarity,
                p.differ_levels,
                p.hough_arc,
                2,
            ));
        }
        for g in guesses.into_iter().take(4) {
            let near = |o: &Outline| (o.circle.x - g.x).hypot(o.circle.y - g.y) < o.circle.r;
            if fits.iter().flatten().any(near) {
                continue;
            }
            if let Ok(o) = self.refine(frame, g, (1.5 * f).max(4.0)) {
                self.sought.push(o.circle);
                fits.push(Ok(o));
            }
        }
    }

    /// Whether this frame, whose blobs are `blobs`, is taken as the frames before
    /// it without a fit: the balls rest in contact where they were found
    /// (`Params::stale_blob` frames running, the same circles within half a pixel)
    /// and the frame's blobs are theirs within a pixel; every [`STALE_RETRY`]th
    /// frame is fitted all the same. Balls that touch are left out either way.
    fn still_in_contact(&mut self, blobs: &[Blob]) -> bool {
        let least = self.params.stale_blob;
        let Some(c) = &mut self.contact else {
            return false;
        };
        let skip = skipped_now(c.frames, least) && same_blobs(&c.blobs, blobs);
        if skip {
            c.frames += 1;
        }
        skip
    }

    /// Notes the frame's two fits where they touch (`touching`: the good fits),
    /// else that they do not, for [`Tracker::still_in_contact`].
    fn note_contact(&mut self, touching: Option<&[Outline]>, blobs: &[Blob]) {
        let Some([a, b]) = touching else {
            self.contact = None;
            return;
        };
        let balls = [a.circle, b.circle];
        let near = |p: &Circle, q: &Circle| (p.x - q.x).abs() <= 0.5 && (p.y - q.y).abs() <= 0.5;
        match &mut self.contact {
            Some(c)
                if c.balls.iter().zip(&balls).all(|(p, q)| near(p, q))
                    && same_blobs(&c.blobs, blobs) =>
            {
                c.frames += 1;
            }
            _ => {
                self.contact = Some(Contact {
                    balls,
                    blobs: blobs.iter().take(6).map(Blob::guess).collect(),
                    frames: 1,
                });
            }
        }
    }

    /// The fits of the first six `blobs` (coarse factor `f`), and which are not to
    /// be searched by Hough ([`Tracker::stale_blobs`]: held no ball for long). A
    /// blob whose own fit keeps failing in place is not fitted (left out for the
    /// reason its last fit was), whether or not other fits found balls inside it.
    fn fit_blobs(
        &mut self,
        frame: &Frame,
        blobs: &[Blob],
        f: f64,
    ) -> (Vec<Result<Outline, LeftOut>>, Vec<bool>) {
        let stale = self.stale_blobs(blobs);
        let mut fits = Vec::new();
        for (b, s) in blobs.iter().take(6).zip(&stale) {
            fits.push(match s.unfitted {
                Some(why) => Err(why),
                None => self.fit_blob(frame, b, f),
            });
        }
        (fits, stale.iter().map(|s| s.unsearched).collect())
    }

    /// For each of the first six `blobs`, what of its work is skipped
    /// (`Params::stale_blob`, each but every [`STALE_RETRY`]th frame: see
    /// [`Stale`]).
    fn stale_blobs(&self, blobs: &[Blob]) -> Vec<StaleSkips> {
        let due = |n: usize| skipped_now(n, self.params.stale_blob);
        blobs
            .iter()
            .take(6)
            .map(|b| match self.stale_entry(&b.guess()) {
                Some(s) => StaleSkips {
                    unfitted: due(s.failed).then_some(s.why),
                    unsearched: due(s.empty),
                },
                None => StaleSkips::default(),
            })
            .collect()
    }

    /// What is known of a blob at `guess` (within a pixel) from the frames before.
    fn stale_entry(&self, guess: &Circle) -> Option<Stale> {
        self.stale
            .iter()
            .find(|s| within_a_pixel(&s.guess, guess))
            .copied()
    }

    /// Counts, for each of the first six `blobs`, the frames running in which its
    /// own fit (`fits`: the blobs' own, in their order, then Hough's and the
    /// follower's) was left out, and of those the frames in which no fit of the
    /// frame lay inside it; a blob that moved or gave a ball starts again.
    fn note_stale(&mut self, blobs: &[Blob], fits: &[Result<Outline, LeftOut>]) {
        if self.params.stale_blob == 0 {
            return;
        }
        let next = blobs
            .iter()
            .take(6)
            .zip(fits)
            .filter_map(|(b, own)| {
                let (guess, why) = (b.guess(), own.err()?);
                let held = fits.iter().flatten().any(|o| {
                    let c = o.circle;
                    (b.left..=b.right).contains(&c.x) && (b.top..=b.bottom).contains(&c.y)
                });
                let before = self.stale_entry(&guess);
                Some(Stale {
                    guess,
                    failed: before.map_or(0, |s| s.failed) + 1,
                    empty: if held {
                        0
                    } else {
                        before.map_or(0, |s| s.empty) + 1
                    },
                    why,
                })
            })
            .collect();
        self.stale = next;
    }

    /// The follower: each ball seen in the last frames looked for about where it is
    /// predicted now, when no blob gave it (a ball at rest over the pixels the
    /// background learned it at, or faint).
    fn follow(&mut self, frame: &Frame, fits: &mut Vec<Result<Outline, LeftOut>>) {
        let k = self.frames.len();
        for slot in 0..2 {
            let Some(l) = self.last.get(slot) else {
                continue;
            };
            // A ball seen once has no velocity yet: predicted where it was, which a
            // rolling ball has left a few frames on (full look 39: 3 frames after a
            // ball's one fit, a circle of the wall 33 px behind it). Followed from
            // one fit only into the next frame.
            let gap = if l.len() >= 2 { 3 } else { 1 };
            let recent = l.last().is_some_and(|(k1, _)| k - k1 <= gap);
            let Some(pred) = predict(l, k).filter(|_| recent) else {
                continue;
            };
            if self.crosses_other(slot, &pred) {
                continue;
            }
            let found = fits
                .iter()
                .flatten()
                .any(|o| (o.circle.x - pred.x).hypot(o.circle.y - pred.y) < 0.5 * pred.r);
            if found {
                continue;
            }
            let band = (self.params.window_radii * pred.r).max(3.0);
            // Where the ball is predicted to have moved on (by over a tenth of a
            // radius: a ball at rest is predicted within the pixel noise of where it
            // was), what the window gives must differ from the background, as a
            // ball that moves does; the follower's own case, a ball at rest over the
            // pixels the background learned it at, is not judged. The velocity of
            // fits either side of an impact (the other ball not yet seen, so no
            // frame of it merged) is neither the ball's before nor after: along it
            // the window lands where the ball is not, on whatever circle the wall
            // offers there (the looks table's seed 2, a checkered wall).
            let moved = l
                .last()
                .is_some_and(|(_, c)| (pred.x - c.x).hypot(pred.y - c.y) > 0.1 * pred.r);
            // A sharp arc (`sharp_rms`) of the balls' radius (`sharp_radius`) is a
            // ball's own edge: a ball of the wall's brightness differs from the
            // background only along it.
            let (p, known) = (self.params, self.radius);
            let sharp = |o: &Outline| {
                o.rms <= p.sharp_rms
                    && known.is_some_and(|r| (o.circle.r - r).abs() < p.sharp_radius * r)
            };
            if let Ok(o) = self.refine(frame, pred, band)
                && !(moved && !sharp(&o) && self.differing(&o.circle) < p.moved_share)
            {
                self.sought.push(o.circle);
                fits.push(Ok(o));
            }
        }
    }

    /// True when `pred`, the ball in `slot` predicted now, overlaps the other ball
    /// predicted now (seen in the last 3 frames): two balls never overlap, so the
    /// predictions have run on across the impact, and the window about either lies
    /// where the ball was headed, not where it is (the looks table's seed 39: a
    /// circle fitted there, 32 px from the ball that had bounced back).
    fn crosses_other(&self, slot: usize, pred: &Circle) -> bool {
        let k = self.frames.len();
        self.last
            .get(1 - slot.min(1))
            .filter(|l| l.last().is_some_and(|(k1, _)| k - k1 <= 3))
            .and_then(|l| predict(l, k))
            .is_some_and(|o| (o.x - pred.x).hypot(o.y - pred.y) < o.r + pred.r)
    }

    /// The share of the upper half of the disc `c` (above the rail) where the frame
    /// differs from the background (`differs_at`), sampled as `stands_out` samples
    /// it; 1 without a background (nothing to tell by).
    fn differing(&self, c: &Circle) -> f64 {
        let (Some(bg), Some(small)) = (self.background.as_ref().map(|b| &b.image), &self.small)
        else {
            return 1.0;
        };
        let step = (c.r / 8.0).max(1.0);
        let (mut hit, mut n) = (0usize, 0usize);
        let mut dy = -0.8 * c.r;
        while dy < 0.0 {
            let mut dx = -0.8 * c.r;
            while dx <= 0.8 * c.r {
                if length(dx, dy) < 0.8 * c.r {
                    n += 1;
                    hit += usize::from(differs_at(small, bg, c.x + dx, c.y + dy, &self.params));
                }
                dx += step;
            }
            dy += step;
        }
        if n == 0 {
            return 1.0;
        }
        hit as f64 / n as f64
    }

    /// In the first frame with a ball seen, the seed (`Params::ball_at`): the fit
    /// whose disc holds it is a ball and sets the radius; fits of another radius in
    /// that frame are not balls. Without such a fit, the outline is sought about the
    /// seed itself. The radius is then learned from the fits as without a seed (one
    /// outline can be a few % off: a lit part, a fringe joined to the ball).
    fn seed(&mut self, frame: &Frame, fits: &mut Vec<Result<Outline, LeftOut>>) {
        let Some((sx, sy)) = self.params.ball_at else {
            return;
        };
        if self.seeded {
            return;
        }
        let holds = |o: &Outline| (o.circle.x - sx).hypot(o.circle.y - sy) <= o.circle.r;
        let mut at = fits.iter().flatten().find(|o| holds(o)).copied();
        if at.is_none() {
            at = seed_fit(&frame.luma, (sx, sy), self.params.min_radius)
                .and_then(|c| self.refine(frame, c, (0.2 * c.r).max(3.0)).ok())
                .filter(holds);
            if let Some(o) = at {
                fits.push(Ok(o));
            }
        }
        let Some(o) = at else { return };
        let r = o.circle.r;
        self.seeded = true;
        self.radius = Some(r);
        let tol = self.params.radius_tolerance;
        for f in fits.iter_mut() {
            if f.as_ref().is_ok_and(|q| (q.circle.r - r).abs() >= tol * r) {
                *f = Err(LeftOut::Poor);
            }
        }
    }

    fn both_seen(&self) -> bool {
        self.last.iter().all(|l| !l.is_empty())
    }

    /// True when this frame shows the impact: a blob about two balls wide, fewer
    /// than two outlines, both balls seen before and predicted near each other.
    fn merged(&self, coarse: &detect::Coarse, fits: &[Result<Outline, LeftOut>]) -> bool {
        !coarse.pairs.is_empty()
            && fits.iter().flatten().count() < 2
            && self.both_seen()
            && self.predicted_close()
    }

    /// True when the two balls are predicted within a radius of touching now (or
    /// either cannot be predicted): a wide blob far from that is no impact.
    fn predicted_close(&self) -> bool {
        let k = self.frames.len();
        match (
            self.last.first().and_then(|l| predict(l, k)),
            self.last.get(1).and_then(|l| predict(l, k)),
        ) {
            (Some(a), Some(b)) => (a.x - b.x).hypot(a.y - b.y) < a.r + b.r + a.r.max(b.r),
            _ => true,
        }
    }

    /// The outline near `guess`, twice: in a band `band` px wide either side (the
    /// coarse look's error, or the search window), then narrowly about the first fit.
    fn refine(&mut self, frame: &Frame, guess: Circle, band: f64) -> Result<Outline, LeftOut> {
        self.refine_with(frame, guess, band, true)
    }

    /// As [`Tracker::refine`]; `colour`: whether the outline may be sought in the
    /// frame's colour difference where brightness gives none, and first in its
    /// difference from the background where `difference_first` asks it (once the
    /// radius is known: a first lock is the frame's own outline).
    fn refine_with(
        &mut self,
        frame: &Frame,
        guess: Circle,
        band: f64,
        colour: bool,
    ) -> Result<Outline, LeftOut> {
        if colour && self.params.difference_first && self.radius().is_some() {
            let near = self.predicted_near(guess).unwrap_or(guess);
            if let Ok(o) = self.refine_difference(frame, near, band) {
                return Ok(o);
            }
        }
        self.refine_frame(frame, guess, band, colour)
    }

    /// The outline in the frame's difference from the background about `guess`
    /// (`difference_outline`), held to a ball's checks: it stands out from around
    /// it, is large enough, lies in the `--roi`, and is shaped as a ball's, its
    /// radius the balls' so far.
    fn refine_difference(
        &self,
        frame: &Frame,
        guess: Circle,
        band: f64,
    ) -> Result<Outline, LeftOut> {
        let p = self.params;
        let o = self
            .difference_outline(frame, guess, band)
            .ok_or(LeftOut::Poor)?;
        stands_as_a_ball(frame, &o.outline.circle, &p)?;
        if !self.shaped(&o, &p, false) {
            return Err(LeftOut::Poor);
        }
        Ok(o.outline)
    }

    /// As [`Tracker::refine_with`], in the frame itself (its brightness, else its
    /// colour).
    fn refine_frame(
        &mut self,
        frame: &Frame,
        guess: Circle,
        band: f64,
        colour: bool,
    ) -> Result<Outline, LeftOut> {
        let guess = self.predicted_near(guess).unwrap_or(guess);
        let mut p = self.params;
        // A first lock needs a clear outline; a circle of the known radius less, if
        // its radius agrees closely (and odd fits are left out over the clip).
        if self.radius().is_some() {
            p.min_coverage = p.min_coverage.min(p.min_coverage_known);
        }
        let known = self.radius();
        // A short arc, but sharp and of the known radius: the ball's edge where the
        // wall behind it contrasts, the rest of its outline lost in a wall of its
        // brightness (the outline of both signs there mixes in the wall's edges).
        let sharp = |o: &OutlineFound| {
            !o.colour
                && o.outline.coverage() >= p.min_coverage_sharp
                && o.outline.rms <= p.sharp_rms
                && known.is_some_and(|r| (o.outline.circle.r - r).abs() < p.sharp_radius * r)
        };
        let o = match self.outline(frame, guess, band, self.polarity) {
            Some(o) if o.outline.coverage() >= p.min_coverage || sharp(&o) => o,
            // Too little outline of one sign: a ball on a wall of its brightness,
            // brighter than part of the wall and darker than the rest. Its edge of
            // both signs, else (a ball of the wall's brightness) in colour.
            weak => {
                let either = (self.polarity != circle::EITHER)
                    .then(|| self.outline(frame, guess, band, circle::EITHER))
                    .flatten()
                    .filter(|o| o.outline.coverage() >= p.min_coverage);
                match (either, weak) {
                    (Some(o), _) | (None, Some(o)) => o,
                    (None, None) if !colour => return Err(LeftOut::Poor),
                    (None, None) => self
                        .colour_outline(frame, guess, band)
                        .ok_or(LeftOut::Poor)?,
                }
            }
        };
        let o = if colour {
            let sharp = sharp(&o);
            let o = self.grey_ball_in_colour(frame, (guess, band), o, &p, sharp);
            self.coloured_in_colour(frame, (guess, band), o, &p)
        } else {
            o
        };
        let c = o.outline.circle;
        let tolerance = self.tolerance(&o.outline);
        stands_as_a_ball(frame, &c, &p)?;
        if !self.shaped(&o, &p, sharp(&o)) {
            self.note_other_radius(&o);
            return Err(LeftOut::Poor);
        }
        // The first lock must be the outermost circular edge about it; once a lock
        // was not (the ball's outline taken instead), so must every fit the balls'
        // radius is learned from (the first 64), each of the radius known so far.
        let learning = !self.seeded && p.radius_px.is_none() && self.radii.len() <= 64;
        let o = if (known.is_none() || (learning && self.outer_taken)) && !o.colour {
            match self.outermost_agrees(frame, &o.outline) {
                Outer::Agrees => o,
                Outer::Instead(q)
                    if known.is_some_and(|r| (q.circle.r - r).abs() >= tolerance * r) =>
                {
                    return Err(LeftOut::Poor);
                }
                Outer::Instead(outline) => {
                    self.outer_taken = true;
                    OutlineFound {
                        outline,
                        colour: false,
                        polarity: outline.polarity,
                    }
                }
                Outer::Poor => return Err(LeftOut::Poor),
            }
        } else {
            o
        };
        if self.polarity == 0.0 && !o.colour {
            self.polarity = o.polarity;
        }
        Ok(o.outline)
    }

    /// Whether the ball about `c` is one [`Tracker::grey_ball_in_colour`] seeks in colour:
    /// grey (the median colour of its disc's upper half within `grey_levels` of
    /// none) and dark (its median brightness under `dark_ball`: a black ball; its
    /// highlight and mark are a small part of it), or, with `grey_in_colour`, of any
    /// brightness where the wall about it is of one colour (`wall_of_one_colour`).
    fn grey_sought_in_colour(&self, frame: &Frame, c: &Circle, p: &Params) -> bool {
        let Some([y, u, v]) = upper_disc(frame, c) else {
            return false;
        };
        let grey = f64::from(u.abs().max(v.abs())) <= p.grey_levels;
        let one_colour = || {
            self.background
                .as_ref()
                .is_some_and(|b| wall_of_one_colour(&b.image, c, p.grey_levels))
        };
        grey && (f64::from(y) < p.dark_ball || (p.grey_in_colour && one_colour()))
    }

    /// A grey ball sought in colour (`grey_sought_in_colour`: a black one on a wall
    /// of its brightness that differs from it in colour): where its outline `o` in
    /// brightness is poor (`sharp`: `o` is a short sharp arc of the known radius; the
    /// wall's own edges mixed in), its outline in colour about `guess` (in a band
    /// `band` px wide) if that is clear: the wall's colour against none. Else `o`.
    fn grey_ball_in_colour(
        &self,
        frame: &Frame,
        (guess, band): (Circle, f64),
        o: OutlineFound,
        p: &Params,
        sharp: bool,
    ) -> OutlineFound {
        if o.colour || self.shaped(&o, p, sharp) || !self.grey_sought_in_colour(frame, &guess, p) {
            return o;
        }
        match self.colour_outline(frame, guess, band) {
            Some(q) if self.shaped(&q, p, false) => q,
            _ => o,
        }
    }

    /// A coloured ball: where its outline in colour about `guess` (in a band `band`
    /// px wide) is clear (`colour_clear_rms`) and its radius lies farther from the
    /// outline `o` in brightness than two circles of one ball differ
    /// (`outer_agree`), the outline in colour. A coloured ball's outline in colour
    /// is its own colour against the wall's; its outline in brightness, where the
    /// two differ so, a circle through its top and the rail's edge or its shadow,
    /// or its lit part (the looks table's seed 26: balls of 12.35 px on a dark
    /// rail, first locks of 14.9 px). So too where `o` is not a ball's outline
    /// (`shaped`) and the ball is of the wall's brightness
    /// (`of_the_walls_brightness`), its outline in colour being a ball's of
    /// `colour_own_radius` or more, on frames of 640 px and wider (the background
    /// learned coarse): its outline in brightness is then the wall's pattern (full
    /// look 43's green balls on a magenta grain of their brightness: circles of
    /// 10–41 px for 29.7). Else `o`; and `o` unsought in colour where it is settled
    /// (a ball's, of the balls' radius: [`Params::colour_settled`]).
    fn coloured_in_colour(
        &self,
        frame: &Frame,
        (guess, band): (Circle, f64),
        o: OutlineFound,
        p: &Params,
    ) -> OutlineFound {
        if o.colour || self.settled(&o, p) || !coloured(frame, &guess, p.grey_levels) {
            return o;
        }
        // A coloured ball on a wall of its brightness: its outline in brightness
        // is the wall's pattern, its outline in colour its own. Once the radius is
        // known, any coloured ball whose outline in brightness is poor takes a
        // clear outline in colour (`colour_over_poor_rms`): a wall of its
        // brightness in places, darker or lighter in others, is as much its
        // outline's pattern.
        let coarse = self.background.as_ref().is_some_and(|b| b.image.factor > 1);
        let walls_own = |q: &OutlineFound| {
            coarse
                && q.outline.circle.r >= p.colour_own_radius
                && !self.shaped(&o, p, false)
                && ((self.radius().is_some() && q.outline.rms <= p.colour_over_poor_rms)
                    || of_the_walls_brightness(frame, &guess, p))
        };
        let clear_and_apart = |q: &OutlineFound| {
            q.outline.rms <= p.colour_clear_rms
                && (q.outline.circle.r - o.outline.circle.r).abs()
                    > p.outer_agree * q.outline.circle.r
        };
        match self.colour_outline_of(frame, guess, band, true) {
            Some(q) if self.shaped(&q, p, false) && (clear_and_apart(&q) || walls_own(&q)) => q,
            _ => o,
        }
    }

    /// True when the outline `o` in brightness is a ball's (`shaped`) and of the
    /// balls' radius within `colour_settled` of it: a coloured ball's outline in
    /// colour is then not sought (see [`Params::colour_settled`]).
    fn settled(&self, o: &OutlineFound, p: &Params) -> bool {
        self.radius()
            .is_some_and(|r| (o.outline.circle.r - r).abs() <= p.colour_settled * r)
            && self.shaped(o, p, false)
    }

    /// True when the outline `o` is clear enough for a ball (`sharp`: a short sharp
    /// arc of the known radius): its coverage, an arc a ball over a rail shows
    /// (`Outline::seen_over_a_rail`), its scatter about its circle (twice as much in
    /// colour: `refine_with`'s tests) and its radius within the tolerance of the
    /// balls' radius so far.
    fn shaped(&self, o: &OutlineFound, p: &Params, sharp: bool) -> bool {
        // The colour planes are half size, brought to full size bilinearly: their
        // edge points scatter about twice as far as the brightness edge's.
        let max_rms = if o.colour { 2.0 * p.max_rms } else { p.max_rms };
        let (c, tolerance) = (o.outline.circle, self.tolerance(&o.outline));
        (o.outline.coverage() >= p.min_coverage || sharp)
            && o.outline.seen_over_a_rail(p.rail_view_deg)
            && o.outline.rms <= max_rms
            && self
                .radius()
                .is_none_or(|r| (c.r - r).abs() < tolerance * r)
    }

    /// Notes the radius of `o`, left out as not shaped, when only its radius kept it
    /// out: a clear outline in brightness (`min_coverage`, `max_rms`, over a rail),
    /// once a frame ([`Tracker::radius_contradicted`]).
    fn note_other_radius(&mut self, o: &OutlineFound) {
        // The coverage of a first lock, not the one lowered once a radius is known.
        let p = self.params;
        let c = o.outline.circle;
        let clear = !o.colour
            && o.outline.coverage() >= p.min_coverage
            && o.outline.seen_over_a_rail(p.rail_view_deg)
            && o.outline.rms <= p.max_rms;
        let again = self
            .other_here
            .iter()
            .any(|q| (q.x - c.x).hypot(q.y - c.y) < 0.01 && (q.r - c.r).abs() < 0.01);
        if clear && !again && self.radius.is_some() {
            self.other_here.push(c);
            self.other_radii.push(c.r);
        }
    }

    /// How far the outline `o`'s radius may lie from the balls' radius so far, as a
    /// share of it: `radius_tolerance`, or `max_radius_spread` where `o` covers less
    /// than a clear outline (`min_coverage`, not lowered once the radius is known).
    fn tolerance(&self, o: &Outline) -> f64 {
        let p = &self.params;
        if o.coverage() < p.min_coverage {
            p.radius_tolerance.min(p.max_radius_spread)
        } else {
            p.radius_tolerance
        }
    }

    /// The outermost circular edge of either sign about the outline `o`
    /// (`circle::outermost`, within the blob that differs from the background):
    /// `o` itself, another outline in its place (of either sign about that edge's
    /// circle, clear and itself outermost), or neither (`o` lies inside a larger
    /// circle or reaches past the ball, and no clear outline is there instead).
    /// Without a background, or without a clear outermost edge, `o` is not judged.
    fn outermost_agrees(&self, frame: &Frame, o: &Outline) -> Outer {
        let p = self.params;
        let (Some(bg), Some(small)) = (self.background.as_ref().map(|b| &b.image), &self.small)
        else {
            return Outer::Agrees;
        };
        let differs = |x: f64, y: f64| differs_at(small, bg, x, y, &p);
        let margin = p.outer_margin + bg.factor as f64;
        let is_clear = |e: &Outline| e.coverage() >= p.min_coverage && e.rms <= p.max_rms;
        // About an outline, one look along the rays: its clear outermost edge, and
        // whether it is a "ball" much smaller than the clear round blob around it
        // (part of a ball whose limb steps too little for an edge), told where the
        // background is learned at full resolution (frames under 640 px wide): on
        // coarse pixels of 2–6 px the blob's outline cannot tell 10 %, and on the
        // full-size looks it left out the first locks of seed 34 (its approach lost).
        let examine = |o: &Outline| {
            let (edge, blob) = circle::outermost(
                &frame.luma,
                o,
                (p.outer_reach, p.outer_step, margin),
                &differs,
            );
            let inside_blob = bg.factor == 1
                && blob.is_some_and(|b| {
                    is_clear(&b) && b.circle.r > (1.0 + p.outer_agree) * o.circle.r + margin
                });
            (edge.filter(is_clear), inside_blob)
        };
        let agree = |a: &Circle, b: &Circle| {
            (a.r - b.r).abs() <= p.outer_agree * a.r
                && (a.x - b.x).hypot(a.y - b.y) <= p.outer_agree * a.r
        };
        let (edge, inside_blob) = examine(o);
        let Some(edge) = edge.filter(|e| !agree(&o.circle, &e.circle)) else {
            return if inside_blob {
                Outer::Poor
            } else {
                Outer::Agrees
            };
        };
        let band = (0.1 * edge.circle.r).max(2.0);
        let Some(found) = self.outline(frame, edge.circle, band, circle::EITHER) else {
            return Outer::Poor;
        };
        let q = found.outline;
        let clear = is_clear(&q)
            && q.circle.r >= p.min_radius
            && agree(&edge.circle, &q.circle)
            && stands_out(frame, &q.circle, p.colour_weight) >= p.differ_levels
            && p.roi.is_none_or(|roi| roi.contains(q.circle.x, q.circle.y))
            && {
                let (edge, inside_blob) = examine(&q);
                edge.is_none_or(|e| agree(&q.circle, &e.circle)) && !inside_blob
            };
        if clear {
            Outer::Instead(q)
        } else {
            Outer::Poor
        }
    }

    /// The rail edges (`rails`) that hide the lower part of the ball about `guess`:
    /// each crossing its disc (within 0.9 of its radius) with the frame the
    /// background's below it (the rail, in front of the ball) and differing above
    /// it (the ball): of the coarse pixels whose middles lie a coarse pixel or more
    /// below the edge at most a quarter differ, of those as far above it at least
    /// half, three of each at least. An edge of the wall's pattern across a ball has
    /// the ball below it too. (`rails` are found only in a background at full
    /// resolution: `Tracker::relearn`.)
    fn rails_hiding(&self, guess: &Circle) -> Vec<circle::StraightEdge> {
        let (Some(bg), Some(small)) = (self.background.as_ref().map(|b| &b.image), &self.small)
        else {
            return Vec::new();
        };
        let p = &self.params;
        let f = bg.factor.max(1) as f64;
        let c = *guess;
        // Every coarse pixel of the disc, or some 80 across a disc wider than that
        // (a blob the size of the frame is no ball, but must cost no more).
        let stride = f.max(c.r / 40.0);
        // The middle of the coarse pixel that `differs_at` reads about `v` (a
        // pixel's middle at its index): what lies above or below an edge.
        let middle = |v: f64| (v / f).floor() * f + 0.5 * (f - 1.0);
        let hides = |l: &circle::StraightEdge| {
            let (mut above, mut below) = ((0usize, 0usize), (0usize, 0usize));
            let n = (c.r / stride).ceil().min(40.0) as i64;
            for j in -n..=n {
                for i in -n..=n {
                    let (x, y) = (c.x + i as f64 * stride, c.y + j as f64 * stride);
                    if length(x - c.x, y - c.y) > 0.9 * c.r {
                        continue;
                    }
                    let d = usize::from(differs_at(small, bg, x, y, p));
                    let (xm, ym) = (middle(x), middle(y));
                    let e = l.at(xm);
                    if ym < e - f {
                        above = (above.0 + d, above.1 + 1);
                    } else if ym > e + f {
                        below = (below.0 + d, below.1 + 1);
                    }
                }
            }
            above.1 >= 3 && below.1 >= 3 && 2 * above.0 >= above.1 && 4 * below.0 <= below.1
        };
        self.rails
            .iter()
            .filter(|l| (c.y - 0.5 * c.r..=c.y + 1.5 * c.r + 3.0).contains(&l.at(c.x)))
            .filter(|l| hides(l))
            .copied()
            .collect()
    }

    /// The outline near `guess` in the frame's luma: in a band `band` px wide, then
    /// narrowly, the rail edges that hide the ball left out
    /// (`Tracker::rails_hiding`), and its cast shadow's edge where it peeks out
    /// (`in_the_walls_shadow`, `circle::fit_keeping`).
    fn outline(
        &self,
        frame: &Frame,
        guess: Circle,
        band: f64,
        polarity: f64,
    ) -> Option<OutlineFound> {
        let rails = self.rails_hiding(&guess);
        let bg = self.background.as_ref().map(|b| &b.image);
        let p = &self.params;
        // An edge whose inside is the wall in shadow is the ball's cast shadow's
        // edge, not the ball's: the shadow beside a ball's dark limb makes one dark
        // ring of the two, and its outer edge a circle larger than the ball.
        let own = |q: [f64; 2]| {
            let (dx, dy) = (guess.x - q[0], guess.y - q[1]);
            let d = length(dx, dy).max(1e-9);
            let inside = (q[0] + SHADOW_INSIDE * dx / d, q[1] + SHADOW_INSIDE * dy / d);
            bg.is_none_or(|bg| !in_the_walls_shadow(frame, bg, inside, p))
        };
        let shadow = (&own as &dyn Fn([f64; 2]) -> bool, p.shadow_outside);
        self.outline_by(&frame.luma, guess, band, polarity, (&rails, shadow))
    }

    /// As [`Tracker::outline`], in any image `img` (a patch about the ball: its own
    /// coordinates), with the rail edges `rails` in them.
    fn outline_by(
        &self,
        img: &Gray,
        guess: Circle,
        band: f64,
        polarity: f64,
        (rails, shadow): (&[circle::StraightEdge], circle::Shadow),
    ) -> Option<OutlineFound> {
        let rail = (self.params.rail_moves, rails);
        let first = circle::fit_keeping(img, guess, band, polarity, rail, shadow)?;
        let o = circle::fit_keeping(img, first.circle, 2.5, first.polarity, rail, shadow)?;
        Some(OutlineFound {
            outline: o,
            colour: false,
            polarity: o.polarity,
        })
    }

    /// The outline near `guess` in colour: the frame's colour difference from the
    /// background, along the ball's own colour difference at its middle, as an
    /// image of its own about the ball (the colour planes bilinearly brought to full
    /// size); `None` without a background or colour to go by.
    fn colour_outline(&self, frame: &Frame, guess: Circle, band: f64) -> Option<OutlineFound> {
        self.colour_outline_of(frame, guess, band, false)
    }

    /// As [`Tracker::colour_outline`]; `own`: a coloured ball's own colour against
    /// the wall's, its colour stepping from the background's at its middle by
    /// `colour_edge_step` or more, the background's colour read between its
    /// samples as the frame's is (`colour_outline` reads the sample a pixel lies
    /// in, as the black ball's outline in colour was measured with).
    fn colour_outline_of(
        &self,
        frame: &Frame,
        guess: Circle,
        band: f64,
        own: bool,
    ) -> Option<OutlineFound> {
        let bg = &self.background.as_ref()?.image;
        let (x0, y0, x1, y1) = patch_box(frame, guess, band)?;
        let chroma = |plane: &[u8], x: f64, y: f64| chroma_at(frame, plane, x, y);
        let back = |plane: &[u8], x: f64, y: f64| background_colour(bg, plane, (x, y), own);
        // The ball's colour difference at its middle (upper half: above the rail).
        let (mx, my) = (guess.x, guess.y - 0.3 * guess.r);
        let du = chroma(&frame.u, mx, my) - back(&bg.u, mx, my);
        let dv = chroma(&frame.v, mx, my) - back(&bg.v, mx, my);
        let norm = du.hypot(dv);
        let least = if own {
            self.params.colour_edge_step
        } else {
            self.params.differ_levels / 2.0
        };
        if f64::from(norm) < least {
            return None;
        }
        let (su, sv) = (du / norm, dv / norm);
        let gain = self.params.colour_weight as f32;
        let (w, h) = (x1 - x0 + 1, y1 - y0 + 1);
        let mut data = vec![0; w * h];
        let mut colour = colour_difference(frame, bg, (x0, x1), own);
        // Row by row over plain slices, so the compiler spreads the loop over
        // vector lanes (pushed a pixel at a time, it was a third of the outline in
        // colour on look 85).
        for (y, out) in (y0..=y1).zip(data.chunks_exact_mut(w)) {
            let [u, v, bu, bv] = colour.planes(y);
            let planes = u.iter().zip(bu).zip(v.iter().zip(bv));
            for (o, ((u, bu), (v, bv))) in out.iter_mut().zip(planes) {
                let d = (u - bu) * su + (v - bv) * sv;
                *o = super::gray::level(64.0 + gain * d);
            }
        }
        let patch = Gray {
            width: w,
            height: h,
            data,
        };
        self.patch_outline(&patch, guess, band, (x0, y0))
    }

    /// The outline of a ball brighter than around it in `patch`, an image of its
    /// own whose first pixel is the frame's (x0, y0), about `guess` (frame px) in a
    /// band `band` px wide, the rail's edges that hide the ball left out; in frame
    /// px, as an outline in colour (held to a colour outline's checks).
    fn patch_outline(
        &self,
        patch: &Gray,
        guess: Circle,
        band: f64,
        (x0, y0): (usize, usize),
    ) -> Option<OutlineFound> {
        let local = Circle {
            x: guess.x - x0 as f64,
            y: guess.y - y0 as f64,
            r: guess.r,
        };
        // The rail edges that hide the ball, in the patch's own pixels.
        let rails: Vec<circle::StraightEdge> = self
            .rails_hiding(&guess)
            .into_iter()
            .map(|l| circle::StraightEdge {
                x0: l.x0 - x0 as f64,
                y0: l.y0 - y0 as f64,
                slope: l.slope,
            })
            .collect();
        let mut found = self.outline_by(
            patch,
            local,
            band.max(3.0),
            1.0,
            (&rails, circle::NO_SHADOW),
        )?;
        found.outline.circle.x += x0 as f64;
        found.outline.circle.y += y0 as f64;
        found.outline.lowest += y0 as f64;
        found.colour = true;
        Some(found)
    }

    /// The outline near `guess` in the frame's difference from the background:
    /// each pixel's distance from the background's in brightness and colour taken
    /// together (`colour_weight` on the colour planes), an image of its own about
    /// the ball, fitted as a ball brighter than around it. The wall's own pattern
    /// (stripes, a checker, grain) is in the background, not in the difference:
    /// what is left is the ball's silhouette, and whatever else differs as much (its
    /// shadow, a compression fringe). Only where the background is learned at full
    /// resolution (a coarse one leaves a fine pattern in the difference); `None`
    /// otherwise, or where too little edge is found.
    fn difference_outline(&self, frame: &Frame, guess: Circle, band: f64) -> Option<OutlineFound> {
        let bg = self.background.as_ref().map(|b| &b.image)?;
        if bg.factor != 1 || bg.width != frame.width() || bg.height != frame.height() {
            return None;
        }
        let (x0, y0, x1, y1) = patch_box(frame, guess, band)?;
        let gain = self.params.colour_weight as f32;
        let mut colour = colour_difference(frame, bg, (x0, x1), true);
        let mut data = Vec::with_capacity((x1 - x0 + 1) * (y1 - y0 + 1));
        for y in y0..=y1 {
            for (x, (du, dv)) in (x0..=x1).zip(colour.row(y)) {
                let i = y * bg.width + x;
                let luma = f32::from(frame.luma.data.get(i).copied().unwrap_or(0))
                    - bg.y.get(i).copied().unwrap_or(0.0);
                // Brightness and colour together: the looks' rule (the larger of the
                // two, 0 for a shadow) measured worse here (BENCHMARKS.md).
                // By square roots, not libm's `hypot` (a call a pixel): the levels
                // neither overflow nor underflow.
                let c = gain * (du * du + dv * dv).sqrt();
                let d = (luma * luma + c * c).sqrt();
                data.push(super::gray::level(d));
            }
        }
        let patch = Gray {
            width: x1 - x0 + 1,
            height: y1 - y0 + 1,
            data,
        };
        self.patch_outline(&patch, guess, band, (x0, y0))
    }

    /// The outline of a ball that moves off where a slot last saw it at rest, about
    /// its blob's guess `guess` (band `band`), in place of `held`, the outline the
    /// blob gave about that rest: a slot whose last two fits lie within
    /// `Params::rest_step` of a radius predicts its ball there, and each refine
    /// about that prediction hugs it, so where the ball turns back or is struck
    /// while the wall there offers an outline (a checker's edges in a compressed
    /// clip), its fits stay put as it moves off (full look 39: 8 frames, up to 31
    /// px behind the ball). Where the blob's guess lies more than `rest_left` of a
    /// radius and `rest_bands` bands from the prediction along the rows
    /// ([`Tracker::rest_near`]), the outline is sought about the guess (at the
    /// prediction's height), no prediction taken, and kept where it is a whole
    /// ball and its upper half differs from the background (`differing`) over
    /// `rest_differ` more of it than `held`'s does, or `held` failed. Else `held`
    /// stands.
    fn moved_off_rest(
        &mut self,
        frame: &Frame,
        guess: Circle,
        band: f64,
        held: Result<Outline, LeftOut>,
    ) -> Result<Outline, LeftOut> {
        let Some(rest) = self.rest_near(guess, band) else {
            return held;
        };
        let p = self.params;
        let about = Circle { x: guess.x, ..rest };
        self.about_guess = true;
        let moved = self.refine(frame, about, band);
        self.about_guess = false;
        let Ok(moved) = moved.and_then(|o| whole_in_blob(o, rest.r, &p)) else {
            return held;
        };
        let differs = match &held {
            Ok(h) => self.differing(&moved.circle) > self.differing(&h.circle) + p.rest_differ,
            Err(_) => true,
        };
        if differs { Ok(moved) } else { held }
    }

    /// The rest a slot predicts its ball at, where the blob's guess `guess` (band
    /// `band`) lies off it: the slot's last two fits within `Params::rest_step` of
    /// a radius of each other, the prediction near `guess` (as `predicted_near`
    /// takes it) but more than `rest_left` of a radius and `rest_bands` bands from
    /// it along the rows; its radius the balls' learned one.
    fn rest_near(&self, guess: Circle, band: f64) -> Option<Circle> {
        let p = self.params;
        let r = self.radius?;
        let k = self.frames.len();
        let rest = self.last.iter().find_map(|l| {
            let [(_, a), (_, b)] = l.as_slice() else {
                return None;
            };
            let at = predict(l, k)?;
            ((a.x - b.x).hypot(a.y - b.y) < p.rest_step * b.r && taken_for(&at, &guess))
                .then_some(at)
        })?;
        ((rest.x - guess.x).abs() > (p.rest_left * rest.r).max(p.rest_bands * band))
            .then_some(Circle { r, ..rest })
    }

    /// Where a slot's ball is expected now (moving on as between its last two fits),
    /// if that is near `guess`; none while outlines are sought about the guess
    /// ([`Tracker::moved_off_rest`]).
    fn predicted_near(&self, guess: Circle) -> Option<Circle> {
        if self.about_guess {
            return None;
        }
        let k = self.frames.len();
        self.last
            .iter()
            .filter_map(|l| predict(l, k))
            .find(|p| taken_for(p, &guess))
    }

    /// Which slot each fit (left to right) belongs to: the slot whose ball was last
    /// seen nearest; fits of two balls keep their left-to-right order.
    fn assign(
        &self,
        fits: Vec<Result<Outline, LeftOut>>,
    ) -> Vec<(usize, Result<Outline, LeftOut>)> {
        let k = self.frames.len();
        let pred: Vec<Option<Circle>> = self.last.iter().map(|l| predict(l, k)).collect();
        let (p0, p1) = (
            pred.first().copied().flatten(),
            pred.get(1).copied().flatten(),
        );
        let mut it = fits.into_iter();
        match (it.next(), it.next()) {
            (None, _) => Vec::new(),
            // Both seen (sorted left to right): slot 0 is the left ball, always. Two
            // balls in one groove never pass each other, so the order in the picture
            // is who is who (a slot kept from an earlier, wrong lock would swap them).
            (Some(a @ Ok(_)), Some(b @ Ok(_))) => vec![(0, a), (1, b)],
            (Some(a), Some(b)) => {
                let mut out = self.assign(vec![a]);
                let other = out.first().map_or(1, |(s, _)| 1 - s);
                out.push((other, b));
                out
            }
            (Some(fit), None) => {
                let x = match &fit {
                    Ok(o) => o.circle.x,
                    Err(_) => return Vec::new(),
                };
                let slot = match (p0, p1) {
                    (Some(a), Some(b)) => usize::from((b.x - x).abs() < (a.x - x).abs()),
                    (None, Some(b)) if (b.x - x).abs() > 2.0 * b.r => 0,
                    (None, Some(_)) => 1,
                    (Some(a), None) if (a.x - x).abs() > 2.0 * a.r => 1,
                    _ => 0,
                };
                vec![(slot, fit)]
            }
        }
    }
}

/// A first circle about the seed `at` (a point on a ball): along 32 rays from it,
/// the first strong luma step; the circle through those steps (least squares of
/// the algebraic distance), `None` when they do not make one.
#[allow(clippy::indexing_slicing)] // the Kåsa fit's three coefficients
fn seed_fit(img: &Gray, at: (f64, f64), min_radius: f64) -> Option<Circle> {
    let reach = (img.width.min(img.height) as f64 / 3.0).max(2.0 * min_radius);
    let inside = |x: f64, y: f64| {
        x >= 0.0 && y >= 0.0 && x < img.width as f64 - 1.0 && y < img.height as f64 - 1.0
    };
    let level = |x: f64, y: f64| {
        if inside(x, y) {
            Some(img.get(x.round() as usize, y.round() as usize))
        } else {
            None
        }
    };
    let start = level(at.0, at.1)?;
    let mut pts = Vec::new();
    for i in 0..32 {
        let a = f64::from(i) * std::f64::consts::TAU / 32.0;
        let (dx, dy) = (a.cos(), a.sin());
        let mut s = 1.0;
        while s < reach {
            let Some(v) = level(at.0 + s * dx, at.1 + s * dy) else {
                break;
            };
            if (v - start).abs() > 25.0 {
                pts.push([at.0 + s * dx, at.1 + s * dy]);
                break;
            }
            s += 1.0;
        }
    }
    if pts.len() < 12 {
        return None;
    }
    // Kåsa's fit: x² + y² + D x + E y + F = 0.
    let mut ata = nalgebra::Matrix3::<f64>::zeros();
    let mut atb = nalgebra::Vector3::<f64>::zeros();
    for p in &pts {
        let row = nalgebra::Vector3::new(p[0], p[1], 1.0);
        ata += row * row.transpose();
        atb -= row * (p[0] * p[0] + p[1] * p[1]);
    }
    let sol = ata.try_inverse()? * atb;
    let (cx, cy) = (-0.5 * sol[0], -0.5 * sol[1]);
    let r2 = cx * cx + cy * cy - sol[2];
    (r2 > min_radius * min_radius && cx.is_finite() && cy.is_finite()).then(|| Circle {
        x: cx,
        y: cy,
        r: r2.sqrt(),
    })
}

/// How much the upper half of the disc `c` differs from a ring around it above its
/// centre (the rail hides the lower half), in `frame` itself, levels: the larger of
/// the mean brightness difference and the weighted mean colour differences (as
/// `background::differences` weighs them, by `colour_weight`). A ball differs from the wall around it
/// in brightness or colour; a ghost of the background or a circle fitted to a
/// textured wall does not, on average.
fn stands_out(frame: &Frame, c: &Circle, colour_weight: f64) -> f64 {
    contrast(frame, c).map_or(f64::INFINITY, |[dl, du, dv]| {
        dl.max(colour_weight * du.max(dv))
    })
}

/// How the upper half of the disc `c` differs from the ring around it above its
/// centre ([`stands_out`]): the mean brightness's and the two mean colours'
/// differences, levels, unweighted; `None` where too little of either is in the
/// picture to tell.
fn contrast(frame: &Frame, c: &Circle) -> Option<[f64; 3]> {
    let (mut inner, mut outer) = ([0.0f64; 4], [0.0f64; 4]);
    let step = (c.r / 8.0).max(1.0);
    let reach = 1.6 * c.r;
    let (w, h) = (frame.width() as f64, frame.height() as f64);
    let mut dy = -reach;
    while dy < 0.0 {
        let mut dx = -reach;
        while dx <= reach {
            let (x, y) = (c.x + dx, c.y + dy);
            let d = length(dx, dy);
            let sum = if d < 0.8 * c.r {
                Some(&mut inner)
            } else if d > 1.2 * c.r && d < reach {
                Some(&mut outer)
            } else {
                None
            };
            if let Some(sum) = sum
                && x >= 0.0
                && y >= 0.0
                && x < w
                && y < h
            {
                let (ix, iy) = (x as usize, y as usize);
                let ci = (iy / 2) * frame.chroma_width + ix / 2;
                sum[0] += f64::from(frame.luma.get(ix, iy));
                sum[1] += frame.u.get(ci).map_or(128.0, |&v| f64::from(v));
                sum[2] += frame.v.get(ci).map_or(128.0, |&v| f64::from(v));
                sum[3] += 1.0;
            }
            dx += step;
        }
        dy += step;
    }
    if inner[3] < 1.0 || outer[3] < 1.0 {
        // Too little of it in the picture to tell: not ruled out here.
        return None;
    }
    let mean = |s: &[f64; 4], i: usize| s.get(i).copied().unwrap_or(0.0) / s[3];
    Some([0, 1, 2].map(|i| (mean(&inner, i) - mean(&outer, i)).abs()))
}

/// The mean colour (U, V levels) of the upper half of the disc `c`
/// ([`upper_disc_pixels`]); `None` where fewer than 8 samples of it are in the
/// picture.
pub fn disc_colour(frame: &Frame, c: &Circle) -> Option<[f64; 2]> {
    let mut sum = [0.0f64; 3];
    for (x, y) in upper_disc_pixels(frame, c) {
        let ci = (y / 2) * frame.chroma_width + x / 2;
        if let (Some(&u), Some(&v)) = (frame.u.get(ci), frame.v.get(ci)) {
            sum[0] += f64::from(u);
            sum[1] += f64::from(v);
            sum[2] += 1.0;
        }
    }
    (sum[2] >= 8.0).then(|| [sum[0] / sum[2], sum[1] / sum[2]])
}

/// True when the ball about `c` differs from the wall around it (`contrast`) in
/// colour, by at least twice `differ_levels` (weighed as `stands_out` weighs
/// it), but in brightness by under `differ_levels`: a ball of the wall's
/// brightness, whose outline in brightness is the wall's own edges.
fn of_the_walls_brightness(frame: &Frame, c: &Circle, p: &Params) -> bool {
    contrast(frame, c).is_some_and(|[dl, du, dv]| {
        dl < p.differ_levels && p.colour_weight * du.max(dv) >= 2.0 * p.differ_levels
    })
}

/// The background `bg`'s colour plane `plane` at the full-size pixel `(x, y)`: the
/// sample of the coarse pixel it lies in, or (`between`) bilinearly between the
/// samples (each coarse pixel's colour is the chroma sample at its block's middle,
/// `Small::of`), as the frame's colour is read between its own samples: where the
/// two are one grid (coarse pixels of 2 px), the wall's colour edges cancel.
fn background_colour(bg: &Small, plane: &[u8], (x, y): (f64, f64), between: bool) -> f32 {
    let f = bg.factor.max(1);
    let across = (
        colour_axis(f, bg.width, x, between),
        colour_axis(f, bg.height, y, between),
    );
    background_between(bg, plane, across)
}

/// Where the full-size coordinate `t` falls among the background's colour samples
/// along an axis of `n` coarse pixels of `f` px ([`background_colour`]): the two
/// samples about it and the second's weight (`between`), or the sample of the
/// coarse pixel it lies in, twice, weighing nothing.
fn colour_axis(f: usize, n: usize, t: f64, between: bool) -> (usize, usize, f32) {
    if !between {
        let i = (t / f as f64) as usize;
        return (i, i, 0.0);
    }
    // Where coarse pixel `i`'s colour sample lies, px.
    let place = |i: usize| (2 * ((i * f + f / 2) / 2)) as f64 + 0.5;
    // `as usize` is the floor held at 0 (negative and NaN give 0), with no libm call.
    let i0 = (((t - 0.5) / f as f64) as usize).min(n.saturating_sub(1));
    let i0 = if i0 > 0 && place(i0) > t { i0 - 1 } else { i0 };
    let i1 = (i0 + 1).min(n.saturating_sub(1));
    let span = place(i1) - place(i0);
    let w = if span > 0.0 {
        ((t - place(i0)) / span).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (i0, i1, w as f32)
}

/// The background's colour plane `plane` weighed between the samples `(i0, i1,
/// fx)` across and `(j0, j1, fy)` down ([`colour_axis`]).
fn background_between(
    bg: &Small,
    plane: &[u8],
    ((i0, i1, fx), (j0, j1, fy)): ((usize, usize, f32), (usize, usize, f32)),
) -> f32 {
    let at = background_sample(bg, plane);
    (at(i0, j0) * (1.0 - fx) + at(i1, j0) * fx) * (1.0 - fy)
        + (at(i0, j1) * (1.0 - fx) + at(i1, j1) * fx) * fy
}

/// The background's colour plane `plane` at sample (i, j), held to the plane; 128
/// (grey) off a short plane.
fn background_sample<'a>(bg: &'a Small, plane: &'a [u8]) -> impl Fn(usize, usize) -> f32 + 'a {
    move |i, j| {
        plane
            .get(j.min(bg.height.saturating_sub(1)) * bg.width + i.min(bg.width.saturating_sub(1)))
            .map_or(128.0, |&v| f32::from(v))
    }
}

/// The frame's colour less the background's (U and V) at each column `x0..=x1` of a
/// patch, a row at a time: each of the four planes weighed across a row of its
/// samples at a time ([`Across`]), the background's between its samples or not
/// (`between`, [`colour_axis`]). The same values as [`chroma_between`] less
/// [`background_between`] per pixel, to the bit.
struct ColourDifference<F, B> {
    u: Across<F>,
    v: Across<F>,
    back_u: Across<B>,
    back_v: Across<B>,
    /// The frame's colour rows, the background's colour rows and factor.
    chroma_height: usize,
    back: (usize, usize),
    between: bool,
    rows: [Vec<f32>; 4],
}

/// The [`ColourDifference`] of `frame` against `bg` over the columns `x0..=x1`.
fn colour_difference<'a>(
    frame: &'a Frame,
    bg: &'a Small,
    (x0, x1): (usize, usize),
    between: bool,
) -> ColourDifference<impl Fn(usize, usize) -> f32 + 'a, impl Fn(usize, usize) -> f32 + 'a> {
    let f = bg.factor.max(1);
    let cw = frame.chroma_width;
    let fcols: Vec<_> = (x0..=x1).map(|x| chroma_axis(cw, x as f64)).collect();
    let bcols: Vec<_> = (x0..=x1)
        .map(|x| colour_axis(f, bg.width, x as f64, between))
        .collect();
    ColourDifference {
        u: Across::new(chroma_sample(&frame.u, cw), fcols.clone()),
        v: Across::new(chroma_sample(&frame.v, cw), fcols),
        back_u: Across::new(background_sample(bg, &bg.u), bcols.clone()),
        back_v: Across::new(background_sample(bg, &bg.v), bcols),
        chroma_height: frame.chroma_height,
        back: (bg.height, f),
        between,
        rows: [const { Vec::new() }; 4],
    }
}

impl<F: Fn(usize, usize) -> f32, B: Fn(usize, usize) -> f32> ColourDifference<F, B> {
    /// Row `y`'s (U, V) differences, one per column.
    fn row(&mut self, y: usize) -> impl Iterator<Item = (f32, f32)> + '_ {
        let [u, v, bu, bv] = self.planes(y);
        u.iter()
            .zip(bu.iter())
            .zip(v.iter().zip(bv.iter()))
            .map(|((u, bu), (v, bv))| (u - bu, v - bv))
    }

    /// Row `y`'s colour planes, one value per column: the frame's U and V, the
    /// background's U and V.
    fn planes(&mut self, y: usize) -> [&[f32]; 4] {
        let (bh, f) = self.back;
        let frow = chroma_axis(self.chroma_height, y as f64);
        let row = colour_axis(f, bh, y as f64, self.between);
        let [u, v, bu, bv] = &mut self.rows;
        self.u.between(frow, u);
        self.v.between(frow, v);
        self.back_u.between(row, bu);
        self.back_v.between(row, bv);
        [u, v, bu, bv].map(|r| r.as_slice())
    }
}

/// A colour plane weighed across at every column of a patch, a row of its samples
/// at a time: the first half of [`chroma_between`]'s and [`background_between`]'s
/// weighing, done once per row of samples instead of per pixel (a frame's row of
/// colour samples serves two rows of pixels, a coarse background's a dozen), in
/// their order of operations: the same values to the bit.
struct Across<F> {
    sample: F,
    /// Per column: the samples before and after and the second's weight.
    cols: Vec<(usize, usize, f32)>,
    /// The rows of samples weighed across so far (the last two asked for).
    rows: Vec<(usize, Vec<f32>)>,
}

impl<F: Fn(usize, usize) -> f32> Across<F> {
    fn new(sample: F, cols: Vec<(usize, usize, f32)>) -> Across<F> {
        Across {
            sample,
            cols,
            rows: Vec::with_capacity(2),
        }
    }

    /// The plane between its rows `(j0, j1, fy)` ([`chroma_axis`],
    /// [`colour_axis`]) at every column, into `out`.
    fn between(&mut self, (j0, j1, fy): (usize, usize, f32), out: &mut Vec<f32>) {
        self.rows.retain(|(j, _)| *j == j0 || *j == j1);
        for j in [j0, j1] {
            if !self.rows.iter().any(|(k, _)| *k == j) {
                let at = &self.sample;
                let row = self
                    .cols
                    .iter()
                    .map(|&(i0, i1, fx)| at(i0, j) * (1.0 - fx) + at(i1, j) * fx)
                    .collect();
                self.rows.push((j, row));
            }
        }
        let find = |j: usize| {
            self.rows
                .iter()
                .find(|(k, _)| *k == j)
                .map_or(&[] as &[f32], |(_, r)| r.as_slice())
        };
        out.clear();
        out.extend(
            find(j0)
                .iter()
                .zip(find(j1))
                .map(|(&a, &b)| a * (1.0 - fy) + b * fy),
        );
    }
}

/// One fit per ball: of fits of one ball (a blob and the follower), the first;
/// the good fits first, from left to right.
fn one_fit_per_ball(fits: Vec<Result<Outline, LeftOut>>) -> Vec<Result<Outline, LeftOut>> {
    let mut kept: Vec<Result<Outline, LeftOut>> = Vec::new();
    for fit in fits {
        let same = |o: &Outline| {
            kept.iter().flatten().any(|q: &Outline| {
                (q.circle.x - o.circle.x).hypot(q.circle.y - o.circle.y) < q.circle.r
            })
        };
        match fit {
            Ok(o) if same(&o) => {}
            other => kept.push(other),
        }
    }
    kept.sort_by(|a, b| match (a, b) {
        (Ok(a), Ok(b)) => a.circle.x.total_cmp(&b.circle.x),
        (Ok(_), Err(_)) => std::cmp::Ordering::Less,
        (Err(_), Ok(_)) => std::cmp::Ordering::Greater,
        _ => std::cmp::Ordering::Equal,
    });
    kept
}

/// How often a stale blob (`Params::stale_blob`) is fitted all the same, frames: a
/// ball may come to rest on it, or roll into it, unfollowed.
const STALE_RETRY: usize = 16;

/// Whether work that stayed the same for `frames` frames running is skipped this
/// frame: after `least` of them (`Params::stale_blob`; 0: never), but every
/// [`STALE_RETRY`]th frame.
fn skipped_now(frames: usize, least: usize) -> bool {
    least > 0 && frames >= least && !frames.is_multiple_of(STALE_RETRY)
}

/// Whether two blobs' guesses are one blob's: centre and radius within a pixel.
fn within_a_pixel(p: &Circle, q: &Circle) -> bool {
    (p.x - q.x).abs() <= 1.0 && (p.y - q.y).abs() <= 1.0 && (p.r - q.r).abs() <= 1.0
}

/// A blob of the frames before whose own fit was left out, frames running
/// (`Params::stale_blob`): where its guess was, in how many frames its own fit was
/// left out (`failed`: then it is not fitted), of those the last in which no fit of
/// the frame lay inside it (`empty`: then neither is it searched by Hough), and why
/// its own fit was left out the last time it was made.
#[derive(Clone, Copy, Debug)]
struct Stale {
    guess: Circle,
    failed: usize,
    empty: usize,
    why: LeftOut,
}

/// What of a blob's work this frame skips ([`Tracker::stale_blobs`]): its own
/// fit (left out for this reason), and Hough's search inside it.
#[derive(Clone, Copy, Debug, Default)]
struct StaleSkips {
    unfitted: Option<LeftOut>,
    unsearched: bool,
}

/// The balls found touching, frames running, at rest: their circles where the run
/// began, the guesses of that frame's first six blobs, and how many frames the run
/// holds (those taken as it without a fit too). After a run of
/// `Params::stale_blob` frames the balls are not fitted again but every
/// [`STALE_RETRY`]th frame while the blobs stay put: look 85's balls rest in
/// contact for its last 223 frames, each of which fitted both (Hough, 1.4 ms a
/// frame) to leave them out as touching.
#[derive(Clone, Debug)]
struct Contact {
    balls: [Circle; 2],
    blobs: Vec<Circle>,
    frames: usize,
}

/// Whether `blobs`' first six guesses are `guesses`, each within a pixel.
fn same_blobs(guesses: &[Circle], blobs: &[Blob]) -> bool {
    blobs.iter().take(6).count() == guesses.len()
        && blobs
            .iter()
            .zip(guesses)
            .all(|(b, g)| within_a_pixel(&b.guess(), g))
}

/// Whether the circle `c` fitted in `frame` can be a ball: something inside it
/// differs from around it (`differ_levels`; else it is a ghost, where the
/// background learned a ball that is not there now, or a circle fitted to the wall's
/// own pattern: not a ball, and no poor outline of one either: unseen), it is
/// `min_radius` or larger and lies in the `--roi` (else poor).
fn stands_as_a_ball(frame: &Frame, c: &Circle, p: &Params) -> Result<(), LeftOut> {
    if stands_out(frame, c, p.colour_weight) < p.differ_levels {
        return Err(LeftOut::Unseen);
    }
    if c.r < p.min_radius || p.roi.is_some_and(|roi| !roi.contains(c.x, c.y)) {
        return Err(LeftOut::Poor);
    }
    Ok(())
}

/// The pixels (x0, y0, x1, y1), inclusive, of the image an outline about `guess` is
/// sought in (a band `band` px wide either side of it, and 4 px more), clipped to
/// `frame`; `None` where fewer than 9 px each way are left.
fn patch_box(frame: &Frame, guess: Circle, band: f64) -> Option<(usize, usize, usize, usize)> {
    let reach = guess.r + band + 4.0;
    let x0 = (guess.x - reach).floor().max(0.0) as usize;
    let y0 = (guess.y - reach).floor().max(0.0) as usize;
    let x1 = ((guess.x + reach).ceil() as usize).min(frame.width().saturating_sub(1));
    let y1 = ((guess.y + reach).ceil() as usize).min(frame.height().saturating_sub(1));
    (x1 > x0 + 8 && y1 > y0 + 8).then_some((x0, y0, x1, y1))
}

/// The colour plane `plane` of `frame` at the full-size point (x, y), bilinearly
/// between its half-size samples (sample (i, j) sits at (2i + 0.5, 2j + 0.5)).
fn chroma_at(frame: &Frame, plane: &[u8], x: f64, y: f64) -> f32 {
    let (cw, ch) = (frame.chroma_width, frame.chroma_height);
    chroma_between(plane, cw, (chroma_axis(cw, x), chroma_axis(ch, y)))
}

/// Where [`chroma_at`] reads the colour samples about the full-size coordinate `t`
/// along an axis of `n` half-size samples: the sample before, the one after (held
/// to the axis) and the second's weight. Found once per column and row of a patch
/// (a pixel's own arithmetic was a sixth of a large ball's outline in colour).
fn chroma_axis(n: usize, t: f64) -> (usize, usize, f32) {
    let c = (t - 0.5) / 2.0;
    // `as usize` is the floor held at 0 (negative and NaN give 0), with no libm call.
    let i0 = c as usize;
    let i1 = (i0 + 1).min(n.saturating_sub(1));
    (i0, i1, (c - i0 as f64).clamp(0.0, 1.0) as f32)
}

/// The colour plane `plane` (`cw` samples wide) between the samples `(i0, i1, fx)`
/// across and `(j0, j1, fy)` down ([`chroma_axis`]); a sample off the plane reads 128.
fn chroma_between(
    plane: &[u8],
    cw: usize,
    ((i0, i1, fx), (j0, j1, fy)): ((usize, usize, f32), (usize, usize, f32)),
) -> f32 {
    let at = chroma_sample(plane, cw);
    (at(i0, j0) * (1.0 - fx) + at(i1, j0) * fx) * (1.0 - fy)
        + (at(i0, j1) * (1.0 - fx) + at(i1, j1) * fx) * fy
}

/// The colour plane `plane` (`cw` samples wide) at sample (i, j); 128 (grey) off
/// the plane.
fn chroma_sample(plane: &[u8], cw: usize) -> impl Fn(usize, usize) -> f32 + '_ {
    move |i, j| plane.get(j * cw + i).map_or(128.0, |&v| f32::from(v))
}

/// How far inside an edge point its inside is read for a shadow, px: past the
/// edge's own blur (a Sobel peak a pixel or two wide).
const SHADOW_INSIDE: f64 = 2.0;

/// Fewest levels a shadow darkens the wall by: less is the wall's noise.
const SHADOW_STEP: f32 = 4.0;

/// True when `frame` at `(x, y)` (px) is the background `bg` in shadow: darker by
/// [`SHADOW_STEP`] levels or more and dimmed alike, the looks' shadow test
/// ([`super::background::dimmed_alike`]), its colour read between the samples.
pub fn in_the_walls_shadow(frame: &Frame, bg: &Small, (x, y): (f64, f64), p: &Params) -> bool {
    if !(x >= 0.0 && y >= 0.0) || x >= frame.width() as f64 || y >= frame.height() as f64 {
        return false;
    }
    let f = bg.factor.max(1);
    let (bx, by) = (x as usize / f, y as usize / f);
    if bx >= bg.width || by >= bg.height {
        return false;
    }
    let Some(&lit) = bg.y.get(by * bg.width + bx) else {
        return false;
    };
    let luma = frame.luma.get(x as usize, y as usize);
    let own = |plane: &[u8]| chroma_at(frame, plane, x, y);
    let wall = |plane: &[u8]| background_colour(bg, plane, (x, y), true);
    luma <= lit - SHADOW_STEP
        && super::background::dimmed_alike(
            (luma, own(&frame.u), own(&frame.v)),
            (lit, wall(&bg.u), wall(&bg.v)),
            p.shadow_darkest as f32,
            p.shadow_hue_levels as f32,
        )
}

/// True when the background `bg` about the ball `c` is of one colour: on a ring of
/// 1.5 radii about it, above its centre (the rail hides the rest), nine in ten of
/// its colour samples lie within `levels` (U and V each) of their median. A grey
/// ball's outline in colour is the wall's colour against none; on a wall of two
/// colours (a checker, stripes) it is the wall's pattern as much as the ball's.
pub fn wall_of_one_colour(bg: &Small, c: &Circle, levels: f64) -> bool {
    const SAMPLES: usize = 24;
    let (w, h) = (
        (bg.width * bg.factor) as f64,
        (bg.height * bg.factor) as f64,
    );
    let (mut u, mut v) = (Vec::with_capacity(SAMPLES), Vec::with_capacity(SAMPLES));
    for i in 0..=SAMPLES {
        let a = std::f64::consts::PI * (1.0 + i as f64 / SAMPLES as f64);
        let (x, y) = (c.x + 1.5 * c.r * a.cos(), c.y + 1.5 * c.r * a.sin());
        if x >= 0.0 && y >= 0.0 && x < w && y < h {
            u.push(f64::from(background_colour(bg, &bg.u, (x, y), false)));
            v.push(f64::from(background_colour(bg, &bg.v, (x, y), false)));
        }
    }
    // Half the ring in the picture at least: a ball at the frame's edge says little.
    if u.len() * 2 <= SAMPLES {
        return false;
    }
    let even = |s: &[f64]| {
        let Some(m) = median(s) else { return false };
        let mut off: Vec<f64> = s.iter().map(|q| (q - m).abs()).collect();
        off.sort_by(f64::total_cmp);
        let k = (off.len() * 9).div_ceil(10).saturating_sub(1);
        off.get(k).is_some_and(|&d| d <= levels)
    };
    even(&u) && even(&v)
}

/// True when the ball about `c` has a colour of its own: the median colour of its
/// disc's upper half (above the rail) lies more than `grey` levels from none.
fn coloured(frame: &Frame, c: &Circle, grey: f64) -> bool {
    upper_disc(frame, c).is_some_and(|[_, u, v]| f64::from(u.abs().max(v.abs())) > grey)
}

/// The median brightness and colour (U, V less 128) of the upper half of the disc
/// `c` ([`upper_disc_pixels`]), `None` where none of it is in the picture.
fn upper_disc(frame: &Frame, c: &Circle) -> Option<[f32; 3]> {
    let (mut y, mut u, mut v) = (Vec::new(), Vec::new(), Vec::new());
    for (ix, iy) in upper_disc_pixels(frame, c) {
        let ci = (iy / 2) * frame.chroma_width + ix / 2;
        y.push(frame.luma.get(ix, iy));
        u.push(frame.u.get(ci).map_or(0.0, |&q| f32::from(q) - 128.0));
        v.push(frame.v.get(ci).map_or(0.0, |&q| f32::from(q) - 128.0));
    }
    Some([
        select::median(&mut y)?,
        select::median(&mut u)?,
        select::median(&mut v)?,
    ])
}

/// The pixels of `frame` sampled over the upper half of the disc `c` (above the
/// rail, which hides the lower half), within 0.8 of its radius (the edge blurs into
/// the wall), every eighth of a radius (or pixel): those in the picture.
fn upper_disc_pixels(frame: &Frame, c: &Circle) -> Vec<(usize, usize)> {
    let step = (c.r / 8.0).max(1.0);
    let (w, h) = (frame.width() as f64, frame.height() as f64);
    let mut out = Vec::new();
    let mut dy = -0.8 * c.r;
    while dy < 0.0 {
        let mut dx = -0.8 * c.r;
        while dx <= 0.8 * c.r {
            let (x, y) = (c.x + dx, c.y + dy);
            if length(dx, dy) < 0.8 * c.r && x >= 0.0 && y >= 0.0 && x < w && y < h {
                out.push((x as usize, y as usize));
            }
            dx += step;
        }
        dy += step;
    }
    out
}

/// True when the circle `c` (a fit) has its centre inside one of the blobs'
/// circles `blobs` (their guesses) and is smaller than `share` of it: that blob's
/// mark or highlight, not a ball (`Params::smallest_in_blob`); `share` 0: never.
pub fn inside_a_larger_blob(c: &Circle, blobs: &[Circle], share: f64) -> bool {
    blobs
        .iter()
        .any(|g| c.r < share * g.r && (g.x - c.x).hypot(g.y - c.y) < g.r)
}

/// True when a frame's good fits' radii (`radii`, px) lie farther apart than
/// `tolerance` of the largest: before the balls' radius is known, such first locks
/// set none (both balls have one radius; a circle through a ball's top and the
/// fringe joined to its blob is larger than the ball, the ball's lit part smaller).
pub fn locks_disagree(radii: &[f64], tolerance: f64) -> bool {
    let lo = radii.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = radii.iter().copied().fold(0.0, f64::max);
    radii.len() >= 2 && hi - lo > tolerance * hi
}

/// The balls' radius `radius` (px) when both balls confirm it: each ball's radii
/// fitted about its blobs' own guesses (`free`, not sought at the known radius),
/// their medians within `spread` of the radius of each other and of it; else `None`.
/// Both balls have one radius, and two balls found apart agreeing on it is what a
/// wrong first lock (the lit part of one ball, a circle through one ball's fringe)
/// does not give.
pub fn confirmed_radius(radius: Option<f64>, free: &[Vec<f64>; 2], spread: f64) -> Option<f64> {
    let r = radius?;
    let [a, b] = free;
    let (ma, mb) = (median(a)?, median(b)?);
    let tol = spread * r;
    ((ma - mb).abs() <= tol && (0.5 * (ma + mb) - r).abs() <= tol).then_some(r)
}

/// The radius (px) that clear outlines left out for their radius alone (`others`,
/// px) agree on where they contradict the radius learned (`radius`, px, from `kept`
/// fits): `Params::min_contradicting` of them or more and more than `kept`, their
/// robust scatter (1.4826 × the median absolute deviation) within
/// `max_radius_spread` of their median, and that median beyond `radius_tolerance` of
/// `radius`; else `None`.
pub fn contradicting_radius(radius: f64, kept: usize, others: &[f64], p: &Params) -> Option<f64> {
    let m = doubting_radius(radius, kept, others, p)?;
    (robust_sd(others, m) <= p.max_radius_spread * m).then_some(m)
}

/// The median radius (px) of clear outlines left out for their radius alone
/// (`others`, px) where they put the radius learned (`radius`, px, from `kept`
/// fits) in doubt: `Params::min_contradicting` of them or more and more than
/// `kept`, their median beyond `radius_tolerance` of `radius`, however they scatter
/// (agreeing within `max_radius_spread` too, they contradict it:
/// [`contradicting_radius`]); else `None`.
pub fn doubting_radius(radius: f64, kept: usize, others: &[f64], p: &Params) -> Option<f64> {
    let m = median(others)?;
    (others.len() >= p.min_contradicting
        && others.len() > kept
        && (m - radius).abs() >= p.radius_tolerance * radius)
        .then_some(m)
}

/// Whether a slot's prediction `at` is taken for the blob's guess `guess`: within
/// half the larger of their radii.
fn taken_for(at: &Circle, guess: &Circle) -> bool {
    (at.x - guess.x).hypot(at.y - guess.y) < 0.5 * guess.r.max(at.r)
}

/// The outline `o` fitted in a blob of radius `blob`, unless it is under
/// `Params::smallest_in_blob` of it: the mark or a highlight fitted in a ball's blob,
/// not the ball.
fn whole_in_blob(o: Outline, blob: f64, p: &Params) -> Result<Outline, LeftOut> {
    if o.circle.r < p.smallest_in_blob * blob {
        Err(LeftOut::Poor)
    } else {
        Ok(o)
    }
}

/// A slot's circle extrapolated to frame `k` from its last two fits.
fn predict(last: &[(usize, Circle)], k: usize) -> Option<Circle> {
    match last {
        [] => None,
        [(_, c)] => Some(*c),
        [.., (k0, a), (k1, b)] => {
            let step = (k - k1) as f64 / (k1 - k0).max(1) as f64;
            Some(Circle {
                x: b.x + (b.x - a.x) * step,
                y: b.y + (b.y - a.y) * step,
                r: b.r,
            })
        }
    }
}

/// The robust standard deviation of `v` about `centre`: 1.4826 × the median absolute
/// deviation (a normal scatter's σ), 0 when `v` is empty.
pub fn robust_sd(v: &[f64], centre: f64) -> f64 {
    let dev: Vec<f64> = v.iter().map(|x| (x - centre).abs()).collect();
    1.4826 * median(&dev).unwrap_or(0.0)
}

/// The median of `v`, `None` when empty.
pub fn median(v: &[f64]) -> Option<f64> {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    s.get(s.len() / 2).copied()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A teal disc (RGB 30, 150, 170) of radius 20 on a grey wall, its lower half
    /// below a red rail: the disc's colour is the teal's (U, V as the frame holds
    /// them, within a level), not the rail's nor the wall's; a disc wholly out of
    /// the picture has none.
    #[test]
    fn a_discs_colour_is_its_upper_halfs() {
        let (w, h) = (120u32, 80u32);
        let img = image::RgbImage::from_fn(w, h, |x, y| {
            let (dx, dy) = (f64::from(x) - 60.0, f64::from(y) - 40.0);
            if y >= 40 {
                image::Rgb([200, 30, 30])
            } else if dx.hypot(dy) < 20.0 {
                image::Rgb([30, 150, 170])
            } else {
                image::Rgb([128, 128, 128])
            }
        });
        let frame = Frame::from_rgb(&img);
        let teal = Frame::from_rgb(&image::RgbImage::from_pixel(
            4,
            4,
            image::Rgb([30, 150, 170]),
        ));
        let want = [f64::from(teal.u[0]), f64::from(teal.v[0])];
        let got = disc_colour(
            &frame,
            &Circle {
                x: 60.0,
                y: 40.0,
                r: 20.0,
            },
        )
        .expect("a colour");
        assert!(
            (got[0] - want[0]).abs() < 1.0 && (got[1] - want[1]).abs() < 1.0,
            "{got:?} for {want:?}"
        );
        assert!((want[0] - 128.0).abs() > 10.0 || (want[1] - 128.0).abs() > 10.0);
        assert_eq!(
            disc_colour(
                &frame,
                &Circle {
                    x: -100.0,
                    y: 40.0,
                    r: 20.0
                }
            ),
            None
        );
    }

    /// A coarse background `w` × `h` coarse pixels of `f` px each, its colour at
    /// each coarse pixel `colour(i, j)` (U, V), its luma 120.
    fn background(
        w: usize,
        h: usize,
        f: usize,
        colour: impl Fn(usize, usize) -> (u8, u8),
    ) -> Small {
        let (mut u, mut v) = (Vec::new(), Vec::new());
        for j in 0..h {
            for i in 0..w {
                let (a, b) = colour(i, j);
                u.push(a);
                v.push(b);
            }
        }
        Small {
            width: w,
            height: h,
            factor: f,
            y: vec![120.0; w * h],
            u,
            v,
        }
    }

    proptest::proptest! {
        /// A wall of one colour, its samples scattered by under `grey_levels`, is
        /// of one colour about any ball well inside the frame; a checker of two
        /// colours apart by more than twice that, of squares up to 0.6 radius wide,
        /// is not; nor a ball whose ring lies mostly off the frame. Squares of
        /// about a radius can hold nine in ten of the ring's samples in one colour
        /// (or blended across their edges near the median): 20 000 cases found 15 px
        /// balls on squares of 14 px, and 11.5 px balls on 10 px, taken for a wall
        /// of one colour (the grey-in-colour rule then stands on the clip's other
        /// checks; squares of two radii are, about the ball, a wall of one colour).
        #[test]
        fn a_wall_of_one_colour_is_told_from_a_checker(
            (u0, v0) in (20u8..235, 20u8..235),
            (du, dv) in (13u8..20, 0u8..20),
            noise in proptest::collection::vec(0u8..6, 64 * 48),
            r in 8.0f64..20.0,
            square in 0.3f64..0.6,
            (x, y) in (0.4f64..0.6, 0.5f64..0.7),
            f in 2usize..5,
        ) {
            let (w, h) = (64, 48);
            let levels = Params::default().grey_levels;
            let c = Circle { x: x * (w * f) as f64, y: y * (h * f) as f64, r };
            let plain = background(w, h, f, |i, j| {
                let n = noise.get(j * w + i).copied().unwrap_or(0);
                (u0 + n - 3, v0 + n - 3)
            });
            proptest::prop_assert!(wall_of_one_colour(&plain, &c, levels));
            let side = (square * r / f as f64).max(1.0) as usize;
            let checker = background(w, h, f, |i, j| {
                if (i / side + j / side).is_multiple_of(2) { (u0, v0) } else { (u0 + du, v0 + dv) }
            });
            proptest::prop_assert!(!wall_of_one_colour(&checker, &c, levels));
            let off = Circle { x: -0.8 * r, ..c };
            proptest::prop_assert!(!wall_of_one_colour(&plain, &off, levels));
        }
    }

    /// A clear outline of a ball of radius 69 px centred at `(x, 278)`.
    fn ball_at(x: f64) -> Outline {
        Outline::upper_half(x, 278.0, 69.0)
    }

    /// A blob whose box spans `x0 … x1` across and `y0 … y1` down.
    fn blob(x0: f64, x1: f64, y0: f64, y1: f64) -> Blob {
        Blob {
            left: x0,
            right: x1,
            top: y0,
            bottom: y1,
            area: (x1 - x0) * (y1 - y0),
            core: None,
        }
    }

    /// A blob that stays put and whose own fit is left out is fitted for
    /// `stale_blob` frames, then skipped (left out for the reason it last was),
    /// fitted again every `STALE_RETRY` frames; it is searched by Hough while a
    /// fit of the frame lies inside it, and only now and then once none has for
    /// as long. Its own fit found, a move of more than a pixel, or `stale_blob` 0
    /// has it fitted every frame.
    #[test]
    fn a_blob_that_stays_put_without_a_ball_is_fitted_only_now_and_then() {
        let mut t = Tracker::new(Params::default());
        let least = t.params.stale_blob;
        assert!(least > 0);
        let wide = blob(822.0, 1074.0, 210.0, 400.0);
        let skipped = |t: &Tracker, b: &Blob| t.stale_blobs(&[*b])[0];
        let fitted = |t: &Tracker, b: &Blob| skipped(t, b).unfitted.is_none();
        let ball = ball_at(890.0);
        // Two balls at rest in contact inside it, found by Hough or the follower:
        // its own fit is skipped as it fails, Hough's search never is.
        let mut pattern = Vec::new();
        for _ in 0..3 * STALE_RETRY {
            let s = skipped(&t, &wide);
            assert!(!s.unsearched);
            pattern.push(s.unfitted.is_none());
            let own = s.unfitted.unwrap_or(LeftOut::Poor);
            t.note_stale(&[wide], &[Err(own), Ok(ball)]);
        }
        // Fitted the first `least` frames, then on the multiples of STALE_RETRY.
        let due = |k: usize| k < least || k.is_multiple_of(STALE_RETRY);
        for (k, fit) in pattern.iter().enumerate() {
            assert_eq!(*fit, due(k), "frame {k}: {pattern:?}");
        }
        // Empty from now: searched for `least` frames more, then now and then,
        // and fitted as before, left out for the reason it last was.
        let mut searched = Vec::new();
        for _ in 0..3 * STALE_RETRY {
            let s = skipped(&t, &wide);
            searched.push(!s.unsearched);
            let own = match s.unfitted {
                Some(why) => why,
                None => LeftOut::Unseen,
            };
            t.note_stale(&[wide], &[Err(own)]);
        }
        for (k, search) in searched.iter().enumerate() {
            assert_eq!(*search, due(k), "frame {k}: {searched:?}");
        }
        assert_eq!(
            t.stale_entry(&wide.guess()).map(|s| s.why),
            Some(LeftOut::Unseen)
        );
        // Within a pixel it is the same blob; moved by two, a new one (one frame
        // more: 6 STALE_RETRY frames running is a retry).
        t.note_stale(&[wide], &[Err(LeftOut::Unseen)]);
        let nudged = blob(822.5, 1074.5, 210.5, 400.5);
        assert!(!fitted(&t, &nudged));
        let moved = blob(824.0, 1076.0, 210.0, 400.0);
        assert!(fitted(&t, &moved));
        // Its own fit found a ball: it starts again.
        t.note_stale(&[wide], &[Ok(ball)]);
        assert!(fitted(&t, &wide));
        assert!(t.stale_entry(&wide.guess()).is_none());
        // Off, every blob is fitted and searched every frame.
        let mut off = Tracker::new(Params {
            stale_blob: 0,
            ..Params::default()
        });
        for _ in 0..2 * STALE_RETRY {
            assert!(fitted(&off, &wide));
            assert!(!skipped(&off, &wide).unsearched);
            off.note_stale(&[wide], &[Err(LeftOut::Poor)]);
        }
    }

    /// A slot's rest is sought off only where its last two fits lie within
    /// `rest_step` of a radius (a ball at rest), the radius is known, and the blob's
    /// guess lies off that rest by more than `rest_left` of a radius and
    /// `rest_bands` bands along the rows, but near enough for the prediction to be
    /// taken for it (half a radius); the rest then has the balls' radius.
    #[test]
    fn a_rest_is_left_only_by_a_blob_off_it_along_the_groove() {
        let r = 42.0;
        let at = |x: f64| Circle {
            x,
            y: 340.0,
            r: 41.0,
        };
        let mut t = Tracker::new(Params::default());
        t.last[1] = vec![(62, at(812.2)), (63, at(812.4))];
        t.frames = vec![[Err(LeftOut::Unseen), Err(LeftOut::Unseen)]; 64];
        let band = 6.0;
        let guess = |x: f64| Circle {
            x,
            y: 352.0,
            r: 60.0,
        };
        // No radius learned yet: no rest.
        assert_eq!(t.rest_near(guess(795.0), band), None);
        t.radius = Some(r);
        // The ball 17.6 px off (over a quarter of the fits' radius, 10.25 px, and
        // two bands, 12).
        let rest = t.rest_near(guess(795.0), band).expect("a rest left");
        assert!(
            (rest.x - 812.6).abs() < 1e-9 && rest.y == 340.0 && rest.r == r,
            "{rest:?}"
        );
        // 11.6 px off: over a quarter radius, within two bands.
        assert_eq!(t.rest_near(guess(801.0), band), None);
        // Wider bands (a coarser look): within them.
        assert_eq!(t.rest_near(guess(795.0), 9.0), None);
        // Beyond half the blob's radius across the groove: no prediction there.
        assert_eq!(
            t.rest_near(
                Circle {
                    y: 380.0,
                    ..guess(795.0)
                },
                band
            ),
            None
        );
        // A ball that moved 5 px between its fits (over a tenth of a radius) is
        // not at rest.
        t.last[1] = vec![(62, at(817.0)), (63, at(812.0))];
        assert_eq!(t.rest_near(guess(790.0), band), None);
        // One fit only: no rest told.
        t.last[1] = vec![(63, at(812.0))];
        assert_eq!(t.rest_near(guess(795.0), band), None);
    }

    /// Balls found touching in the same places for `stale_blob` frames running,
    /// the blobs staying put, are taken as touching without a fit but every
    /// `STALE_RETRY`th frame; a blob that moves, balls that move by more than half
    /// a pixel, a frame where they do not touch, or `stale_blob` 0 has them fitted.
    #[test]
    fn balls_at_rest_in_contact_are_fitted_only_now_and_then() {
        let least = Params::default().stale_blob;
        assert!(least > 0);
        let pair = [ball_at(890.0), ball_at(1029.0)];
        let wide = blob(822.0, 1080.0, 204.0, 312.0);
        // One frame of the tracker: skipped, or fitted and found as `fits`.
        let frame = |t: &mut Tracker, fits: Option<&[Outline]>, b: &Blob| {
            let skip = t.still_in_contact(&[*b]);
            if !skip {
                t.note_contact(fits, &[*b]);
            }
            skip
        };
        let mut t = Tracker::new(Params::default());
        let pattern: Vec<bool> = (0..3 * STALE_RETRY)
            .map(|_| !frame(&mut t, Some(&pair), &wide))
            .collect();
        for (k, fitted) in pattern.iter().enumerate() {
            let due = k < least || k.is_multiple_of(STALE_RETRY);
            assert_eq!(*fitted, due, "frame {k}: {pattern:?}");
        }
        // A blob moved by two pixels: fitted (the run stands for the blob as was).
        assert!(!frame(&mut t, Some(&pair), &wide));
        let moved = blob(824.0, 1082.0, 204.0, 312.0);
        assert!(!t.still_in_contact(&[moved]));
        assert!(t.still_in_contact(&[wide]));
        // A frame fitted where they do not touch ends the run.
        let mut t = Tracker::new(Params::default());
        (0..least).for_each(|_| assert!(!frame(&mut t, Some(&pair), &wide)));
        assert!(frame(&mut t, Some(&pair), &wide));
        t.note_contact(None, &[wide]);
        assert!(!frame(&mut t, Some(&pair), &wide));
        // Balls that moved by more than half a pixel start a run of their own.
        let mut t = Tracker::new(Params::default());
        (1..least).for_each(|_| assert!(!frame(&mut t, Some(&pair), &wide)));
        let crept = [ball_at(890.7), ball_at(1029.7)];
        assert!(!frame(&mut t, Some(&crept), &wide));
        assert!(!frame(&mut t, Some(&crept), &wide));
        // Off, they are fitted every frame.
        let mut off = Tracker::new(Params {
            stale_blob: 0,
            ..Params::default()
        });
        for _ in 0..2 * STALE_RETRY {
            assert!(!frame(&mut off, Some(&pair), &wide));
        }
    }

    /// A fixed LCG (the test reads no clock): the next value in 0 … 1.
    fn next(x: &mut u64) -> f64 {
        *x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (*x >> 11) as f64 / (1u64 << 53) as f64
    }

    /// `Across` weighs a plane as `chroma_between` and `background_between` do per
    /// pixel, bit for bit: over drawn planes (some shorter than their size says, read
    /// as grey), coarse factors, patches reaching off the plane and rows asked in
    /// order, again and out of order.
    #[test]
    fn weighing_rows_across_gives_each_pixels_own_value() {
        let mut x = 7u64;
        for case in 0..300 {
            let (w, h) = (
                1 + (next(&mut x) * 40.0) as usize,
                1 + (next(&mut x) * 30.0) as usize,
            );
            let short = if case % 5 == 0 {
                (next(&mut x) * (w * h) as f64) as usize
            } else {
                w * h
            };
            let plane: Vec<u8> = (0..short).map(|_| (next(&mut x) * 256.0) as u8).collect();
            let f = 1 + (next(&mut x) * 6.0) as usize;
            let between = case % 2 == 0;
            let bg = Small {
                width: w,
                height: h,
                factor: f,
                y: vec![0.0; w * h],
                u: plane.clone(),
                v: plane.clone(),
            };
            // Full-size coordinates over the plane and past its edges.
            let span = |n: usize, x: &mut u64| -> Vec<f64> {
                let a = next(x) * (n as f64 + 8.0) - 4.0;
                (0..12)
                    .map(|i| a + i as f64 * 0.5 + next(x) * 0.3)
                    .collect()
            };
            let (xs, ys) = (span(2 * w, &mut x), span(2 * h, &mut x));
            let mut ys2 = ys.clone();
            ys2.reverse();
            let fcols: Vec<_> = xs.iter().map(|&t| chroma_axis(w, t)).collect();
            let bcols: Vec<_> = xs.iter().map(|&t| colour_axis(f, w, t, between)).collect();
            let mut frame = Across::new(chroma_sample(&plane, w), fcols.clone());
            let mut back = Across::new(background_sample(&bg, &bg.u), bcols.clone());
            let mut out = Vec::new();
            for &t in ys.iter().chain(&ys2) {
                let frow = chroma_axis(h, t);
                frame.between(frow, &mut out);
                assert_eq!(out.len(), fcols.len());
                for (&v, &col) in out.iter().zip(&fcols) {
                    let own = chroma_between(&plane, w, (col, frow));
                    assert_eq!(v.to_bits(), own.to_bits(), "case {case}: {v} for {own}");
                }
                let row = colour_axis(f, h, t, between);
                back.between(row, &mut out);
                assert_eq!(out.len(), bcols.len());
                for (&v, &col) in out.iter().zip(&bcols) {
                    let own = background_between(&bg, &bg.u, (col, row));
                    assert_eq!(v.to_bits(), own.to_bits(), "case {case}: {v} for {own}");
                }
            }
        }
    }
}
