//! A ball's outline to sub-pixel accuracy: edge points where the luma gradient peaks
//! across the expected circle (Sobel gradient, its maximum along the gradient's axis
//! refined by a parabola through three pixels, as Devernay's sub-pixel Canny does),
//! only points whose gradient points along the radius (the near rail's straight top
//! edge does not) and of the ball's polarity; then a circle fitted to them by least
//! squares of the geometric distance, outliers left out in rounds. The near rail
//! hides the ball's lower part, so the points cover an arc, not the whole circle.

use super::frame::Frame;
use super::gray::{Gray, sobel_sums};

/// A circle in pixels (x right, y down).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    pub x: f64,
    pub y: f64,
    pub r: f64,
}

/// A circle fitted to a ball's visible edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outline {
    pub circle: Circle,
    /// Standard errors of the centre's x and y and of the radius, px.
    pub sigma: [f64; 3],
    /// The covariance of (x, y, r), px²: on an arc the three are far from
    /// independent (a centre set lower asks for a larger radius, and one moved
    /// along a lopsided arc for both), which a centre moved onto its ball's line
    /// follows (`tracks`). Zeros where unknown.
    pub covariance: [[f64; 3]; 3],
    /// Root mean square distance of the kept edge points from the circle, px.
    pub rms: f64,
    /// Edge points kept.
    pub points: usize,
    /// Which of the circle's 36 sectors of 10° hold kept points: bit `i` for the
    /// angles `10 i … 10 (i + 1)`° from the right, clockwise in the picture (y down:
    /// sector 9 is straight down).
    pub sectors: u64,
    /// The lowest kept edge point, px, or where a known rail edge crosses below the
    /// circle's centre when the fit left that edge out (`fit`): the ball is hidden
    /// below it (the rail).
    pub lowest: f64,
    /// +1 when the ball is brighter than its surroundings, −1 when darker.
    pub polarity: f64,
}

#[cfg(test)]
impl Outline {
    /// For tests: a clear outline of the circle at `(x, y)` of radius `r` in a
    /// ball brighter than the wall, its upper half's edge (sectors 18–35: the rail
    /// hides the rest), 60 points 0.2 px off it, the rail's edge 0.3 radii below
    /// the centre.
    pub fn upper_half(x: f64, y: f64, r: f64) -> Outline {
        Outline {
            circle: Circle { x, y, r },
            sigma: [0.1; 3],
            covariance: [[0.0; 3]; 3],
            rms: 0.2,
            points: 60,
            sectors: 0xF_FFFC_0000,
            lowest: y + 0.3 * r,
            polarity: 1.0,
        }
    }
}

impl Outline {
    /// Share of the circle's 36 sectors of 10° holding kept points (0 … 1).
    pub fn coverage(&self) -> f64 {
        f64::from(self.sectors.count_ones()) / 36.0
    }

    /// kR, px (at least 1): how far below its centre the ball rolls on the rails'
    /// edges, the rail's top edge being the outline's lowest point (k clamped to
    /// 0.2 … 1); rolling by Δx turns it by Δx / (kR).
    pub fn rolling_radius(&self) -> f64 {
        let c = self.circle;
        (c.r * ((self.lowest - c.y) / c.r.max(1.0)).clamp(0.2, 1.0)).max(1.0)
    }

    /// Whether the outline is one a ball behind a rail shows: its bottom hidden, or
    /// shown with a side. Edge points within `within` degrees of straight down and
    /// none within it of level on either side are not a ball's (a rail hides a
    /// ball from below, so what shows its bottom shows its sides): they are two
    /// level edges taken for the top and bottom of a circle (a shadow's, or a
    /// compression block's, along the rail's lower edge: small looks table seed
    /// 28). `within` 0: every outline is.
    pub fn seen_over_a_rail(&self, within: f64) -> bool {
        // The sectors (10° each, from the right, clockwise in the picture) that
        // reach within `within` of the angle `at`, degrees.
        let near = |at: f64| {
            let (from, to) = (
                ((at - within) / 10.0).floor(),
                ((at + within) / 10.0).ceil(),
            );
            (from as i64..to as i64).any(|i| self.sectors & (1 << i.rem_euclid(36)) != 0)
        };
        within <= 0.0 || !near(90.0) || near(0.0) || near(180.0)
    }

    /// The point `(x, y)` (px) as a place in the ball's disc, in radii from its
    /// centre: the same place of the disc whatever the ball's size in the frame.
    pub fn in_disc(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let c = self.circle;
        let r = c.r.max(1.0);
        ((x - c.x) / r, (y - c.y) / r)
    }
}

/// The polarity that keeps edge points of both signs: a ball on a wall of its own
/// brightness (stripes, squares, grain) is brighter than some of it and darker
/// than the rest.
pub const EITHER: f64 = 2.0;

/// Fits the outline of the ball near `guess`, searching `band` px either side of it;
/// `polarity` the ball's (+1 brighter, −1 darker than around it), 0 to take the
/// sign most edge points have, or [`EITHER`] to take both. `None` when too few edge
/// points are found.
///
/// `rails`: the near rail's edges known to hide this ball (`rail::edges`, judged
/// by `Tracker::rails_hiding`): where the highest of them crosses the fitted circle
/// (`rail_under`: from a quarter radius above its centre to just below its bottom),
/// the points on or below it are the rail's and the circle is fitted again without
/// them, taken where the rest lie on their circle at least twice as closely, the
/// radius moves by more than `rail_moves` of it and at most doubles. `rail_moves`
/// infinite: neither that nor the straight edge sought under each fit.
pub fn fit(
    img: &Gray,
    guess: Circle,
    band: f64,
    polarity: f64,
    rail_moves: f64,
    rails: &[StraightEdge],
) -> Option<Outline> {
    fit_keeping(img, guess, band, polarity, (rail_moves, rails), NO_SHADOW)
}

/// Which edge points are a ball's own (the rest its cast shadow's edge, by their
/// inside) and how far outside the ball's circle those must lie to be left out, px.
pub type Shadow<'a> = (&'a dyn Fn([f64; 2]) -> bool, f64);

