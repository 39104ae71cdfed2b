//! Candidate events of a segment: every time at which the current polynomial motion
//! can end (rolling starts, pure gliding or slipping, a stop, an impact) as a
//! closed-form root, and how a non-impact event changes a ball when it comes.

use super::{Candidates, Engine, EventCandidate};
use crate::physics::model::{BallState, Phase, slip};
use crate::physics::solution::{EventKind, Who};

impl Engine {
    /// Applies a non-impact event to ball `i`; `before` is the segment's start state.
    pub(super) fn apply(&mut self, c: EventCandidate, before: &[BallState; 2]) -> (EventKind, Who) {
        match c {
            EventCandidate::Roll(i) => {
                // While sliding freely `u + 5/2 k² v` is conserved: the rolling speed
                // comes from it, not from the rounded end of the polynomial.
                let v = if self.together {
                    self.state[i].v
                } else {
                    self.groove.rolling_speed(before[i])
                };
                if v.abs() <= self.eps_v {
                    self.stop(i);
                    (EventKind::Rest, Who::ball(i))
                } else {
                    self.state[i].v = v;
                    self.state[i].u = v;
                    self.phase[i] = Phase::Rolling;
                    (EventKind::Rolling, Who::ball(i))
                }
            }
            EventCandidate::Glide(i) => {
                self.state[i].u = 0.0;
                (EventKind::PureGliding, Who::ball(i))
            }
            EventCandidate::Slip(i) => {
                self.state[i].v = 0.0;
                (EventKind::PureSlipping, Who::ball(i))
            }
            EventCandidate::Stop(i) => {
                self.stop(i);
                (EventKind::Rest, Who::ball(i))
            }
            EventCandidate::Impact => unreachable!("impacts are applied by collide"),
        }
    }

    fn stop(&mut self, i: usize) {
        self.state[i].v = 0.0;
        self.state[i].u = 0.0;
        self.phase[i] = Phase::Resting;
    }

    /// Every event the current segment can end in, with its time from now.
    pub(super) fn candidates(&self) -> Candidates {
        let mut out = Candidates::default();
        for i in 0..2 {
            let s = self.state[i];
            let (a, du) = self.accel[i];
            match self.phase[i] {
                Phase::Sliding { sign } => {
                    let sign = f64::from(sign);
                    let sl = slip(s);
                    let ds = a - du;
                    let t_roll = if sign * sl >= 0.0 && sign * ds < 0.0 {
                        let t = -sl / ds;
                        (t > 0.0).then_some(t)
                    } else {
                        None
                    };
                    if let Some(t) = t_roll {
                        out.push((t, EventCandidate::Roll(i)));
                    }
                    let before_roll =
                        |t: f64| t > 0.0 && t_roll.is_none_or(|tr| t < tr * (1.0 - 1e-12));
                    if s.u * du < 0.0 && before_roll(-s.u / du) {
                        out.push((-s.u / du, EventCandidate::Glide(i)));
                    }
                    if s.v * a < 0.0 && before_roll(-s.v / a) {
                        out.push((-s.v / a, EventCandidate::Slip(i)));
                    }
                }
                Phase::Rolling => {
                    if s.v * a < 0.0 {
                        out.push((-s.v / a, EventCandidate::Stop(i)));
                    }
                }
                Phase::Resting => {}
            }
        }
        if !self.together {
            let w = self.state[1].v - self.state[0].v;
            let c = self.accel[1].0 - self.accel[0].0;
            if let Some(t) = closing_time(self.gap, w, c) {
                out.push((t, EventCandidate::Impact));
            }
        }
        out
    }
}

/// Time until the gap `g0 + w τ + ½ c τ²` closes (reaches 0 while shrinking), if ever.
/// Roots by the cancellation-free pair `q / (c/2)` and `g0 / q`.
fn closing_time(g0: f64, w: f64, c: f64) -> Option<f64> {
    let closing = |t: f64| t > 0.0 && t.is_finite() && w + c * t <= 0.0;
    if c == 0.0 {
        return (w < 0.0).then(|| -g0 / w).filter(|&t| closing(t));
    }
    let disc = w * w - 2.0 * c * g0;
    if disc < 0.0 {
        return None;
    }
    let q = -0.5 * (w + disc.sqrt().copysign(w));
    let roots = [q / (0.5 * c), if q != 0.0 { g0 / q } else { f64::NAN }];
    roots.into_iter().filter(|&t| closing(t)).reduce(f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn closing_time_finds_the_first_touch() {
        // Balls 1 cm apart, closing at 1 m/s, no acceleration: 10 ms.
        assert_relative_eq!(closing_time(0.01, -1.0, 0.0).unwrap(), 0.01);
        // Just separated at 1 m/s, pulled back at 2 m/s²: back after 1 s.
        assert_relative_eq!(closing_time(0.0, 1.0, -2.0).unwrap(), 1.0);
        // Separating and pushed apart: never.
        assert_eq!(closing_time(0.0, 1.0, 2.0), None);
        // Approaching but braked before touching: never.
        assert_eq!(closing_time(1.0, -1.0, 2.0), None);
        // Touching at rest: no impact.
        assert_eq!(closing_time(0.0, 0.0, -1.0), None);
    }

    #[test]
    fn closing_time_keeps_digits_for_a_tiny_gap() {
        // g0 = 1e-20 m at 1 m/s closing with a large acceleration: τ ≈ 1e-20 s.
        let t = closing_time(1e-20, -1.0, 1e3).unwrap();
        assert_relative_eq!(t, 1e-20, max_relative = 1e-12);
    }
}
