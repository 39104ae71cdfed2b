//! Frames of a position track whose centre lies far off the fitted model: slips of
//! the tracking (a heavily compressed clip's frame that shows the ball where a
//! neighbouring frame has it, a mis-click in Tracker). They are found from the
//! headline's centre residuals and left out of the fits made again (with each derived
//! velocity they move beyond its ±), and said.

use serde::Serialize;

use super::model::{ModelFit, PERFECT_POSITION_RMS};
use super::problem::Evals;
use super::residuals;
use crate::physics::scene::Scene;
use crate::study::measured::series::{Measured, Stencil, Stencils};

/// A frame whose centre lies more than this many robust spreads of the residuals off
/// the fitted model is a slip. Default 5: Gaussian scatter reaches it once in two
/// million frames, while a compressed clip's frame that repeats its neighbour's
/// picture lies a ball's step a frame off (small look 99 of the looks table: 2–6 px
/// where the residuals spread by 0.4 px).
pub const SLIP_SPREADS: f64 = 5.0;

/// At most this share of a track's frames are left out as slips; where more lie that
/// far off, the model or the whole track is in question, and none are (the fit's
/// verdict says so). Default 0.1.
pub const SLIP_SHARE: f64 = 0.1;

/// Rounds of finding slips and fitting again without them: large slips pull the
/// first fit (and the place its residuals are aligned by), and a smaller one shows
/// only against the fit made without them (small look 99's frame 66, 3.8 mm off,
/// beside frames 6–9 mm off; three frozen frames 4, 9 and 14 mm off in a test).
/// Default 3.
pub const SLIP_ROUNDS: usize = 3;

/// The slips left out of a track's fits ([`super::Fits::slips`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Slips {
    /// Each slipped frame's time, s from the first impact (the series' own t).
    pub t: Vec<f64>,
    /// Each one's centre residual against the fit made without them, m (model minus
    /// data).
    pub residual: Vec<f64>,
    /// The residual beyond which a frame is a slip, m: [`SLIP_SPREADS`] times the
    /// residuals' robust spread (1.4826 × their median absolute value).
    pub beyond: f64,
    /// The frames with a centre position before any was left out.
    pub frames: usize,
    /// Derived velocities of other frames left out of the velocity fit and the line
    /// fits with them (each whose local fit the slips move beyond its ±).
    pub velocities_left_out: usize,
    /// The slipped points' indices in the series, in order (`residual` is theirs).
    #[serde(skip)]
    pub points: Vec<usize>,
}

/// The slips of the series `m` against its position fit `head` on `scene` (made
/// without the slips found `before`, which then weigh nothing in the shifts the
/// residuals are aligned by, as in the fit), with `m` without them for the position
/// fit and for the velocity fit ([`without`]): `None` for a fit to velocities, or
/// where no frame lies beyond [`SLIP_SPREADS`] robust spreads (and the data's own
/// scatter), or more than [`SLIP_SHARE`] of them do.
pub(super) fn of(
    scene: &Scene,
    m: &Measured,
    head: &ModelFit,
    before: Option<&Slips>,
    evals: &mut Evals,
) -> Option<(Slips, (Measured, Measured))> {
    if head.fitted_to != "positions" {
        return None;
    }
    let out = before.map_or(&[][..], |s| &s.points[..]);
    let misses = residuals::centre_misses(&head.scene_of(scene), m, out, evals);
    let (points, beyond) = slipped(&misses, head.scatter.unwrap_or(0.0))?;
    // `slipped` names only indices of `misses`, each with a finite residual.
    let residual: Vec<f64> = points
        .iter()
        .filter_map(|&i| misses.get(i).copied())
        .collect();
    let (positions, velocities) = without(m, &points, &residual);
    let slips = Slips {
        t: points
            .iter()
            .filter_map(|&i| m.t().get(i).copied())
            .collect(),
        residual,
        beyond,
        frames: misses.iter().filter(|r| r.is_finite()).count(),
        velocities_left_out: positions.t().len().saturating_sub(velocities.t().len()),
        points,
    };
    Some((slips, (positions, velocities)))
}

/// The indices of `misses` (residuals, NaN where none) beyond [`SLIP_SPREADS`] times
/// their robust spread, the data's `scatter` and [`PERFECT_POSITION_RMS`] (exact data
/// have no spread to speak of), with that bound; `None` where there are none, or
/// more than [`SLIP_SHARE`] of the residuals.
fn slipped(misses: &[f64], scatter: f64) -> Option<(Vec<usize>, f64)> {
    let mut size: Vec<f64> = misses
        .iter()
        .filter(|r| r.is_finite())
        .map(|r| r.abs())
        .collect();
    size.sort_by(f64::total_cmp);
    let median = size.get(size.len() / 2).copied()?;
    let spread = (1.4826 * median).max(scatter).max(PERFECT_POSITION_RMS);
    let beyond = SLIP_SPREADS * spread;
    let out: Vec<usize> = (0..misses.len())
        .filter(|&i| {
            misses
                .get(i)
                .is_some_and(|r| r.is_finite() && r.abs() > beyond)
        })
        .collect();
    let most = (SLIP_SHARE * size.len() as f64).floor() as usize;
    (!out.is_empty() && out.len() <= most).then_some((out, beyond))
}