/// No cast shadow sought: every edge point is the ball's own.
pub const NO_SHADOW: Shadow<'static> = (&|_| true, 0.0);

/// As [`fit`], the edge points `keep` does not keep (a point, px: a cast shadow's
/// edge, by its inside) left out where the rest lie on their circle at least
/// twice as closely as all did on theirs (`RAIL_RMS_DROP`: a shadow's edge and
/// the ball's fit no circle together) and the points left out lie outside it by
/// more than `outside` px (median, `Params::shadow_outside`): a ball's shadow
/// peeks out beside it.
/// Otherwise all are fitted: points on that circle, or a clean fit of all, are the
/// ball's own edge (a grey ball's shaded limb on a grey wall reads as the wall in
/// shadow: small look 38's white balls, 12 px fits of 0.2 px RMS, went to 10.5 px
/// without the first test).
pub fn fit_keeping(
    img: &Gray,
    guess: Circle,
    band: f64,
    polarity: f64,
    (rail_moves, rails): (f64, &[StraightEdge]),
    (keep, outside): Shadow,
) -> Option<Outline> {
    let (mut points, sign) = edge_points(img, guess, band, polarity)?;
    let mut o = fit_points(points.clone(), guess, band, sign)?;
    let (own, shadow): (Vec<[f64; 2]>, Vec<[f64; 2]>) = points.iter().partition(|p| keep(**p));
    if !shadow.is_empty()
        && let Some(q) = fit_points(own.clone(), guess, band, sign)
        && q.rms <= RAIL_RMS_DROP * o.rms
        && middle(
            shadow
                .iter()
                .map(|p| dist(p, &q.circle) - q.circle.r)
                .collect(),
        )
        .is_some_and(|out| out > outside)
    {
        (points, o) = (own, q);
    }
    if rail_moves.is_finite()
        && let Some(line) = rail_under(rails, &o.circle)
    {
        let above: Vec<[f64; 2]> = points
            .iter()
            .filter(|p| p[1] < line.at(p[0]) - RAIL_CLEARANCE)
            .copied()
            .collect();
        // Taken where the points left lie on their circle far closer than all did
        // on theirs (`RAIL_RMS_DROP`: an arc and a straight edge fit no circle
        // together; where the points dropped were the wall's, or the ball's edge
        // is lost in it, the rest fits little better) and, as for the edge sought
        // under each fit, the radius moves by more than `rail_moves` of it. The
        // ball is hidden from the rail's edge down: its outline's lowest point is
        // there, not the clearance above it (the rolling radius).
        if let Some(mut q) = fit_points(above.clone(), guess, band, sign)
            && q.rms <= RAIL_RMS_DROP * o.rms
            && (q.circle.r - o.circle.r).abs() > rail_moves * o.circle.r
            && q.circle.r <= 2.0 * o.circle.r
        {
            q.lowest = q
                .lowest
                .max(line.at(q.circle.x))
                .min(q.circle.y + q.circle.r);
            (points, o) = (above, q);
        }
    }
    // A circle closed by a straight edge (the rail's) is not the ball's: what lies
    // on or below that edge is the rail, so it goes and the rest is fitted again
    // (twice at most: a rail's lower edge, then its top edge), where that moves
    // the radius by more than `rail_moves` of it (`Params::rail_moves`: the circle
    // was the rail's doing; a smaller change is the edge's own scatter, and the fit
    // with more points is kept).
    for _ in 0..2 {
        let Some(line) = straight_edge_below(img, &o, &points) else {
            break;
        };
        points.retain(|p| p[1] < line.at(p[0]) - RAIL_CLEARANCE);
        let Some(q) = fit_points(points.clone(), guess, band, sign) else {
            break;
        };
        if (q.circle.r - o.circle.r).abs() <= rail_moves * o.circle.r {
            break;
        }
        o = q;
    }
    Some(o)
}

/// How far above a straight edge under a ball its outline's points must lie to be
/// the ball's, px: the edge's own blur (a Sobel peak a pixel wide) and a pixel.
const RAIL_CLEARANCE: f64 = 1.5;

/// How much closer to their circle the points above a known rail edge must lie
/// than all did on theirs, RMS, for the rail to have been in the fit: the small
/// looks' seed 87 drawn sharp, 1.2–1.4 px with the rail's lower edge, 0.03–0.05
/// without; fits whose dropped points were the wall's, 0.7–1 of it.
const RAIL_RMS_DROP: f64 = 0.5;

/// A straight edge in the picture, y = y0 + slope (x − x0), px.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StraightEdge {
    pub x0: f64,
    pub y0: f64,
    pub slope: f64,
}

impl StraightEdge {
    /// The edge's y at `x`.
    pub fn at(&self, x: f64) -> f64 {
        self.y0 + self.slope * (x - self.x0)
    }

    /// The line through `points` (least squares in y; level where they share one
    /// x), `None` without points.
    pub fn through(points: &[[f64; 2]]) -> Option<StraightEdge> {
        if points.is_empty() {
            return None;
        }
        let n = points.len() as f64;
        let x0 = points.iter().map(|p| p[0]).sum::<f64>() / n;
        let y0 = points.iter().map(|p| p[1]).sum::<f64>() / n;
        let sxx: f64 = points.iter().map(|p| (p[0] - x0).powi(2)).sum();
        let sxy: f64 = points.iter().map(|p| (p[0] - x0) * (p[1] - y0)).sum();
        let slope = if sxx > 1e-9 { sxy / sxx } else { 0.0 };
        Some(StraightEdge { x0, y0, slope })
    }
}

/// The highest of `rails` that crosses the circle `c` below a quarter radius above
/// its centre and above its bottom (2.5 px below it at most): a rail's top edge
/// over the ball's lower part, or a circle closed by it (its centre then lies low).
pub fn rail_under(rails: &[StraightEdge], c: &Circle) -> Option<StraightEdge> {
    rails
        .iter()
        .filter(|l| (c.y - 0.25 * c.r..=c.y + c.r + 2.5).contains(&l.at(c.x)))
        .min_by(|a, b| a.at(c.x).total_cmp(&b.at(c.x)))
        .copied()
}

