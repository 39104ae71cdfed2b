//! The regime the data show, to hold against the model's: the band of speeds that
//! counts as rest and the mean motion after the sliding phase.

use crate::physics::derived::Regime;
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
pub use crate::study::measured::noise::rest_band;
use crate::study::measured::noise::{sliding_noise, sliding_window};
use crate::study::measured::series::{Measured, Stencil};
use crate::study::measured::track::derivative::scatter;

/// The data's own v_cm and v_t say when sliding ends: measured velocities (not a
/// track's derived ones) with v_t in at least three frames after the impact. Without
/// (no rim mark, or one lost soon after the impact) the fitted model says.
pub(super) fn v_t_says_sliding_end(m: &Measured) -> bool {
    let v_t_after = m
        .t()
        .iter()
        .zip(m.v_t())
        .filter(|(t, v_t)| **t > 0.0 && v_t.is_finite())
        .count();
    m.stencils().is_none() && v_t_after >= 3
}

/// Where the sliding phase after the first impact ends for the line fits and the
/// observed regime, given the fitted model `fitted`: of a velocity file where its
/// measured v_cm and v_t meet ([`sliding_window`]). Of a track, where the model rolls
/// again, back to the last frame whose derived velocities were made from frames
/// before it: a derived v_t is noisy enough to cross v_cm and back again well into
/// rolling, and a local fit over the corner at t' rounds it (the window ran 40 ms
/// into rolling and bent |a_cm| from 2.75 to 2.29 m/s²).
pub(super) fn sliding_end(m: &Measured, fitted: &Scene) -> Option<f64> {
    if v_t_says_sliding_end(m) {
        return sliding_window(m).map(|w| w.1);
    }
    let t_roll = rolling_time(fitted)?;
    let Some(st) = &m.stencils() else {
        return Some(t_roll - 1e-9);
    };
    let before = |stencil: Option<&Option<Stencil>>, times: &[f64]| match stencil {
        Some(Some(s)) => times.get(s.hi).is_some_and(|&t| t < t_roll),
        _ => true,
    };
    m.t()
        .iter()
        .enumerate()
        .rev()
        .find(|&(i, &t)| {
            t > 0.0
                && t < t_roll
                && before(st.v_cm.get(i), &st.centre_times)
                && before(st.v_t.get(i), &st.mark_times)
        })
        .map(|(_, &t)| t)
        .or(Some(t_roll - 1e-9))
}

/// The data's scatter in the units of a fit's RMS residual (positions: m; velocities:
/// m/s), or `None` where it cannot be told: tracked positions from their third
/// differences; derived velocities by the median of their own uncertainties (their
/// errors are correlated, which third differences would hide); a velocity file's as
/// its rest band takes it (about lines over the sliding phase: digitised points are
/// smoother than their error, which third differences would take for the scatter).
pub(super) fn data_scatter(m: &Measured, positions: bool) -> Option<f64> {
    let s = match (positions, m.x(), &m.v_cm_sigma()) {
        (true, Some(x), _) => scatter(m.t(), x),
        (true, None, _) => return None,
        (false, _, Some(sigma)) => {
            let mut s: Vec<f64> = sigma.iter().copied().filter(|v| v.is_finite()).collect();
            s.sort_by(f64::total_cmp);
            *s.get(s.len() / 2)?
        }
        (false, _, None) => sliding_noise(m)?,
    };
    (s.is_finite() && s > 0.0).then_some(s)
}

/// When the left ball of `scene` rolls again after the first impact: where a series
/// without v_t has its sliding phase end.
pub(super) fn rolling_time(scene: &Scene) -> Option<f64> {
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

/// What the data show after the sliding phase, which ends at `to`: the mean v_cm of
/// the left ball from there to the end of the series (or the next impact, a jump in
/// v_cm); `None` where the data end before it (nothing after the sliding phase was
/// seen: the tracks of a clip that stops near the balls' turn said "rest" and the
/// verdict DISAGREES).
pub(super) fn observed_after(m: &Measured, band: f64, to: Option<f64>) -> Option<Regime> {
    let Some(to) = to else {
        return Some(Regime::Rest);
    };
    let after: Vec<f64> = m
        .t()
        .iter()
        .zip(m.v_cm())
        .filter(|(t, _)| **t > to)
        .map(|(_, v)| *v)
        .collect();
    let mut speeds = Vec::new();
    for (&v0, &v1) in after.iter().zip(after.iter().skip(1)) {
        speeds.push(v0);
        // A jump down of more than half the speed is the next impact.
        if v1 < v0 - 0.5 * v0.abs().max(band) {
            break;
        }
    }
    if speeds.is_empty() {
        return None;
    }
    let mean = speeds.iter().sum::<f64>() / speeds.len() as f64;
    Some(if mean > band {
        Regime::Recollide
    } else if mean < -band {
        Regime::Depart
    } else {
        Regime::Rest
    })
}
