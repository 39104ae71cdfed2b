//! Where the measured left ball is at any time: the tracked centre of a position
//! track, else its v_cm integrated from the impact place, on the model's x axis.

use super::series::Measured;

/// The measured ball's centre at each measured time, model's x (m): the tracked
/// displacement from the impact place (where the model's left ball is at −R), else
/// the cumulative integral of v_cm shifted so that the ball is at −R at t = 0.
pub(super) fn track(m: &Measured, radius: f64) -> Vec<f64> {
    match &m.x() {
        Some(x) => x.iter().map(|x| x - radius).collect(),
        None => {
            let cum = cumulative(m);
            let at_impact = integral_to(m, &cum, 0.0);
            cum.iter().map(|c| c - at_impact - radius).collect()
        }
    }
}

/// Whether `t` lies within the measured times.
fn inside(m: &Measured, t: f64) -> bool {
    matches!((m.t().first(), m.t().last()), (Some(&a), Some(&b)) if (a..=b).contains(&t))
}

/// The measured point at or before `t` and the one after it (the last two at the
/// end): their indices `(i − 1, i)`; `None` with fewer than two points.
fn bracket(m: &Measured, t: f64) -> Option<(usize, usize)> {
    let last = m.t().len().checked_sub(1).filter(|&l| l >= 1)?;
    let i = m.t().partition_point(|&x| x <= t).clamp(1, last);
    Some((i - 1, i))
}

/// The centre at `t` from its `track`: interpolated between tracked frames, or the
/// integral of the linearly interpolated v_cm; `None` outside the series.
pub(super) fn x_at(m: &Measured, track: &[f64], t: f64) -> Option<f64> {
    if !inside(m, t) {
        return None;
    }
    if m.x().is_some() {
        return interpolate(m.t(), track, t);
    }
    // `track` is the cumulative integral shifted by a constant: the integral from the
    // frame before `t` is added to that frame's value.
    let (a, _) = bracket(m, t)?;
    Some(track.get(a)? + 0.5 * (m.v_cm().get(a)? + v_at(m, t)) * (t - m.t().get(a)?))
}

/// The rim mark's turn since the first impact at `t`, rad; `None` without a tracked
/// mark or outside the series.
pub(super) fn turn_at(m: &Measured, t: f64) -> Option<f64> {
    let angle = m.angle()?;
    if !inside(m, t) {
        return None;
    }
    interpolate(m.t(), angle, t)
}

/// `v_cm` linearly interpolated at `t` inside the series; NaN with fewer than two
/// points.
fn v_at(m: &Measured, t: f64) -> f64 {
    let at = |a: usize, b: usize| {
        let (ta, tb, va, vb) = (
            m.t().get(a)?,
            m.t().get(b)?,
            m.v_cm().get(a)?,
            m.v_cm().get(b)?,
        );
        Some(va + (t - ta) / (tb - ta) * (vb - va))
    };
    bracket(m, t)
        .and_then(|(a, b)| at(a, b))
        .unwrap_or(f64::NAN)
}

/// ∫ v_cm from the first measured time to each measured time (trapezoids: exact for
/// the linearly interpolated series).
fn cumulative(m: &Measured) -> Vec<f64> {
    let mut acc = 0.0;
    let t = m.t().iter().zip(m.v_cm());
    std::iter::once(0.0)
        .chain(t.clone().zip(t.skip(1)).map(|((t0, v0), (t1, v1))| {
            acc += 0.5 * (v0 + v1) * (t1 - t0);
            acc
        }))
        .collect()
}

/// ∫ v_cm from the first measured time to `t`, from the cumulative table; NaN with
/// fewer than two points.
fn integral_to(m: &Measured, cum: &[f64], t: f64) -> f64 {
    let at =
        |a: usize| Some(cum.get(a)? + 0.5 * (m.v_cm().get(a)? + v_at(m, t)) * (t - m.t().get(a)?));
    bracket(m, t).and_then(|(a, _)| at(a)).unwrap_or(f64::NAN)
}

/// `ys` linearly interpolated at `t` between the neighbouring finite values (a gap in
/// a track is bridged); `None` when there is none on one side.
fn interpolate(ts: &[f64], ys: &[f64], t: f64) -> Option<f64> {
    let points = || ts.iter().zip(ys);
    let i = ts.partition_point(|&x| x <= t);
    let (t0, y0) = points().take(i).rev().find(|(_, y)| y.is_finite())?;
    if *t0 == t {
        return Some(*y0);
    }
    let (t1, y1) = points().skip(i).find(|(_, y)| y.is_finite())?;
    let f = (t - t0) / (t1 - t0);
    Some(y0 + f * (y1 - y0))
}
