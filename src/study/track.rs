//! From a position track to velocities with uncertainties: finds the first impact and
//! the direction toward the other ball in the motion itself, differentiates the centre
//! and the rim mark's angle by local quadratic least squares (Savitzky–Golay on even
//! frames) that never reach across an impact, and fits the model both to the derived
//! velocities and directly to the positions.
//!
//! The window rule: the position scatter σ is estimated from third differences of the
//! centre track (they cancel constant acceleration; their variance is 20σ², the
//! median is used so impacts do not count). The half-window is the smallest n ≥ 2
//! frames whose slope standard error `σ / (Δt · sqrt(n(n+1)(2n+1)/3))` is at most
//! [`Derive::target_se`] (default 1 cm/s), but at most [`Derive::max_half_window`]
//! (default 50 ms: longer windows smear the end of sliding). Near an impact and the
//! ends of the track the window keeps only the frames on its own side, so it shrinks.

use serde::Serialize;

use crate::input::data::{self, DataError, Measured, Reading, Series};
use crate::input::tracks::Track;
use crate::physics::scene::Scene;
use crate::study::fit::{self, FitError, Free, ModelFit};

/// How to derive velocities from a track.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Derive {
    /// Half-width of the local fit, s; `None`: chosen by the rule of the module doc.
    pub half_window: Option<f64>,
    /// Standard error of v_cm the rule aims at, m/s. Default 0.01.
    pub target_se: f64,
    /// Largest half-width the rule may choose, s. Default 0.05.
    pub max_half_window: f64,
    /// Time of the first impact in the file's time, s; found in the motion when `None`.
    pub impact_at: Option<f64>,
    /// Fewest frames needed on each side of the first impact. Default 5.
    pub min_frames: usize,
}

impl Default for Derive {
    fn default() -> Self {
        Derive {
            half_window: None,
            target_se: 0.01,
            max_half_window: 0.05,
            impact_at: None,
            min_frames: 5,
        }
    }
}

/// What the derivation found in the track, for the user to check.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Found {
    /// "Tracker multi-track", "Tracker single-track" or "CSV".
    pub format: &'static str,
    pub centre: String,
    /// The rim mark's track, `None` when there is none (then v_t is not measured).
    pub mark: Option<String>,
    /// Frames with a centre position.
    pub frames: usize,
    /// Frames per second (from the median spacing).
    pub frame_rate: f64,
    /// Estimated scatter of a tracked position, m.
    pub scatter: f64,
    /// Half-width of the local fits, s, and in frames.
    pub half_window: f64,
    pub half_window_frames: usize,
    /// The first impact in the file's time, s (becomes t = 0).
    pub impact_t: f64,
    /// True when found in the motion, false when given.
    pub impact_detected: bool,
    /// The file's x of the centre at the first impact, m (becomes x = 0).
    pub impact_x: f64,
    /// +1 when the other ball lies toward the file's +x, −1 when toward −x.
    pub direction: f64,
    /// Speed of the centre toward the other ball just before the impact, m/s.
    pub approach_speed: f64,
    pub frames_before: usize,
    pub frames_after: usize,
    /// Later impacts found in the motion, s from the first; the derivative does not
    /// reach across them either.
    pub later_impacts: Vec<f64>,
    /// Median distance of the mark from the centre, m.
    pub mark_radius: Option<f64>,
}

