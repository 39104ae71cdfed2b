//! One ball in the groove and the impact between two: the state `(x, v, u)`, its
//! motion phases, the constant accelerations inside a phase, and the impact law.
//! Small pure functions, each one a formula of physics.md.

use serde::Serialize;

/// A ball's state: centre position `x` (m), centre velocity `v` (m/s) and the
/// contact circle's tangential velocity `u = ω r` (m/s), signed so that rolling ⇔ `v = u`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct BallState {
    pub x: f64,
    pub v: f64,
    pub u: f64,
}

impl BallState {
    /// State after `tau` seconds under constant accelerations `a = dv/dt` and `du = du/dt`.
    pub fn advanced(self, a: f64, du: f64, tau: f64) -> BallState {
        BallState {
            x: self.x + tau * (self.v + 0.5 * a * tau),
            v: self.v + a * tau,
            u: self.u + du * tau,
        }
    }
}

/// How a ball moves; decides its accelerations.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Phase {
    /// The contact points slip; `sign` is the sign of the slip `s = v − u` (±1).
    Sliding { sign: i8 },
    /// `v = u ≠ 0`.
    Rolling,
    /// `v = u = 0`.
    Resting,
}

impl Phase {
    pub fn name(self) -> &'static str {
        match self {
            Phase::Sliding { .. } => "sliding",
            Phase::Rolling => "rolling",
            Phase::Resting => "resting",
        }
    }
}

/// Slip velocity of the contact points, `s = v − u`.
pub fn slip(state: BallState) -> f64 {
    state.v - state.u
}

/// The constants of one ball's motion on its groove's two rails (the edges it rolls on):
/// what the per-ball formulas need of the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rails {
    /// `k = r / R`.
    pub k: f64,
    pub mu: f64,
    pub g: f64,
    pub rolling_resistance: f64,
}

impl Rails {
    /// `(dv/dt, du/dt)` while sliding with slip sign `sign`:
    /// `(−sgn(s) μ_k g / k, +sgn(s) 5/2 k μ_k g)`.
    pub fn sliding_accelerations(&self, sign: f64) -> (f64, f64) {
        let a = -sign * self.mu * self.g / self.k;
        let du = sign * 2.5 * self.k * self.mu * self.g;
        (a, du)
    }

    /// Rolling deceleration from rolling resistance, `−sgn(v) c_rr g` (both `dv/dt` and `du/dt`).
    pub fn rolling_acceleration(&self, v: f64) -> f64 {
        if v == 0.0 {
            0.0
        } else {
            -v.signum() * self.rolling_resistance * self.g
        }
    }

    /// Speed at which a sliding ball rolls again. `u + 5/2 k² v` is conserved while it
    /// slides, so `v_roll = (2u + 5k² v)/(2 + 5k²)`.
    pub fn rolling_speed(&self, state: BallState) -> f64 {
        let k2 = self.k * self.k;
        (2.0 * state.u + 5.0 * k2 * state.v) / (2.0 + 5.0 * k2)
    }

    /// Time a free sliding ball needs to roll again, `|s| / (μ_k g (1/k + 5k/2))`.
    pub fn time_to_roll(&self, s: f64) -> f64 {
        s.abs() / self.slip_rate()
    }

    /// How fast friction closes the slip, `|ds/dt| = μ_k g (1/k + 5k/2)`.
    pub fn slip_rate(&self) -> f64 {
        self.mu * self.g * (1.0 / self.k + 2.5 * self.k)
    }

    /// Mass a rolling ball shows to a push through its centre: `m (2 + 5k²)/(5k²)`
    /// (static friction at the edges takes the rest of the push into spin).
    pub fn effective_rolling_mass(&self, mass: f64) -> f64 {
        let k2 = self.k * self.k;
        mass * (2.0 + 5.0 * k2) / (5.0 * k2)
    }

    /// Static friction a rolling ball needs under push `p`: `2|p| / (2 + 5k²)`.
    pub fn static_friction_needed(&self, p: f64) -> f64 {
        2.0 * p.abs() / (2.0 + 5.0 * self.k * self.k)
    }

    /// Largest kinetic (and static) friction the edges give, `μ_k m g / k`.
    pub fn friction_limit(&self, mass: f64) -> f64 {
        self.mu * mass * self.g / self.k
    }

