//! Derivatives of a tracked series by local quadratic least squares that never reach
//! across an impact, with the scatter estimate that sets their window and errors.

use crate::study::measured::series::Stencil;

/// Fewest frames on each side of a local quadratic fit: with one, its three points
/// have no residual left to tell the slope's error.
pub(super) const MIN_HALF_WINDOW: usize = 2;

/// A local quadratic least-squares fit about `t0`: value, slope and the slope's
/// standard error, and the weights that made the slope from the frames (neighbouring
/// slopes share frames, so their errors are correlated).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Local {
    pub value: f64,
    pub slope: f64,
    pub slope_se: f64,
    pub stencil: Stencil,
}

/// A quadratic least-squares fit about `t0` ([`quadratic`]).
pub(super) struct Quadratic {
    /// Coefficients (c0, c1, c2) of `c0 + c1 τ + c2 τ²`, τ = t − t0.
    pub c: [f64; 3],
    /// The (1,1) element of (AᵀA)⁻¹: the slope's variance per unit noise variance.
    pub v11: f64,
    /// The residual sum of squares.
    pub rss: f64,
    /// The slope's weights on the points, as a [`Stencil`] over them (`lo` = 0).
    pub stencil: Stencil,
}

/// Quadratic least squares of `ys` on `ts` about `t0`; `None` with fewer than 3
/// distinct times.
pub(super) fn quadratic(ts: &[f64], ys: &[f64], t0: f64) -> Option<Quadratic> {
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
        let powers = [1.0, u, u * u, u * u * u, u * u * u * u];
        for (sk, p) in s.iter_mut().zip(powers) {
            *sk += p;
        }
        for (bk, p) in b.iter_mut().zip(powers) {
            *bk += p * y;
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
    let inv = adj.map(|row| row.map(|v| v / det));
    // Coefficient i of τ^i is row i of the inverse times b, over h^i.
    let mut c = [0.0; 3];
    for ((ci, row), scale) in c.iter_mut().zip(&inv).zip([1.0, h, h * h]) {
        *ci = row.iter().zip(&b).map(|(r, b)| r * b).sum::<f64>() / scale;
    }
    let rss: f64 = ts
        .iter()
        .zip(ys)
        .map(|(&t, &y)| {
            let u = t - t0;
            (y - c[0] - c[1] * u - c[2] * u * u).powi(2)
        })
        .sum();
    // The slope c1 = Σ_j inv(1, j) b_j / h with b_j = Σ_k u_k^j y_k: linear in the ys.
    let [_, slope_row, _] = inv;
    let stencil = Stencil {
        lo: 0,
        hi: ts.len().saturating_sub(1),
        t0,
        h,
        c: slope_row.map(|v| v / h),
    };
    Some(Quadratic {
        c,
        v11: slope_row[1] / (h * h),
        rss,
        stencil,
    })
}

/// The local fit of `ys` at `ts[i]` over the indices `lo..=hi`; the residual variance
/// is pooled with `sigma²` worth `PRIOR` degrees of freedom, so a window of 3–5 frames
/// does not claim a tiny error by chance.
fn local(ts: &[f64], ys: &[f64], i: usize, lo: usize, hi: usize, sigma: f64) -> Option<Local> {
    const PRIOR: f64 = 4.0;
    let q = quadratic(ts.get(lo..=hi)?, ys.get(lo..=hi)?, *ts.get(i)?)?;
    let dof = (hi + 1 - lo) as f64 - 3.0;
    let s2 = (q.rss + PRIOR * sigma * sigma) / (dof + PRIOR);
    Some(Local {
        value: q.c[0],
        slope: q.c[1],
        slope_se: (s2 * q.v11).sqrt(),
        stencil: Stencil {
            lo,
            hi,
            ..q.stencil
        },
    })
}

/// Scatter of a smooth series `ys` sampled at times `ts`, from its third differences
/// over four neighbouring samples (robust: the median). They cancel a constant
/// acceleration; where frames are missing between samples the samples are unevenly
/// spaced, and the plain differences no longer cancel even a constant speed (a ball at
/// 0.8 m/s with one frame of 30 missing gave a "scatter" of 4 mm where the centres
/// scatter by 0.2 mm): there the third divided differences are taken, scaled to the
/// noise's σ, which cancel any quadratic whatever the spacing.
pub fn scatter(ts: &[f64], ys: &[f64]) -> f64 {
    let windows = || ts.windows(4).zip(ys.windows(4));
    let even = windows().all(|(t, _)| evenly_spaced(t));
    let mut d: Vec<f64> = if even {
        windows()
            .filter_map(|(_, y)| match *y {
                [a, b, c, d] => Some((d - 3.0 * c + 3.0 * b - a).abs()),
                _ => None,
            })
            .filter(|v| v.is_finite())
            .collect()
    } else {
        windows()
            .filter_map(|(t, y)| divided_third(t, y))
            .map(|v| v * 20f64.sqrt())
            .filter(|v| v.is_finite())
            .collect()
    };
    if d.is_empty() {
        return 0.0;
    }
    let mid = d.len() / 2;
    let (_, m, _) = d.select_nth_unstable_by(mid, f64::total_cmp);
    *m / 0.6745 / 20f64.sqrt()
}

/// Whether four sample times are evenly spaced but for the rounding of times written
/// with a few digits or a camera's jitter (a quarter of a frame): a missing frame
/// doubles a spacing.
fn evenly_spaced(t: &[f64]) -> bool {
    match *t {
        [a, b, c, d] => {
            let h = b - a;
            (c - b - h).abs() <= 0.25 * h.abs() && (d - c - h).abs() <= 0.25 * h.abs()
        }
        _ => false,
    }
}

/// The third divided difference of four samples over the root of its weights' sum
/// of squares: its size is the noise's σ (in the median's sense) for pure noise, and
/// 0 for any quadratic; `None` unless the times are distinct.
fn divided_third(t: &[f64], y: &[f64]) -> Option<f64> {
    let (&[t0, t1, t2, t3], &[y0, y1, y2, y3]) = (t, y) else {
        return None;
    };
    let ts = [t0, t1, t2, t3];
    let w = ts.map(|ti| {
        1.0 / ts
            .iter()
            .filter(|&&tj| tj != ti)
            .map(|tj| ti - tj)
            .product::<f64>()
    });
    let norm = w.iter().map(|w| w * w).sum::<f64>().sqrt();
    let dd = w[0] * y0 + w[1] * y1 + w[2] * y2 + w[3] * y3;
    (norm.is_finite() && norm > 0.0).then(|| (dd / norm).abs())
}

pub(super) fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    let mid = v.len() / 2;
    let (_, m, _) = v.select_nth_unstable_by(mid, f64::total_cmp);
    *m
}

