//! The mark on a ball (a dot drawn on it, seen from the side circling the centre):
//! the spot inside the visible disc that stands out most from the ball's own shading
//! (each pixel against the mean of a box around it), then located to sub-pixel by the
//! centroid of its contrast against the shading fitted as a plane on a ring around it,
//! twice, the second time about the first centroid; last, measured again by a model
//! of a drawn disc over the shading (`mark_fit`) where the model fits. Its standard
//! error follows from the pixel noise through the centroid's formula.

use super::circle::{Outline, length};
use super::gray::Gray;

/// A mark found on a ball, in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mark {
    pub x: f64,
    pub y: f64,
    /// Standard error of x and of y, px.
    pub sigma: f64,
    /// Its contrast against the ball around it, luma levels (signed: − darker).
    pub contrast: f64,
}

/// The mark on the ball `ball`, given the pixel noise `noise` (luma levels); `None`
/// when no spot stands out (the mark is hidden by the rail or turned away) or it lies
/// too near the limb or the rail to be measured against the ball's shading. The mark
/// is whatever contrasts most with the ball's own surface, darker or lighter (`sign`
/// 0), or of the sign found before (−1 darker, +1 lighter: once known, a highlight
/// of the other sign is not taken for it); it must stand out by `levels.0` noise
/// scatters and `levels.1` luma levels, at least, and is located by the centroid of
/// its contrast above `levels.2` of its peak (`Params::mark_cut`), then by the disc
/// model where its edge is no softer than `levels.3` px (`Params::mark_soft`; 0:
/// the centroid always).
pub fn find(
    img: &Gray,
    ball: &Outline,
    noise: f64,
    sign: f64,
    levels: (f64, f64, f64, f64),
) -> InDisc {
    let mut spots = Vec::new();
    let mark = find_mark(img, ball, noise, sign, levels, &mut spots);
    InDisc {
        mark,
        spots: strongest_spots(spots, ball.circle.r),
    }
}

/// The spots of a disc (see [`InDisc::spots`]), at most this many: 8, so that a
/// highlight is among them in frames where the rail's edge or a compressed clip's
/// blocks give four stronger ones (with 4, the looks table's seed 9 found its
/// highlight in under 70 % of the frames, not known as fixed, and took it for the
/// mark where the drawn one was hidden: 18 and 22 px off).
pub const SPOTS: usize = 8;

/// The strongest spots of a disc, [`SPOTS`] at most, the strongest first: where
/// (x, y, px) and how much the pixel there stands out from the mean around it
/// (luma levels, signed: − darker).
pub type Spots = [Option<(f64, f64, f64)>; SPOTS];

/// What was found inside a ball's disc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InDisc {
    /// The mark (see [`find`]).
    pub mark: Option<Mark>,
    /// The strongest spots that stand out from the ball's surface, of either sign,
    /// a quarter of a radius apart at least, whichever the mark is: over the clip, a
    /// spot that stays at one place of both balls' discs in most frames is no mark
    /// (a glossy highlight, a feature of the shading; `mark_check`), and a mark
    /// found there is not taken.
    pub spots: Spots,
}

/// The strongest of `found` (contrast, x, y), a quarter of the radius `r` apart.
fn strongest_spots(mut found: Vec<(f64, isize, isize)>, r: f64) -> Spots {
    found.sort_by(|a, b| b.0.abs().total_cmp(&a.0.abs()));
    let apart = (0.25 * r).max(2.0);
    let mut out: Spots = [None; SPOTS];
    let mut n = 0;
    for (d, x, y) in found {
        let (x, y) = (x as f64, y as f64);
        if out
            .iter()
            .flatten()
            .any(|s| (s.0 - x).hypot(s.1 - y) < apart)
        {
            continue;
        }
        if let Some(slot) = out.get_mut(n) {
            *slot = Some((x, y, d));
            n += 1;
        } else {
            break;
        }
    }
    out
}

