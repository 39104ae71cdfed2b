//! From a position track to velocities with uncertainties: finds the first impact and
//! the direction toward the other ball in the motion itself, differentiates the centre
//! and the rim mark's angle by local quadratic least squares (Savitzky–Golay on even
//! frames) that never reach across an impact, and fits the model both to the derived
//! velocities and directly to the positions.
//!
//! The window rule: the position scatter σ is estimated from third differences of the
//! centre track (they cancel constant acceleration; their variance is 20σ², the
//! median is used so impacts do not count; divided differences where frames are
//! missing). The half-window is the smallest n ≥ 2 frames whose slope standard error
//! `σ / (Δt · sqrt(n(n+1)(2n+1)/3))` is at most [`Derive::target_se`] (default 1 cm/s),
//! but at most [`Derive::max_half_window`] (default 50 ms: longer windows smear the end
//! of sliding). Near an impact and the
//! ends of the track the window keeps only the frames on its own side, so it shrinks.

pub mod derivative;
mod found;
mod impacts;
mod sigmas;

use super::series::{Measured, MeasuredParts, Stencil, Stencils, Track};

use super::line::{Line, line};

pub use derivative::Local;
pub use found::{Found, MarkLeftOut, Skipped, more_runs, ordinal, runs_text};
pub use impacts::TrackError;

use derivative::{MIN_HALF_WINDOW, derivatives, median, scatter, unwrap};
use found::{runs, steady_every};
use impacts::impacts;

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
    /// Fewest frames needed on each side of the first impact. Default 4: the line
    /// through them (the approach speed) and the quadratic that places the impact
    /// each keep a degree of freedom for their scatter, and the fit's ± covers the
    /// truth as often with 4 frames on a side as with 5 or more
    /// (`tests/it/data/tracks.rs`, `four_frames_on_a_side_fit_with_an_honest_uncertainty`).
    pub min_frames: usize,
}

impl Default for Derive {
    fn default() -> Self {
        Derive {
            half_window: None,
            target_se: 0.01,
            max_half_window: 0.05,
            impact_at: None,
            min_frames: 4,
        }
    }
}

/// The half-window of the local fits, frames: the one asked for, else the smallest
/// n ≥ 2 whose slope's standard error (frame spacing `dt`, position noise `sigma`)
/// reaches the target, at most the largest half-window allowed.
fn half_window(dt: f64, sigma: f64, opts: &Derive) -> usize {
    match opts.half_window {
        Some(h) => ((h / dt).round() as usize).max(MIN_HALF_WINDOW),
        None => {
            let cap = ((opts.max_half_window / dt).floor() as usize).max(MIN_HALF_WINDOW);
            (MIN_HALF_WINDOW..=cap)
                .find(|&n| {
                    let s = (n * (n + 1) * (2 * n + 1)) as f64 / 3.0;
                    sigma / (dt * s.sqrt()) <= opts.target_se
                })
                .unwrap_or(cap)
        }
    }
}

/// The rim mark's angle about the centre and its local fits.
struct Spin {
    /// Times of the frames with a mark (and a centre), s.
    at: Vec<f64>,
    /// The unwrapped angle θ = atan2(dx, dy), 0 with the mark on top, growing as it
    /// moves toward the other ball over the top.
    theta: Vec<f64>,
    fits: Vec<Option<Local>>,
    /// The mark's median distance from the centre, m.
    radius: f64,
    /// Its distance's 10th and 90th percentiles, m: a mark on the ball keeps one.
    range: [f64; 2],
    /// Those frames' rows of the track.
    valid: Vec<usize>,
    /// The frames in a step of its angle's unwrapping: 1, or k for a mark followed
    /// in every k-th frame only that surely turns slowly enough in k frames.
    step_frames: usize,
}

