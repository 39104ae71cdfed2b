//! The model fit's search: the free values applied to the scene, a μ scan, then
//! Levenberg–Marquardt with numerical derivatives of the residuals
//! ([`super::residuals`]).

// Not yet converted to `get`, iterators and typed errors (issue 35, open): its
// indices come from its own loops over vectors of one length.
#![allow(
    clippy::indexing_slicing,
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic
)]

use super::problem::{Evals, FitError, Free};
use super::residuals::{Target, fit_points, mean_cost, residuals};
use super::uncertainty::{clamped, solve};
use crate::physics::scene::Scene;
use crate::study::measured::series::Measured;

/// One fit's problem, which the search and its derivatives take whole: the scene it
/// starts from, the data, the values it frees and what it compares with the data.
/// The search takes the counter of its model evaluations ([`Evals`]) beside it.
#[derive(Clone, Copy)]
pub(super) struct Problem<'a> {
    pub scene: &'a Scene,
    pub m: &'a Measured,
    pub free: &'a [Free],
    pub target: Target,
}

impl Problem<'_> {
    /// The scene with the free values `p`.
    pub fn at(&self, p: &[f64]) -> Scene {
        with(self.scene, self.free, p)
    }

    /// The weighted residuals of the free values `p` at the frames `idx`.
    pub fn residuals(&self, p: &[f64], idx: &[usize], evals: &mut Evals) -> Vec<f64> {
        residuals(&self.at(p), self.m, idx, self.target, evals)
    }

    /// The sum of the squared weighted residuals of `p` at `idx`.
    fn cost(&self, p: &[f64], idx: &[usize], evals: &mut Evals) -> f64 {
        self.residuals(p, idx, evals).iter().map(|r| r * r).sum()
    }
}

/// Scene with the fit parameters `p` applied, each written by its row of the
/// parameter table; a step of the search that leaves the physical range is held at
/// its edge (μ_k just above 0, 0 ≤ e ≤ 1, c_rr ≥ 0).
pub(super) fn with(scene: &Scene, free: &[Free], p: &[f64]) -> Scene {
    let mut s = *scene;
    let mut span = crate::physics::scene::Span::default();
    for (f, &v) in free.iter().zip(p) {
        let v = match f {
            Free::Mu => v.max(1e-6),
            Free::V0 => v,
            Free::Restitution => v.clamp(0.0, 1.0),
            Free::RollingResistance => v.max(0.0),
        };
        (f.key().param().set)(&mut s, &mut span, v);
    }
    s
}

/// `n + 1` values of μ spaced evenly in log from 0.01 to 1.
fn mu_grid(n: u32) -> Vec<f64> {
    (0..=n)
        .map(|k| 0.01 * 100f64.powf(f64::from(k) / f64::from(n)))
        .collect()
}

/// The values `p` with the μ (at `i`) of a coarse scan (21 values) that fits best, and
/// their [`mean_cost`]: to choose among starts of a fit.
pub(super) fn coarse_mu(
    pb: &Problem,
    evals: &mut Evals,
    p: &[f64],
    i: usize,
) -> Result<(Vec<f64>, f64), FitError> {
    let mut best = (p.to_vec(), f64::INFINITY);
    for mu in mu_grid(20) {
        evals.next()?;
        let mut q = p.to_vec();
        q[i] = mu;
        let cost = mean_cost(&pb.at(&q), pb.m, pb.target, evals);
        if cost < best.1 {
            best = (q, cost);
        }
    }
    Ok(best)
}

/// The μ that minimises [`mean_cost`]: a log-spaced scan of 0.01 … 1, then golden
/// section between the neighbours of the best scan point.
pub(super) fn scan_mu(
    pb: &Problem,
    evals: &mut Evals,
    p: &[f64],
    i: usize,
) -> Result<f64, FitError> {
    // On the frames the start leaves (a μ whose later impacts pass more frames would
    // otherwise leave out the ones it fits worst, and look better than it is).
    let idx = fit_points(pb.m, &pb.at(p), pb.target, evals);
    let mut cost = |mu: f64| {
        evals.next()?;
        let mut q = p.to_vec();
        q[i] = mu;
        let r = pb.residuals(&q, &idx, evals);
        Ok(r.iter().map(|x| x * x).sum::<f64>() / r.len().max(1) as f64)
    };
    let grid = mu_grid(80);
    let costs = grid
        .iter()
        .map(|&mu| cost(mu))
        .collect::<Result<Vec<f64>, FitError>>()?;
    let best = (0..grid.len())
        .min_by(|&a, &b| costs[a].total_cmp(&costs[b]))
        .unwrap_or(0);
    let (mut a, mut b) = (
        grid[best.saturating_sub(1)],
        grid[(best + 1).min(grid.len() - 1)],
    );
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - phi * (b - a);
    let mut d = a + phi * (b - a);
    let (mut fc, mut fd) = (cost(c)?, cost(d)?);
    while b - a > 1e-7 * b {
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - phi * (b - a);
            fc = cost(c)?;
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + phi * (b - a);
            fd = cost(d)?;
        }
    }
    Ok(0.5 * (a + b))
}