/// The mark (see [`find`]); every pixel standing out by the threshold is added to
/// `spots` (contrast, x, y).
fn find_mark(
    img: &Gray,
    ball: &Outline,
    noise: f64,
    sign: f64,
    levels: (f64, f64, f64, f64),
    spots: &mut Vec<(f64, isize, isize)>,
) -> Option<Mark> {
    let least = (levels.0 * noise).max(levels.1);
    let cut = levels.2;
    let c = ball.circle;
    // The search region: inside the limb, above the rail.
    let inner = c.r - (0.1 * c.r).max(3.0);
    let bottom = ball.lowest - 1.0;
    let half = ((0.12 * c.r).round() as isize).max(2);
    let x0 = ((c.x - inner).floor() as isize).max(half);
    let x1 = ((c.x + inner).ceil() as isize).min(img.width as isize - 1 - half);
    let y0 = ((c.y - inner).floor() as isize).max(half);
    let y1 = ((c.y + inner).ceil() as isize)
        .min(bottom.floor() as isize)
        .min(img.height as isize - 1 - half);
    if x1 <= x0 || y1 <= y0 {
        return None;
    }
    let sums = Integral::new(img, x0 - half, y0 - half, x1 + half, y1 + half);
    let mut best = (0.0f64, 0isize, 0isize);
    for y in y0..=y1 {
        for x in x0..=x1 {
            if length(x as f64 - c.x, y as f64 - c.y) > inner - 1.5 * half as f64
                || (y + half) as f64 >= bottom
            {
                continue;
            }
            let mean = sums.mean(x - half, y - half, x + half, y + half);
            let d = f64::from(img.at(x as usize, y as usize)) - mean;
            if d.abs() >= least {
                spots.push((d, x, y));
            }
            let better = if sign == 0.0 {
                d.abs() > best.0.abs()
            } else {
                sign * d > sign * best.0
            };
            if better {
                best = (d, x, y);
            }
        }
    }
    let (peak, px, py) = best;
    if peak.abs() < least || (sign != 0.0 && peak * sign <= 0.0) {
        return None;
    }
    // The spot's radius, at least 1.2 times the box's half-width: a mark larger
    // than the box stands out from the box's mean only about its rim (inside it the
    // box holds the mark alone), so its peak is found at its rim, and its size from
    // the pixels over half the peak is that rim's; a centroid over so small a disc,
    // with the shading's ring on the mark itself, stayed near the rim (3–6 px off on
    // marks of 0.2 R).
    let size = spot_radius(img, px, py, peak, half, &sums).max(1.2 * half as f64);
    // The spot (its centroid's disc) must lie on the ball, above the rail; the ring
    // the shading is fitted on is the part of it on the ball, above the rail. (A ring
    // wholly on the ball was asked before: a mark near the limb was then found only
    // where its centroid fell short of it, toward the centre: 3–5 px on looks with the
    // mark at 0.6–0.7 R.)
    let spot = rings(size).0;
    let on_ball = Surface {
        x: c.x,
        y: c.y,
        inside: c.r - 1.0,
        bottom,
    };
    let fits =
        |x: f64, y: f64| length(x - c.x, y - c.y) + spot < on_ball.inside && y + spot < bottom;
    let mut at = (px as f64, py as f64);
    let mut out = None;
    for _ in 0..6 {
        if !fits(at.0, at.1) {
            return None;
        }
        let m = centroid(img, at, size, peak.signum(), noise, &on_ball, cut)?;
        let moved = (m.x - at.0).hypot(m.y - at.1);
        at = (m.x, m.y);
        out = Some(m);
        if moved < 0.05 {
            break;
        }
    }
    let found = out.filter(|m| fits(m.x, m.y))?;
    Some(refined(img, found, size, peak.signum(), &on_ball, levels.3))
}

/// The mark `m` (its centroid, of a spot of radius `size`, px, and sign `sign`)
/// measured again by the disc model ([`super::mark_fit`]) over the centroid's ring
/// (2.2 spot radii + 1.5 px), on the ball above the rail; the model's place is
/// taken where its edge is no softer than `soft` px, it moved by under the spot's
/// radius, its radius is a pixel or more and its level stands out from the
/// shading with the mark's sign. Else the centroid stays.
fn refined(img: &Gray, m: Mark, size: f64, sign: f64, ball: &Surface, soft: f64) -> Mark {
    let at = (m.x, m.y);
    let (inner, ring0, ring1) = rings(size);
    let Some(plane) = ring_plane(img, at, (ring0, ring1), ball) else {
        return m;
    };
    let Some(level) = mark_level(img, at, inner, sign) else {
        return m;
    };
    let start = super::mark_fit::Start {
        at,
        radius: size,
        level,
        plane: (plane.x, plane.y, plane.z),
    };
    let Some(d) = super::mark_fit::fit(img, start, ring1, |x, y| ball.holds(x, y)) else {
        return m;
    };
    let moved = (d.x - m.x).hypot(d.y - m.y);
    let kept = d.soft <= soft
        && moved <= size
        && (1.0..=2.0 * ring1).contains(&d.radius)
        && sign * (d.level - d.shade) > 0.0;
    if kept {
        Mark {
            x: d.x,
            y: d.y,
            ..m
        }
    } else {
        m
    }
}