impl Found {
    /// What was found, in a few lines for people.
    pub fn describe(&self) -> String {
        let name = |n: &str| {
            if n.is_empty() {
                "x, y".to_string()
            } else {
                format!("'{n}'")
            }
        };
        let mut s = format!(
            "position track ({}): centre {}, {}; {} frames at {:.1} frames/s, scatter ≈ {:.2} mm\n",
            self.format,
            name(&self.centre),
            match &self.mark {
                Some(m) => format!(
                    "rim mark {} (at {:.1} mm from the centre)",
                    name(m),
                    1e3 * self.mark_radius.unwrap_or(f64::NAN)
                ),
                None => "no rim mark: v_t is not measured, the fits use v_cm (x) only".to_string(),
            },
            self.frames,
            self.frame_rate,
            1e3 * self.scatter
        );
        s += &format!(
            "first impact {} at t = {:.4} s, x = {:.2} mm of the file ({} frames before, {} after); the other ball lies toward {}x; approach speed {:.3} m/s\n",
            if self.impact_detected {
                "found"
            } else {
                "given"
            },
            self.impact_t,
            1e3 * self.impact_x,
            self.frames_before,
            self.frames_after,
            if self.direction > 0.0 { "+" } else { "−" },
            self.approach_speed
        );
        s += &format!(
            "velocities by local quadratic fits over ±{:.1} ms ({} frames), never across an impact",
            1e3 * self.half_window,
            self.half_window_frames
        );
        if !self.later_impacts.is_empty() {
            let later: Vec<String> = self
                .later_impacts
                .iter()
                .map(|t| format!("{t:.3}"))
                .collect();
            s += &format!(" (later impacts at t = {} s)", later.join(", "));
        }
        s.push('\n');
        s
    }
}

/// Why a track cannot be used.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct TrackError(pub String);

/// A local quadratic least-squares fit about `t0`: value, slope and the slope's
/// standard error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Local {
    pub value: f64,
    pub slope: f64,
    pub slope_se: f64,
}

/// Quadratic least squares of `ys` on `ts` about `t0`: coefficients (c0, c1, c2) of
/// `c0 + c1 τ + c2 τ²` (τ = t − t0), the (1,1) element of (AᵀA)⁻¹ and the residual sum
/// of squares; `None` with fewer than 3 distinct times.
fn quadratic(ts: &[f64], ys: &[f64], t0: f64) -> Option<([f64; 3], f64, f64)> {
    if ts.len() < 3 {
        return None;
    }
    // Scale τ by the window's span so the normal equations stay well conditioned.
    let h = ts
        .iter()
        .map(|t| (t - t0).abs())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut s = [0.0; 5];
    let mut b = [0.0; 3];
    for (&t, &y) in ts.iter().zip(ys) {
        let u = (t - t0) / h;
        let mut p = 1.0;
        for (k, sk) in s.iter_mut().enumerate() {
            *sk += p;
            if k < 3 {
                b[k] += p * y;
            }
            p *= u;
        }
    }
    let a = [[s[0], s[1], s[2]], [s[1], s[2], s[3]], [s[2], s[3], s[4]]];
    let det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    if !det.is_finite() || det.abs() <= 1e-12 * s[0].powi(3) {
        return None;
    }
    // The inverse of the symmetric matrix: its adjugate over the determinant.
    let adj = [
        [
            a[1][1] * a[2][2] - a[1][2] * a[2][1],
            a[0][2] * a[2][1] - a[0][1] * a[2][2],
            a[0][1] * a[1][2] - a[0][2] * a[1][1],
        ],
        [
            a[1][2] * a[2][0] - a[1][0] * a[2][2],
            a[0][0] * a[2][2] - a[0][2] * a[2][0],
            a[0][2] * a[1][0] - a[0][0] * a[1][2],
        ],
        [
            a[1][0] * a[2][1] - a[1][1] * a[2][0],
            a[0][1] * a[2][0] - a[0][0] * a[2][1],
            a[0][0] * a[1][1] - a[0][1] * a[1][0],
        ],
    ];
    let inv = |i: usize, j: usize| adj[i][j] / det;
    let c: [f64; 3] =
        std::array::from_fn(|i| (0..3).map(|j| inv(i, j) * b[j]).sum::<f64>() / h.powi(i as i32));
    let rss: f64 = ts
        .iter()
        .zip(ys)
        .map(|(&t, &y)| {
            let u = t - t0;
            (y - c[0] - c[1] * u - c[2] * u * u).powi(2)
        })
        .sum();
    Some((c, inv(1, 1) / (h * h), rss))
}

