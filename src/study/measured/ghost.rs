//! Where the measured left ball is at any time: the tracked centre of a position
//! track, else its v_cm integrated from the impact place, on the model's x axis.

use super::series::Measured;

/// The measured ball's centre at each measured time, model's x (m): the tracked
/// displacement from the impact place (where the model's left ball is at −R), else
/// the cumulative integral of v_cm shifted so that the ball is at −R at t = 0.
pub(super) fn track(m: &Measured, radius: f64) -> Vec<f64> {
    match &m.x {
        Some(x) => x.iter().map(|x| x - radius).collect(),
        None => {
            let cum = cumulative(m);
            let at_impact = integral_to(m, &cum, 0.0);
            cum.iter().map(|c| c - at_impact - radius).collect()
        }
    }
}

/// The centre at `t` from its `track`: interpolated between tracked frames, or the
/// integral of the linearly interpolated v_cm; `None` outside the series.
pub(super) fn x_at(m: &Measured, track: &[f64], t: f64) -> Option<f64> {
    if m.t.is_empty() || t < m.t[0] || t > *m.t.last()? {
        return None;
    }
    if m.x.is_some() {
        return interpolate(&m.t, track, t);
    }
    // `track` is the cumulative integral shifted by a constant: the integral from the
    // frame before `t` is added to that frame's value.
    let i = m.t.partition_point(|&x| x <= t).clamp(1, m.t.len() - 1);
    Some(track[i - 1] + 0.5 * (m.v_cm[i - 1] + v_at(m, t)) * (t - m.t[i - 1]))
}

/// The rim mark's turn since the first impact at `t`, rad; `None` without a tracked
/// mark or outside the series.
pub(super) fn turn_at(m: &Measured, t: f64) -> Option<f64> {
    let angle = m.angle.as_ref()?;
    if m.t.is_empty() || t < m.t[0] || t > *m.t.last()? {
        return None;
    }
    interpolate(&m.t, angle, t)
}

/// `v_cm` linearly interpolated at `t` inside the series.
fn v_at(m: &Measured, t: f64) -> f64 {
    let i = m.t.partition_point(|&x| x <= t).clamp(1, m.t.len() - 1);
    let f = (t - m.t[i - 1]) / (m.t[i] - m.t[i - 1]);
    m.v_cm[i - 1] + f * (m.v_cm[i] - m.v_cm[i - 1])
}

/// ∫ v_cm from the first measured time to each measured time (trapezoids: exact for
/// the linearly interpolated series).
fn cumulative(m: &Measured) -> Vec<f64> {
    let mut acc = 0.0;
    std::iter::once(0.0)
        .chain(m.t.windows(2).enumerate().map(|(i, w)| {
            acc += 0.5 * (m.v_cm[i] + m.v_cm[i + 1]) * (w[1] - w[0]);
            acc
        }))
        .collect()
}

/// ∫ v_cm from the first measured time to `t`, from the cumulative table.
fn integral_to(m: &Measured, cum: &[f64], t: f64) -> f64 {
    let i = m.t.partition_point(|&x| x <= t).clamp(1, m.t.len() - 1);
    let t0 = m.t[i - 1];
    cum[i - 1] + 0.5 * (m.v_cm[i - 1] + v_at(m, t)) * (t - t0)
}

/// `ys` linearly interpolated at `t` between the neighbouring finite values (a gap in
/// a track is bridged); `None` when there is none on one side.
fn interpolate(ts: &[f64], ys: &[f64], t: f64) -> Option<f64> {
    let i = ts.partition_point(|&x| x <= t);
    let before = (0..i).rev().find(|&j| ys[j].is_finite())?;
    if ts[before] == t {
        return Some(ys[before]);
    }
    let after = (i..ts.len()).find(|&j| ys[j].is_finite())?;
    let f = (t - ts[before]) / (ts[after] - ts[before]);
    Some(ys[before] + f * (ys[after] - ys[before]))
}