/// The mark's [`Spin`] over the centre's `rows` (moving in direction `dir`), fitted
/// over ±`n` frames (`dt` apart) between the impacts `cuts`, the first at `t_impact`
/// where the ball arrives at `speed`; `None` without a mark.
fn spin_of(
    track: &Track,
    (rows, dir): (&[usize], f64),
    (n, dt): (usize, f64),
    cuts: &[f64],
    (speed, t_impact): (f64, f64),
) -> Option<Spin> {
    track.mark().as_ref()?;
    let valid: Vec<usize> = rows
        .iter()
        .copied()
        .filter(|&i| {
            let f = track.at(i);
            [f.mark_x, f.mark_y, f.y].iter().all(|v| v.is_finite())
        })
        .collect();
    // A mark never seen with its centre is no mark to derive a spin from.
    if valid.is_empty() {
        return None;
    }
    let at: Vec<f64> = valid.iter().map(|&i| track.at(i).t).collect();
    let seen: Vec<f64> = valid
        .iter()
        .map(|&i| {
            let (dx, dy) = track.at(i).mark_offset();
            (dir * dx).atan2(dy)
        })
        .collect();
    let mut distances: Vec<f64> = valid
        .iter()
        .map(|&i| {
            let (dx, dy) = track.at(i).mark_offset();
            dx.hypot(dy)
        })
        .collect();
    distances.sort_by(f64::total_cmp);
    // The fits reach across neither an impact nor a gap whose turn is unknown; a
    // mark followed every k-th frame has its gaps counted in its own steps where it
    // surely turns slowly enough in them to be unwrapped.
    let (mut step, mut theta) = (cadence(&at, dt), seen.clone());
    let mut gaps = unwrap(&at, &mut theta, step);
    let radius = median(distances.clone());
    if step > dt && !turns_slowly(&at, &theta, step, (speed, t_impact), radius) {
        (step, theta) = (dt, seen);
        gaps = unwrap(&at, &mut theta, dt);
    }
    let mut cuts = [cuts, &gaps].concat();
    cuts.sort_by(f64::total_cmp);
    // `valid` is not empty (above), nor then are its distances.
    let decile = |q: usize| {
        distances
            .get(distances.len().saturating_sub(1) * q / 10)
            .copied()
            .unwrap_or(f64::NAN)
    };
    let range = [decile(1), decile(9)];
    let s_theta = scatter(&at, &theta).max(1e-7);
    let fits = derivatives(&at, &theta, n, &cuts, s_theta);
    Some(Spin {
        at,
        theta,
        fits,
        radius,
        range,
        valid,
        step_frames: (step / dt).round() as usize,
    })
}

/// The step between the mark's frames at the times `at`: the frames' `dt`, or k of
/// them where the mark was followed in every k-th frame only (a student clicking
/// the rim every second frame in Tracker): the median step, in whole frames.
fn cadence(at: &[f64], dt: f64) -> f64 {
    let steps: Vec<f64> = at
        .windows(2)
        .filter_map(|w| match *w {
            [a, b] => Some(b - a),
            _ => None,
        })
        .collect();
    let frames = (median(steps) / dt).round();
    if frames.is_finite() && frames > 1.0 {
        frames * dt
    } else {
        dt
    }
}

/// Whether the mark's angles `theta` at `at`, unwrapped in steps of `step` (k
/// frames), surely turn by less than half a turn a step: by under 2π/5 each step, and
/// before the impact at `t_impact` slowly enough for the ball arriving at `speed` to
/// roll on a radius under 1.2 times the mark's distance `radius` from the centre.
/// A mark turning by nearly a whole turn a step (every 8th frame of a paper ball at
/// 60 frames/s: 7.6 rad) shows a slow turn, or a slow turn backwards: within 2π/5 of
/// a whole turn, on a rolling radius at least 4 times the ball's (its contact radius
/// kR, k over 0.3 for a groove up to b = 1.9 R).
fn turns_slowly(
    at: &[f64],
    theta: &[f64],
    step: f64,
    (speed, t_impact): (f64, f64),
    radius: f64,
) -> bool {
    let mut rates = Vec::new();
    for (t, a) in at.windows(2).zip(theta.windows(2)) {
        let (&[t0, t1], &[a0, a1]) = (t, a) else {
            continue;
        };
        if t1 - t0 > 1.5 * step {
            continue;
        }
        if (a1 - a0).abs() > 0.4 * std::f64::consts::PI {
            return false;
        }
        if t1 < t_impact {
            rates.push((a1 - a0).abs() / (t1 - t0));
        }
    }
    let spin = median(rates);
    spin > 0.0 && speed / spin <= 1.2 * radius
}