/// The straight edge across the lower half of the outline `o` (its edge points
/// `points`), when one runs on past the circle on both sides: a near
/// rail's top or lower edge, which closes a ball's visible cap into a smaller
/// circle or takes the rail into a larger one. The edge points below the centre
/// and within a radius of it across, in the two rows holding most of them (five
/// at least), give the line; it must run through the circle's lower half or just
/// below it, and beside the circle (from 1.1 r + 1 px out, for 0.6 r each side) the
/// luma must step across it, with those points' sign and at least half their
/// step, in 80 % of the columns each side. A ball's own bottom curves away beside
/// it, so only an edge straight there passes.
fn straight_edge_below(img: &Gray, o: &Outline, points: &[[f64; 2]]) -> Option<StraightEdge> {
    let c = o.circle;
    let lower: Vec<[f64; 2]> = points
        .iter()
        .filter(|p| p[1] > c.y && (p[0] - c.x).abs() < c.r && p[1] < c.y + c.r + 2.5)
        .copied()
        .collect();
    // The two rows (from one point's row on) holding most of them.
    let row = lower
        .iter()
        .map(|p| {
            (
                p[1],
                lower.iter().filter(|q| (q[1] - p[1]).abs() <= 1.0).count(),
            )
        })
        .max_by(|a, b| a.1.cmp(&b.1).then(b.0.total_cmp(&a.0)))?;
    let on_row: Vec<[f64; 2]> = lower
        .iter()
        .filter(|q| (q[1] - row.0).abs() <= 1.0)
        .copied()
        .collect();
    if on_row.len() < 5 {
        return None;
    }
    let line = StraightEdge::through(&on_row)?;
    if line.slope.abs() > 0.2 || !(c.y..=c.y + c.r + 2.5).contains(&line.at(c.x)) {
        return None;
    }
    let step = |x: f64, y: f64| Some(bilinear(img, x, y + 1.0)? - bilinear(img, x, y - 1.0)?);
    let steps: Vec<f64> = on_row.iter().filter_map(|p| step(p[0], p[1])).collect();
    let sign = steps.iter().sum::<f64>().signum();
    let least = 0.5 * middle(steps.iter().map(|s| s.abs()).collect())?;
    if least <= 0.0 {
        return None;
    }
    let columns = (0.6 * c.r).round().max(4.0) as usize;
    let runs_on = |side: f64| {
        let found = (0..columns)
            .filter(|&k| {
                let x = c.x + side * (1.1 * c.r + 1.0 + k as f64);
                (-3..=3).any(|t| {
                    step(x, line.at(x) + 0.5 * f64::from(t)).is_some_and(|s| sign * s >= least)
                })
            })
            .count();
        found as f64 >= 0.8 * columns as f64
    };
    (runs_on(-1.0) && runs_on(1.0)).then_some(line)
}

/// The circle through `points` (least squares of the geometric distance from
/// `start`, outliers beyond `band` and then beyond 3 robust scatters left out in
/// rounds), described with the polarity `sign`; `None` with fewer than 12 points.
#[allow(clippy::indexing_slicing)] // the median of a non-empty list (at least 12 points, checked above)
pub(crate) fn fit_points(
    points: Vec<[f64; 2]>,
    start: Circle,
    band: f64,
    sign: f64,
) -> Option<Outline> {
    let mut keep: Vec<[f64; 2]> = points;
    let mut c = start;
    let mut cut = band.max(1.0);
    for round in 0..6 {
        if keep.len() < 12 {
            return None;
        }
        c = geometric(&keep, c)?;
        let d: Vec<f64> = keep.iter().map(|p| dist(p, &c) - c.r).collect();
        let mut abs: Vec<f64> = d.iter().map(|v| v.abs()).collect();
        // The middle by selection: the value a sort puts there.
        let mid = abs.len() / 2;
        let mad = *abs.select_nth_unstable_by(mid, f64::total_cmp).1 * 1.4826;
        let next = (3.0 * mad).max(0.25).min(cut);
        let before = keep.len();
        keep = keep
            .into_iter()
            .zip(&d)
            .filter(|(_, v)| v.abs() <= next)
            .map(|(p, _)| p)
            .collect();
        if round > 1 && keep.len() == before && next >= cut * 0.99 {
            break;
        }
        cut = next;
    }
    if keep.len() < 12 {
        return None;
    }
    let c = geometric(&keep, c)?;
    Some(describe(&keep, c, sign))
}

/// The outline's numbers from the kept `points` and their circle `c`.
#[allow(clippy::indexing_slicing)] // fixed 3×3 sums over 0..3
fn describe(points: &[[f64; 2]], c: Circle, polarity: f64) -> Outline {
    let n = points.len() as f64;
    let res2: f64 = points.iter().map(|p| (dist(p, &c) - c.r).powi(2)).sum();
    let rms = (res2 / n).sqrt();
    // Covariance of (x, y, r): σ² (JᵀJ)⁻¹, J's rows (−cos, −sin, −1).
    let mut a = [[0.0f64; 3]; 3];
    let mut sectors = 0u64;
    let mut lowest = f64::NEG_INFINITY;
    for p in points {
        let (dx, dy) = (p[0] - c.x, p[1] - c.y);
        let rho = length(dx, dy).max(1e-9);
        let j = [dx / rho, dy / rho, 1.0];
        for i in 0..3 {
            for k in 0..3 {
                a[i][k] += j[i] * j[k];
            }
        }
        let a = dy.atan2(dx).rem_euclid(std::f64::consts::TAU);
        sectors |= 1 << ((a / std::f64::consts::TAU * 36.0) as u32).min(35);
        lowest = lowest.max(p[1]);
    }
    let s2 = res2 / (n - 3.0).max(1.0);
    let jtj = nalgebra::Matrix3::from_fn(|i, k| a[i][k]);
    let cov = jtj.try_inverse().unwrap_or_else(nalgebra::Matrix3::zeros) * s2;
    Outline {
        circle: c,
        sigma: [cov[(0, 0)].sqrt(), cov[(1, 1)].sqrt(), cov[(2, 2)].sqrt()],
        covariance: std::array::from_fn(|i| std::array::from_fn(|k| cov[(i, k)])),
        rms,
        points: points.len(),
        sectors,
        lowest,
        polarity,
    }
}

