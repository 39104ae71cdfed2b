//! Following both balls through a stream of frames, one frame at a time (memory: one
//! frame and the numbers found so far): each frame is looked at coarsely for
//! ball-shaped blobs, each blob's outline is fitted to sub-pixel accuracy near where
//! the ball was last seen, and its mark is found inside it. A ball is left out of a
//! frame, and counted, when it is not seen (hidden or out of the picture), when the
//! two balls touch (at an impact their outlines merge), or when its outline is poor
//! (blurred, or too little of it visible); nothing is filled in.

use super::circle::{self, Circle, Outline};
use super::detect;
use super::gray::Gray;
use super::mark::{self, Mark};

/// One ball in one frame, in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fix {
    pub outline: Outline,
    /// Standard error of the centre's x and y, px.
    pub sigma: f64,
    pub mark: Option<Mark>,
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

/// The state of tracking: the balls' last fits and every frame's result.
#[derive(Clone, Debug, Default)]
pub struct Tracker {
    /// Smallest ball radius looked for, px.
    pub min_radius: f64,
    pub frames: Vec<FrameFixes>,
    pub counts: Counts,
    /// Each slot's last two fits (frame index, circle), newest last.
    last: [Vec<(usize, Circle)>; 2],
    polarity: f64,
    radii: Vec<f64>,
    /// The median of `radii`, renewed while they are few and then every 256.
    radius: Option<f64>,
}

impl Tracker {
    pub fn new(min_radius: f64) -> Tracker {
        Tracker {
            min_radius,
            ..Tracker::default()
        }
    }

    /// The median radius fitted so far, px.
    pub fn radius(&self) -> Option<f64> {
        self.radius
    }

    /// Every radius fitted, px.
    pub fn radii(&self) -> &[f64] {
        &self.radii
    }

    /// Tracks one more frame.
    pub fn push(&mut self, img: &Gray) {
        let k = self.frames.len();
        self.counts.frames += 1;
        let coarse = detect::coarse(img, self.min_radius);
        if coarse.balls.len() > 2 {
            self.counts.crowded += 1;
        }
        let noise = pixel_noise(img);
        let mut fits: Vec<Result<Outline, LeftOut>> = coarse
            .balls
            .iter()
            .take(3)
            .map(|b| self.refine(img, b.guess(), detect::factor(img.width) as f64))
            .collect();
        let merged = !coarse.pairs.is_empty() && coarse.balls.len() < 2 && self.both_seen();
        if fits.is_empty() && !merged {
            self.counts.empty += 1;
        }
        // Two outlines touching: the impact; neither is measured.
        let good: Vec<Outline> = fits.iter().filter_map(|f| f.ok()).collect();
        let touching = good.len() == 2 && {
            let (a, b) = (good[0].circle, good[1].circle);
            (a.x - b.x).hypot(a.y - b.y) < a.r + b.r + 2.0
        };
        let mut out: FrameFixes = [Err(LeftOut::Unseen), Err(LeftOut::Unseen)];
        if merged || touching {
            out = [Err(LeftOut::Merged), Err(LeftOut::Merged)];
            self.frames.push(out);
            return;
        }
        fits.truncate(2);
        for (slot, fit) in self.assign(fits) {
            out[slot] = fit.map(|o| {
                self.last[slot].push((k, o.circle));
                if self.last[slot].len() > 2 {
                    self.last[slot].remove(0);
                }
                self.radii.push(o.circle.r);
                if self.radii.len() <= 64 || self.radii.len().is_multiple_of(256) {
                    self.radius = median(&self.radii);
                }
                Fix {
                    outline: o,
                    sigma: 0.5 * (o.sigma[0] + o.sigma[1]),
                    mark: mark::find(img, &o, noise),
                }
            });
        }
        self.frames.push(out);
    }

    fn both_seen(&self) -> bool {
        self.last.iter().all(|l| !l.is_empty())
    }

    /// The outline near `guess` (from a blob reduced `factor` times), twice: in a band
    /// as wide as the coarse look's error, then narrowly about the first fit.
    fn refine(&mut self, img: &Gray, guess: Circle, factor: f64) -> Result<Outline, LeftOut> {
        let guess = self.predicted_near(guess).unwrap_or(guess);
        let band = (1.5 * factor).max(4.0);
        let first = circle::fit(img, guess, band, self.polarity).ok_or(LeftOut::Poor)?;
        let o = circle::fit(img, first.circle, 2.5, first.polarity).ok_or(LeftOut::Poor)?;
        let r_ok = self
            .radius()
            .is_none_or(|r| (o.circle.r - r).abs() < 0.15 * r);
        if o.coverage < 0.35 || o.rms > 1.0 || !r_ok {
            return Err(LeftOut::Poor);
        }
        if self.polarity == 0.0 {
            self.polarity = o.polarity;
        }
        Ok(o)
    }

    /// Where a slot's ball is expected now (moving on as between its last two fits),
    /// if that is near `guess`.
    fn predicted_near(&self, guess: Circle) -> Option<Circle> {
        let k = self.frames.len();
        self.last
            .iter()
            .filter_map(|l| predict(l, k))
            .find(|p| (p.x - guess.x).hypot(p.y - guess.y) < 0.5 * guess.r.max(p.r))
    }

    /// Which slot each fit (left to right) belongs to: the slot whose ball was last
    /// seen nearest; fits of two balls keep their left-to-right order.
    fn assign(
        &self,
        fits: Vec<Result<Outline, LeftOut>>,
    ) -> Vec<(usize, Result<Outline, LeftOut>)> {
        let k = self.frames.len();
        let pred: Vec<Option<Circle>> = self.last.iter().map(|l| predict(l, k)).collect();
        match fits.len() {
            0 => Vec::new(),
            2 => {
                // Both seen: the slots' left-to-right order, once known, is kept.
                let swapped = match (pred[0], pred[1]) {
                    (Some(a), Some(b)) => a.x > b.x,
                    _ => false,
                };
                let mut it = fits.into_iter();
                let (a, b) = (
                    it.next().unwrap_or(Err(LeftOut::Poor)),
                    it.next().unwrap_or(Err(LeftOut::Poor)),
                );
                if swapped {
                    vec![(1, a), (0, b)]
                } else {
                    vec![(0, a), (1, b)]
                }
            }
            _ => {
                let fit = fits.into_iter().next().unwrap_or(Err(LeftOut::Poor));
                let x = match &fit {
                    Ok(o) => o.circle.x,
                    Err(_) => return Vec::new(),
                };
                let slot = match (pred[0], pred[1]) {
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

/// The pixel noise of a frame, luma levels: from neighbouring pixels' differences
/// over a sparse sample (their median, so edges do not count).
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
    median(&d).map_or(1.0, |m| m * 1.4826 / std::f64::consts::SQRT_2)
}

/// The median of `v`, `None` when empty.
pub fn median(v: &[f64]) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    Some(s[s.len() / 2])
}