/// Unwraps angles (rad) so that neighbours differ by less than π: within a run of
/// consecutive frames, where the mark turns by far less than π from one to the next.
fn unwrap_run(angles: &mut [f64]) {
    let tau = std::f64::consts::TAU;
    let mut shift = 0.0;
    let Some((&mut first, rest)) = angles.split_first_mut() else {
        return;
    };
    let mut previous = first;
    for a in rest {
        let d = *a + shift - previous;
        shift -= tau * (d / tau).round();
        *a += shift;
        previous = *a;
    }
}

/// With the spin measured on one side of a gap only, how much it may have changed
/// across the gap, as a share of itself (the rails' friction slows a sliding ball's
/// spin by ~10 % in a tenth of a second; twice that, to be safe).
const ONE_SIDED_DOUBT: f64 = 0.25;

/// Largest sum of the miss (measured turn across a gap against the predicted one)
/// and the prediction's doubt, rad, for which the gap's whole turns are taken as
/// known: beyond it, the nearest branch could be the wrong one.
const MOST_DOUBT: f64 = std::f64::consts::FRAC_PI_2;

/// The spin (rad/s) at one end of a run of frames: the slope of a line through its
/// last (`last`) or first few frames; `None` for a run of one frame.
fn end_rate(ts: &[f64], angles: &[f64], last: bool) -> Option<f64> {
    const FRAMES: usize = 4;
    let n = ts.len().min(FRAMES);
    if n < 2 {
        return None;
    }
    let r = if last { ts.len() - n..ts.len() } else { 0..n };
    let (t, a) = (ts.get(r.clone())?, angles.get(r)?);
    let mt = t.iter().sum::<f64>() / n as f64;
    let ma = a.iter().sum::<f64>() / n as f64;
    let (sxy, sxx) = t.iter().zip(a).fold((0.0, 0.0), |(sxy, sxx), (t, a)| {
        (sxy + (t - mt) * (a - ma), sxx + (t - mt) * (t - mt))
    });
    (sxx > 0.0).then(|| sxy / sxx)
}

