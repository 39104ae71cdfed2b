//! Fitting the model to measured velocity series of the left ball: the paper's line
//! fits over the sliding phase (table 1), and a least-squares fit of the exact model
//! to every point, with uncertainties and the regime compared with what was seen.

use serde::Serialize;

use crate::input::data::Measured;
use crate::physics::closed_form;
use crate::physics::derived::{Derived, Regime};
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
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
    let after: Vec<usize> = (0..m.t.len()).filter(|&i| m.t[i] > 0.0).collect();
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
    let from = window.0.or(auto.map(|w| w.0)).ok_or_else(|| {
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
    let vt = line(&ts, &idx.iter().map(|&i| m.v_t[i]).collect::<Vec<_>>());
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Free {
    Mu,
    V0,
    Restitution,
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
    /// Set when the series had more than [`MAX_MODEL_POINTS`] frames: the fit used
    /// every this-many-th frame.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub every: Option<usize>,
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
fn fit_points(m: &Measured, scene: &Scene) -> Vec<usize> {
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

fn residuals(scene: &Scene, m: &Measured, idx: &[usize]) -> Vec<f64> {
    let t0 = m.t[0].min(-1e-3);
    let sol = engine::solve(
        scene,
        &Span {
            t_start: t0,
            t_end: None,
        },
    );
    let mut r = Vec::with_capacity(2 * idx.len());
    for &i in idx {
        let s = sol.at(m.t[i]);
        r.push(s.left.v - m.v_cm[i]);
        r.push(s.left.u - m.v_t[i]);
    }
    r
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
    let pick = |v: &[f64]| v.iter().step_by(k).copied().collect();
    Some((
        Measured {
            t: pick(&m.t),
            v_cm: pick(&m.v_cm),
            v_t: pick(&m.v_t),
        },
        k,
    ))
}

/// Least squares of the exact model's v_cm and v_t of the left ball to all measured
/// points (Levenberg–Marquardt, numerical derivatives), free `free`; a series longer
/// than [`MAX_MODEL_POINTS`] is [`thinned`] first. Stops when `progress` says so.
pub fn model_fit(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
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
        p[i] = scan_mu(scene, m, free, &p, i, &evals)?;
    }
    // Then every free value together from there, on the frames away from the model's
    // impacts (chosen again once the fit has moved them).
    let mut idx = fit_points(m, &with(scene, free, &p));
    for _ in 0..3 {
        p = least_squares(scene, m, free, &idx, p, &evals)?;
        let next = fit_points(m, &with(scene, free, &p));
        if next == idx {
            break;
        }
        idx = next;
    }
    let fitted = with(scene, free, &p);
    let r = residuals(&fitted, m, &idx);
    let n = p.len();
    let cost: f64 = r.iter().map(|x| x * x).sum();
    let s2 = cost / (r.len() - n) as f64;
    let j = jacobian(scene, m, free, &idx, &p, &r);
    let cov = inverse(&normal_matrix(&j)).unwrap_or_else(|| vec![vec![f64::NAN; n]; n]);
    let se = |f: Free| {
        free.iter()
            .position(|x| *x == f)
            .map(|i| (s2 * cov[i][i]).sqrt())
            .filter(|x| x.is_finite())
    };
    let rest_band = rest_band(m);
    let v_roll = closed_form::v_roll(fitted.k(), fitted.restitution, fitted.left.v0);
    let regime_predicted = if v_roll.abs() <= rest_band {
        Regime::Rest
    } else {
        Derived::of(&fitted).regime
    };
    Ok(ModelFit {
        mu: fitted.mu,
        mu_se: se(Free::Mu).unwrap_or(f64::NAN),
        v0: fitted.left.v0,
        v0_se: se(Free::V0),
        restitution: fitted.restitution,
        restitution_se: se(Free::Restitution),
        rms: (cost / r.len() as f64).sqrt(),
        points: idx.len(),
        regime_predicted,
        regime_observed: observed_regime(m, rest_band),
        rest_band,
        v_roll,
        every,
    })
}

/// Mean squared residual of `scene`, over the frames away from its own impacts.
fn mean_cost(scene: &Scene, m: &Measured) -> f64 {
    let idx = fit_points(m, scene);
    let r = residuals(scene, m, &idx);
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
    evals: &Evals,
) -> Result<f64, FitError> {
    let cost = |mu: f64| {
        evals.next()?;
        let mut q = p.to_vec();
        q[i] = mu;
        Ok(mean_cost(&with(scene, free, &q), m))
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
) -> Vec<Vec<f64>> {
    (0..p.len())
        .map(|j| {
            let mut h = 1e-6 * p[j].abs().max(0.1);
            if free[j] == Free::Restitution && p[j] + h > 1.0 {
                h = -h;
            }
            let mut q = p.to_vec();
            q[j] += h;
            residuals(&with(scene, free, &q), m, idx)
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
        residuals(&with(scene, free, p), m, idx)
            .iter()
            .map(|r| r * r)
            .sum()
    };
    let mut lambda = 1e-3;
    let mut c = cost(&p);
    for _ in 0..100 {
        evals.next()?;
        let r0 = residuals(&with(scene, free, &p), m, idx);
        let j = jacobian(scene, m, free, idx, &p, &r0);
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
            let q: Vec<f64> = p.iter().zip(&step).map(|(a, b)| a + b).collect();
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
    let Some((_, to)) = sliding_window(m) else {
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
    Ok(Fits {
        line_fit: line_fit(m, scene, window)?,
        model_fit: model_fit(scene, m, free, progress)?,
    })
}