/// `m` without the points `slips` (in order, their centre residuals `residual`, m):
/// for the position fit, those points; for the velocity fit and the line fits, also
/// every point whose derived v_cm the slips move by more than its own standard error
/// (its local fit's weight on each slipped frame times that frame's residual: a slip
/// in a local fit over many frames moves its slope little, and that velocity stays),
/// and every derived v_t whose local fit takes in a slipped frame (a gap: the mark
/// there is off by its own amount, which the centre's residual does not tell).
fn without(m: &Measured, slips: &[usize], residual: &[f64]) -> (Measured, Measured) {
    // Both lists below are in the order of the points (a series may hold a million).
    let is_slip = |i: usize| slips.binary_search(&i).is_ok();
    let positions = m.retain_points(|i| !is_slip(i));
    let Some(st) = m.stencils() else {
        return (positions.clone(), positions);
    };
    // The slipped frames among the centre's frames (the stencils' indices), with
    // their residuals (v_cm is `centre_sign` times the slope of the file's x, and the
    // series' x is that sign times the file's: the signs cancel).
    let frames: Vec<(usize, f64)> = slips
        .iter()
        .zip(residual)
        .filter_map(|(&i, &r)| Some((centre_frame(st, *m.t().get(i)?)?, r)))
        .collect();
    let residual_at = |k: usize| {
        frames
            .binary_search_by_key(&k, |f| f.0)
            .ok()
            .and_then(|j| frames.get(j))
            .map(|f| f.1)
    };
    let moved = |s: &Stencil| -> f64 {
        s.weights(&st.centre_times)
            .filter_map(|(k, w)| residual_at(k).map(|r| w * r))
            .sum::<f64>()
            .abs()
    };
    let mark_slipped = |s: &Stencil| {
        (s.lo..=s.hi).any(|j| {
            st.mark_frames
                .get(j)
                .is_some_and(|f| residual_at(f.0).is_some())
        })
    };
    let velocities = m
        .without_v_t_at(|i| {
            st.v_t
                .get(i)
                .copied()
                .flatten()
                .is_some_and(|s| mark_slipped(&s))
        })
        .retain_points(|i| {
            let se = m
                .v_cm_sigma()
                .and_then(|s| s.get(i).copied())
                .unwrap_or(0.0);
            !is_slip(i)
                && !st
                    .v_cm
                    .get(i)
                    .copied()
                    .flatten()
                    .is_some_and(|s| moved(&s) > se)
        });
    (positions, velocities)
}

/// The centre frame (index of the stencils' frames) at the series' time `t`: the
/// points are made from those frames, their times shifted alike.
fn centre_frame(st: &Stencils, t: f64) -> Option<usize> {
    let k = st.centre_times.partition_point(|&c| c < t - 1e-9);
    st.centre_times
        .get(k)
        .filter(|&&c| (c - t).abs() <= 1e-9)
        .map(|_| k)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_far_beyond_the_spread_are_slips_a_few_at_most() {
        // Residuals of ±0.1 mm about the model, two frames 2 mm off.
        let mut r: Vec<f64> = (0..40).map(|i| 1e-4 * f64::from(i % 5 - 2) / 2.0).collect();
        r[7] = 2e-3;
        r[30] = -3e-3;
        r[12] = f64::NAN;
        let (out, beyond) = slipped(&r, 0.0).unwrap();
        assert_eq!(out, vec![7, 30]);
        // median |r| 0.05 mm → spread 0.074 mm → bound 0.37 mm.
        assert!((beyond - 5.0 * 1.4826 * 5e-5).abs() < 1e-12, "{beyond}");
        // The data's own scatter raises the bound: 0.5 mm → 2.5 mm, the 2 mm frame stays.
        assert_eq!(slipped(&r, 5e-4).unwrap().0, vec![30]);
        // Exact data: nothing beyond the perfect fit's bound.
        let exact: Vec<f64> = (0..40).map(|i| 1e-13 * f64::from(i)).collect();
        assert!(slipped(&exact, 0.0).is_none());
        // More than a tenth of the frames that far off: the model is in question,
        // not a frame; none left out.
        let mut bad = r.clone();
        for k in [1, 3, 5, 9, 11] {
            bad[k] = 3e-3;
        }
        assert!(slipped(&bad, 0.0).is_none());
        assert!(slipped(&[], 0.0).is_none());
    }
}
