//! A mark's place measured by a model of it: a disc of one level drawn over the
//! ball's shading (a plane), its edge a soft step, fitted to the pixels about the
//! mark's centroid by Levenberg–Marquardt. The centroid of a mark's contrast
//! weighs each of its pixels by how much it stands out from the shading there, so
//! where the shading darkens across a dark mark (the ball's lower part, toward the
//! rail) the mark's lower part weighs less and the centroid sits high, 1–3.5 px on
//! the looks table; the model's disc has one level whatever the shading behind it,
//! and its place is told by its edge. Where the model does not fit (a highlight's
//! glow beside the mark, a blurred or blocky mark), its edge comes out soft and the
//! centroid is kept (`Params::mark_soft`).

use super::circle::length;
use super::gray::Gray;
use nalgebra::{SMatrix, SVector};

/// The model's parameters: the disc's centre x, y and radius (px), its level, the
/// shading plane's level at the centroid and its slopes along x and y (levels a
/// px), and the edge's softness (px: the logistic step's scale).
type Theta = SVector<f64, 8>;

/// What the fit starts from: the centroid (the plane's origin too), the spot's
/// radius, the mark's level and the shading plane about the centroid.
#[derive(Clone, Copy, Debug)]
pub struct Start {
    pub at: (f64, f64),
    pub radius: f64,
    pub level: f64,
    pub plane: (f64, f64, f64),
}

/// The disc fitted (see [`fit`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disc {
    pub x: f64,
    pub y: f64,
    pub radius: f64,
    pub level: f64,
    /// The shading's level at the centroid.
    pub shade: f64,
    /// The edge's softness, px: the scale of the logistic step from the shading to
    /// the disc's level (a drawn edge blurred by a pixel or so comes out 0.3–1.4;
    /// a glow, a smear, or a spot that is no disc, more).
    pub soft: f64,
}

/// Least edge softness the fit may take, px (the step of a sharp edge sampled by
/// whole pixels).
const SOFTEST: f64 = 0.3;
/// Rounds of Levenberg–Marquardt at most, and tries of its damping a round. (By hand,
/// eight parameters on fixed-size matrices: the `levenberg-marquardt` crate, 0.15, is
/// built on nalgebra 0.34, this crate on 0.35, whose types it would not take.)
const ROUNDS: usize = 30;
const TRIES: usize = 10;

/// The disc fitted to the pixels of `img` within `reach` px of `start.at` where
/// `keep(x, y)` (on the ball, above the rail), least squares; `None` with under 20
/// pixels or a singular step.
pub fn fit(img: &Gray, start: Start, reach: f64, keep: impl Fn(f64, f64) -> bool) -> Option<Disc> {
    let pts = pixels(img, start.at, reach, keep);
    if pts.len() < 20 {
        return None;
    }
    let (a0, a1, a2) = start.plane;
    let mut th = Theta::from_column_slice(&[
        start.at.0,
        start.at.1,
        start.radius,
        start.level,
        a0,
        a1,
        a2,
        0.8,
    ]);
    // The cost and the normal equations in one pass over the pixels: a step taken
    // starts the next round from the equations its cost was measured with.
    let mut here = Normal::of(&pts, start.at, &th);
    let mut lam = 1e-3;
    for _ in 0..ROUNDS {
        let mut stepped = None;
        for _ in 0..TRIES {
            let mut a = here.jtj;
            for i in 0..8 {
                if let Some(d) = a.get_mut((i, i)) {
                    *d *= 1.0 + lam;
                }
            }
            let step = a.lu().solve(&here.jtr)?;
            let mut next = th + step;
            if let Some(s) = next.get_mut(7) {
                *s = s.max(SOFTEST);
            }
            let there = Normal::of(&pts, start.at, &next);
            if there.cost < here.cost {
                (th, here) = (next, there);
                lam = (lam / 3.0).max(1e-6);
                stepped = Some(step);
                break;
            }
            lam *= 5.0;
        }
        let Some(step) = stepped else { break };
        let moved = |i: usize| step.get(i).map_or(0.0, |d| d.abs());
        if moved(0) < 1e-3 && moved(1) < 1e-3 {
            break;
        }
    }
    let p = |i: usize| th.get(i).copied().unwrap_or(f64::NAN);
    let disc = Disc {
        x: p(0),
        y: p(1),
        radius: p(2),
        level: p(3),
        shade: p(4),
        soft: p(7),
    };
    [disc.x, disc.y, disc.radius, disc.level, disc.soft]
        .iter()
        .all(|v| v.is_finite())
        .then_some(disc)
}

/// The pixels (x, y, level) within `reach` of `at` where `keep` holds.
fn pixels(
    img: &Gray,
    at: (f64, f64),
    reach: f64,
    keep: impl Fn(f64, f64) -> bool,
) -> Vec<(f64, f64, f64)> {
    let r = reach.ceil() as isize;
    let (cx, cy) = (at.0.round() as isize, at.1.round() as isize);
    let mut out = Vec::new();
    for y in (cy - r)..=(cy + r) {
        for x in (cx - r)..=(cx + r) {
            let (fx, fy) = (x as f64, y as f64);
            if x < 0
                || y < 0
                || x as usize >= img.width
                || y as usize >= img.height
                || length(fx - at.0, fy - at.1) > reach
                || !keep(fx, fy)
            {
                continue;
            }
            out.push((fx, fy, f64::from(img.at(x as usize, y as usize))));
        }
    }
    out
}

/// The logistic step, 0 … 1.
fn step(z: f64) -> f64 {
    if z > 30.0 {
        1.0
    } else if z < -30.0 {
        0.0
    } else {
        1.0 / (1.0 + (-z).exp())
    }
}

/// The model's level at `(x, y)` and its derivatives by the parameters.
#[allow(clippy::indexing_slicing)] // the eight parameters of a fixed-size vector
fn model(th: &Theta, at: (f64, f64), x: f64, y: f64) -> (f64, Theta) {
    let (mx, my, rho, level) = (th[0], th[1], th[2], th[3]);
    let s = th[7].max(SOFTEST);
    let (dx, dy) = (x - at.0, y - at.1);
    let shade = th[4] + th[5] * dx + th[6] * dy;
    let d = length(x - mx, y - my).max(1e-6);
    let z = (rho - d) / s;
    let c = step(z);
    // d(model)/d(rho): the disc's level against the shading, times the step's slope.
    let g = (level - shade) * c * (1.0 - c) / s;
    let j = Theta::from_column_slice(&[
        g * (x - mx) / d,
        g * (y - my) / d,
        g,
        c,
        1.0 - c,
        (1.0 - c) * dx,
        (1.0 - c) * dy,
        -g * z,
    ]);
    (shade * (1.0 - c) + level * c, j)
}

/// The sum of squared residuals of the model `th` over `pts`, and the normal
/// equations JᵀJ and Jᵀr there.
struct Normal {
    cost: f64,
    jtj: SMatrix<f64, 8, 8>,
    jtr: Theta,
}

impl Normal {
    fn of(pts: &[(f64, f64, f64)], at: (f64, f64), th: &Theta) -> Normal {
        let mut n = Normal {
            cost: 0.0,
            jtj: SMatrix::zeros(),
            jtr: Theta::zeros(),
        };
        for &(x, y, v) in pts {
            let (m, j) = model(th, at, x, y);
            let r = v - m;
            n.cost += r * r;
            // JᵀJ is symmetric: its lower half summed, the upper copied after.
            n.jtj.syger(1.0, &j, &j, 1.0);
            n.jtr += j * r;
        }
        n.jtj.fill_upper_triangle_with_lower_triangle();
        n
    }
}