impl Spin {
    /// k where the mark, missing in the runs `gaps` (frames `dt` apart), was
    /// followed in every k-th frame only and unwrapped in those steps.
    fn every(&self, gaps: &[[f64; 2]], dt: f64) -> Option<usize> {
        steady_every(gaps, dt).filter(|&k| k == self.step_frames)
    }

    /// The spin's sign: the balls roll before the impact at `t_impact`, so there v_t
    /// has v_cm's sign (`dx`: the centre's fits at `ts`; a mirrored or upside-down
    /// picture flips the angle's sense, not the physics).
    fn sign(&self, ts: &[f64], dx: &[Option<Local>], t_impact: f64, dir: f64) -> f64 {
        let dot: f64 = self
            .at
            .iter()
            .zip(&self.fits)
            .filter(|(t, _)| **t < t_impact)
            .filter_map(|(t, l)| {
                let i = ts.partition_point(|x| x < t);
                Some(l.as_ref()?.slope * dx.get(i)?.as_ref()?.slope * dir)
            })
            .sum();
        if dot < 0.0 { -1.0 } else { 1.0 }
    }

    /// The angle at the impact at `t_impact`: from the last local fit before it.
    fn angle_at(&self, t_impact: f64) -> Option<f64> {
        let i = self.at.partition_point(|&t| t < t_impact);
        let j = i.checked_sub(1).unwrap_or(i);
        let l = self.fits.get(j)?.as_ref()?;
        Some(l.value + l.slope * (t_impact - self.at.get(j)?))
    }

    /// At the centre's frame `t`: v_t (ω times the contact radius `r`), its standard
    /// error, the angle turned since the impact (from `theta0` there), all signed by
    /// `sign`, and the fit's stencil; NaN (and no stencil) where the mark has no fit.
    fn rim_at(
        &self,
        t: f64,
        sign: f64,
        theta0: Option<f64>,
        r: f64,
    ) -> (f64, f64, f64, Option<Stencil>) {
        let k = self.at.partition_point(|&a| a < t);
        match (
            self.at.get(k) == Some(&t),
            self.fits.get(k).copied().flatten(),
        ) {
            (true, Some(ld)) => (
                sign * ld.slope * r,
                ld.slope_se * r,
                sign * (self.theta.get(k).copied().unwrap_or(f64::NAN)
                    - theta0.unwrap_or(f64::NAN)),
                Some(ld.stencil),
            ),
            _ => (f64::NAN, f64::NAN, f64::NAN, None),
        }
    }
}

/// Fewest position scatters a rim mark must lie from the centre for its angle to be
/// used: nearer, its angle turns with the noise more than with the ball.
const MARK_SCATTERS: f64 = 10.0;

/// Within this many position scatters the mark lies at the centre within the noise:
/// the same track given as centre and mark (it put the mark at 0.0 mm and derived a
/// v_t of noise), refused.
const MARK_AT_CENTRE_SCATTERS: f64 = 3.0;