pub(super) fn normal_matrix(j: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let n = j.len();
    (0..n)
        .map(|a| {
            (0..n)
                .map(|b| j[a].iter().zip(&j[b]).map(|(x, y)| x * y).sum())
                .collect()
        })
        .collect()
}

/// Where a derivative is taken: the frames `idx`, the free values `p` and their
/// residuals `r0` there.
pub(super) struct At<'a> {
    pub idx: &'a [usize],
    pub p: &'a [f64],
    pub r0: &'a [f64],
}

/// ∂r/∂p by forward differences (backward at the upper bound of e); one row per
/// parameter.
pub(super) fn jacobian(pb: &Problem, evals: &mut Evals, at: &At) -> Vec<Vec<f64>> {
    let p = at.p;
    (0..p.len())
        .map(|j| {
            let mut h = step(p[j]);
            if pb.free[j] == Free::Restitution && p[j] + h > 1.0 {
                h = -h;
            }
            difference(pb, evals, at, (j, h))
        })
        .collect()
}

/// The step of a numerical derivative at `v`.
fn step(v: f64) -> f64 {
    1e-6 * v.abs().max(0.1)
}

/// (r(p + h e_j) − r(p)) / h, for `(j, h)`.
fn difference(pb: &Problem, evals: &mut Evals, at: &At, (j, h): (usize, f64)) -> Vec<f64> {
    let r0 = at.r0;
    let mut q = at.p.to_vec();
    q[j] += h;
    let r = pb.residuals(&q, at.idx, evals);
    if r.len() != r0.len() {
        // A point dropped or gained at the step: no derivative to take.
        return vec![0.0; r0.len()];
    }
    r.iter().zip(r0).map(|(a, b)| (a - b) / h).collect()
}

/// [`jacobian`] for the uncertainties: each residual's derivative is the smaller of
/// the forward and the backward difference. A residual can jump between two nearby
/// values of a parameter (a data point that a later impact or the end of sliding
/// passes, a window that starts to hold a corner): a one-sided difference over the
/// jump is the jump over the step, huge, and would make the ± collapse to nothing.
/// Where the residual is smooth both differences agree to O(step).
pub(super) fn smooth_jacobian(pb: &Problem, evals: &mut Evals, at: &At) -> Vec<Vec<f64>> {
    let p = at.p;
    (0..p.len())
        .map(|j| {
            let h = step(p[j]);
            let up = difference(pb, evals, at, (j, h));
            // At a bound the step back or forward leaves the allowed range.
            let (lo, hi) = super::uncertainty::bounds(pb.free[j]);
            if p[j] - h <= lo || p[j] + h >= hi {
                return up;
            }
            let down = difference(pb, evals, at, (j, -h));
            up.iter()
                .zip(&down)
                .map(|(&a, &b)| if a.abs() <= b.abs() { a } else { b })
                .collect()
        })
        .collect()
}

/// Levenberg–Marquardt from `p` on the points `idx`.
pub(super) fn least_squares(
    pb: &Problem,
    evals: &mut Evals,
    idx: &[usize],
    mut p: Vec<f64>,
) -> Result<Vec<f64>, FitError> {
    let free = pb.free;
    if idx.len() < free.len() + 2 {
        return Err(FitError::TooFewPoints {
            usable: idx.len(),
            needed: free.len() + 2,
        });
    }
    let mut lambda = 1e-3;
    let mut c = pb.cost(&p, idx, evals);
    for _ in 0..100 {
        evals.next()?;
        let r0 = pb.residuals(&p, idx, evals);
        let j = jacobian(
            pb,
            evals,
            &At {
                idx,
                p: &p,
                r0: &r0,
            },
        );
        let jtj = normal_matrix(&j);
        let jtr: Vec<f64> = j
            .iter()
            .map(|row| -row.iter().zip(&r0).map(|(x, y)| x * y).sum::<f64>())
            .collect();
        let mut improved = false;
        for _ in 0..20 {
            let mut damped = jtj.clone();
            for (d, row) in damped.iter_mut().enumerate() {
                row[d] *= 1.0 + lambda;
            }
            let Some(step) = solve(damped, jtr.clone()) else {
                lambda *= 10.0;
                continue;
            };
            // Steps stay inside the bounds (e ≤ 1): outside, the model would not change.
            let q: Vec<f64> = clamped(
                free,
                &p.iter().zip(&step).map(|(a, b)| a + b).collect::<Vec<_>>(),
            );
            evals.next()?;
            let cq = pb.cost(&q, idx, evals);
            if cq < c {
                improved = (c - cq) > 1e-12 * c;
                p = q;
                c = cq;
                lambda = (lambda / 10.0).max(1e-12);
                break;
            }
            lambda *= 10.0;
        }
        if !improved {
            break;
        }
    }
    Ok(p)
}