/// The mark's level to start its model from: of the pixels within `inner` px of
/// `at`, the tenth darkest (a dark mark, `sign` −1) or lightest (+1): most of the
/// disc is the mark, and a tenth in leaves its darkest noise out.
fn mark_level(img: &Gray, at: (f64, f64), inner: f64, sign: f64) -> Option<f64> {
    let mut v: Vec<f32> = Vec::new();
    let (x0, y0) = (
        (at.0 - inner).floor() as isize,
        (at.1 - inner).floor() as isize,
    );
    let (x1, y1) = (
        (at.0 + inner).floor() as isize + 1,
        (at.1 + inner).floor() as isize + 1,
    );
    for y in y0.max(0)..=y1.min(img.height as isize - 1) {
        for x in x0.max(0)..=x1.min(img.width as isize - 1) {
            if length(x as f64 - at.0, y as f64 - at.1) <= inner {
                v.push(img.at(x as usize, y as usize));
            }
        }
    }
    v.sort_unstable_by(f32::total_cmp);
    let n = v.len();
    let i = if sign < 0.0 {
        n / 10
    } else {
        n.checked_sub(1 + n / 10)?
    };
    v.get(i).map(|&l| f64::from(l))
}

/// Where the ball's own surface is seen: within `inside` px of its centre, above the
/// rail's edge `bottom`.
struct Surface {
    x: f64,
    y: f64,
    inside: f64,
    bottom: f64,
}

impl Surface {
    fn holds(&self, x: f64, y: f64) -> bool {
        length(x - self.x, y - self.y) < self.inside && y < self.bottom
    }
}

/// The spot's radius, px: from the pixels beyond half its peak contrast near it.
fn spot_radius(img: &Gray, px: isize, py: isize, peak: f64, half: isize, sums: &Integral) -> f64 {
    let mut n = 0usize;
    for y in (py - 2 * half)..=(py + 2 * half) {
        for x in (px - 2 * half)..=(px + 2 * half) {
            if !sums.inside(x - half, y - half, x + half, y + half) {
                continue;
            }
            let d = f64::from(img.at(x as usize, y as usize))
                - sums.mean(x - half, y - half, x + half, y + half);
            if d * peak.signum() > 0.5 * peak.abs() {
                n += 1;
            }
        }
    }
    ((n as f64 / std::f64::consts::PI).sqrt()).max(1.0)
}

/// The centroid of the spot's contrast around `at`: the shading fitted as a plane
/// to the ring from 1.6 to 2.2 spot radii (+ 1 px), the weights the contrast against
/// it within 1.4 radii (+ 1 px), signed by `sign`.
#[allow(clippy::indexing_slicing)] // the plane's three coefficients
fn centroid(
    img: &Gray,
    at: (f64, f64),
    size: f64,
    sign: f64,
    noise: f64,
    ball: &Surface,
    cut: f64,
) -> Option<Mark> {
    let (inner, ring0, ring1) = rings(size);
    let reach = ring1.ceil() as isize;
    let (cx, cy) = in_frame(img, at, reach)?;
    let plane = ring_plane(img, at, (ring0, ring1), ball)?;
    // Each pixel of the spot's disc and its contrast against the shading.
    let mut px: Vec<(f64, f64, f64)> = Vec::new();
    for y in (cy - reach)..=(cy + reach) {
        for x in (cx - reach)..=(cx + reach) {
            let (dx, dy) = (x as f64 - at.0, y as f64 - at.1);
            if length(dx, dy) > inner {
                continue;
            }
            let shade = plane[0] + plane[1] * dx + plane[2] * dy;
            let w = sign * (f64::from(img.at(x as usize, y as usize)) - shade);
            px.push((x as f64, y as f64, w));
        }
    }
    let total: f64 = px.iter().map(|p| p.2).sum();
    // The centroid of the contrast above `cut` of its peak, less that: the plane
    // misses the shading's curvature (darker toward the limb, a light spot beside
    // the mark) by a few levels over the disc, which, summed over its many pixels,
    // pulled the centroid of all the contrast toward the ball's centre by up to 5
    // px on marks near the limb; the mark stands out by tens of levels.
    let peak = px.iter().map(|p| p.2).fold(0.0, f64::max);
    let floor = cut * peak;
    let (mut sw, mut sx, mut sy) = (0.0, 0.0, 0.0);
    for &(x, y, w) in &px {
        let w = (w - floor).max(0.0);
        sw += w;
        sx += w * x;
        sy += w * y;
    }
    if sw <= 0.0 || total <= 0.0 {
        return None;
    }
    let (mx, my) = (sx / sw, sy / sw);
    let spread: f64 = px
        .iter()
        .filter(|p| p.2 > floor)
        .map(|(x, y, _)| 0.5 * ((x - mx).powi(2) + (y - my).powi(2)))
        .sum();
    Some(Mark {
        x: mx,
        y: my,
        sigma: noise.max(0.5) * spread.sqrt() / sw,
        contrast: sign * total / (std::f64::consts::PI * size * size),
    })
}