/// The mark's spin, kept when the mark lies [`MARK_SCATTERS`] position scatters or more
/// from the centre; left out (`Ok((None, Some(what was left out)))`, the fits then use the
/// centre alone and say so) when nearer but off the centre by more than the noise (a
/// video whose centres jitter by a few pixels: the mark is real, its angle is noise);
/// refused, saying how near, when within [`MARK_AT_CENTRE_SCATTERS`] of it.
fn mark_off_the_centre(
    spin: Option<Spin>,
    scatter: f64,
    name: Option<&str>,
) -> Result<(Option<Spin>, Option<MarkLeftOut>), TrackError> {
    match spin {
        Some(s) if s.radius < MARK_AT_CENTRE_SCATTERS * scatter => {
            Err(TrackError::MarkAtTheCentre {
                radius: s.radius,
                scatter,
                scatters: MARK_AT_CENTRE_SCATTERS,
            })
        }
        Some(s) if s.radius < MARK_SCATTERS * scatter => Ok((
            None,
            Some(MarkLeftOut {
                name: name.unwrap_or_default().to_string(),
                radius: s.radius,
                scatters: MARK_SCATTERS,
                range: None,
            }),
        )),
        Some(s) if wanders(s.range, s.radius, scatter) => Ok((
            None,
            Some(MarkLeftOut {
                name: name.unwrap_or_default().to_string(),
                radius: s.radius,
                scatters: MARK_SCATTERS,
                range: Some(s.range),
            }),
        )),
        spin => Ok((spin, None)),
    }
}

/// True when a mark's distance from the centre (10th to 90th percentile `range`,
/// median `radius`) changes by more than half its median and six position scatters:
/// a mark on the ball keeps one distance, so this is another thing (a second run
/// side by side came and went from 0 to 45 mm and was read as a mark).
fn wanders(range: [f64; 2], radius: f64, scatter: f64) -> bool {
    range[1] - range[0] > 0.5 * radius + 6.0 * scatter
}

/// How many frames come before and after the impact at `impact_t`, or why fewer than
/// `min_frames` on a side cannot be fitted.
fn frames_around(
    ts: &[f64],
    impact_t: f64,
    min_frames: usize,
) -> Result<(usize, usize), TrackError> {
    let before = ts.iter().filter(|&&t| t < impact_t).count();
    let after = ts.len() - before;
    for (count, side) in [(before, "before"), (after, "after")] {
        if count < min_frames {
            return Err(TrackError::FewFramesBeside {
                count,
                side,
                at: impact_t,
                min: min_frames,
            });
        }
    }
    Ok((before, after))
}

