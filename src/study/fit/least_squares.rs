//! The model fit's machinery: what it compares with the data ([`Target`]), the
//! residuals and the frames they use, and the search (a μ scan, then
//! Levenberg–Marquardt with numerical derivatives).

use super::uncertainty::{clamped, solve};
use super::{Evals, FitError, Free};
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::study::measured::series::Measured;

/// Scene with the fit parameters `p` applied.
pub(super) fn with(scene: &Scene, free: &[Free], p: &[f64]) -> Scene {
    let mut s = *scene;
    for (f, &v) in free.iter().zip(p) {
        match f {
            Free::Mu => s.mu = v.max(1e-6),
            Free::V0 => {
                s.left.v0 = v;
                s.right.v0 = v;
            }
            Free::Restitution => s.restitution = v.clamp(0.0, 1.0),
            Free::RollingResistance => s.rolling_resistance = v.max(0.0),
        }
    }
    s
}

/// Points the model fit uses: all but the frames that straddle an impact of the
/// model `scene` (a frame holding a jump measures neither side of it).
pub(super) fn fit_points(m: &Measured, scene: &Scene, target: Target) -> Vec<usize> {
    // Positions do not jump at an impact: every frame counts.
    if target == Target::Position {
        return (0..m.t.len()).collect();
    }
    let frame =
        m.t.windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min);
    let sol = engine::solve(
        scene,
        &Span {
            t_start: m.t[0].min(-1e-3),
            t_end: None,
        },
    );
    let impacts: Vec<f64> = sol
        .events
        .iter()
        .filter(|e| e.kind == crate::physics::solution::EventKind::Collision)
        .map(|e| e.t)
        .collect();
    (0..m.t.len())
        .filter(|&i| impacts.iter().all(|&a| (m.t[i] - a).abs() >= frame))
        .collect()
}

/// What a model fit compares with the data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Target {
    /// v_cm and v_t, each residual divided by its uncertainty when the data carry one.
    Velocity,
    /// The centre's x (m) and the mark's angle as an arc of the contact circle (r θ, m).
    Position,
}

/// Residuals of `scene` against `m` at `idx`, weighted (divided by the points'
/// uncertainties, where known) or not; points not measured (NaN) are left out.
pub(super) fn residuals_of(
    scene: &Scene,
    m: &Measured,
    idx: &[usize],
    target: Target,
    weighted: bool,
) -> Vec<f64> {
    let t0 = m.t[0].min(-1e-3);
    let sol = engine::solve(
        scene,
        &Span {
            t_start: t0,
            t_end: None,
        },
    );
    let mut r = Vec::with_capacity(2 * idx.len());
    // A residual over its uncertainty; one without a usable uncertainty is dropped.
    let push = |r: &mut Vec<f64>, d: f64, sigma: Option<&Vec<f64>>, i: usize| {
        if !d.is_finite() {
            return;
        }
        match sigma.filter(|_| weighted).map(|s| s[i]) {
            None => r.push(d),
            Some(s) if s > 0.0 && s.is_finite() => r.push(d / s),
            Some(_) => {}
        }
    };
    match target {
        Target::Velocity => {
            for &i in idx {
                let s = sol.at(m.t[i]);
                push(&mut r, s.left.v - m.v_cm[i], m.v_cm_sigma.as_ref(), i);
                push(&mut r, s.left.u - m.v_t[i], m.v_t_sigma.as_ref(), i);
            }
        }
        Target::Position => {
            let (Some(x), radius) = (m.x.as_ref(), scene.k() * scene.radius) else {
                return r;
            };
            // The impact's time and place, and the mark's angle then, were estimated
            // from the same noisy track: each residual gets the best shift δt, δx, δθ
            // (linearised: x moves by v δt, r θ by u δt), profiled out of the fit.
            let theta0 = sol.angle_at(0.0)[0];
            // (residual, ∂/∂δt, ∂/∂δx, ∂/∂δθ)
            let mut rows: Vec<[f64; 4]> = Vec::with_capacity(2 * idx.len());
            for &i in idx {
                let s = sol.at(m.t[i]);
                rows.push([s.left.x + scene.radius - x[i], s.left.v, -1.0, 0.0]);
                if let Some(a) = &m.angle {
                    let model = sol.angle_at(m.t[i])[0] - theta0;
                    rows.push([radius * (model - a[i]), s.left.u, 0.0, -radius]);
                }
            }
            rows.retain(|row| row.iter().all(|v| v.is_finite()));
            let k = if m.angle.is_some() { 3 } else { 2 };
            let mut ata = vec![vec![0.0; k]; k];
            let mut atb = vec![0.0; k];
            for row in &rows {
                for a in 0..k {
                    atb[a] -= row[1 + a] * row[0];
                    for b in 0..k {
                        ata[a][b] += row[1 + a] * row[1 + b];
                    }
                }
            }
            let shift = solve(ata, atb).unwrap_or_else(|| vec![0.0; k]);
            for row in rows {
                let d = row[0] + (0..k).map(|a| row[1 + a] * shift[a]).sum::<f64>();
                push(&mut r, d, None, 0);
            }
        }
    }
    r
}