/// The local fit of `ys` at `ts[i]` over the indices `lo..=hi`; the residual variance
/// is pooled with `sigma²` worth `PRIOR` degrees of freedom, so a window of 3–5 frames
/// does not claim a tiny error by chance.
fn local(ts: &[f64], ys: &[f64], i: usize, lo: usize, hi: usize, sigma: f64) -> Option<Local> {
    const PRIOR: f64 = 4.0;
    let (c, v11, rss) = quadratic(&ts[lo..=hi], &ys[lo..=hi], ts[i])?;
    let dof = (hi + 1 - lo) as f64 - 3.0;
    let s2 = (rss + PRIOR * sigma * sigma) / (dof + PRIOR);
    Some(Local {
        value: c[0],
        slope: c[1],
        slope_se: (s2 * v11).sqrt(),
    })
}

/// Least-squares slope of a straight line through `ys` over `ts`.
fn line_slope(ts: &[f64], ys: &[f64]) -> f64 {
    let n = ts.len() as f64;
    let mt = ts.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for (t, y) in ts.iter().zip(ys) {
        sxy += (t - mt) * (y - my);
        sxx += (t - mt) * (t - mt);
    }
    sxy / sxx
}

/// Scatter of a smooth series from its third differences (robust: the median).
fn scatter(ys: &[f64]) -> f64 {
    let mut d: Vec<f64> = ys
        .windows(4)
        .map(|w| (w[3] - 3.0 * w[2] + 3.0 * w[1] - w[0]).abs())
        .filter(|v| v.is_finite())
        .collect();
    if d.is_empty() {
        return 0.0;
    }
    let mid = d.len() / 2;
    let (_, m, _) = d.select_nth_unstable_by(mid, f64::total_cmp);
    *m / 0.6745 / 20f64.sqrt()
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    let mid = v.len() / 2;
    let (_, m, _) = v.select_nth_unstable_by(mid, f64::total_cmp);
    *m
}

/// An impact located between frames: its time and the centre's position then.
#[derive(Clone, Copy, Debug)]
struct Kink {
    t: f64,
    x: f64,
    /// Velocity just before it, m/s, in the file's x.
    before: f64,
}

/// Velocity jumps across each frame: slope of the line over the `k` frames after it
/// minus that over the `k` frames before (each side at least 3 frames).
fn jumps(ts: &[f64], xs: &[f64], k: usize) -> Vec<(f64, f64)> {
    let n = ts.len();
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(k), (i + k).min(n - 1));
            if i < a + 2 || b < i + 2 {
                return (0.0, f64::NAN);
            }
            let before = line_slope(&ts[a..=i], &xs[a..=i]);
            let after = line_slope(&ts[i..=b], &xs[i..=b]);
            (after - before, before)
        })
        .collect()
}

/// Where the two quadratics fitted on each side of frame `i` (frames `lo..i` and
/// `i+1..=hi`) meet: the impact time and place. Falls back to frame `i` itself.
fn locate(ts: &[f64], xs: &[f64], i: usize, lo: usize, hi: usize) -> (f64, f64) {
    let t0 = ts[i];
    let fallback = (t0, xs[i]);
    if i < lo + 3 || hi < i + 3 {
        return fallback;
    }
    let (Some((b, _, _)), Some((a, _, _))) = (
        quadratic(&ts[lo..i], &xs[lo..i], t0),
        quadratic(&ts[i + 1..=hi], &xs[i + 1..=hi], t0),
    ) else {
        return fallback;
    };
    let (qa, qb, qc) = (a[2] - b[2], a[1] - b[1], a[0] - b[0]);
    let span = (ts[i - 1] - t0, ts[i + 1] - t0);
    let mut roots = Vec::new();
    if qa.abs() > 1e-300 {
        let disc = qb * qb - 4.0 * qa * qc;
        if disc >= 0.0 {
            let q = -0.5 * (qb + qb.signum() * disc.sqrt());
            roots.push(q / qa);
            if q != 0.0 {
                roots.push(qc / q);
            }
        }
    }
    if qb != 0.0 {
        roots.push(-qc / qb);
    }
    match roots
        .into_iter()
        .filter(|r| r.is_finite() && *r >= span.0 && *r <= span.1)
        .min_by(|p, q| p.abs().total_cmp(&q.abs()))
    {
        Some(tau) => (t0 + tau, b[0] + b[1] * tau + b[2] * tau * tau),
        None => fallback,
    }
}