/// Derives the left ball's measured series from a track: t from the first impact,
/// v_cm (and v_t from the mark, with `contact_radius` r = kR) with uncertainties, and
/// the positions. The tracked ball plays the model's left ball.
pub fn derive(
    track: &Track,
    contact_radius: f64,
    opts: &Derive,
) -> Result<(Measured, Found), TrackError> {
    let rows = centre_rows(track);
    let ts: Vec<f64> = rows.iter().map(|&i| track.at(i).t).collect();
    let xs: Vec<f64> = rows.iter().map(|&i| track.at(i).x).collect();
    enough_frames(ts.len(), opts)?;
    let dt = frame_step(&ts);
    let sigma = scatter(&ts, &xs).max(1e-7);
    let n = half_window(dt, sigma, opts);
    let kinks = impacts(&ts, &xs, n.max(3), sigma, dt, opts.impact_at)?;
    let first = first_kink(&kinks)?;
    let dir = first.before.signum();
    let (before, after) = frames_around(&ts, first.t, opts.min_frames)?;
    let approach = approach_line(&ts, &xs, before);
    let cuts: Vec<f64> = kinks.iter().map(|k| k.t).collect();
    let dx = derivatives(&ts, &xs, n, &cuts, sigma);
    let arrival = (approach.slope.abs(), first.t);
    let spin = spin_of(track, (&rows, dir), (n, dt), &cuts, arrival);
    let (spin, mark_left_out) = mark_off_the_centre(spin, sigma, track.mark_name())?;
    let spin_sign = spin
        .as_ref()
        .map_or(1.0, |s| s.sign(&ts, &dx, first.t, dir));
    let mut m = MeasuredParts::default();
    let (mut sig_cm, mut sig_t, mut pos, mut ang) = (vec![], vec![], vec![], vec![]);
    // The stencils in the model's time (first impact at 0), as the points are.
    let shifted = |ts: &[f64]| ts.iter().map(|t| t - first.t).collect();
    let mut stencils = Stencils {
        centre_times: shifted(&ts),
        centre_sign: dir,
        scatter: sigma,
        mark_times: spin.as_ref().map(|s| shifted(&s.at)).unwrap_or_default(),
        mark_frames: spin.as_ref().map_or_else(Vec::new, |s| {
            mark_frames(track, &rows, &s.valid, dir, spin_sign)
        }),
        ..Stencils::default()
    };
    let shift = |s: Stencil| Stencil {
        t0: s.t0 - first.t,
        ..s
    };
    let theta0 = spin.as_ref().and_then(|s| s.angle_at(first.t));
    for ((l, &t), &x) in dx.iter().zip(&ts).zip(&xs) {
        let Some(l) = l else { continue };
        m.t.push(t - first.t);
        m.v_cm.push(dir * l.slope);
        sig_cm.push(l.slope_se);
        stencils.v_cm.push(Some(shift(l.stencil)));
        pos.push(dir * (x - first.x));
        let (vt, st, a, stencil) = match &spin {
            Some(spin) => spin.rim_at(t, spin_sign, theta0, contact_radius),
            None => (f64::NAN, f64::NAN, f64::NAN, None),
        };
        stencils.v_t.push(stencil.map(shift));
        m.v_t.push(vt);
        sig_t.push(st);
        ang.push(a);
    }
    // Recorded with x away from the other ball: turned, and said so; the scale's ±.
    (m.mirrored, m.scale_rel_se) = (dir < 0.0, track.scale_rel_se());
    m.v_cm_sigma = Some(sig_cm);
    m.stencils = Some(std::sync::Arc::new(stencils));
    m.x = Some(pos);
    (m.x_sigma, m.angle_sigma) = sigmas::point_sigmas(track, &rows, &dx, spin.is_some());
    if spin.is_some() {
        (m.v_t_sigma, m.angle) = (Some(sig_t), Some(ang));
    }
    let (centre_gaps, mark_missing, mark_gaps) = gaps(track, &rows, &ts, spin.as_ref());
    let found = Found {
        format: track.format(),
        centre: track.centre_name().to_string(),
        mark: spin.as_ref().and(track.mark_name().map(str::to_string)),
        frames: ts.len(),
        frames_dropped: track.t().len() - ts.len(),
        centre_gaps,
        mark_missing,
        mark_every: spin.as_ref().and_then(|s| s.every(&mark_gaps, dt)),
        mark_gaps,
        skipped: Skipped::of(track.t(), dt),
        frame_rate: 1.0 / dt,
        scatter: sigma,
        half_window: n as f64 * dt,
        half_window_frames: n,
        half_window_widened_from: widened_from(opts, dt),
        impact_t: first.t,
        impact_detected: opts.impact_at.is_none(),
        impact_x: first.x,
        direction: dir,
        approach_speed: approach.slope.abs(),
        approach_speed_se: with_scale(approach.slope_se, approach.slope, m.scale_rel_se),
        frames_before: before,
        frames_after: after,
        later_impacts: kinks.iter().skip(1).map(|k| k.t - first.t).collect(),
        mark_radius: spin.as_ref().map(|s| s.radius),
        mark_left_out,
    };
    Ok((Measured::new(m)?, found))
}

/// The half-width asked for (`--window`), s, where it was under the fewest frames a
/// local quadratic needs (so widened to them).
fn widened_from(opts: &Derive, dt: f64) -> Option<f64> {
    opts.half_window
        .filter(|h| ((h / dt).round() as usize) < MIN_HALF_WINDOW)
}

