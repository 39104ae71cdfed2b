//! Finding the impacts in the centre's motion: jumps of the velocity between line fits
//! on either side of a frame, each one placed between frames where the two sides'
//! quadratics meet; and why a track cannot be used (`TrackError`, for the whole derivation).

use super::derivative::{Quadratic, quadratic};
use crate::settings::units::{Dimension, show_exact, show_small, significant};

/// Why a track cannot be used (times in s, speeds in m/s, lengths in m).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TrackError {
    /// The derived series broke a rule of `Measured` (a bug: a derivation keeps them).
    #[error(transparent)]
    Rule(#[from] crate::study::measured::series::Rule),
    #[error(
        "--impact-at {} leaves fewer than 3 frames on one side of the impact, at least 3 needed on each: allowed a time within the track's, t = {} … {} s, 3 frames from either end",
        show_exact(*at, Dimension::Time),
        short(*first),
        short(*last)
    )]
    GivenImpactAtAnEnd { at: f64, first: f64, last: f64 },
    #[error(
        "no impact found: the centre's velocity never changes sharply (largest change {biggest:.3} m/s, noise {noise:.3} m/s); give its time with --impact-at"
    )]
    NoSharpChange { biggest: f64, noise: f64 },
    #[error(
        "the track starts too late: its sharpest change of velocity is at its start (t = {at:.4} s); it needs frames from before the first impact"
    )]
    ChangeAtTheStart { at: f64 },
    #[error(
        "{} {}; an impact would slow it by at least a third",
        if *given { format!("no impact at the time --impact-at gives, t = {at:.4} s: the change of the centre's velocity there") } else { format!("no impact found: the sharpest change of the centre's velocity, at t = {at:.4} s,") },
        seen(*before, *after)
    )]
    NoSlowDown {
        at: f64,
        before: f64,
        after: f64,
        /// Whether `at` is the time `--impact-at` gave (else the one found).
        given: bool,
    },
    #[error(
        "the track starts too late: before the sharpest slow-down (t = {at:.4} s) the ball does not approach steadily (mean {mean:.3} m/s against {before:.3} m/s); it needs frames from before the first impact"
    )]
    NoSteadyApproach { at: f64, mean: f64, before: f64 },
    #[error(
        "the rim mark lies {:.2} from the centre, within {scatters}× the position scatter ({:.2}): its angle would be noise; track a mark near the rim (the same file given for centre and mark?)",
        show_small(*radius, Dimension::Length),
        show_small(*scatter, Dimension::Length)
    )]
    MarkAtTheCentre {
        radius: f64,
        scatter: f64,
        scatters: f64,
    },
    #[error(
        "the centre's velocity near t = {} s is not a finite number (velocity before it {before:e} m/s): positions this large are no measurement",
        short(*at)
    )]
    NotFinite { at: f64, before: f64 },
    #[error(
        "only {count} frame{} {side} the impact at t = {at:.4} s, at least {min} needed to fit the motion {side} it",
        if *count == 1 { "" } else { "s" }
    )]
    FewFramesBeside {
        count: usize,
        side: &'static str,
        at: f64,
        min: usize,
    },
    #[error(
        "{frames} frame{} with a centre position, at least {need} needed ({min} before and after the impact)",
        if *frames == 1 { "" } else { "s" }
    )]
    FewFrames {
        frames: usize,
        need: usize,
        min: usize,
    },
}

/// A time as a person writes it: 0.25, 1e308.
fn short(t: f64) -> String {
    if t != 0.0 && !(1e-3..1e6).contains(&t.abs()) {
        format!("{t:e}")
    } else {
        significant(t, 6)
    }
}

/// What a change of the centre's velocity from `before` to `after` (m/s, the file's
/// x) that is no impact did: started the ball, sped it up, or slowed it a little (a
/// reversal is an impact: it slows the ball by more than its speed).
fn seen(before: f64, after: f64) -> String {
    // Speeds, not the file's signed velocities (-1.554 m/s read as a speed below 0).
    let (b, a) = (before.abs(), after.abs());
    let (bs, as_) = (speed(b), speed(a));
    if b < 1e-9 {
        format!("starts the ball from rest to {as_} m/s (a push or a release)")
    } else if a >= b {
        format!("speeds the ball up from {bs} to {as_} m/s (a push, a release or a slope)")
    } else {
        format!(
            "slows the ball by only {:.0} % (from {bs} to {as_} m/s)",
            100.0 * (b - a) / b
        )
    }
}