/// The centroid's disc and the shading's ring about a spot of radius `size`, px:
/// the disc within 1.4 spot radii (+ 1 px), the ring from 1.6 to 2.2 (+ 1, + 1.5 px).
fn rings(size: f64) -> (f64, f64, f64) {
    (1.4 * size + 1.0, 1.6 * size + 1.0, 2.2 * size + 1.5)
}

/// The pixel nearest `at` when the square `reach` px about it lies in the frame.
fn in_frame(img: &Gray, at: (f64, f64), reach: isize) -> Option<(isize, isize)> {
    let (cx, cy) = (at.0.round() as isize, at.1.round() as isize);
    let inside = cx - reach >= 0
        && cy - reach >= 0
        && cx + reach < img.width as isize
        && cy + reach < img.height as isize;
    inside.then_some((cx, cy))
}

/// The ball's shading about `at` as a plane (level at `at`, slopes along x and y),
/// fitted to the ring `ring.0 ..= ring.1` px about it, its part on the ball only;
/// `None` with under half the ring there (the plane is held on both sides of the
/// spot) or none inside the frame.
fn ring_plane(
    img: &Gray,
    at: (f64, f64),
    ring: (f64, f64),
    ball: &Surface,
) -> Option<nalgebra::Vector3<f64>> {
    let reach = ring.1.ceil() as isize;
    let (cx, cy) = in_frame(img, at, reach)?;
    let mut ata = nalgebra::Matrix3::<f64>::zeros();
    let mut atb = nalgebra::Vector3::<f64>::zeros();
    let (mut all, mut kept) = (0usize, 0usize);
    for y in (cy - reach)..=(cy + reach) {
        for x in (cx - reach)..=(cx + reach) {
            let (dx, dy) = (x as f64 - at.0, y as f64 - at.1);
            if (ring.0..=ring.1).contains(&length(dx, dy)) {
                all += 1;
                // Only the ring's part on the ball: the wall and the rail beyond
                // its limb are no part of its shading.
                if !ball.holds(x as f64, y as f64) {
                    continue;
                }
                kept += 1;
                let b = nalgebra::Vector3::new(1.0, dx, dy);
                ata += b * b.transpose();
                atb += b * f64::from(img.at(x as usize, y as usize));
            }
        }
    }
    if 2 * kept < all {
        return None;
    }
    Some(ata.try_inverse()? * atb)
}

/// Sums of a box of the frame for box means in O(1).
struct Integral {
    x0: isize,
    y0: isize,
    w: usize,
    h: usize,
    sum: Vec<f64>,
}

impl Integral {
    /// Over columns `x0..=x1`, rows `y0..=y1` (clipped to the frame).
    #[allow(clippy::indexing_slicing)] // the box is clipped to the frame; the sums are (w + 1) × (h + 1)
    fn new(img: &Gray, x0: isize, y0: isize, x1: isize, y1: isize) -> Integral {
        let x0 = x0.max(0);
        let y0 = y0.max(0);
        let x1 = x1.min(img.width as isize - 1);
        let y1 = y1.min(img.height as isize - 1);
        let (w, h) = ((x1 - x0 + 1).max(0) as usize, (y1 - y0 + 1).max(0) as usize);
        let mut sum = vec![0.0; (w + 1) * (h + 1)];
        for y in 0..h {
            let mut row = 0.0;
            for x in 0..w {
                row += f64::from(img.at(x0 as usize + x, y0 as usize + y));
                sum[(y + 1) * (w + 1) + x + 1] = sum[y * (w + 1) + x + 1] + row;
            }
        }
        Integral { x0, y0, w, h, sum }
    }

