//! Fitting the model to measured series of the left ball: the paper's line fits over
//! the sliding phase (table 1), and least-squares fits of the exact model to every
//! point — of the velocities (weighted by their uncertainties when known) or of the
//! tracked positions — with uncertainties and the regime compared with what was seen.

use serde::Serialize;

use crate::input::data::Measured;
use crate::physics::closed_form;
use crate::physics::derived::{Derived, Regime};
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::story::Verdict;
use crate::study::Progress;

/// Most frames the model fit uses. A longer series is thinned to every k-th frame
/// (the output says so): each model evaluation walks every point used, and a fit
/// takes a few hundred evaluations, so 1 000 000 frames took 10 s where 20 000 take
/// a fifth of a second. Video analysis gives 30–1000 frames a second: a real series
/// stays far below the cap.
pub const MAX_MODEL_POINTS: usize = 20_000;

/// Why a fit cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FitError {
    #[error("{0}")]
    Data(String),
    /// The caller's [`Progress`] asked to stop.
    #[error("cancelled")]
    Cancelled,
}

/// Counts model evaluations for [`Progress`] and stops when it asks.
struct Evals<'a> {
    progress: &'a dyn Progress,
    done: std::cell::Cell<u64>,
}

impl Evals<'_> {
    /// Before each model evaluation.
    fn next(&self) -> Result<(), FitError> {
        let done = self.done.get() + 1;
        self.done.set(done);
        self.progress.tick(done, 0);
        if self.progress.cancelled() {
            Err(FitError::Cancelled)
        } else {
            Ok(())
        }
    }
}

/// A straight line `y = a + b t` by least squares, with standard errors.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Line {
    pub intercept: f64,
    pub slope: f64,
    pub slope_se: f64,
    pub intercept_se: f64,
}

/// Ordinary least squares of `ys` on `ts` (at least 3 points).
pub fn line(ts: &[f64], ys: &[f64]) -> Line {
    let n = ts.len() as f64;
    let mt = ts.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let sxx: f64 = ts.iter().map(|t| (t - mt).powi(2)).sum();
    let sxy: f64 = ts.iter().zip(ys).map(|(t, y)| (t - mt) * (y - my)).sum();
    let slope = sxy / sxx;
    let intercept = my - slope * mt;
    let rss: f64 = ts
        .iter()
        .zip(ys)
        .map(|(t, y)| (y - intercept - slope * t).powi(2))
        .sum();
    let s2 = if n > 2.0 { rss / (n - 2.0) } else { f64::NAN };
    Line {
        intercept,
        slope,
        slope_se: (s2 / sxx).sqrt(),
        intercept_se: (s2 * (1.0 / n + mt * mt / sxx)).sqrt(),
    }
}

/// The paper's table-1 quantities from line fits over the sliding phase (magnitudes).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LineFit {
    /// Window used, s.
    pub from: f64,
    pub to: f64,
    pub points: usize,
    pub a_cm: f64,
    pub a_cm_se: f64,
    pub a_t: f64,
    pub a_t_se: f64,
    /// μ_k,cm = k |a_cm| / g.
    pub mu_cm: f64,
    pub mu_cm_se: f64,
    /// μ_k,t = 2 |a_t| / (5 k g).
    pub mu_t: f64,
    pub mu_t_se: f64,
    /// |F_net| = μ_k,cm m g / k, N.
    pub f_net: f64,
    /// |τ_net| = μ_k,cm m g R, N m.
    pub tau_net: f64,
}

/// The sliding phase after the first impact (at t = 0): from the first frame after
/// it until the measured v_cm and v_t meet (the last frame before they cross).
pub fn sliding_window(m: &Measured) -> Option<(f64, f64)> {
    // Frames without a measured v_t (a track without its rim mark) cannot say.
    let after: Vec<usize> = (0..m.t.len())
        .filter(|&i| m.t[i] > 0.0 && m.v_t[i].is_finite())
        .collect();
    let first = *after.first()?;
    let sign0 = (m.v_cm[first] - m.v_t[first]).signum();
    let last = after
        .iter()
        .take_while(|&&i| (m.v_cm[i] - m.v_t[i]).signum() == sign0)
        .last()?;
    Some((m.t[first], m.t[*last]))
}