/// The rows of `track` with a centre position.
fn centre_rows(track: &Track) -> Vec<usize> {
    (0..track.t().len())
        .filter(|&i| track.at(i).x.is_finite())
        .collect()
}

/// The first impact of those `impacts` found (it finds one or says why not).
fn first_kink(kinks: &[impacts::Kink]) -> Result<impacts::Kink, TrackError> {
    kinks.first().copied().ok_or(TrackError::NoSharpChange {
        biggest: 0.0,
        noise: f64::NAN,
    })
}

/// The straight line through the centre's first `before` frames: the approach.
fn approach_line(ts: &[f64], xs: &[f64], before: usize) -> Line {
    line(
        ts.get(..before).unwrap_or_default(),
        xs.get(..before).unwrap_or_default(),
    )
}

/// At least `2 · max(min_frames, 3)` frames with a centre position (`frames`).
fn enough_frames(frames: usize, opts: &Derive) -> Result<(), TrackError> {
    let need = 2 * opts.min_frames.max(3);
    if frames < need {
        return Err(TrackError::FewFrames {
            frames,
            need,
            min: opts.min_frames,
        });
    }
    Ok(())
}

/// The track's gaps, said and never filled in: the rows without a centre (as runs of
/// the file's times), and the centre's frames `rows` (at times `ts`) without the rim
/// mark, where one is tracked at all (how many, and as runs).
fn gaps(
    track: &Track,
    rows: &[usize],
    ts: &[f64],
    spin: Option<&Spin>,
) -> (Vec<[f64; 2]>, usize, Vec<[f64; 2]>) {
    let no_centre: Vec<bool> = track.x().iter().map(|x| !x.is_finite()).collect();
    let no_mark: Vec<bool> = match spin {
        Some(sp) => rows
            .iter()
            .map(|i| sp.valid.binary_search(i).is_err())
            .collect(),
        None => Vec::new(),
    };
    (
        runs(track.t(), &no_centre),
        no_mark.iter().filter(|&&m| m).count(),
        runs(ts, &no_mark),
    )
}

/// For each frame `valid` of the mark (rows of `track`): its centre's frame among
/// `rows`, and how a small move of the centre (x, y) turns the derived angle (its
/// spin-signed ∂θ/∂x, ∂θ/∂y; a move of the mark turns it the other way). The
/// centre's noise reaches both v_cm and v_t this way.
fn mark_frames(
    track: &Track,
    rows: &[usize],
    valid: &[usize],
    dir: f64,
    spin_sign: f64,
) -> Vec<(usize, f64, f64)> {
    if track.mark().is_none() {
        return Vec::new();
    }
    valid
        .iter()
        .map(|&i| {
            let (dx, dy) = track.at(i).mark_offset();
            let dx = dir * dx;
            let rho2 = (dx * dx + dy * dy).max(f64::MIN_POSITIVE);
            // θ = atan2(dx, dy): ∂θ/∂dx = dy/ρ², ∂θ/∂dy = −dx/ρ², and the centre's
            // x enters dx as −dir·x, its y enters dy as −y.
            (
                rows.partition_point(|&r| r < i),
                spin_sign * -dir * dy / rho2,
                spin_sign * dx / rho2,
            )
        })
        .collect()
}

/// The time between frames, s: the mean of the steps within half a frame of their
/// median (a missing frame's double step left out). Not the median itself: times
/// exported rounded (Logger Pro's 0.1 ms at 120 frames/s: 8.3 and 8.4 ms) would give
/// 8.3 ms, 120.5 frames/s.
fn frame_step(ts: &[f64]) -> f64 {
    let steps: Vec<f64> = ts
        .windows(2)
        .filter_map(|w| w.last().zip(w.first()).map(|(b, a)| b - a))
        .collect();
    let mid = median(steps.clone());
    let near: Vec<f64> = steps
        .into_iter()
        .filter(|d| (d - mid).abs() <= 0.5 * mid)
        .collect();
    if near.is_empty() {
        return mid;
    }
    near.iter().sum::<f64>() / near.len() as f64
}