/// Parameters a fit to `target` estimates besides the free scene values.
pub(super) fn nuisance(m: &Measured, target: Target) -> usize {
    match (target, m.angle.is_some()) {
        (Target::Velocity, _) => 0,
        (Target::Position, false) => 2,
        (Target::Position, true) => 3,
    }
}

pub(super) fn residuals(scene: &Scene, m: &Measured, idx: &[usize], target: Target) -> Vec<f64> {
    residuals_of(scene, m, idx, target, true)
}

/// Mean squared residual of `scene`, over the frames away from its own impacts.
fn mean_cost(scene: &Scene, m: &Measured, target: Target) -> f64 {
    let idx = fit_points(m, scene, target);
    let r = residuals(scene, m, &idx, target);
    r.iter().map(|x| x * x).sum::<f64>() / r.len().max(1) as f64
}

/// The μ that minimises [`mean_cost`]: a log-spaced scan of 0.01 … 1, then golden
/// section between the neighbours of the best scan point.
pub(super) fn scan_mu(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    p: &[f64],
    i: usize,
    target: Target,
    evals: &Evals,
) -> Result<f64, FitError> {
    let cost = |mu: f64| {
        evals.next()?;
        let mut q = p.to_vec();
        q[i] = mu;
        Ok(mean_cost(&with(scene, free, &q), m, target))
    };
    let grid: Vec<f64> = (0..=80)
        .map(|k| 0.01 * 100f64.powf(k as f64 / 80.0))
        .collect();
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

/// ∂r/∂p by forward differences (backward at the upper bound of e); one row per
/// parameter.
pub(super) fn jacobian(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    idx: &[usize],
    p: &[f64],
    r0: &[f64],
    target: Target,
) -> Vec<Vec<f64>> {
    (0..p.len())
        .map(|j| {
            let mut h = 1e-6 * p[j].abs().max(0.1);
            if free[j] == Free::Restitution && p[j] + h > 1.0 {
                h = -h;
            }
            let mut q = p.to_vec();
            q[j] += h;
            residuals(&with(scene, free, &q), m, idx, target)
                .iter()
                .zip(r0)
                .map(|(a, b)| (a - b) / h)
                .collect()
        })
        .collect()
}

/// Levenberg–Marquardt from `p` on the points `idx`.
pub(super) fn least_squares(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    idx: &[usize],
    mut p: Vec<f64>,
    target: Target,
    evals: &Evals,
) -> Result<Vec<f64>, FitError> {
    if idx.len() < free.len() + 2 {
        return Err(FitError::Data(format!(
            "{} usable points, allowed at least {}",
            idx.len(),
            free.len() + 2
        )));
    }
    let cost = |p: &[f64]| -> f64 {
        residuals(&with(scene, free, p), m, idx, target)
            .iter()
            .map(|r| r * r)
            .sum()
    };
    let mut lambda = 1e-3;
    let mut c = cost(&p);
    for _ in 0..100 {
        evals.next()?;
        let r0 = residuals(&with(scene, free, &p), m, idx, target);
        let j = jacobian(scene, m, free, idx, &p, &r0, target);
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
            let cq = cost(&q);
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