/// Line fits of v_cm and v_t over `[from, to]` (default: the sliding phase).
pub fn line_fit(
    m: &Measured,
    scene: &Scene,
    window: (Option<f64>, Option<f64>),
) -> Result<LineFit, FitError> {
    let auto = sliding_window(m);
    // Without v_t the window still starts at the first frame after the impact.
    let first_after = m.t.iter().copied().find(|&t| t > 0.0);
    let from = window
        .0
        .or(auto.map(|w| w.0))
        .or(first_after)
        .ok_or_else(|| {
            FitError::Data("no measured points after the impact (t > 0) to fit".into())
        })?;
    let to = window.1.or(auto.map(|w| w.1)).unwrap_or(from);
    let idx: Vec<usize> = (0..m.t.len())
        .filter(|&i| m.t[i] >= from - 1e-12 && m.t[i] <= to + 1e-12)
        .collect();
    if idx.len() < 3 {
        return Err(FitError::Data(format!(
            "the window {from} … {to} s holds {} points, allowed at least 3",
            idx.len()
        )));
    }
    let ts: Vec<f64> = idx.iter().map(|&i| m.t[i]).collect();
    let cm = line(&ts, &idx.iter().map(|&i| m.v_cm[i]).collect::<Vec<_>>());
    // v_t where it was measured (all of a velocity file; none of a track without mark).
    let with_t: Vec<usize> = idx
        .iter()
        .copied()
        .filter(|&i| m.v_t[i].is_finite())
        .collect();
    let vt = if with_t.len() >= 3 {
        line(
            &with_t.iter().map(|&i| m.t[i]).collect::<Vec<_>>(),
            &with_t.iter().map(|&i| m.v_t[i]).collect::<Vec<_>>(),
        )
    } else {
        Line {
            intercept: f64::NAN,
            slope: f64::NAN,
            slope_se: f64::NAN,
            intercept_se: f64::NAN,
        }
    };
    let k = scene.k();
    let g = scene.g;
    let mass = scene.left.mass;
    let mu_cm = k * cm.slope.abs() / g;
    Ok(LineFit {
        from,
        to,
        points: idx.len(),
        a_cm: cm.slope.abs(),
        a_cm_se: cm.slope_se,
        a_t: vt.slope.abs(),
        a_t_se: vt.slope_se,
        mu_cm,
        mu_cm_se: k * cm.slope_se / g,
        mu_t: 2.0 * vt.slope.abs() / (5.0 * k * g),
        mu_t_se: 2.0 * vt.slope_se / (5.0 * k * g),
        f_net: mu_cm * mass * g / k,
        tau_net: mu_cm * mass * g * scene.radius,
    })
}

/// Which scene values a model fit may change.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Free {
    Mu,
    V0,
    Restitution,
}

impl Free {
    /// The name on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Free::Mu => "mu",
            Free::V0 => "v0",
            Free::Restitution => "restitution",
        }
    }
}

/// The whole-model least-squares fit.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ModelFit {
    pub mu: f64,
    pub mu_se: f64,
    /// Fitted v0 and e (the scene's when not free) and their standard errors.
    pub v0: f64,
    pub v0_se: Option<f64>,
    pub restitution: f64,
    pub restitution_se: Option<f64>,
    /// Root-mean-square residual over all v_cm and v_t points used, m/s.
    pub rms: f64,
    pub points: usize,
    pub regime_predicted: Regime,
    pub regime_observed: Regime,
    /// Speeds within ± this of zero count as "at rest" for both regimes, m/s.
    pub rest_band: f64,
    /// The model's rolling speed after the impact, m/s (positive back toward).
    pub v_roll: f64,
    /// The predicted regime with its margin against the rest band, in words (as the
    /// app and `simulate` say it): "recollide (v' = +0.028 m/s, within …)".
    pub verdict: String,
    /// True when the predicted v' lies inside the rest band.
    pub indistinguishable_from_rest: bool,
    /// True when what was observed agrees with the prediction (the same regime, or
    /// rest where the prediction cannot be told from rest).
    pub agrees: bool,
    /// Free values the data cannot pin down, and why (their `_se` is null).
    pub not_identified: Vec<NotIdentified>,
    /// Set when the series had more than [`MAX_MODEL_POINTS`] frames: the fit used
    /// every this-many-th frame.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub every: Option<usize>,
}