/// The impacts in the centre's motion (`ts`, `xs` without gaps), first one first.
fn impacts(
    ts: &[f64],
    xs: &[f64],
    k: usize,
    sigma: f64,
    dt: f64,
    given: Option<f64>,
) -> Result<Vec<Kink>, TrackError> {
    let n = ts.len();
    let j = jumps(ts, xs, k);
    // Standard error of one jump: two line slopes over k+1 frames.
    let m = (k + 1) as f64;
    let se = 2f64.sqrt() * sigma / (dt * (m * (m * m - 1.0) / 12.0).sqrt());
    let size = |i: usize| j[i].0.abs();
    let is_peak = |i: usize| {
        j[i].0.is_finite()
            && (i.saturating_sub(k)..=(i + k).min(n - 1)).all(|l| {
                size(l).partial_cmp(&size(i)) != Some(std::cmp::Ordering::Greater) || l == i
            })
    };
    let first = match given {
        Some(at) => {
            let i = ts.partition_point(|&t| t < at).min(n - 1);
            let i = if i > 0 && (at - ts[i - 1]) < (ts[i] - at) {
                i - 1
            } else {
                i
            };
            if j[i].1.is_nan() {
                return Err(TrackError(format!(
                    "the given impact at t = {at} s has fewer than 3 frames on one side, at least 3 needed on each"
                )));
            }
            i
        }
        None => {
            let biggest = (0..n)
                .filter(|&i| j[i].0.is_finite())
                .map(size)
                .fold(0.0, f64::max);
            if biggest.partial_cmp(&(8.0 * se)) != Some(std::cmp::Ordering::Greater) {
                return Err(TrackError(format!(
                    "no impact found: the centre's velocity never changes sharply (largest change {biggest:.3} m/s, noise {se:.3} m/s); give its time with --impact-at"
                )));
            }
            (0..n)
                .find(|&i| size(i) >= 0.5 * biggest && is_peak(i))
                .expect("the biggest jump is a peak")
        }
    };
    let (jump, before) = j[first];
    let dir = before.signum();
    if before == 0.0 || jump * dir >= 0.0 || jump.abs() < before.abs() / 3.0 {
        if first < k {
            return Err(TrackError(format!(
                "the track starts too late: its sharpest change of velocity is at its start (t = {:.4} s); it needs frames from before the first impact",
                ts[first]
            )));
        }
        return Err(TrackError(format!(
            "no impact found: at t = {:.4} s the centre's velocity goes from {before:.3} to {:.3} m/s, an impact slows the ball by at least a third",
            ts[first],
            before + jump
        )));
    }
    // Before the first impact the ball approaches at a steady speed: a track that
    // starts after it (the ball moving away, then back to a later impact) must not
    // pass its later impact off as the first.
    if given.is_none() && first > 0 {
        let mean = (xs[first] - xs[0]) / (ts[first] - ts[0]) * dir;
        if mean < 0.5 * before.abs() {
            return Err(TrackError(format!(
                "the track starts too late: before the sharpest slow-down (t = {:.4} s) the ball does not approach steadily (mean {mean:.3} m/s against {:.3} m/s); it needs frames from before the first impact",
                ts[first],
                before.abs()
            )));
        }
    }
    // The side fits that place the impact reach over 60 ms (the motion on each side is
    // one parabola for much longer than that in a lab groove), at least 2k frames.
    let wide = (2 * k).max(6).max((0.06 / dt).round() as usize);
    let mut found = Vec::new();
    let mut lo = 0;
    let mut i = first;
    loop {
        let next = (i + k + 1..n).find(|&l| {
            size(l) >= (0.1 * jump.abs()).max(8.0 * se) && j[l].0 * dir < 0.0 && is_peak(l)
        });
        let hi = next.map_or(n - 1, |l| l - 1).min(i + wide);
        let (t, x) = if found.is_empty() && given.is_some() {
            (given.unwrap_or(ts[i]), xs[i])
        } else {
            // Again about the frame nearest the located impact, so that no frame on
            // the wrong side of it bends the side fits.
            let mut at = i;
            let mut place = locate(ts, xs, at, lo.max(at.saturating_sub(wide)), hi);
            for _ in 0..3 {
                let near = ts.partition_point(|&t| t < place.0).min(n - 1);
                let near = if near > 0 && place.0 - ts[near - 1] < ts[near] - place.0 {
                    near - 1
                } else {
                    near
                };
                if near == at || near <= lo || near >= hi {
                    break;
                }
                at = near;
                place = locate(ts, xs, at, lo.max(at.saturating_sub(wide)), hi);
            }
            place
        };
        found.push(Kink {
            t,
            x,
            before: j[i].1,
        });
        match next {
            Some(l) => {
                lo = i + 1;
                i = l;
            }
            None => break,
        }
    }
    Ok(found)
}

