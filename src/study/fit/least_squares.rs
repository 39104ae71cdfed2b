//! The model fit's search: the free values applied to the scene, a profile scan of
//! μ_k over its range, then Levenberg–Marquardt with numerical derivatives of the residuals
//! ([`super::residuals`]).

use super::problem::{Evals, FitError, Free};
use super::residuals::{Target, fit_points, residuals};
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

/// How many steps apart the profile scan's ends are ([`profile_mu`]: 49 values of
/// μ_k), spaced evenly in log over [`PROFILE_RANGE`], about 10 % apart, so the
/// profile's lowest grid value lies within one step of its minimum.
const PROFILE_POINTS: u32 = 48;

/// The range of μ_k the profile scan covers: every plausible μ_k of a ball in a
/// groove (0.01 … 1; the full fit may leave it, as data in the wrong unit do).
const PROFILE_RANGE: (f64, f64) = (0.01, 1.0);

/// Levenberg–Marquardt steps for the other free values at one μ_k of the profile:
/// started from the neighbouring μ_k's optimum they are one step away (v0 and the
/// positions are nearly linear), and the full fit polishes the best. Three steps
/// cost twice the fit's time and found the same optima on the truth grid (540
/// tables); on one track they ended a check fit in a worse valley than one step did.
const PROFILE_STEPS: usize = 1;

/// `n + 1` values of μ spaced evenly in log over [`PROFILE_RANGE`].
fn mu_grid(n: u32) -> Vec<f64> {
    let (lo, hi) = PROFILE_RANGE;
    (0..=n)
        .map(|k| lo * (hi / lo).powf(f64::from(k) / f64::from(n)))
        .collect()
}

/// `p` with the μ_k (at `i`) of 21 values over [`PROFILE_RANGE`] that fits best, each
/// on the frames its own impacts leave.
fn coarse_mu(pb: &Problem, evals: &mut Evals, p: &[f64], i: usize) -> Result<Vec<f64>, FitError> {
    let mut best = (f64::INFINITY, p.to_vec());
    for mu in mu_grid(20) {
        evals.next()?;
        let mut q = p.to_vec();
        if let Some(v) = q.get_mut(i) {
            *v = mu;
        }
        let idx = fit_points(pb.m, &pb.at(&q), pb.target, evals);
        let cost = mean_square(&pb.residuals(&q, &idx, evals));
        if cost < best.0 {
            best = (cost, q);
        }
    }
    Ok(best.1)
}

/// The mean squared weighted residual of `r`.
fn mean_square(r: &[f64]) -> f64 {
    r.iter().map(|x| x * x).sum::<f64>() / r.len().max(1) as f64
}

/// The values `p` with μ_k (at `i`) where the fit's profile over μ_k is lowest: μ_k
/// is one number and a solve costs microseconds, so its whole range is scanned
/// ([`PROFILE_POINTS`] values) before any local search, with the other free values
/// optimised at each (a few Levenberg–Marquardt steps with μ_k held, from the better
/// of `p`'s values and the previous μ_k's optimum); then golden section between the
/// lowest grid value's neighbours, the others held at its optimum (the cost is not
/// smooth where impacts move past data points, and local steps get caught there).
/// A local search alone stopped in another minimum: an exact track at μ_k = 0.18
/// fitted to 0.1966 with 1.6 mm RMS (issue 35).
/// On the frames the start leaves (a μ whose later impacts pass more frames would
/// otherwise leave out the ones it fits worst, and look better than it is), among
/// `within` when given.
pub(super) fn profile_mu(
    pb: &Problem,
    evals: &mut Evals,
    p: &[f64],
    i: usize,
    within: Option<&[usize]>,
) -> Result<Vec<f64>, FitError> {
    // The frames of the μ_k a coarse scan finds (each μ_k on the frames its own
    // impacts leave), not of the start's μ_k: the fit must not depend on where μ_k
    // started (the app's fitted μ_k against `fit`'s preset one).
    let coarse = match pb.target {
        Target::Velocity => coarse_mu(pb, evals, p, i)?,
        Target::Position => p.to_vec(),
    };
    let mut idx = fit_points(pb.m, &pb.at(&coarse), pb.target, evals);
    if let Some(w) = within {
        idx.retain(|k| w.binary_search(k).is_ok());
    }
    let others: Vec<Free> = pb
        .free
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != i)
        .map(|(_, f)| *f)
        .collect();
    let rest: Vec<f64> = p
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != i)
        .map(|(_, v)| *v)
        .collect();
    let join = |mu: f64, rest: &[f64]| {
        let mut q = rest.to_vec();
        q.insert(i.min(q.len()), mu);
        q
    };
    let grid = mu_grid(PROFILE_POINTS);
    let mut previous: Option<Vec<f64>> = None;
    let mut profile = Vec::with_capacity(grid.len());
    for &mu in &grid {
        evals.next()?;
        let held = with(pb.scene, &[Free::Mu], &[mu]);
        let sub = Problem {
            scene: &held,
            m: pb.m,
            free: &others,
            target: pb.target,
        };
        let (q, cost) = if others.is_empty() {
            (Vec::new(), mean_square(&sub.residuals(&[], &idx, evals)))
        } else {
            let mut best: Option<(Vec<f64>, Vec<f64>, f64)> = None;
            for start in std::iter::once(rest.clone()).chain(previous.take()) {
                let r = sub.residuals(&start, &idx, evals);
                let c = mean_square(&r);
                if best.as_ref().is_none_or(|b| c < b.2) {
                    best = Some((start, r, c));
                }
            }
            let start = best.map_or_else(
                || {
                    let r = sub.residuals(&rest, &idx, evals);
                    (rest.clone(), r)
                },
                |b| (b.0, b.1),
            );
            let (q, r) = steps_from(&sub, evals, &idx, start, PROFILE_STEPS)?;
            (q, mean_square(&r))
        };
        previous = Some(q.clone());
        profile.push((mu, q, cost));
    }
    let lowest = (0..profile.len())
        .filter(|&k| profile.get(k).is_some_and(|(_, _, c)| c.is_finite()))
        .min_by(|&a, &b| {
            let cost = |k: usize| profile.get(k).map_or(f64::INFINITY, |e| e.2);
            cost(a).total_cmp(&cost(b))
        });
    let Some((mu, q, _)) = lowest.and_then(|k| profile.get(k)) else {
        return Ok(p.to_vec());
    };
    let k = lowest.unwrap_or(0);
    let around = |k: Option<usize>| k.and_then(|k| grid.get(k)).copied().unwrap_or(*mu);
    let bracket = (around(k.checked_sub(1)), around(Some(k + 1)));
    let held = join(*mu, q);
    let mu = golden_mu(pb, evals, &held, i, bracket, &idx)?;
    Ok(join(mu, q))
}