/// A free value without an uncertainty, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NotIdentified {
    pub parameter: &'static str,
    pub reason: String,
}

/// A fitted value's bounds: restitution lies in [0, 1], μ_k above 0.
fn bounds(f: Free) -> (f64, f64) {
    match f {
        Free::Mu => (1e-6, f64::INFINITY),
        Free::V0 => (f64::NEG_INFINITY, f64::INFINITY),
        Free::Restitution => (0.0, 1.0),
    }
}

/// `p` moved into the bounds of each free value.
fn clamped(free: &[Free], p: &[f64]) -> Vec<f64> {
    free.iter()
        .zip(p)
        .map(|(f, v)| {
            let (lo, hi) = bounds(*f);
            v.clamp(lo, hi)
        })
        .collect()
}

/// Standard errors from the normal matrix `jtj` (residual variance `s2`) of the free
/// values `p`: a value on its bound, one the data do not depend on, and values along a
/// direction the data cannot see (an eigenvector of the scaled matrix with a
/// negligible eigenvalue) get no ± but a reason; the rest from the inverse of the
/// matrix without them (the others held at their fitted values).
fn uncertainties(
    jtj: &[Vec<f64>],
    s2: f64,
    free: &[Free],
    p: &[f64],
) -> (Vec<Option<f64>>, Vec<NotIdentified>) {
    let n = free.len();
    let mut out = vec![None; n];
    let mut why = Vec::new();
    let mut active = Vec::new();
    for i in 0..n {
        let (lo, hi) = bounds(free[i]);
        if p[i] <= lo || p[i] >= hi {
            why.push(NotIdentified {
                parameter: free[i].name(),
                reason: format!(
                    "at its bound {} = {}: the best fit lies on the edge of the allowed range, so it has no ± (fix it and fit the others)",
                    free[i].name(),
                    p[i]
                ),
            });
        } else if !(jtj[i][i] > 0.0 && jtj[i][i].is_finite()) {
            why.push(NotIdentified {
                parameter: free[i].name(),
                reason: "the fitted points do not depend on it".into(),
            });
        } else {
            active.push(i);
        }
    }
    // Scaled to unit diagonal, the matrix's small eigenvalues are directions the data
    // cannot see; a value with a large share in one is not identifiable.
    let m = active.len();
    let d: Vec<f64> = active.iter().map(|&i| jtj[i][i].sqrt()).collect();
    let scaled = nalgebra::DMatrix::from_fn(m, m, |a, b| jtj[active[a]][active[b]] / (d[a] * d[b]));
    let mut unseen = vec![false; m];
    if m > 0 {
        let eig = scaled.symmetric_eigen();
        for (k, &lambda) in eig.eigenvalues.iter().enumerate() {
            if lambda > 1e-9 {
                continue;
            }
            let v = eig.eigenvectors.column(k);
            let involved: Vec<usize> = (0..m).filter(|&a| v[a].abs() > 0.2).collect();
            for &a in &involved {
                if unseen[a] {
                    continue;
                }
                unseen[a] = true;
                let others: Vec<&str> = involved
                    .iter()
                    .filter(|&&b| b != a)
                    .map(|&b| free[active[b]].name())
                    .collect();
                why.push(NotIdentified {
                    parameter: free[active[a]].name(),
                    reason: if others.is_empty() {
                        "not identifiable from these data".into()
                    } else {
                        format!(
                            "not identifiable from these data: correlated with {}",
                            others.join(", ")
                        )
                    },
                });
            }
        }
    }
    let kept: Vec<usize> = (0..m).filter(|&a| !unseen[a]).collect();
    let sub: Vec<Vec<f64>> = kept
        .iter()
        .map(|&a| kept.iter().map(|&b| jtj[active[a]][active[b]]).collect())
        .collect();
    if let Some(cov) = inverse(&sub) {
        for (x, &a) in kept.iter().enumerate() {
            let se = (s2 * cov[x][x]).sqrt();
            if se.is_finite() {
                out[active[a]] = Some(se);
            } else {
                why.push(NotIdentified {
                    parameter: free[active[a]].name(),
                    reason: "its uncertainty cannot be computed from these data".into(),
                });
            }
        }
    }
    (out, why)
}

