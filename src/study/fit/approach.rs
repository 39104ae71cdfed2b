//! What measured data say of their own scene before any fit: the left ball's speed
//! as it approaches the first impact (the scene's v0, which the user need not give),
//! with its standard error.

use serde::Serialize;

use super::uncertainty::effective_points;

/// The approach speed the data measure.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Approach {
    /// Speed toward the other ball just before the first impact, m/s.
    pub speed: f64,
    /// Its standard error, m/s.
    pub se: f64,
    /// The frames before the impact it comes from.
    pub frames: usize,
}

/// Fewest frames before the impact for the data to give the approach speed.
pub const APPROACH_FRAMES: usize = 3;

impl Approach {
    /// A track's approach speed (its line through the frames before the first
    /// impact) with its standard error; `None` when it is no usable approach.
    pub fn of_track(speed: f64, se: f64, frames: usize) -> Option<Approach> {
        Some(Approach { speed, se, frames }).filter(Approach::usable)
    }

    /// At least [`APPROACH_FRAMES`] frames, toward the impact, finite.
    fn usable(&self) -> bool {
        self.frames >= APPROACH_FRAMES
            && self.speed > 0.0
            && self.speed.is_finite()
            && self.se.is_finite()
    }
}

/// The approach speed of a velocity series (times `t` from the first impact, `v_cm`):
/// the mean v_cm over the frames before the impact (the ball rolls in at a steady
/// speed), leaving out the frame that may straddle it; its ± counts frames whose
/// errors go together as fewer points. `None` with fewer than [`APPROACH_FRAMES`]
/// such frames, or no speed toward the impact.
pub fn of_velocities(t: &[f64], v_cm: &[f64]) -> Option<Approach> {
    let frame = t
        .iter()
        .zip(t.iter().skip(1))
        .map(|(a, b)| b - a)
        .fold(f64::INFINITY, f64::min);
    let v: Vec<f64> = t
        .iter()
        .zip(v_cm)
        .filter(|(t, v)| **t <= -frame && v.is_finite())
        .map(|(_, v)| *v)
        .collect();
    if v.len() < APPROACH_FRAMES {
        return None;
    }
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let r: Vec<f64> = v.iter().map(|x| x - mean).collect();
    let labels: Vec<(usize, bool)> = (0..v.len()).map(|i| (i, false)).collect();
    let var = r.iter().map(|x| x * x).sum::<f64>() / (n - 1.0);
    let worth = effective_points(&r, &labels).max(1.0);
    Some(Approach {
        speed: mean,
        se: (var / worth).sqrt(),
        frames: v.len(),
    })
    .filter(Approach::usable)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_velocity_series_gives_the_mean_speed_before_the_impact_without_the_straddling_frame() {
        // Frames 0.01 s apart, the impact at t = 0 between −0.005 and 0.005: the frame
        // at −0.005 may hold the jump and is left out.
        let t: Vec<f64> = (0..20).map(|i| -0.095 + 0.01 * f64::from(i)).collect();
        let v_cm: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(i, &t)| match t {
                t if t > -0.006 => -0.3,
                _ => 0.5 + if i % 2 == 0 { 0.01 } else { -0.01 },
            })
            .collect();
        let a = of_velocities(&t, &v_cm).unwrap();
        // −0.095 … −0.015: 9 frames, alternating ±0.01 around 0.5 (mean 0.5 + 0.01/9).
        assert_eq!(a.frames, 9);
        assert!((a.speed - (0.5 + 0.01 / 9.0)).abs() < 1e-12, "{a:?}");
        // Errors that alternate are not worth more than the frames: sd/√n at most.
        assert!(a.se > 0.0 && a.se <= 0.0106 / 3.0 + 1e-12, "{a:?}");
    }

    #[test]
    fn too_few_frames_before_the_impact_give_no_approach() {
        let t = vec![-0.015, -0.005, 0.005, 0.015];
        assert_eq!(of_velocities(&t, &[0.5, 0.5, -0.3, -0.2]), None);
    }
}