fn dist(p: &[f64; 2], c: &Circle) -> f64 {
    length(p[0] - c.x, p[1] - c.y)
}

/// The length of (dx, dy) in pixels: a plain square root, as pixel offsets neither
/// overflow nor underflow (`f64::hypot` guards against both, at several times the
/// cost, in the fit's innermost loops and the mark's per-pixel ones).
#[inline]
pub(crate) fn length(dx: f64, dy: f64) -> f64 {
    (dx * dx + dy * dy).sqrt()
}

/// Gauss–Newton on the geometric distances from `start`; `None` if it diverges.
#[allow(clippy::indexing_slicing)] // fixed 3×3 sums over 0..3
fn geometric(points: &[[f64; 2]], start: Circle) -> Option<Circle> {
    let mut c = start;
    for _ in 0..20 {
        let (mut a, mut g) = ([[0.0f64; 3]; 3], [0.0f64; 3]);
        for p in points {
            let (dx, dy) = (p[0] - c.x, p[1] - c.y);
            let rho = length(dx, dy).max(1e-9);
            let res = rho - c.r;
            let j = [-dx / rho, -dy / rho, -1.0];
            for i in 0..3 {
                for k in 0..3 {
                    a[i][k] += j[i] * j[k];
                }
                g[i] += j[i] * res;
            }
        }
        let jtj = nalgebra::Matrix3::from_fn(|i, k| a[i][k]);
        let jtr = nalgebra::Vector3::from_row_slice(&g);
        let step = jtj.try_inverse()? * jtr;
        c = Circle {
            x: c.x - step[0],
            y: c.y - step[1],
            r: c.r - step[2],
        };
        if !(c.x.is_finite() && c.y.is_finite() && c.r > 1.0) {
            return None;
        }
        if step.norm() < 1e-6 {
            break;
        }
    }
    Some(c)
}

/// The columns of row `dy` px below a circle's centre at `cx` that can lie between
/// the squared radii `lo2` and `hi2` of it, within `from..=to`: one or two runs
/// (an empty run is `(1, 0)`), a pixel wider than the ring each way, so that every
/// pixel of the ring is in them (each is still tested: the runs only spare the
/// test of the box's pixels far from the ring, inside it above all, the larger part
/// of a large ball's box).
fn ring_columns(
    cx: f64,
    dy: f64,
    (lo2, hi2): (f64, f64),
    (from, to): (isize, isize),
) -> [(isize, isize); 2] {
    const NONE: (isize, isize) = (1, 0);
    let rest = hi2 - dy * dy;
    if rest.is_nan() || rest < 0.0 {
        return [NONE, NONE];
    }
    let outer = rest.sqrt() + 1.0;
    let inside = lo2 - dy * dy;
    let inner = if inside > 0.0 {
        (inside.sqrt() - 1.0).max(0.0)
    } else {
        0.0
    };
    let (a, d) = (
        ((cx - outer).floor() as isize).max(from),
        ((cx + outer).ceil() as isize).min(to),
    );
    let (b, c) = (
        ((cx - inner).ceil() as isize).min(to),
        ((cx + inner).floor() as isize).max(from),
    );
    if b >= c {
        [(a, d), NONE]
    } else {
        [(a, b), (c, d)]
    }
}

/// The pixels between two radii about a circle's centre, held as squared radii (no
/// root taken per pixel of a box).
#[derive(Clone, Copy, Debug)]
struct Ring {
    cx: f64,
    cy: f64,
    lo2: f64,
    hi2: f64,
}

impl Ring {
    /// True when the pixel (x, y) lies in the ring.
    fn holds(&self, x: isize, y: isize) -> bool {
        let (dx, dy) = (x as f64 - self.cx, y as f64 - self.cy);
        let d2 = dx * dx + dy * dy;
        self.lo2 <= d2 && d2 <= self.hi2
    }

    /// The runs `(a, b)` of row `y`'s columns within `from..=to` that can hold its
    /// pixels ([`ring_columns`]; an empty run has `a > b`).
    fn runs(&self, y: isize, within: (isize, isize)) -> [(isize, isize); 2] {
        ring_columns(self.cx, y as f64 - self.cy, (self.lo2, self.hi2), within)
    }

    /// The columns of row `y` within `from..=to` that can hold its pixels.
    fn columns(&self, y: isize, within: (isize, isize)) -> impl Iterator<Item = isize> {
        self.runs(y, within).into_iter().flat_map(|(a, b)| a..=b)
    }
}

/// The Sobel gradient (x, y, magnitude; per pixel) over the box `(x0, y0, x1, y1)`,
/// computed over the runs of each row's columns that hold `ring`'s pixels
/// ([`Ring::runs`]; a pixel or so beyond the ring at each run's ends) and zero
/// elsewhere. Whole runs, row by row, so the loop is one over plain slices the
/// compiler spreads over vector lanes; the sums are of whole levels (at most
/// 4 × 255 a side), so they, their squares and the squares' sum are exact in
/// `f32` whatever the order: each value is the per-pixel formula's to the bit.
#[allow(clippy::type_complexity)]
fn gradient(
    img: &Gray,
    (x0, y0, x1, y1): (isize, isize, isize, isize),
    ring: &Ring,
) -> (Vec<f32>, Vec<f32>, Vec<f32>) {
    let (bw, bh) = ((x1 - x0 + 1) as usize, (y1 - y0 + 1) as usize);
    let mut gx = vec![0.0f32; bw * bh];
    let mut gy = vec![0.0f32; bw * bh];
    let mut mag = vec![0.0f32; bw * bh];
    let w = img.width;
    let row = |y: isize| img.data.get(y as usize * w..(y as usize + 1) * w);
    for y in y0..=y1 {
        let (Some(up), Some(mid), Some(down)) = (row(y - 1), row(y), row(y + 1)) else {
            continue;
        };
        let at = (y - y0) as usize * bw;
        for (a, b) in ring.runs(y, (x0, x1)) {
            if a > b {
                continue;
            }
            // The run's pixels and a neighbour each side (the box lies a pixel
            // inside the frame).
            let (from, n) = ((a - 1) as usize, (b - a + 1) as usize);
            let rows = (
                up.get(from..from + n + 2),
                mid.get(from..from + n + 2),
                down.get(from..from + n + 2),
            );
            let out = at + (a - x0) as usize..at + (b - x0) as usize + 1;
            let (Some(u), Some(m), Some(d)) = rows else {
                continue;
            };
            let (Some(gx), Some(gy), Some(mag)) = (
                gx.get_mut(out.clone()),
                gy.get_mut(out.clone()),
                mag.get_mut(out),
            ) else {
                continue;
            };
            sobel_run((u, m, d), (gx, gy, mag));
        }
    }
    (gx, gy, mag)
}