/// Unwraps the mark's angles (rad) at the times `ts` (frames `dt` apart), and returns
/// the times where their local fits must not reach across a gap.
///
/// Within a run of consecutive frames neighbours differ by less than π. Across a gap
/// (the mark hidden by the rail, the ball merged with the other at the impact) the
/// mark may turn by more than π, so the turn is predicted from the spin measured at
/// the runs' ends beside it (their mean: exact for a steady angular deceleration)
/// and the branch nearest the prediction taken. Where the prediction is too doubtful
/// to tell the branch ([`MOST_DOUBT`]: the spins beside the gap differ, or only one
/// side has two frames), the gap is left out: its middle is returned as a cut, and
/// the angles after it are unwrapped as if it were a single frame step (their
/// whole turn then unknown, which the position fit does not depend on).
pub(super) fn unwrap(ts: &[f64], angles: &mut [f64], dt: f64) -> Vec<f64> {
    let tau = std::f64::consts::TAU;
    let len = ts.len().min(angles.len());
    // The first frame of each run of consecutive frames, then the end.
    let mut starts = vec![0];
    starts.extend(
        ts.windows(2)
            .enumerate()
            .filter(|(_, w)| matches!(**w, [t0, t1] if t1 - t0 > 1.5 * dt))
            .map(|(i, _)| i + 1)
            .filter(|&i| i < len),
    );
    starts.push(len);
    for w in starts.windows(2) {
        if let [a, b] = *w
            && let Some(run) = angles.get_mut(a..b)
        {
            unwrap_run(run);
        }
    }
    let mut cuts = Vec::new();
    for w in starts.windows(3) {
        let [a, b, c] = *w else { continue };
        let (Some(t_run), Some(t_next_run)) = (ts.get(a..b), ts.get(b..c)) else {
            continue;
        };
        let (Some(a_run), Some(a_next_run)) = (angles.get(a..b), angles.get(b..c)) else {
            continue;
        };
        let before = end_rate(t_run, a_run, true);
        let after = end_rate(t_next_run, a_next_run, false);
        let (Some(&t_last), Some(&t_next), Some(&a_last), Some(&a_next)) = (
            t_run.last(),
            t_next_run.first(),
            a_run.last(),
            a_next_run.first(),
        ) else {
            continue;
        };
        let gap = t_next - t_last;
        let (predicted, doubt) = match (before, after) {
            (Some(w0), Some(w1)) => (0.5 * (w0 + w1) * gap, 0.5 * (w0 - w1).abs() * gap),
            (Some(w), None) | (None, Some(w)) => (w * gap, ONE_SIDED_DOUBT * w.abs() * gap),
            (None, None) => (0.0, f64::INFINITY),
        };
        let d = a_next - a_last;
        let turns = ((predicted - d) / tau).round();
        let miss = (d + tau * turns - predicted).abs();
        let shift = if miss + doubt <= MOST_DOUBT {
            tau * turns
        } else {
            cuts.push(0.5 * (t_last + t_next));
            -tau * (d / tau).round()
        };
        for x in angles.iter_mut().skip(b) {
            *x += shift;
        }
    }
    cuts
}