// A track that cannot be fitted (no impact found, too few frames on a side of it) as
// the app still shows it: the centre's velocity over the file's own time and x, by
// the same local fits as a fitted track's, never cut at an impact (none is known).

/// The centre's v_cm (m/s, along the file's +x) at each frame with a position, in the
/// file's time; `x` from the first such frame, m; no v_t (no contact radius is known
/// without a scene, and no impact fixes the spin's sign). `None` with too few frames
/// for one local fit.
pub fn in_file_time(track: &Track) -> Option<Measured> {
    let (ts, xs): (Vec<f64>, Vec<f64>) = track
        .t()
        .iter()
        .zip(track.x())
        .filter(|(t, x)| t.is_finite() && x.is_finite())
        .map(|(t, x)| (*t, *x))
        .unzip();
    if ts.len() < 2 * MIN_HALF_WINDOW + 1 {
        return None;
    }
    let dt = frame_step(&ts);
    if !(dt.is_finite() && dt > 0.0) {
        return None;
    }
    let sigma = scatter(&ts, &xs).max(1e-7);
    let n = half_window(dt, sigma, &Derive::default());
    let x0 = *xs.first()?;
    let mut m = MeasuredParts::default();
    let (mut sig, mut pos) = (Vec::new(), Vec::new());
    for ((local, t), x) in derivatives(&ts, &xs, n, &[], sigma)
        .into_iter()
        .zip(&ts)
        .zip(&xs)
    {
        let Some(l) = local else { continue };
        if !(l.slope.is_finite() && l.slope_se.is_finite()) {
            continue;
        }
        m.t.push(*t);
        m.v_cm.push(l.slope);
        m.v_t.push(f64::NAN);
        sig.push(l.slope_se);
        pos.push(x - x0);
    }
    if m.t.is_empty() {
        return None;
    }
    m.v_cm_sigma = Some(sig);
    m.x = Some(pos);
    Measured::new(m).ok()
}

/// The standard error `se` of a speed `v` (m/s, from lengths read through a scale)
/// with the scale's relative ± (`scale_rel_se`, a video's px per metre) added in
/// quadrature, as every length carries it.
fn with_scale(se: f64, v: f64, scale_rel_se: Option<f64>) -> f64 {
    se.hypot(v * scale_rel_se.unwrap_or(0.0))
}

#[cfg(test)]
mod file_time_tests {
    use super::*;

    fn track(t: Vec<f64>, x: Vec<f64>) -> Track {
        let n = t.len();
        Track::new(super::super::series::TrackParts {
            t,
            x,
            y: vec![f64::NAN; n],
            mark: None,
            centre_name: "ball".into(),
            mark_name: None,
            format: "CSV",
            scale_rel_se: None,
            sigma: None,
            mark_sigma: None,
        })
        .unwrap()
    }

    #[test]
    fn a_steady_ball_has_its_speed_at_every_frame_in_the_files_time() {
        // x = 0.3 + 0.5 t − 0.4 t²: v = 0.5 − 0.8 t, which a local quadratic fit
        // recovers exactly (to rounding), at the file's own times.
        let t: Vec<f64> = (0..40).map(|k| 2.0 + k as f64 * 0.01).collect();
        let x = t.iter().map(|t| 0.3 + 0.5 * t - 0.4 * t * t).collect();
        let m = in_file_time(&track(t.clone(), x)).unwrap();
        assert_eq!(m.t(), t);
        for (t, v) in m.t().iter().zip(m.v_cm()) {
            assert!((v - (0.5 - 0.8 * t)).abs() < 1e-9, "t = {t}: {v}");
        }
        let x = m.x().unwrap();
        assert_eq!(x.first(), Some(&0.0));
        let last = 0.5 * 0.39 - 0.4 * (2.39f64.powi(2) - 4.0);
        assert!((x.last().unwrap() - last).abs() < 1e-12);
        assert!(m.v_t().iter().all(|v| v.is_nan()));
    }