    fn inside(&self, x0: isize, y0: isize, x1: isize, y1: isize) -> bool {
        x0 >= self.x0
            && y0 >= self.y0
            && x1 < self.x0 + self.w as isize
            && y1 < self.y0 + self.h as isize
    }

    /// The mean over columns `x0..=x1`, rows `y0..=y1`, clipped to the box.
    #[allow(clippy::indexing_slicing)] // corners clamped to the sums' size
    fn mean(&self, x0: isize, y0: isize, x1: isize, y1: isize) -> f64 {
        let cx = |x: isize| ((x - self.x0).clamp(0, self.w as isize)) as usize;
        let cy = |y: isize| ((y - self.y0).clamp(0, self.h as isize)) as usize;
        let (a, b) = (cx(x0), cx(x1 + 1));
        let (c, d) = (cy(y0), cy(y1 + 1));
        let n = ((b - a) * (d - c)).max(1) as f64;
        let s = |x: usize, y: usize| self.sum[y * (self.w + 1) + x];
        (s(b, d) - s(a, d) - s(b, c) + s(a, c)) / n
    }
}

/// A mark found before the marks' sign is settled: a vote for its sign.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vote {
    /// The ball's slot (0 the left ball).
    pub slot: usize,
    /// The ball's centre's x, its radius and kR (px: it rolls on the rails' edges,
    /// kR below its centre).
    pub x: f64,
    pub r: f64,
    pub kr: f64,
    /// The mark's place in the disc, radii from the centre.
    pub at: (f64, f64),
    /// −1 darker than the ball, +1 lighter.
    pub sign: f64,
}

/// A vote stays put when, against another vote of its ball and sign, its place in
/// the disc moved by under half what a drawn mark's would have turning with the
/// ball, where that is this many radii at least (to tell from the centres' errors,
/// a pixel or two on a 15 px radius).
const STAY_LEAST: f64 = 0.25;

/// The sign the marks of `votes` have, the votes of spots that stayed put in their
/// disc while the ball rolled left out (a glossy highlight, which the light keeps at
/// one place: small look 27, a steel ball with a dark mark, had its highlight as most
/// of its first marks and took it for the mark in every frame after, 5–17 px off);
/// of all the votes when every one stayed. −1 darker (also on a tie), +1 lighter.
pub fn settled_sign(votes: &[Vote]) -> f64 {
    let count = |all: bool| {
        let kept = (0..votes.len()).filter(|&i| all || !stays(votes, i));
        let signs: Vec<f64> = kept.filter_map(|i| votes.get(i).map(|v| v.sign)).collect();
        let dark = signs.iter().filter(|s| **s < 0.0).count();
        (dark, signs.len() - dark)
    };
    let (dark, light) = match count(false) {
        (0, 0) => count(true),
        some => some,
    };
    if dark >= light { -1.0 } else { 1.0 }
}

/// True when vote `i` stayed at its place of the disc, against another vote of its
/// ball and sign, while the ball rolled: a drawn mark ρ radii from the centre moves
/// by 2ρ sin(θ/2) in the disc as the ball turns by θ, θ at least the ball's move
/// over its radius (kR ≤ R), and under half a turn (its move over kR) it cannot
/// have come back round.
fn stays(votes: &[Vote], i: usize) -> bool {
    let Some(a) = votes.get(i) else { return false };
    votes.iter().enumerate().any(|(j, b)| {
        if j == i || b.slot != a.slot || b.sign != a.sign {
            return false;
        }
        let moved = (b.x - a.x).abs();
        if moved / a.kr.max(1.0) >= std::f64::consts::PI {
            return false;
        }
        let turn = moved / a.r.max(1.0);
        let rho = 0.5 * (a.at.0.hypot(a.at.1) + b.at.0.hypot(b.at.1));
        let expected = 2.0 * rho * (0.5 * turn).sin();
        let d = (a.at.0 - b.at.0).hypot(a.at.1 - b.at.1);
        expected >= STAY_LEAST && d < 0.5 * expected
    })
}