/// Unwraps angles (rad) so that neighbours differ by less than π.
fn unwrap(angles: &mut [f64]) {
    let tau = std::f64::consts::TAU;
    let mut shift = 0.0;
    for i in 1..angles.len() {
        let d = angles[i] + shift - angles[i - 1];
        shift -= tau * (d / tau).round();
        angles[i] += shift;
    }
}

/// Derivatives of `ys` at each of `ts` by local quadratic fits over ±`n` frames that
/// stay between consecutive `cuts` (impact times).
fn derivatives(ts: &[f64], ys: &[f64], n: usize, cuts: &[f64], sigma: f64) -> Vec<Option<Local>> {
    let len = ts.len();
    // The first index of each piece between cuts.
    let mut starts = vec![0];
    for &c in cuts {
        let s = ts.partition_point(|&t| t <= c);
        if s > *starts.last().unwrap_or(&0) && s < len {
            starts.push(s);
        }
    }
    starts.push(len);
    let mut out = Vec::with_capacity(len);
    for p in starts.windows(2) {
        let (a, b) = (p[0], p[1] - 1);
        for i in a..=b {
            let lo = i.saturating_sub(n).max(a);
            let hi = (i + n).min(b);
            out.push(local(ts, ys, i, lo, hi, sigma));
        }
    }
    out
}