    #[test]
    fn too_few_frames_or_no_positions_give_none() {
        assert!(in_file_time(&track(vec![0.0, 0.1, 0.2], vec![0.0; 3])).is_none());
        let t: Vec<f64> = (0..20).map(|k| k as f64 * 0.01).collect();
        assert!(in_file_time(&track(t, vec![f64::NAN; 20])).is_none());
    }
}

#[cfg(test)]
mod mark_rule_tests {
    use super::*;

    /// A ball rolling at 0.8 m/s into an impact at t = 0.5 s and on at 0.05 m/s, its
    /// centre jittered by ±`jitter` m (alternating signs: a scatter of about 2.7
    /// `jitter` from third differences),
    /// a mark `mark_at` m above the centre turning as it rolls (R = 2.75 cm).
    fn track(jitter: f64, mark_at: f64) -> Track {
        let t: Vec<f64> = (0..100).map(|k| f64::from(k) / 100.0).collect();
        let x: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(k, &t)| {
                let clean = if t < 0.5 {
                    0.8 * t
                } else {
                    0.4 + 0.05 * (t - 0.5)
                };
                clean + if k % 2 == 0 { jitter } else { -jitter }
            })
            .collect();
        let y = vec![0.0; t.len()];
        let (mx, my) = x
            .iter()
            .map(|&x| {
                let a = x / 0.0275;
                (x + mark_at * a.sin(), mark_at * a.cos())
            })
            .unzip();
        Track::new(super::super::series::TrackParts {
            t,
            x,
            y,
            mark: Some((mx, my)),
            centre_name: "ball".into(),
            mark_name: Some("mark".into()),
            format: "Tracker multi-track",
            ..Default::default()
        })
        .unwrap()
    }

    #[test]
    fn a_mark_far_off_the_centre_gives_a_spin() {
        let (m, found) = derive(&track(1e-4, 0.02), 0.45 * 0.0275, &Derive::default()).unwrap();
        assert!(found.mark.is_some() && found.mark_left_out.is_none());
        assert!(m.v_t().iter().any(|v| v.is_finite()));
    }

    /// A video's centres that jitter by a millimetre: the mark is real (10 mm off the
    /// centre, about 7 scatters) but its angle would be noise. Left out and said; the centre
    /// alone is fitted.
    #[test]
    fn a_mark_within_ten_scatters_is_left_out_and_said() {
        let (m, found) = derive(&track(5e-4, 0.01), 0.45 * 0.0275, &Derive::default()).unwrap();
        let ratio = 0.01 / found.scatter;
        assert!((3.0..10.0).contains(&ratio), "{ratio}");
        assert!(found.mark.is_none());
        let left = found.mark_left_out.as_ref().unwrap();
        assert!((left.radius - 0.01).abs() < 1e-3, "{}", left.radius);
        assert!(m.v_t().iter().all(|v| v.is_nan()));
        assert!(m.v_cm().iter().all(|v| v.is_finite()));
        let said = found.describe();
        assert!(said.contains("rim mark 'mark' left out"), "{said}");
    }

    /// Within three scatters the "mark" lies at the centre within the noise (the same
    /// track given twice): refused.
    #[test]
    fn a_mark_at_the_centre_within_the_noise_is_refused() {
        let got = derive(&track(5e-4, 2e-3), 0.45 * 0.0275, &Derive::default());
        assert!(
            matches!(got, Err(TrackError::MarkAtTheCentre { .. })),
            "{got:?}"
        );
    }
}