/// Scene with the fit parameters `p` applied.
fn with(scene: &Scene, free: &[Free], p: &[f64]) -> Scene {
    let mut s = *scene;
    for (f, &v) in free.iter().zip(p) {
        match f {
            Free::Mu => s.mu = v.max(1e-6),
            Free::V0 => {
                s.left.v0 = v;
                s.right.v0 = v;
            }
            Free::Restitution => s.restitution = v.clamp(0.0, 1.0),
        }
    }
    s
}

/// Points the model fit uses: all but the frames that straddle an impact of the
/// model `scene` (a frame holding a jump measures neither side of it).
fn fit_points(m: &Measured, scene: &Scene, target: Target) -> Vec<usize> {
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
enum Target {
    /// v_cm and v_t, each residual divided by its uncertainty when the data carry one.
    Velocity,
    /// The centre's x (m) and the mark's angle as an arc of the contact circle (r θ, m).
    Position,
}

/// Residuals of `scene` against `m` at `idx`, weighted (divided by the points'
/// uncertainties, where known) or not; points not measured (NaN) are left out.
fn residuals_of(
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
fn nuisance(m: &Measured, target: Target) -> usize {
    match (target, m.angle.is_some()) {
        (Target::Velocity, _) => 0,
        (Target::Position, false) => 2,
        (Target::Position, true) => 3,
    }
}

fn residuals(scene: &Scene, m: &Measured, idx: &[usize], target: Target) -> Vec<f64> {
    residuals_of(scene, m, idx, target, true)
}

/// Solves the small system `a x = b` (LU with partial pivoting, nalgebra).
fn solve(a: Vec<Vec<f64>>, b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    let m = nalgebra::DMatrix::from_fn(n, n, |i, j| a[i][j]);
    let x = m.lu().solve(&nalgebra::DVector::from_vec(b))?;
    x.iter()
        .all(|v| v.is_finite())
        .then(|| x.iter().copied().collect())
}

fn inverse(a: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let inv = nalgebra::DMatrix::from_fn(n, n, |i, j| a[i][j]).try_inverse()?;
    Some(
        (0..n)
            .map(|i| (0..n).map(|j| inv[(i, j)]).collect())
            .collect(),
    )
}

/// Every `k`-th frame of `m`, with `k` the smallest that leaves at most
/// [`MAX_MODEL_POINTS`] frames; `None` if the series is short enough already.
pub fn thinned(m: &Measured) -> Option<(Measured, usize)> {
    let n = m.t.len();
    if n <= MAX_MODEL_POINTS {
        return None;
    }
    let k = n.div_ceil(MAX_MODEL_POINTS);
    let pick = |v: &[f64]| -> Vec<f64> { v.iter().step_by(k).copied().collect() };
    let pick_opt = |v: &Option<Vec<f64>>| v.as_deref().map(pick);
    Some((
        Measured {
            t: pick(&m.t),
            v_cm: pick(&m.v_cm),
            v_t: pick(&m.v_t),
            v_cm_sigma: pick_opt(&m.v_cm_sigma),
            v_t_sigma: pick_opt(&m.v_t_sigma),
            x: pick_opt(&m.x),
            angle: pick_opt(&m.angle),
        },
        k,
    ))
}

/// Least squares of the exact model's v_cm and v_t of the left ball to all measured
/// points (Levenberg–Marquardt, numerical derivatives), free `free`. Points with an
/// uncertainty (`v_cm_sigma`, `v_t_sigma`) count by its inverse square; a v_t that
/// was not measured (NaN) is left out. A series longer than [`MAX_MODEL_POINTS`] is
/// [`thinned`] first. Stops when `progress` says so.
pub fn model_fit(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    progress: &dyn Progress,
) -> Result<ModelFit, FitError> {
    model_fit_of(scene, m, free, Target::Velocity, progress)
}

/// Least squares of the exact model's positions to a tracked series (`m.x`, and
/// `m.angle` when the rim mark was tracked): no differentiation, so its uncertainty
/// comes from independent residuals. `rms` is then in metres (x and r θ).
pub fn position_fit(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    progress: &dyn Progress,
) -> Result<ModelFit, FitError> {
    if m.x.is_none() {
        return Err(FitError::Data(
            "the data hold no positions (a velocity file): no position fit".into(),
        ));
    }
    model_fit_of(scene, m, free, Target::Position, progress)
}

fn model_fit_of(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    target: Target,
    progress: &dyn Progress,
) -> Result<ModelFit, FitError> {
    let thin = thinned(m);
    let (m, every) = match &thin {
        Some((t, k)) => (t, Some(*k)),
        None => (m, None),
    };
    let evals = Evals {
        progress,
        done: std::cell::Cell::new(0),
    };
    let start: Vec<f64> = free
        .iter()
        .map(|f| match f {
            Free::Mu => scene.mu.max(0.01),
            Free::V0 => scene.left.v0,
            Free::Restitution => scene.restitution,
        })
        .collect();
    // μ first, by a global scan and golden-section search: the cost is not smooth
    // where impacts move past data points, and local steps get caught there.
    let mut p = start;
    if let Some(i) = free.iter().position(|f| *f == Free::Mu) {
        p[i] = scan_mu(scene, m, free, &p, i, target, &evals)?;
    }
    // Then every free value together from there, on the frames away from the model's
    // impacts (chosen again once the fit has moved them).
    let mut idx = fit_points(m, &with(scene, free, &p), target);
    for _ in 0..3 {
        p = least_squares(scene, m, free, &idx, p, target, &evals)?;
        let next = fit_points(m, &with(scene, free, &p), target);
        if next == idx {
            break;
        }
        idx = next;
    }
    let fitted = with(scene, free, &p);
    let r = residuals(&fitted, m, &idx, target);
    let n = p.len();
    let cost: f64 = r.iter().map(|x| x * x).sum();
    let s2 = cost / r.len().saturating_sub(n + nuisance(m, target)).max(1) as f64;
    let j = jacobian(scene, m, free, &idx, &p, &r, target);
    let (ses, not_identified) = uncertainties(&normal_matrix(&j), s2, free, &p);
    let se = |f: Free| free.iter().position(|x| *x == f).and_then(|i| ses[i]);
    let rest_band = rest_band(m);
    let v_roll = closed_form::v_roll(fitted.k(), fitted.restitution, fitted.left.v0);
    let derived = Derived::of(&fitted);
    let sol = engine::solve(&fitted, &Span::default());
    let verdict = Verdict::of(&sol, &derived, Some(rest_band));
    let regime_observed = observed_after(
        m,
        rest_band,
        sliding_window(m)
            .map(|w| w.1)
            .or_else(|| rolling_time(&fitted)),
    );
    Ok(ModelFit {
        mu: fitted.mu,
        mu_se: se(Free::Mu).unwrap_or(f64::NAN),
        v0: fitted.left.v0,
        v0_se: se(Free::V0),
        restitution: fitted.restitution,
        restitution_se: se(Free::Restitution),
        rms: {
            // In the data's own units, whatever the weights.
            let raw = residuals_of(&fitted, m, &idx, target, false);
            (raw.iter().map(|x| x * x).sum::<f64>() / raw.len().max(1) as f64).sqrt()
        },
        points: idx.len(),
        regime_predicted: derived.regime,
        regime_observed,
        rest_band,
        v_roll,
        verdict: verdict.text("±"),
        indistinguishable_from_rest: verdict.indistinguishable_from_rest(),
        agrees: verdict.agrees_with(regime_observed),
        not_identified,
        every,
    })
}

/// Mean squared residual of `scene`, over the frames away from its own impacts.
fn mean_cost(scene: &Scene, m: &Measured, target: Target) -> f64 {
    let idx = fit_points(m, scene, target);
    let r = residuals(scene, m, &idx, target);
    r.iter().map(|x| x * x).sum::<f64>() / r.len().max(1) as f64
}

/// The μ that minimises [`mean_cost`]: a log-spaced scan of 0.01 … 1, then golden
/// section between the neighbours of the best scan point.
fn scan_mu(
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

fn normal_matrix(j: &[Vec<f64>]) -> Vec<Vec<f64>> {
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
fn jacobian(
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
fn least_squares(
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

/// Speeds within ± this of zero count as rest: three times the scatter of the
/// measured points about straight lines over the sliding phase (the data's own
/// resolution), at least 2 cm/s.
pub fn rest_band(m: &Measured) -> f64 {
    let noise = sliding_window(m)
        .and_then(|(from, to)| {
            let idx: Vec<usize> = (0..m.t.len())
                .filter(|&i| m.t[i] >= from && m.t[i] <= to)
                .collect();
            (idx.len() >= 3).then(|| {
                let ts: Vec<f64> = idx.iter().map(|&i| m.t[i]).collect();
                let mut sq = 0.0;
                for series in [&m.v_cm, &m.v_t] {
                    let ys: Vec<f64> = idx.iter().map(|&i| series[i]).collect();
                    let l = line(&ts, &ys);
                    sq += ts
                        .iter()
                        .zip(&ys)
                        .map(|(t, y)| (y - l.intercept - l.slope * t).powi(2))
                        .sum::<f64>();
                }
                (sq / (2 * idx.len()) as f64).sqrt()
            })
        })
        .unwrap_or(0.0);
    (3.0 * noise).max(0.02)
}

/// What the data show after the sliding phase: the mean v_cm of the left ball from
/// the end of sliding to the end of the series (or the next impact, a jump in v_cm).
pub fn observed_regime(m: &Measured, band: f64) -> Regime {
    observed_after(m, band, sliding_window(m).map(|w| w.1))
}

/// When the left ball of `scene` rolls again after the first impact: where a series
/// without v_t has its sliding phase end.
fn rolling_time(scene: &Scene) -> Option<f64> {
    let sol = engine::solve(scene, &Span::default());
    sol.events
        .iter()
        .find(|e| {
            e.t > 0.0
                && e.kind == crate::physics::solution::EventKind::Rolling
                && e.ball != crate::physics::solution::Who::Right
        })
        .map(|e| e.t)
}

/// [`observed_regime`] with the end of the sliding phase given.
fn observed_after(m: &Measured, band: f64, to: Option<f64>) -> Regime {
    let Some(to) = to else {
        return Regime::Rest;
    };
    let after: Vec<usize> = (0..m.t.len()).filter(|&i| m.t[i] > to).collect();
    let mut speeds = Vec::new();
    for w in after.windows(2) {
        speeds.push(m.v_cm[w[0]]);
        // A jump down of more than half the speed is the next impact.
        if m.v_cm[w[1]] < m.v_cm[w[0]] - 0.5 * m.v_cm[w[0]].abs().max(band) {
            break;
        }
    }
    if speeds.is_empty() {
        return Regime::Rest;
    }
    let mean = speeds.iter().sum::<f64>() / speeds.len() as f64;
    if mean > band {
        Regime::Recollide
    } else if mean < -band {
        Regime::Depart
    } else {
        Regime::Rest
    }
}

/// The paper's table 1 (b in m; |a_cm|, μ_k,cm, |F_net|, |a_t|, μ_k,t, |τ_net|).
pub const PAPER_TABLE: [(f64, [f64; 6]); 3] = [
    (0.035, [2.15, 0.17, 0.36, 2.92, 0.15, 0.008]),
    (0.044, [2.86, 0.18, 0.48, 2.61, 0.17, 0.009]),
    (0.049, [3.26, 0.17, 0.54, 2.00, 0.16, 0.008]),
];

/// The paper's row for groove width `b`, if it is one of its three.
pub fn paper_row(b: f64) -> Option<[f64; 6]> {
    PAPER_TABLE
        .iter()
        .find(|(w, _)| (w - b).abs() < 1e-9)
        .map(|(_, row)| *row)
}

/// Both fits of one series.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Fits {
    pub line_fit: LineFit,
    pub model_fit: ModelFit,
}

/// Line fit over `window` and model fit with `free`, on `scene` and `m`; stops when
/// `progress` says so (`FitError::Cancelled`).
pub fn fit_all(
    scene: &Scene,
    m: &Measured,
    window: (Option<f64>, Option<f64>),
    free: &[Free],
    progress: &dyn Progress,
) -> Result<Fits, FitError> {
    let model_fit = model_fit(scene, m, free, progress)?;
    // Without v_t the data cannot say when sliding ends: the fitted model does.
    let window = match window {
        (from, None) if !m.has_v_t() => {
            let fitted = Scene {
                mu: model_fit.mu,
                restitution: model_fit.restitution,
                left: crate::physics::scene::Ball {
                    v0: model_fit.v0,
                    ..scene.left
                },
                right: crate::physics::scene::Ball {
                    v0: model_fit.v0,
                    ..scene.right
                },
                ..*scene
            };
            (from, rolling_time(&fitted).map(|t| t - 1e-9))
        }
        w => w,
    };
    let fits = Fits {
        line_fit: line_fit(m, scene, window)?,
        model_fit,
    };
    check_finite(&fits, m.has_v_t())?;
    Ok(fits)
}

/// Every number a fit reports is finite, or the fit is an error: an overflowing
/// scene (v0 = 1e308) must not print "RMS residual inf" or "± NaN". Without a
/// measured v_t (a track without a rim mark) its line fit is not a number by design.
fn check_finite(f: &Fits, has_v_t: bool) -> Result<(), FitError> {
    let (l, m) = (&f.line_fit, &f.model_fit);
    let spin = |v: f64| if has_v_t { v } else { 0.0 };
    let named = [
        ("model fit v0 error", m.v0_se.unwrap_or(0.0)),
        ("model fit e error", m.restitution_se.unwrap_or(0.0)),
        ("line fit a_cm", l.a_cm),
        ("line fit a_t", spin(l.a_t)),
        ("line fit μ_k,cm", l.mu_cm),
        ("line fit μ_k,t", spin(l.mu_t)),
        ("model fit μ_k", m.mu),
        ("model fit μ_k error", m.mu_se),
        ("model fit v0", m.v0),
        ("model fit e", m.restitution),
        ("model fit RMS residual", m.rms),
        ("model fit rolling speed v'", m.v_roll),
    ];
    let bad: Vec<&str> = named
        .iter()
        .filter(|(_, v)| !v.is_finite())
        .map(|(n, _)| *n)
        .collect();
    if bad.is_empty() {
        return Ok(());
    }
    Err(FitError::Data(format!(
        "the fit gives no finite {} for this scene and data (an overflow: check that v0, masses and times are of lab size)",
        bad.join(", ")
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_on_its_bound_or_along_an_unseen_direction_gets_a_reason_not_a_nan() {
        let free = [Free::Mu, Free::V0, Free::Restitution];
        // μ and v0 enter the data only as μ + v0 (equal columns), e is fine.
        let jtj = vec![
            vec![4.0, 4.0, 1.0],
            vec![4.0, 4.0, 1.0],
            vec![1.0, 1.0, 9.0],
        ];
        let (se, why) = uncertainties(&jtj, 1.0, &free, &[0.2, 0.5, 0.8]);
        assert_eq!(se[0], None);
        assert_eq!(se[1], None);
        // e alone: 1/sqrt(9).
        assert!((se[2].unwrap() - 1.0 / 3.0).abs() < 1e-12, "{se:?}");
        assert_eq!(why.len(), 2, "{why:?}");
        assert!(why[0].reason.contains("correlated with v0"), "{why:?}");
        assert!(why[1].reason.contains("correlated with mu"), "{why:?}");
        // e at its upper bound: μ and v0 from the matrix without it.
        let jtj = vec![
            vec![4.0, 0.0, 1.0],
            vec![0.0, 16.0, 1.0],
            vec![1.0, 1.0, 9.0],
        ];
        let (se, why) = uncertainties(&jtj, 1.0, &free, &[0.2, 0.5, 1.0]);
        assert!((se[0].unwrap() - 0.5).abs() < 1e-12);
        assert!((se[1].unwrap() - 0.25).abs() < 1e-12);
        assert_eq!(se[2], None);
        assert_eq!(why[0].parameter, "restitution");
        assert!(why[0].reason.contains("bound"), "{why:?}");
    }
}