/// A speed as the hint writes it: three decimals of a lab's m/s (0.793), and four
/// significant digits of a file's own units (318 units/s of pixels, never 318.000).
fn speed(v: f64) -> String {
    if v.abs() < 10.0 {
        format!("{v:.3}")
    } else {
        significant(v, 4)
    }
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

/// An impact located between frames: its time and the centre's position then.
#[derive(Clone, Copy, Debug)]
pub(super) struct Kink {
    pub(super) t: f64,
    pub(super) x: f64,
    /// Velocity just before it, m/s, in the file's x.
    pub(super) before: f64,
}

/// Velocity jumps across each frame: slope of the line over the `k` frames after it
/// minus that over the `k` frames before (each side at least 3 frames).
fn jumps(ts: &[f64], xs: &[f64], k: usize) -> Vec<(f64, f64)> {
    let n = ts.len().min(xs.len());
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(k), (i + k).min(n.saturating_sub(1)));
            if i < a + 2 || b < i + 2 {
                return (0.0, f64::NAN);
            }
            match (ts.get(a..=i), xs.get(a..=i), ts.get(i..=b), xs.get(i..=b)) {
                (Some(tb), Some(xb), Some(ta), Some(xa)) => {
                    let before = line_slope(tb, xb);
                    (line_slope(ta, xa) - before, before)
                }
                _ => (0.0, f64::NAN),
            }
        })
        .collect()
}