/// Derives the left ball's measured series from a track: t from the first impact,
/// v_cm (and v_t from the mark, with `contact_radius` r = kR) with uncertainties, and
/// the positions. The tracked ball plays the model's left ball.
pub fn derive(
    track: &Track,
    contact_radius: f64,
    opts: &Derive,
) -> Result<(Measured, Found), TrackError> {
    let rows: Vec<usize> = (0..track.t.len())
        .filter(|&i| track.x[i].is_finite())
        .collect();
    let ts: Vec<f64> = rows.iter().map(|&i| track.t[i]).collect();
    let xs: Vec<f64> = rows.iter().map(|&i| track.x[i]).collect();
    let need = 2 * opts.min_frames.max(3);
    if ts.len() < need {
        return Err(TrackError(format!(
            "{} frames with a centre position, at least {need} needed ({} before and after the impact)",
            ts.len(),
            opts.min_frames
        )));
    }
    let dt = median(ts.windows(2).map(|w| w[1] - w[0]).collect());
    let sigma = scatter(&xs).max(1e-7);
    let n = match opts.half_window {
        Some(h) => ((h / dt).round() as usize).max(2),
        None => {
            let cap = ((opts.max_half_window / dt).floor() as usize).max(2);
            (2..=cap)
                .find(|&n| {
                    let s = (n * (n + 1) * (2 * n + 1)) as f64 / 3.0;
                    sigma / (dt * s.sqrt()) <= opts.target_se
                })
                .unwrap_or(cap)
        }
    };
    let kinks = impacts(&ts, &xs, n.max(3), sigma, dt, opts.impact_at)?;
    let first = kinks[0];
    let dir = first.before.signum();
    let before = ts.iter().filter(|&&t| t < first.t).count();
    let after = ts.len() - before;
    for (count, side) in [(before, "before"), (after, "after")] {
        if count < opts.min_frames {
            return Err(TrackError(format!(
                "only {count} frames {side} the impact at t = {:.4} s, at least {} needed to fit the motion {side} it",
                first.t, opts.min_frames
            )));
        }
    }
    let cuts: Vec<f64> = kinks.iter().map(|k| k.t).collect();
    let dx = derivatives(&ts, &xs, n, &cuts, sigma);
    // The mark's angle about the centre: θ = atan2(dx, dy), 0 with the mark on top,
    // growing as it moves toward the other ball over the top.
    let spin = track.mark.as_ref().map(|(mx, my)| {
        let valid: Vec<usize> = rows
            .iter()
            .copied()
            .filter(|&i| mx[i].is_finite() && my[i].is_finite() && track.y[i].is_finite())
            .collect();
        let at: Vec<f64> = valid.iter().map(|&i| track.t[i]).collect();
        let mut theta: Vec<f64> = valid
            .iter()
            .map(|&i| (dir * (mx[i] - track.x[i])).atan2(my[i] - track.y[i]))
            .collect();
        unwrap(&mut theta);
        let radius = median(
            valid
                .iter()
                .map(|&i| (mx[i] - track.x[i]).hypot(my[i] - track.y[i]))
                .collect(),
        );
        let s_theta = scatter(&theta).max(1e-7);
        let d = derivatives(&at, &theta, n, &cuts, s_theta);
        (at, theta, d, radius)
    });
    // The spin's sign: the balls roll before the impact, so there v_t has v_cm's sign
    // (a mirrored or upside-down picture flips the angle's sense, not the physics).
    let spin_sign = spin.as_ref().map_or(1.0, |(at, _, d, _)| {
        let dot: f64 = at
            .iter()
            .zip(d)
            .filter(|(t, _)| **t < first.t)
            .filter_map(|(t, l)| {
                let i = ts.partition_point(|x| x < t);
                Some(l.as_ref()?.slope * dx.get(i)?.as_ref()?.slope * dir)
            })
            .sum();
        if dot < 0.0 { -1.0 } else { 1.0 }
    });
    let mut m = Measured::default();
    let (mut sig_cm, mut sig_t, mut pos, mut ang) = (vec![], vec![], vec![], vec![]);
    // Angle at the impact: from the last local fit before it.
    let theta0 = spin.as_ref().and_then(|(at, _, d, _)| {
        let i = at.partition_point(|&t| t < first.t);
        let (j, l) = (
            i.checked_sub(1).or(Some(i))?,
            d.get(i.checked_sub(1).unwrap_or(i))?.as_ref()?,
        );
        Some(l.value + l.slope * (first.t - at[j]))
    });
    for (i, l) in dx.iter().enumerate() {
        let Some(l) = l else { continue };
        m.t.push(ts[i] - first.t);
        m.v_cm.push(dir * l.slope);
        sig_cm.push(l.slope_se);
        pos.push(dir * (xs[i] - first.x));
        let (vt, st, a) = match &spin {
            Some((at, theta, d, _)) => {
                let k = at.partition_point(|&t| t < ts[i]);
                match (at.get(k) == Some(&ts[i]), d.get(k).copied().flatten()) {
                    (true, Some(ld)) => (
                        spin_sign * ld.slope * contact_radius,
                        ld.slope_se * contact_radius,
                        spin_sign * (theta[k] - theta0.unwrap_or(f64::NAN)),
                    ),
                    _ => (f64::NAN, f64::NAN, f64::NAN),
                }
            }
            None => (f64::NAN, f64::NAN, f64::NAN),
        };
        m.v_t.push(vt);
        sig_t.push(st);
        ang.push(a);
    }
    m.v_cm_sigma = Some(sig_cm);
    m.x = Some(pos);
    if spin.is_some() {
        m.v_t_sigma = Some(sig_t);
        m.angle = Some(ang);
    }
    let found = Found {
        format: track.format,
        centre: track.centre_name.clone(),
        mark: spin.as_ref().and(track.mark_name.clone()),
        frames: ts.len(),
        frame_rate: 1.0 / dt,
        scatter: sigma,
        half_window: n as f64 * dt,
        half_window_frames: n,
        impact_t: first.t,
        impact_detected: opts.impact_at.is_none(),
        impact_x: first.x,
        direction: dir,
        approach_speed: first.before.abs(),
        frames_before: before,
        frames_after: after,
        later_impacts: kinks[1..].iter().map(|k| k.t - first.t).collect(),
        mark_radius: spin.as_ref().map(|s| s.3),
    };
    Ok((m, found))
}