    /// Kinetic energy `½ m v² + m u²/(5k²)` (translation, rotation).
    pub fn energy(&self, mass: f64, state: BallState) -> (f64, f64) {
        (
            0.5 * mass * state.v * state.v,
            mass * state.u * state.u / (5.0 * self.k * self.k),
        )
    }

    /// Resistive force on a rolling ball that loses energy at the rate rolling
    /// resistance does: `dE/dt = m v a (1 + 2/(5k²))`, so `c_rr m g (1 + 2/(5k²))`.
    pub fn rolling_resistance_force(&self, mass: f64) -> f64 {
        self.rolling_resistance * mass * self.g * (1.0 + 2.0 / (5.0 * self.k * self.k))
    }
}

/// Central impact with Newton restitution `e`: velocities `(v_L', v_R')` right after.
pub fn impact(m_left: f64, m_right: f64, v_left: f64, v_right: f64, e: f64) -> (f64, f64) {
    let p = m_left * v_left + m_right * v_right;
    let m = m_left + m_right;
    let closing = v_left - v_right;
    (
        (p - m_right * e * closing) / m,
        (p + m_left * e * closing) / m,
    )
}

/// Energy an impact dissipates, `½ (1 − e²) m_L m_R (v_L − v_R)² / (m_L + m_R)`.
pub fn impact_loss(m_left: f64, m_right: f64, v_left: f64, v_right: f64, e: f64) -> f64 {
    let w = v_left - v_right;
    0.5 * (1.0 - e * e) * m_left * m_right * w * w / (m_left + m_right)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const GROOVE: Rails = Rails {
        k: 0.6,
        mu: 0.2,
        g: 9.81,
        rolling_resistance: 0.0,
    };

    #[test]
    fn sliding_ends_at_the_rolling_speed() {
        let s0 = BallState {
            x: 0.0,
            v: -0.5,
            u: 0.5,
        };
        let sign = slip(s0).signum();
        let (a, du) = GROOVE.sliding_accelerations(sign);
        let t = GROOVE.time_to_roll(slip(s0));
        let s1 = s0.advanced(a, du, t);
        assert_relative_eq!(s1.v, s1.u, max_relative = 1e-14);
        assert_relative_eq!(s1.v, GROOVE.rolling_speed(s0), max_relative = 1e-14);
    }

    #[test]
    fn equal_elastic_balls_swap_velocities() {
        let (l, r) = impact(1.0, 1.0, 0.6, -0.2, 1.0);
        assert_relative_eq!(l, -0.2);
        assert_relative_eq!(r, 0.6);
        assert_eq!(impact_loss(1.0, 1.0, 0.6, -0.2, 1.0), 0.0);
    }

    #[test]
    fn inelastic_impact_loses_what_kinetic_energy_says() {
        let (ml, mr, vl, vr, e) = (0.2, 0.5, 1.0, -0.3, 0.4);
        let (l, r) = impact(ml, mr, vl, vr, e);
        let before = 0.5 * ml * vl * vl + 0.5 * mr * vr * vr;
        let after = 0.5 * ml * l * l + 0.5 * mr * r * r;
        assert_relative_eq!(
            before - after,
            impact_loss(ml, mr, vl, vr, e),
            max_relative = 1e-13
        );
        assert_relative_eq!(ml * vl + mr * vr, ml * l + mr * r, max_relative = 1e-14);
        assert_relative_eq!(r - l, e * (vl - vr), max_relative = 1e-14);
    }

    #[test]
    fn rolling_resistance_force_matches_energy_rate() {
        let groove = Rails {
            rolling_resistance: 0.01,
            ..GROOVE
        };
        let (m, v) = (0.3, 0.8);
        let a = groove.rolling_acceleration(v);
        let state = BallState { x: 0.0, v, u: v };
        let (t0, r0) = groove.energy(m, state);
        let dt = 1e-6;
        let (t1, r1) = groove.energy(m, state.advanced(a, a, dt));
        let rate = (t0 + r0 - t1 - r1) / dt;
        assert_relative_eq!(
            rate,
            groove.rolling_resistance_force(m) * v,
            max_relative = 1e-5
        );
    }
}