/// The Sobel gradient of a run of pixels, from the rows above, at and below it
/// (`u`, `m`, `d`: the run and a pixel each side), into `gx`, `gy`, `mag` (the
/// run's length each).
#[allow(clippy::indexing_slicing)] // each j + 2 < the rows' length, n + 2 (checked)
fn sobel_run(
    (u, m, d): (&[u8], &[u8], &[u8]),
    (gx, gy, mag): (&mut [f32], &mut [f32], &mut [f32]),
) {
    let n = gx.len();
    if u.len() != n + 2 || m.len() != n + 2 || d.len() != n + 2 || gy.len() != n || mag.len() != n {
        return;
    }
    for j in 0..n {
        let (sx, sy) = sobel_sums(&u[j..j + 3], &m[j..j + 3], &d[j..j + 3]);
        let (x, y) = (sx as f32 / 8.0, sy as f32 / 8.0);
        gx[j] = x;
        gy[j] = y;
        mag[j] = (x * x + y * y).sqrt();
    }
}

/// Sub-pixel edge points within `band` of the circle `guess`, of the polarity asked
/// for (or the most common one), and that polarity.
#[allow(clippy::indexing_slicing)] // pixels one inside the clipped box, so their neighbours are in it
fn edge_points(
    img: &Gray,
    guess: Circle,
    band: f64,
    polarity: f64,
) -> Option<(Vec<[f64; 2]>, f64)> {
    let (w, h) = (img.width as isize, img.height as isize);
    let reach = guess.r + band + 2.0;
    let x0 = ((guess.x - reach).floor() as isize).max(1);
    let x1 = ((guess.x + reach).ceil() as isize).min(w - 2);
    let y0 = ((guess.y - reach).floor() as isize).max(1);
    let y1 = ((guess.y + reach).ceil() as isize).min(h - 2);
    if x1 - x0 < 4 || y1 - y0 < 4 {
        return None;
    }
    let bw = (x1 - x0 + 1) as usize;
    // Within band + extra of the circle; the gradient a pixel and a half beyond,
    // for the maxima's neighbours.
    let ring = |extra: f64| {
        let (lo, hi) = ((guess.r - band - extra).max(0.0), guess.r + band + extra);
        Ring {
            cx: guess.x,
            cy: guess.y,
            lo2: lo * lo,
            hi2: hi * hi,
        }
    };
    let (inner, outer) = (ring(0.0), ring(1.5));
    let (gx, gy, mag) = gradient(img, (x0, y0, x1, y1), &outer);
    let mut found: Vec<([f64; 2], f32, f64)> = Vec::new();
    for y in (y0 + 1)..y1 {
        for x in inner.columns(y, (x0 + 1, x1 - 1)) {
            if !inner.holds(x, y) {
                continue;
            }
            let i = (y - y0) as usize * bw + (x - x0) as usize;
            let m = mag[i];
            if m <= 0.0 {
                continue;
            }
            let (rx, ry) = (x as f64 - guess.x, y as f64 - guess.y);
            let rho = length(rx, ry).max(1e-9);
            let along = (f64::from(gx[i]) * rx + f64::from(gy[i]) * ry) / rho;
            if along.abs() < 0.9 * f64::from(m) {
                continue;
            }
            let horizontal = gx[i].abs() >= gy[i].abs();
            let (a, b) = if horizontal {
                (mag[i - 1], mag[i + 1])
            } else {
                (mag[i - bw], mag[i + bw])
            };
            if !(m > a && m >= b) {
                continue;
            }
            let den = a - 2.0 * m + b;
            let eta = if den < 0.0 {
                f64::from(0.5 * (a - b) / den).clamp(-0.5, 0.5)
            } else {
                0.0
            };
            let pt = if horizontal {
                [x as f64 + eta, y as f64]
            } else {
                [x as f64, y as f64 + eta]
            };
            // Outward luma falls (−) for a bright ball: polarity −sign(along).
            found.push((pt, m, -along.signum()));
        }
    }
    if found.len() < 12 {
        return None;
    }
    if polarity == EITHER {
        found.retain(|f| f.2 != 0.0);
        return Some((strong_points(found)?, EITHER));
    }
    let sign = if polarity != 0.0 {
        polarity
    } else {
        let s: f64 = found.iter().map(|f| f.2 * f64::from(f.1)).sum();
        if s >= 0.0 { 1.0 } else { -1.0 }
    };
    found.retain(|f| f.2 == sign);
    Some((strong_points(found)?, sign))
}

/// The edge points of `found` (point, gradient, sign) above a quarter of the strong
/// ones' gradient: weak maxima are noise.
fn strong_points(found: Vec<([f64; 2], f32, f64)>) -> Option<Vec<[f64; 2]>> {
    let mut mags: Vec<f32> = found.iter().map(|f| f.1).collect();
    // The upper quartile by selection: the value a sort puts there.
    let q = mags.len() * 3 / 4;
    if q >= mags.len() {
        return None;
    }
    let strong = *mags.select_nth_unstable_by(q, f32::total_cmp).1;
    Some(
        found
            .into_iter()
            .filter(|f| f.1 >= 0.25 * strong)
            .map(|f| f.0)
            .collect(),
    )
}