/// A data file read and, for a position track, its velocities derived.
#[derive(Clone, Debug, PartialEq)]
pub struct Loaded {
    pub measured: Measured,
    /// What the derivation found; `None` for a velocity file.
    pub found: Option<Found>,
}

/// Reads a velocity file or a position track (`input::data::read`) and derives the
/// velocities of a track with the scene's contact radius r = kR.
pub fn load(
    text: &str,
    file: &str,
    reading: &Reading,
    scene: &Scene,
    derive_opts: &Derive,
) -> Result<Loaded, DataError> {
    match data::read(text, file, reading)? {
        Series::Velocities(measured) => Ok(Loaded {
            measured,
            found: None,
        }),
        Series::Positions(track) => {
            let opts = Derive {
                impact_at: reading.impact_at.or(derive_opts.impact_at),
                ..*derive_opts
            };
            let (measured, found) =
                derive(&track, scene.k() * scene.radius, &opts).map_err(|e| DataError {
                    file: file.to_string(),
                    what: e.0,
                })?;
            Ok(Loaded {
                measured,
                found: Some(found),
            })
        }
    }
}

/// Both model fits of a tracked series, side by side.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TrackFits {
    /// The model's v_cm and v_t against the derived velocities, weighted by their
    /// uncertainties.
    pub velocity: ModelFit,
    /// The model's x(t) (and the mark's angle) against the track itself.
    pub position: ModelFit,
    /// False when no rim mark was tracked: both fits use the centre only.
    pub uses_spin: bool,
}

/// Fits the model to the derived velocities and directly to the positions of `m`
/// (which must carry `x`), freeing `free`.
pub fn fit_tracks(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    progress: &dyn crate::study::Progress,
) -> Result<TrackFits, FitError> {
    Ok(TrackFits {
        velocity: fit::model_fit(scene, m, free, progress)?,
        position: fit::position_fit(scene, m, free, progress)?,
        uses_spin: m.has_v_t(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_fit_is_exact_on_a_parabola_with_uneven_frames() {
        let ts = [0.0, 0.011, 0.019, 0.032, 0.04, 0.052];
        let ys: Vec<f64> = ts.iter().map(|t| 1.0 + 2.0 * t - 3.0 * t * t).collect();
        let l = local(&ts, &ys, 2, 0, 5, 0.0).unwrap();
        // Slope 2 − 6 t at t = 0.019; rounding only.
        assert!((l.slope - (2.0 - 6.0 * 0.019)).abs() < 1e-9, "{l:?}");
        assert!(l.slope_se < 1e-6);
    }

    #[test]
    fn scatter_of_white_noise_on_a_parabola() {
        // Deterministic ±σ alternation has third differences of 8σ: the estimate is
        // 8σ / 0.6745 / √20 ≈ 2.65σ; what matters here is that the parabola drops out.
        let ys: Vec<f64> = (0..50)
            .map(|i| {
                let t = i as f64 * 0.01;
                0.5 * t * t + if i % 2 == 0 { 1e-3 } else { -1e-3 }
            })
            .collect();
        let s = scatter(&ys);
        assert!((s - 8e-3 / 0.6745 / 20f64.sqrt()).abs() < 1e-9, "{s}");
    }

    #[test]
    fn unwrap_removes_jumps_of_two_pi() {
        let mut a = vec![3.0, -3.0, -2.5];
        unwrap(&mut a);
        assert!((a[1] - (-3.0 + std::f64::consts::TAU)).abs() < 1e-12);
        assert!(a[2] > a[1]);
    }
}