/// Derivatives of `ys` at each of `ts` by local quadratic fits over ±`n` frames that
/// stay between consecutive `cuts` (impact times); empty for an empty series (the
/// frames of a mark that never shows with its centre).
pub(super) fn derivatives(
    ts: &[f64],
    ys: &[f64],
    n: usize,
    cuts: &[f64],
    sigma: f64,
) -> Vec<Option<Local>> {
    let len = ts.len().min(ys.len());
    // The first index of each piece between cuts, then the end.
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
        let [a, end] = *p else { continue };
        for i in a..end {
            // i < end, so end ≥ 1: the piece's last index.
            let lo = i.saturating_sub(n).max(a);
            let hi = (i + n).min(end - 1);
            out.push(local(ts, ys, i, lo, hi, sigma));
        }
    }
    out
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
        // The stencil's weights make the same slope from the frames.
        let w: f64 = l.stencil.weights(&ts).map(|(k, w)| w * ys[k]).sum();
        assert!((w - l.slope).abs() < 1e-9, "{w} vs {}", l.slope);
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
        let ts: Vec<f64> = (0..50).map(|i| i as f64 * 0.01).collect();
        let s = scatter(&ts, &ys);
        assert!((s - 8e-3 / 0.6745 / 20f64.sqrt()).abs() < 1e-9, "{s}");
    }

    #[test]
    fn scatter_across_missing_frames_is_the_noise_not_the_motion() {
        // A ball at 0.8 m/s decelerating at 1.7 m/s², 30 frames/s, with frames
        // missing in runs of one to three: without noise no scatter at all; with a
        // fixed ±0.2 mm jitter, about that (the plain differences gave millimetres).
        let kept: Vec<usize> = (0..60)
            .filter(|k| k % 5 != 2 && k % 11 != 7 && k % 13 != 4)
            .collect();
        let ts: Vec<f64> = kept.iter().map(|&k| k as f64 / 30.0).collect();
        let motion = |t: f64| 0.8 * t - 0.85 * t * t;
        let smooth: Vec<f64> = ts.iter().map(|&t| motion(t)).collect();
        assert!(scatter(&ts, &smooth) < 1e-12, "{}", scatter(&ts, &smooth));
        let jitter = |k: usize| 2e-4 * ((k as f64 * 12.9898).sin() * 43758.5453).fract();
        let noisy: Vec<f64> = (ts.iter().zip(&kept))
            .map(|(&t, &k)| motion(t) + jitter(k))
            .collect();
        let even: Vec<f64> = (0..60)
            .map(|k| motion(k as f64 / 30.0) + jitter(k))
            .collect();
        let all: Vec<f64> = (0..60).map(|k| k as f64 / 30.0).collect();
        let (gappy, whole) = (scatter(&ts, &noisy), scatter(&all, &even));
        // The same jitter seen through other neighbours: within a factor 1.5.
        assert!(
            gappy < 1.5 * whole && whole < 1.5 * gappy,
            "{gappy} vs {whole}"
        );
        assert!(whole > 2e-5 && whole < 2e-4, "{whole}");
    }

    #[test]
    fn an_empty_series_has_no_derivatives_and_nothing_to_unwrap() {
        // A mark never seen with its centre gives no frames: this once panicked.
        assert!(derivatives(&[], &[], 2, &[0.05], 1e-4).is_empty());
        assert!(unwrap(&[], &mut [], 0.01).is_empty());
        // Lengths that differ read only the common frames.
        let d = derivatives(&[0.0, 0.01, 0.02, 0.03], &[0.0, 1.0], 2, &[], 1e-4);
        assert_eq!(d.len(), 2);
        assert!(d.iter().all(Option::is_none), "two points fit no quadratic");
    }

    #[test]
    fn unwrap_removes_jumps_of_two_pi() {
        let mut a = vec![3.0, -3.0, -2.5];
        let cuts = unwrap(&[0.0, 0.01, 0.02], &mut a, 0.01);
        assert!((a[1] - (-3.0 + std::f64::consts::TAU)).abs() < 1e-12);
        assert!(a[2] > a[1]);
        assert!(cuts.is_empty());
    }

    /// The mark's principal angle atan2 of a ball turning at `w0` rad/s, slowing at
    /// `alpha` rad/s², at the frames `ts`.
    fn wrapped(ts: &[f64], w0: f64, alpha: f64) -> (Vec<f64>, Vec<f64>) {
        let truth: Vec<f64> = ts.iter().map(|t| w0 * t - 0.5 * alpha * t * t).collect();
        let seen = truth.iter().map(|a| a.sin().atan2(a.cos())).collect();
        (truth, seen)
    }

    #[test]
    fn a_gap_longer_than_half_a_turn_takes_the_turn_the_spin_predicts() {
        use std::f64::consts::PI;
        // 100 frames/s, 63 rad/s slowing at 125 rad/s² (a paper ball sliding on its
        // rails); frames 5–10 hidden: the mark turns by 3.8 rad > π across the gap.
        let dt = 0.01;
        let ts: Vec<f64> = (0..20)
            .filter(|k| !(5..=10).contains(k))
            .map(|k| k as f64 * dt)
            .collect();
        let (truth, mut a) = wrapped(&ts, 63.0, 125.0);
        assert!(truth[5] - truth[4] > PI);
        let cuts = unwrap(&ts, &mut a, dt);
        assert!(cuts.is_empty(), "{cuts:?}");
        for (got, want) in a.iter().zip(&truth) {
            assert!((got - want).abs() < 1e-9, "{got} vs {want}");
        }
        // Plain unwrapping of neighbours takes the wrong branch across that gap.
        let (_, mut plain) = wrapped(&ts, 63.0, 125.0);
        unwrap_run(&mut plain);
        assert!((plain[5] - truth[5]).abs() > 1.0);
    }

    #[test]
    fn a_gap_whose_turn_is_doubtful_is_left_out() {
        // One frame before the gap (no spin there), a long gap after it, and a spin
        // known from one side only: the turn across 0.25 s at 63 rad/s (≈ 16 rad)
        // could be off by a turn, so the gap is cut, not guessed.
        let dt = 0.01;
        let ts = [0.0, 0.25, 0.26, 0.27, 0.28];
        let (_, mut a) = wrapped(&ts, 63.0, 0.0);
        let cuts = unwrap(&ts, &mut a, dt);
        assert_eq!(cuts, vec![0.125]);
        // Within the run after the gap, neighbours still agree with the spin.
        for w in a[1..].windows(2) {
            assert!((w[1] - w[0] - 0.63).abs() < 1e-9, "{w:?}");
        }
    }
}