/// The outermost circular edge of either sign about the outline `o` (a ball's
/// outline is the outermost closed circular edge of the blob that moves; a circle
/// inside it, the lit part of a ball, its shading's terminator or its mark, is
/// smaller, and one reaching past it into the wall or the rail is larger): along 64
/// rays from `o`'s centre, above its lowest edge point (the rail hides what is
/// below), the outermost place between 0.4 and `reach` radii where the luma steps by
/// at least `min_step` levels across 2 px, mostly along the ray (not a straight edge
/// crossing it), and no farther than `margin` px beyond the last place on the ray
/// where `differs` (the frame differs from its background there); the circle fitted
/// to those places (polarity [`EITHER`]), `None` when fewer than 12 rays give one.
/// And the blob's own outline: the circle fitted to where each ray leaves the run of
/// differing places it starts in (for 1.5 px or more), `None` likewise.
pub fn outermost(
    img: &Gray,
    o: &Outline,
    (reach, min_step, margin): (f64, f64, f64),
    differs: &impl Fn(f64, f64) -> bool,
) -> (Option<Outline>, Option<Outline>) {
    let c = o.circle;
    let step = 0.5;
    let (s0, s1) = (0.4 * c.r, reach * c.r);
    let n = ((s1 - s0) / step).ceil().max(0.0) as usize + 1;
    let mut points = Vec::new();
    let mut blob = Vec::new();
    for i in 0..64 {
        let a = f64::from(i) * std::f64::consts::TAU / 64.0;
        let (ux, uy) = (a.cos(), a.sin());
        let at = |s: f64, t: f64| bilinear(img, c.x + s * ux - t * uy, c.y + s * uy + t * ux);
        // Per place on the ray: the step along it, the step across it, differing.
        let mut along = Vec::with_capacity(n);
        let mut last_differing = f64::NEG_INFINITY;
        // Where the run of differing places from the lock's middle ends.
        let (mut blob_end, mut quiet) = (None, 0);
        for j in 0..n {
            let s = s0 + j as f64 * step;
            if c.y + s * uy > o.lowest + 0.5 {
                break;
            }
            let (Some(inner), Some(outer), Some(left), Some(right)) =
                (at(s - 1.0, 0.0), at(s + 1.0, 0.0), at(s, -1.0), at(s, 1.0))
            else {
                break;
            };
            let (d, t) = ((outer - inner).abs(), (right - left).abs());
            along.push(if d >= 0.5 * length(d, t) { d } else { 0.0 });
            if differs(c.x + s * ux, c.y + s * uy) {
                last_differing = s;
                quiet = 0;
            } else if last_differing > s0 && blob_end.is_none() {
                quiet += 1;
                if quiet == 3 {
                    blob_end = Some(last_differing + 0.5 * step);
                }
            }
        }
        // A ray cut short (by the rail, or the frame's border) while the blob goes
        // on: its outermost edge is hidden.
        let end = s0 + along.len().saturating_sub(1) as f64 * step;
        if along.len() < n && last_differing + margin >= end {
            continue;
        }
        let found = (1..along.len().saturating_sub(1)).rev().find_map(|j| {
            let s = s0 + j as f64 * step;
            let (a, m, b) = (
                along.get(j - 1).copied()?,
                along.get(j).copied()?,
                along.get(j + 1).copied()?,
            );
            let peak = m >= min_step && m >= a && m > b && s <= last_differing + margin;
            peak.then(|| {
                let den = a - 2.0 * m + b;
                let eta = if den < 0.0 {
                    (0.5 * (a - b) / den).clamp(-0.5, 0.5)
                } else {
                    0.0
                };
                s + eta * step
            })
        });
        if let Some(s) = found {
            points.push([c.x + s * ux, c.y + s * uy]);
        }
        if let Some(s) = blob_end {
            blob.push([c.x + s * ux, c.y + s * uy]);
        }
    }
    let circle = |p: Vec<[f64; 2]>| {
        if p.len() < 12 {
            return None;
        }
        fit_points(p, c, 0.5 * c.r, EITHER)
    };
    (circle(points), circle(blob))
}

/// How far the outline's edge moves when it is defined otherwise, px, per ray of
/// the visible arc (above `lowest`, where the rail hides the ball): the crossing of
/// the level half-way between the luma `k` px inside and `k` px outside the fitted
/// circle, for `k` 2 and 4 px, each the median over the rays with a step there
/// (signed, + outward). A clean blurred step gives the same edge by every
/// definition (all about 0); a ball whose own shading runs steeply into a limb of
/// little contrast with the wall (shaded, glossy, wooden balls) gives edges that
/// differ by up to a pixel, and that spread is how unsure the edge, and so the
/// radius and the scale, is. `None` when too few rays show a step.
pub fn edge_offsets(img: &Gray, o: &Outline) -> Option<[f64; 2]> {
    let c = o.circle;
    let mut offsets: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
    for i in 0..72 {
        let a = f64::from(i) * std::f64::consts::TAU / 72.0;
        let (ux, uy) = (a.cos(), a.sin());
        // Below the lowest edge point the rail hides the ball.
        if c.y + (c.r + 4.0) * uy > o.lowest {
            continue;
        }
        let level = |s: f64| bilinear(img, c.x + (c.r + s) * ux, c.y + (c.r + s) * uy);
        for (k, list) in [2.0, 4.0].into_iter().zip(offsets.iter_mut()) {
            if let Some(s) = crossing(&level, k) {
                list.push(s);
            }
        }
    }
    let [a, b] = offsets;
    if a.len() < 8 || b.len() < 8 {
        return None;
    }
    Some([middle(a)?, middle(b)?])
}