/// Where the two quadratics fitted on each side of frame `i` (frames `lo..i` and
/// `i+1..=hi`) meet: the impact time and place. Falls back to frame `i` itself.
fn locate(ts: &[f64], xs: &[f64], i: usize, lo: usize, hi: usize) -> (f64, f64) {
    let (Some(&t0), Some(&x0)) = (ts.get(i), xs.get(i)) else {
        // Never: `i` is one of the track's frames.
        return (f64::NAN, f64::NAN);
    };
    let fallback = (t0, x0);
    if i < lo + 3 || hi < i + 3 {
        return fallback;
    }
    let (Some(Quadratic { c: b, .. }), Some(Quadratic { c: a, .. })) = (
        ts.get(lo..i)
            .zip(xs.get(lo..i))
            .and_then(|(t, x)| quadratic(t, x, t0)),
        ts.get(i + 1..=hi)
            .zip(xs.get(i + 1..=hi))
            .and_then(|(t, x)| quadratic(t, x, t0)),
    ) else {
        return fallback;
    };
    let (qa, qb, qc) = (a[2] - b[2], a[1] - b[1], a[0] - b[0]);
    let (Some(&t_prev), Some(&t_next)) = (ts.get(i - 1), ts.get(i + 1)) else {
        return fallback;
    };
    let span = (t_prev - t0, t_next - t0);
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

/// The frame nearest the time `at` (the earlier one on a tie).
fn nearest_frame(ts: &[f64], at: f64) -> usize {
    let i = ts
        .partition_point(|&t| t < at)
        .min(ts.len().saturating_sub(1));
    match (i.checked_sub(1).and_then(|p| ts.get(p)), ts.get(i)) {
        (Some(&before), Some(&here)) if at - before < here - at => i - 1,
        _ => i,
    }
}

/// True if the jump at frame `i` is finite and none within `k` frames is larger.
fn is_peak(j: &[(f64, f64)], k: usize, i: usize) -> bool {
    let size = |l: usize| j.get(l).map_or(f64::NAN, |v| v.0.abs());
    size(i).is_finite()
        && (i.saturating_sub(k)..=(i + k).min(j.len().saturating_sub(1)))
            .all(|l| size(l).partial_cmp(&size(i)) != Some(std::cmp::Ordering::Greater) || l == i)
}

/// The frame of the first impact: the one nearest the `given` time, else the first
/// peak of at least half the largest jump, which must stand above the noise (`se`:
/// the standard error of one jump).
fn first_impact(
    ts: &[f64],
    j: &[(f64, f64)],
    k: usize,
    se: f64,
    given: Option<f64>,
) -> Result<usize, TrackError> {
    let size = |i: usize| j.get(i).map_or(f64::NAN, |v| v.0.abs());
    if let Some(at) = given {
        let i = nearest_frame(ts, at);
        if j.get(i).is_none_or(|v| v.1.is_nan()) {
            return Err(TrackError::GivenImpactAtAnEnd {
                at,
                first: ts.first().copied().unwrap_or(f64::NAN),
                last: ts.last().copied().unwrap_or(f64::NAN),
            });
        }
        return Ok(i);
    }
    // A frame whose side fits are not finite numbers (positions near the largest
    // float: their differences overflow) has no velocity to compare: refused, not
    // read as "no change".
    if let Some((&(_, before), &at)) = j
        .iter()
        .zip(ts)
        .find(|((jump, before), _)| !(jump.is_finite() && (before.is_finite() || *jump == 0.0)))
    {
        return Err(TrackError::NotFinite { at, before });
    }
    let biggest = (0..j.len())
        .map(size)
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    if biggest.partial_cmp(&(8.0 * se)) != Some(std::cmp::Ordering::Greater) {
        return Err(TrackError::NoSharpChange { biggest, noise: se });
    }
    // The largest jump is a peak, so this finds one; were it not, no impact is found.
    (0..j.len())
        .find(|&i| size(i) >= 0.5 * biggest && is_peak(j, k, i))
        .ok_or(TrackError::NoSharpChange { biggest, noise: se })
}

/// Whether the jump at `first` is an impact the track shows whole: it slows the ball
/// by at least a third, with frames before it, and (when found, not given) after a
/// steady approach: a track that starts after the first impact (the ball moving
/// away, then back to a later impact) must not pass its later impact off as the first.
fn check_first(
    (ts, xs): (&[f64], &[f64]),
    (jump, before): (f64, f64),
    first: usize,
    k: usize,
    given: Option<f64>,
) -> Result<(), TrackError> {
    let dir = before.signum();
    let (Some(&at), Some(&x_at), Some(&t_start), Some(&x_start)) =
        (ts.get(first), xs.get(first), ts.first(), xs.first())
    else {
        return Err(TrackError::FewFrames {
            frames: ts.len().min(xs.len()),
            need: first + 1,
            min: 0,
        });
    };
    if before == 0.0 || jump * dir >= 0.0 || jump.abs() < before.abs() / 3.0 {
        if first < k {
            return Err(TrackError::ChangeAtTheStart { at });
        }
        return Err(TrackError::NoSlowDown {
            at,
            before,
            after: before + jump,
            given: given.is_some(),
        });
    }
    if given.is_none() && first > 0 {
        let mean = (x_at - x_start) / (at - t_start) * dir;
        if mean < 0.5 * before.abs() {
            return Err(TrackError::NoSteadyApproach {
                at,
                mean,
                before: before.abs(),
            });
        }
    }
    Ok(())
}

/// The impact near frame `i` located by side fits within frames `lo` … `hi` (at most
/// `wide` back), then again about the frame nearest the located impact (up to three
/// times), so that no frame on the wrong side of it bends the side fits.
fn located(ts: &[f64], xs: &[f64], i: usize, (lo, hi): (usize, usize), wide: usize) -> (f64, f64) {
    let mut at = i;
    let mut place = locate(ts, xs, at, lo.max(at.saturating_sub(wide)), hi);
    for _ in 0..3 {
        let near = nearest_frame(ts, place.0);
        if near == at || near <= lo || near >= hi {
            break;
        }
        at = near;
        place = locate(ts, xs, at, lo.max(at.saturating_sub(wide)), hi);
    }
    place
}

/// The impacts in the centre's motion (`ts`, `xs` without gaps), first one first.
pub(super) fn impacts(
    ts: &[f64],
    xs: &[f64],
    k: usize,
    sigma: f64,
    dt: f64,
    given: Option<f64>,
) -> Result<Vec<Kink>, TrackError> {
    let n = ts.len().min(xs.len());
    let j = jumps(ts, xs, k);
    // Standard error of one jump: two line slopes over k+1 frames.
    let m = (k + 1) as f64;
    let se = 2f64.sqrt() * sigma / (dt * (m * (m * m - 1.0) / 12.0).sqrt());
    let first = first_impact(ts, &j, k, se, given)?;
    let (jump, before) = j.get(first).copied().unwrap_or((0.0, 0.0));
    check_first((ts, xs), (jump, before), first, k, given)?;
    let dir = before.signum();
    // The side fits that place the impact reach over 60 ms (the motion on each side is
    // one parabola for much longer than that in a lab groove), at least 2k frames.
    let wide = (2 * k).max(6).max((0.06 / dt).round() as usize);
    let mut found = Vec::new();
    let mut lo = 0;
    let mut i = first;
    loop {
        let next = (i + k + 1..n).find(|&l| {
            j.get(l).is_some_and(|&(jl, _)| {
                jl.abs() >= (0.1 * jump.abs()).max(8.0 * se) && jl * dir < 0.0
            }) && is_peak(&j, k, l)
        });
        let hi = next.map_or(n.saturating_sub(1), |l| l - 1).min(i + wide);
        let (t, x) = if found.is_empty()
            && let Some(at) = given
        {
            (at, xs.get(i).copied().unwrap_or(f64::NAN))
        } else {
            located(ts, xs, i, (lo, hi), wide)
        };
        found.push(Kink {
            t,
            x,
            before: j.get(i).map_or(f64::NAN, |v| v.1),
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
