//! How noisy a measured series is, as its rest band: the speeds that cannot be told
//! from rest. From the series alone: the median of its v_cm's uncertainties, or the
//! scatter of its points about straight lines over the sliding phase (which ends where
//! the measured v_cm and v_t meet, [`sliding_window`]).

use super::line::line;
use super::series::Measured;

/// Speeds within ± this of zero count as rest: three times the data's own resolution
/// of v_cm (the speed the regime is read from), at least 2 cm/s. Of a velocity file,
/// the scatter of its points about straight lines over the sliding phase; of a track,
/// the median uncertainty of its derived v_cm — not the scatter of v_t, derived from
/// a rim mark a few millimetres from the centre and several times noisier, which made
/// the band (and the observed regime) swing from one track to the next.
pub fn rest_band(m: &Measured) -> f64 {
    let noise = match m.v_cm_sigma() {
        Some(sigma) => median(sigma),
        None => sliding_noise(m),
    };
    (3.0 * noise.unwrap_or(0.0)).max(0.02)
}

/// The median of the finite values of `v`; `None` without one.
fn median(v: &[f64]) -> Option<f64> {
    let mut s: Vec<f64> = v.iter().copied().filter(|x| x.is_finite()).collect();
    s.sort_by(f64::total_cmp);
    s.get(s.len() / 2).copied()
}

/// The sliding phase after the first impact (at t = 0): from the first frame after
/// it until the measured v_cm and v_t meet (the last frame before they cross).
/// `None` without a v_t measured after the impact.
pub fn sliding_window(m: &Measured) -> Option<(f64, f64)> {
    // Sliding starts at the impact whether or not the rim mark was seen then: a
    // track whose mark the rail hid for the first frames after the impact began its
    // window at the first mark seen, after the sliding phase the model put it in
    // (`fit` said "the window 0.2494 … 0.2161 s holds 0 points").
    let first = m.t().iter().copied().find(|&t| t > 0.0)?;
    // Frames without a measured v_t (a track without its rim mark) cannot say.
    let mut after = m
        .t()
        .iter()
        .zip(m.v_cm().iter().zip(m.v_t()))
        .filter(|(t, (_, v_t))| **t > 0.0 && v_t.is_finite())
        .map(|(t, (v_cm, v_t))| (*t, (v_cm - v_t).signum()));
    let (seen, sign0) = after.next()?;
    let last = after
        .take_while(|(_, sign)| *sign == sign0)
        .last()
        .map_or(seen, |(t, _)| t);
    Some((first, last))
}

/// The scatter of v_cm and v_t about straight lines over the sliding phase (NaN where
/// a v_t is missing); `None` without a sliding phase of three points.
pub fn sliding_noise(m: &Measured) -> Option<f64> {
    let (from, to) = sliding_window(m)?;
    let inside = |t: &f64| *t >= from && *t <= to;
    let pick = |v: &[f64]| -> Vec<f64> {
        m.t()
            .iter()
            .zip(v)
            .filter(|(t, _)| inside(t))
            .map(|(_, v)| *v)
            .collect()
    };
    let ts = pick(m.t());
    (ts.len() >= 3).then(|| {
        let mut sq = 0.0;
        for ys in [pick(m.v_cm()), pick(m.v_t())] {
            let l = line(&ts, &ys);
            sq += ts
                .iter()
                .zip(&ys)
                .map(|(t, y)| (y - l.intercept - l.slope * t).powi(2))
                .sum::<f64>();
        }
        (sq / (2 * ts.len()) as f64).sqrt()
    })
}
