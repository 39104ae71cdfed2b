//! A track that cannot be fitted (no impact found, too few frames on a side of it) as
//! the app still shows it: the centre's velocity over the file's own time and x, by
//! the same local fits as a fitted track's, never cut at an impact (none is known).

use super::derivative::{MIN_HALF_WINDOW, derivatives, scatter};
use super::{Derive, frame_step, half_window};
use crate::study::measured::series::{Measured, Track};

/// The centre's v_cm (m/s, along the file's +x) at each frame with a position, in the
/// file's time; `x` from the first such frame, m; no v_t (no contact radius is known
/// without a scene, and no impact fixes the spin's sign). `None` with too few frames
/// for one local fit.
pub fn in_file_time(track: &Track) -> Option<Measured> {
    let (ts, xs): (Vec<f64>, Vec<f64>) = track
        .t
        .iter()
        .zip(&track.x)
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
    let sigma = scatter(&xs).max(1e-7);
    let n = half_window(dt, sigma, &Derive::default());
    let x0 = *xs.first()?;
    let mut m = Measured::default();
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
    Some(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn track(t: Vec<f64>, x: Vec<f64>) -> Track {
        let n = t.len();
        Track {
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
        }
    }

    #[test]
    fn a_steady_ball_has_its_speed_at_every_frame_in_the_files_time() {
        // x = 0.3 + 0.5 t − 0.4 t²: v = 0.5 − 0.8 t, which a local quadratic fit
        // recovers exactly (to rounding), at the file's own times.
        let t: Vec<f64> = (0..40).map(|k| 2.0 + k as f64 * 0.01).collect();
        let x = t.iter().map(|t| 0.3 + 0.5 * t - 0.4 * t * t).collect();
        let m = in_file_time(&track(t.clone(), x)).unwrap();
        assert_eq!(m.t, t);
        for (t, v) in m.t.iter().zip(&m.v_cm) {
            assert!((v - (0.5 - 0.8 * t)).abs() < 1e-9, "t = {t}: {v}");
        }
        let x = m.x.unwrap();
        assert_eq!(x.first(), Some(&0.0));
        let last = 0.5 * 0.39 - 0.4 * (2.39f64.powi(2) - 4.0);
        assert!((x.last().unwrap() - last).abs() < 1e-12);
        assert!(m.v_t.iter().all(|v| v.is_nan()));
    }

    #[test]
    fn too_few_frames_or_no_positions_give_none() {
        assert!(in_file_time(&track(vec![0.0, 0.1, 0.2], vec![0.0; 3])).is_none());
        let t: Vec<f64> = (0..20).map(|k| k as f64 * 0.01).collect();
        assert!(in_file_time(&track(t, vec![f64::NAN; 20])).is_none());
    }
}