/// The ball's radius in colour less the outline `o`'s (fitted in brightness), px:
/// along 72 rays of the visible arc (above `lowest`), where the colour (U, V)
/// `reach` px inside and outside the circle differ by at least `min_step` levels
/// and the ball's is no grey (further than `grey` levels from none), and the colour
/// steps by more than the brightness (the colour's step weighed by `weight`), the place nearest the circle where the colour crosses half-way between them;
/// a circle fitted to those places (at least 12) when it is clear (35 % of the
/// circle, 1 px RMS), `None` otherwise. A ball of the wall's brightness but another
/// colour shows its edge in colour where its brightness shows little: a circle
/// fitted to its lit part, or to the wall's faint edges about it, is pixels off it.
pub fn colour_offset(
    frame: &Frame,
    o: &Outline,
    reach: f64,
    (min_step, grey, weight): (f64, f64, f64),
) -> Option<f64> {
    let c = o.circle;
    let mut points = Vec::new();
    for i in 0..72 {
        let a = f64::from(i) * std::f64::consts::TAU / 72.0;
        let (ux, uy) = (a.cos(), a.sin());
        // The upper half, and below it down to the outline's lowest point (a lit
        // part's outline ends high above the rail).
        if uy > 0.0 && c.y + (c.r + reach) * uy > o.lowest {
            continue;
        }
        let inside = reach.min(0.6 * c.r);
        let at = |s: f64| chroma(frame, c.x + (c.r + s) * ux, c.y + (c.r + s) * uy);
        let luma = |s: f64| bilinear(&frame.luma, c.x + (c.r + s) * ux, c.y + (c.r + s) * uy);
        let (Some(inner), Some(outer)) = (at(-inside), at(reach)) else {
            continue;
        };
        let d = [inner[0] - outer[0], inner[1] - outer[1]];
        let step = length(d[0], d[1]);
        // A grey ball's edge in colour is the wall's colour: its pattern, not the
        // ball (a black ball on a coloured checker).
        if step < min_step || length(inner[0] - 128.0, inner[1] - 128.0) <= grey {
            continue;
        }
        // Only where the ball stands out more in colour than in brightness (its
        // colour weighed as the difference from the background weighs it): there
        // the colour's edge is the ball's, and the brightness's may be another.
        let (Some(li), Some(lo)) = (luma(-inside), luma(reach)) else {
            continue;
        };
        if weight * step <= (li - lo).abs() {
            continue;
        }
        // The colour's share of the way from outside to inside; the ball's colour
        // ends where it last falls below a half, going out.
        let level = |s: f64| {
            at(s).map(|p| ((p[0] - outer[0]) * d[0] + (p[1] - outer[1]) * d[1]) / (step * step))
        };
        if let Some(s) = last_crossing(&level, (-inside, reach), 0.5) {
            points.push([c.x + (c.r + s) * ux, c.y + (c.r + s) * uy]);
        }
    }
    let found = fit_points(points, c, reach, EITHER)?;
    (found.coverage() >= 0.35 && found.rms <= 1.0).then_some(found.circle.r - c.r)
}

/// Where `level(s)`, for s from `from` to `to` px, last falls from above `half` to
/// below it.
fn last_crossing(
    level: &impl Fn(f64) -> Option<f64>,
    (from, to): (f64, f64),
    half: f64,
) -> Option<f64> {
    let step = 0.25;
    let n = ((to - from) / step).round() as usize;
    let mut last: Option<f64> = None;
    let mut prev = (from, level(from)? - half);
    for j in 1..=n {
        let s = from + j as f64 * step;
        let v = level(s)? - half;
        if prev.1 >= 0.0 && v < 0.0 {
            last = Some(prev.0 + step * prev.1 / (prev.1 - v));
        }
        prev = (s, v);
    }
    last
}

/// The colour (U, V) at the frame's pixel `(x, y)`, interpolated between the four
/// samples of the half-size colour planes around it (each the mean of a 2×2 block,
/// centred half a pixel into it); `None` outside the planes.
fn chroma(frame: &Frame, x: f64, y: f64) -> Option<[f64; 2]> {
    let (cx, cy) = ((x - 0.5) / 2.0, (y - 0.5) / 2.0);
    if !(cx >= 0.0 && cy >= 0.0) {
        return None;
    }
    // Truncation is the floor of these non-negative values, with no libm call.
    let (i, j) = (cx as usize, cy as usize);
    let w = frame.chroma_width;
    if i + 1 >= w || j + 1 >= frame.chroma_height {
        return None;
    }
    let (fx, fy) = (cx - i as f64, cy - j as f64);
    let plane = |p: &[u8]| -> Option<f64> {
        let g = |a: usize, b: usize| p.get(b * w + a).map(|v| f64::from(*v));
        Some(
            (g(i, j)? * (1.0 - fx) + g(i + 1, j)? * fx) * (1.0 - fy)
                + (g(i, j + 1)? * (1.0 - fx) + g(i + 1, j + 1)? * fx) * fy,
        )
    };
    Some([plane(&frame.u)?, plane(&frame.v)?])
}

/// Where the profile `level(s)` (s px outward from the circle) crosses the level
/// half-way between `level(−k)` and `level(k)`, nearest to 0; `None` without a
/// step of at least 8 levels there.
fn crossing(level: &impl Fn(f64) -> Option<f64>, k: f64) -> Option<f64> {
    let (inner, outer) = (level(-k)?, level(k)?);
    if (inner - outer).abs() < 8.0 {
        return None;
    }
    let half = 0.5 * (inner + outer);
    let step = 0.25;
    let n = (2.0 * k / step).round() as usize;
    let mut best: Option<f64> = None;
    let mut prev = (-k, inner - half);
    for j in 1..=n {
        let s = -k + j as f64 * step;
        let v = level(s)? - half;
        if prev.1 == 0.0 || prev.1.signum() != v.signum() {
            let at = if v == prev.1 {
                prev.0
            } else {
                prev.0 + step * prev.1 / (prev.1 - v)
            };
            if best.is_none_or(|b| at.abs() < b.abs()) {
                best = Some(at);
            }
        }
        prev = (s, v);
    }
    best
}

/// The median of `v`, `None` when empty.
fn middle(mut v: Vec<f64>) -> Option<f64> {
    // By selection: the value a sort puts there.
    let mid = v.len() / 2;
    if v.is_empty() {
        return None;
    }
    Some(*v.select_nth_unstable_by(mid, f64::total_cmp).1)
}