/// The μ_k (at `i` of `p`, the others held) in `bracket` that minimises the mean
/// squared residual on the frames `idx`, by golden section to 1e-7 relative.
fn golden_mu(
    pb: &Problem,
    evals: &mut Evals,
    p: &[f64],
    i: usize,
    bracket: (f64, f64),
    idx: &[usize],
) -> Result<f64, FitError> {
    let mut cost = |mu: f64| {
        evals.next()?;
        let mut q = p.to_vec();
        if let Some(v) = q.get_mut(i) {
            *v = mu;
        }
        Ok(mean_square(&pb.residuals(&q, idx, evals)))
    };
    let (mut a, mut b) = bracket;
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
    j.iter()
        .map(|a| {
            j.iter()
                .map(|b| a.iter().zip(b).map(|(x, y)| x * y).sum())
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
    at.p.iter()
        .zip(pb.free)
        .enumerate()
        .map(|(j, (&v, &free))| {
            let mut h = step(v);
            if free == Free::Restitution && v + h > 1.0 {
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
    if let Some(v) = q.get_mut(j) {
        *v += h;
    }
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
    at.p.iter()
        .zip(pb.free)
        .enumerate()
        .map(|(j, (&v, &free))| {
            let h = step(v);
            let up = difference(pb, evals, at, (j, h));
            // At a bound the step back or forward leaves the allowed range.
            let (lo, hi) = super::uncertainty::bounds(free);
            if v - h <= lo || v + h >= hi {
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

/// Levenberg–Marquardt from `p` on the points `idx`, to convergence.
pub(super) fn least_squares(
    pb: &Problem,
    evals: &mut Evals,
    idx: &[usize],
    p: Vec<f64>,
) -> Result<Vec<f64>, FitError> {
    steps(pb, evals, idx, p, 100)
}

/// At most `most` Levenberg–Marquardt steps from `p` on the points `idx`.
fn steps(
    pb: &Problem,
    evals: &mut Evals,
    idx: &[usize],
    p: Vec<f64>,
    most: usize,
) -> Result<Vec<f64>, FitError> {
    let r0 = pb.residuals(&p, idx, evals);
    steps_from(pb, evals, idx, (p, r0), most).map(|(p, _)| p)
}

/// [`steps`] from `p` whose residuals `r0` are known, giving the values reached and
/// their residuals (a profile scan already has both: no motion is solved twice).
fn steps_from(
    pb: &Problem,
    evals: &mut Evals,
    idx: &[usize],
    (mut p, mut r0): (Vec<f64>, Vec<f64>),
    most: usize,
) -> Result<(Vec<f64>, Vec<f64>), FitError> {
    let free = pb.free;
    if idx.len() < free.len() + 2 {
        return Err(FitError::TooFewPoints {
            usable: idx.len(),
            needed: free.len() + 2,
        });
    }
    let mut lambda = 1e-3;
    let mut c: f64 = r0.iter().map(|r| r * r).sum();
    for _ in 0..most {
        evals.next()?;
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
                if let Some(x) = row.get_mut(d) {
                    *x *= 1.0 + lambda;
                }
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
            // A step that moves nothing (a value held at its bound, the rest at their
            // optimum) stays nothing at any larger damping: no motion is solved for it
            // (20 of them at each point of a profile with e at 1 were half its cost).
            if q == p {
                break;
            }
            evals.next()?;
            let rq = pb.residuals(&q, idx, evals);
            // A step that drops or gains a residual is not comparable: too far.
            let cq: f64 = if rq.len() == r0.len() {
                rq.iter().map(|r| r * r).sum()
            } else {
                f64::INFINITY
            };
            if cq < c {
                // Settled when a step gains less than 1e-10 of the cost: below that,
                // a model with a value on its bound crawled along it for all 100
                // steps (500 motions solved) without moving a printed digit.
                improved = (c - cq) > 1e-10 * c;
                p = q;
                r0 = rq;
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
    Ok((p, r0))
}