/// The luma at `(x, y)` interpolated between the four pixels around it; `None`
/// outside the frame.
fn bilinear(img: &Gray, x: f64, y: f64) -> Option<f64> {
    if !(x >= 0.0 && y >= 0.0) {
        return None;
    }
    // Truncation is the floor of these non-negative values, with no libm call.
    let (i, j) = (x as usize, y as usize);
    if i + 1 >= img.width || j + 1 >= img.height {
        return None;
    }
    let (fx, fy) = (x - i as f64, y - j as f64);
    let p = |a: usize, b: usize| f64::from(img.get(a, b));
    Some(
        (p(i, j) * (1.0 - fx) + p(i + 1, j) * fx) * (1.0 - fy)
            + (p(i, j + 1) * (1.0 - fx) + p(i + 1, j + 1) * fx) * fy,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The gradient as it was first written, a pixel at a time, each pixel of
    /// `ring` only: the reference for [`gradient`].
    #[allow(clippy::type_complexity, clippy::indexing_slicing)]
    fn gradient_by_pixel(
        img: &Gray,
        (x0, y0, x1, y1): (isize, isize, isize, isize),
        ring: &Ring,
    ) -> (Vec<f32>, Vec<f32>, Vec<f32>) {
        let (bw, bh) = ((x1 - x0 + 1) as usize, (y1 - y0 + 1) as usize);
        let mut gx = vec![0.0f32; bw * bh];
        let mut gy = vec![0.0f32; bw * bh];
        let mut mag = vec![0.0f32; bw * bh];
        let p = |x: isize, y: isize| img.at(x as usize, y as usize);
        for y in y0..=y1 {
            for x in ring.columns(y, (x0, x1)) {
                if !ring.holds(x, y) {
                    continue;
                }
                let sx = (p(x + 1, y - 1) + 2.0 * p(x + 1, y) + p(x + 1, y + 1))
                    - (p(x - 1, y - 1) + 2.0 * p(x - 1, y) + p(x - 1, y + 1));
                let sy = (p(x - 1, y + 1) + 2.0 * p(x, y + 1) + p(x + 1, y + 1))
                    - (p(x - 1, y - 1) + 2.0 * p(x, y - 1) + p(x + 1, y - 1));
                let i = (y - y0) as usize * bw + (x - x0) as usize;
                gx[i] = sx / 8.0;
                gy[i] = sy / 8.0;
                mag[i] = (gx[i] * gx[i] + gy[i] * gy[i]).sqrt();
            }
        }
        (gx, gy, mag)
    }

    #[test]
    fn the_gradient_by_runs_is_the_per_pixel_gradient_on_the_ring() {
        // A fixed LCG over images (smooth, noisy and saturated levels), rings and
        // boxes clipped a pixel inside the image, as `edge_points` clips them.
        let mut s: u64 = 11;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        for case in 0..300 {
            let (w, h) = (3 + (next() * 120.0) as usize, 3 + (next() * 90.0) as usize);
            let kind = case % 3;
            let data: Vec<u8> = (0..w * h)
                .map(|i| match kind {
                    0 => ((i % w) * 2 + (i / w) * 3) as u8,
                    1 => (next() * 256.0) as u8,
                    _ => {
                        if next() < 0.5 {
                            0
                        } else {
                            255
                        }
                    }
                })
                .collect();
            let img = Gray {
                width: w,
                height: h,
                data,
            };
            let (cx, cy) = (next() * w as f64, next() * h as f64);
            let (r, band, extra) = (next() * 60.0, next() * 10.0, 1.5);
            let (lo, hi) = ((r - band - extra).max(0.0), r + band + extra);
            let ring = Ring {
                cx,
                cy,
                lo2: lo * lo,
                hi2: hi * hi,
            };
            let reach = r + band + 2.0;
            let b = (
                ((cx - reach).floor() as isize).max(1),
                ((cy - reach).floor() as isize).max(1),
                ((cx + reach).ceil() as isize).min(w as isize - 2),
                ((cy + reach).ceil() as isize).min(h as isize - 2),
            );
            if b.2 < b.0 || b.3 < b.1 {
                continue;
            }
            let (bw, bh) = ((b.2 - b.0 + 1) as usize, (b.3 - b.1 + 1) as usize);
            let fast = gradient(&img, b, &ring);
            let slow = gradient_by_pixel(&img, b, &ring);
            for i in 0..bw * bh {
                let (x, y) = (b.0 + (i % bw) as isize, b.1 + (i / bw) as isize);
                if ring.holds(x, y) {
                    for (f, g) in [(&fast.0, &slow.0), (&fast.1, &slow.1), (&fast.2, &slow.2)] {
                        assert_eq!(f[i].to_bits(), g[i].to_bits(), "case {case} at ({x}, {y})");
                    }
                }
            }
        }
    }

    #[test]
    fn a_rings_columns_hold_every_pixel_of_the_ring_in_order() {
        // A fixed LCG over centres, rows, radii and boxes (the test reads no clock).
        let mut x: u64 = 7;
        let mut draw = |lo: f64, hi: f64| {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            lo + (hi - lo) * ((x >> 11) as f64 / (1u64 << 53) as f64)
        };
        for _ in 0..20_000 {
            let cx = draw(-20.0, 220.0);
            let dy = draw(-90.0, 90.0);
            let r = draw(0.0, 80.0);
            let band = draw(0.0, 6.0);
            let (lo, hi) = ((r - band).max(0.0), r + band);
            let (from, to) = (draw(-5.0, 100.0) as isize, draw(100.0, 260.0) as isize);
            let runs = ring_columns(cx, dy, (lo * lo, hi * hi), (from, to));
            let inside = |c: isize| runs.iter().any(|&(a, b)| (a..=b).contains(&c));
            for c in from..=to {
                let d2 = (c as f64 - cx).powi(2) + dy * dy;
                if lo * lo <= d2 && d2 <= hi * hi {
                    assert!(inside(c), "column {c}: {runs:?} for {cx} {dy} {lo} {hi}");
                }
            }
            // Two runs are apart and in order (the edge points keep the box's order).
            if runs.iter().all(|&(a, b)| a <= b) {
                assert!(runs[0].1 < runs[1].0, "{runs:?}");
            }
        }
        // NaN gives nothing.
        let none = ring_columns(f64::NAN, 0.0, (f64::NAN, f64::NAN), (0, 10));
        assert!(none.iter().all(|&(a, b)| a > b), "{none:?}");
    }
}
