//! Pressed contact: the phases and accelerations of the next segment, including the
//! one-dimensional complementarity problem of touching balls that friction drives
//! into each other.

use super::Engine;
use crate::physics::model::Phase;

/// A push below this fraction of the forces on the pair is no push: it is what
/// rounding leaves of two equal accelerations (~1e-16), far below anything physical.
const ZERO_PUSH: f64 = 1e-9;

/// `(dv/dt, du/dt)` of both balls.
type Accelerations = [(f64, f64); 2];

impl Engine {
    /// Free accelerations `(dv/dt, du/dt)` of ball `i` in `phase`, and the mass it
    /// shows to a push through its centre.
    fn free_motion(&self, i: usize, phase: Phase) -> ((f64, f64), f64) {
        match phase {
            Phase::Sliding { sign } => (
                self.groove.sliding_accelerations(f64::from(sign)),
                self.mass[i],
            ),
            Phase::Rolling | Phase::Resting => {
                let a = self.groove.rolling_acceleration(self.state[i].v);
                ((a, a), self.groove.effective_rolling_mass(self.mass[i]))
            }
        }
    }

    /// Accelerations of both balls in `phase`, the push between them (0 when nothing
    /// presses them together or they do not touch), and whether they move as one.
    fn motion(&self, phase: [Phase; 2], touching: bool) -> ([(f64, f64); 2], f64, bool) {
        let motion = [self.free_motion(0, phase[0]), self.free_motion(1, phase[1])];
        let free = motion.map(|(accel, _)| accel);
        let pressed = if touching {
            self.pair_motion(phase, motion)
        } else {
            None
        };
        match pressed {
            None => (free, 0.0, false),
            Some((shared, push)) => {
                let accel = std::array::from_fn(|i| match phase[i] {
                    Phase::Sliding { .. } => (shared, free[i].1),
                    Phase::Rolling | Phase::Resting => (shared, shared),
                });
                (accel, push, true)
            }
        }
    }

    /// Decides the phases and accelerations of the next segment. Touching balls with
    /// equal speed form the one-dimensional complementarity problem of physics.md: a
    /// compressive push `P ≥ 0` exactly when friction drives them into each other.
    /// [`Engine::record_contact`] reports what this changes.
    pub(super) fn settle(&mut self) {
        let touching = self.gap == 0.0 && self.state[0].v == self.state[1].v;
        let mut phase = self.phase;
        let (mut accel, mut push, mut together) = self.motion(phase, touching);
        let mut share = [1.0; 2];
        // A rolling ball whose static friction cannot hold the push starts sliding, in
        // the direction that stays consistent (its slip must grow in the sign assumed).
        // If neither direction is consistent (a Painlevé-type corner: rolling
        // resistance acts only at s = 0), it rolls on with the rail friction at its
        // limit and only the share of rolling resistance that keeps it rolling.
        for i in 0..2 {
            let rolling = !matches!(phase[i], Phase::Sliding { .. });
            if !rolling
                || push == 0.0
                || self.groove.static_friction_needed(push)
                    <= self.groove.friction_limit(self.mass[i]) * (1.0 + 1e-12)
            {
                continue;
            }
            let outward: i8 = if i == 0 { -1 } else { 1 };
            let mut slides = false;
            for sign in [outward, -outward] {
                let mut trial = phase;
                trial[i] = Phase::Sliding { sign };
                let (a, p, joined) = self.motion(trial, touching);
                let slip_rate = a[i].0 - a[i].1;
                if f64::from(sign) * slip_rate > 0.0 {
                    (phase, accel, push, together) = (trial, a, p, joined);
                    slides = true;
                    break;
                }
            }
            if !slides && let Some((a, p, lambda)) = self.saturated_rolling(i, phase) {
                (accel, push) = (a, p);
                share[i] = lambda;
            }
        }
        for i in 0..2 {
            if !matches!(phase[i], Phase::Sliding { .. }) {
                phase[i] = if accel[i].0 != 0.0 || self.state[i].v != 0.0 {
                    Phase::Rolling
                } else {
                    Phase::Resting
                };
            }
        }
        self.phase = phase;
        self.accel = accel;
        self.push = push;
        self.together = together;
        self.rolling_share = share;
    }

    /// Ball `i` rolling under a push its rail friction cannot hold, where sliding
    /// either way is inconsistent too (physics.md, "Rolling resistance"): it keeps
    /// s = 0 with the rail friction at its limit F, which fixes the push at
    /// P* = (1 + 5k²/2) F; the other ball's motion under P* fixes the pair's
    /// acceleration, and that the share λ of rolling resistance. `None` where this does
    /// not apply (the other ball at rest, no rolling resistance, λ outside 0..=1).
    fn saturated_rolling(&self, i: usize, phase: [Phase; 2]) -> Option<(Accelerations, f64, f64)> {
        let j = 1 - i;
        // The push acts on ball i along `dir` (outward), on ball j against it.
        let dir = if i == 0 { -1.0 } else { 1.0 };
        let k2 = self.groove.k * self.groove.k;
        let limit = self.groove.friction_limit(self.mass[i]);
        let push = (1.0 + 2.5 * k2) * limit;
        let other_rests = !matches!(phase[j], Phase::Sliding { .. }) && self.state[j].v == 0.0;
        let resistance = self.groove.rolling_acceleration(self.state[i].v);
        if other_rests || resistance == 0.0 {
            return None;
        }
        let ((a_j, du_j), m_j) = self.free_motion(j, phase[j]);
        let a = a_j - dir * push / m_j;
        let lambda = (a - dir * 2.5 * k2 * limit / self.mass[i]) / resistance;
        if !(-1e-9..=1.0 + 1e-9).contains(&lambda) {
            return None;
        }
        let mut accel = [(a, a); 2];
        if matches!(phase[j], Phase::Sliding { .. }) {
            accel[j].1 = du_j;
        }
        Some((accel, push, lambda.clamp(0.0, 1.0)))
    }

    /// Touching balls moving as one: their shared acceleration and the push between
    /// them, or `None` if nothing presses them together. A ball at rest resists being
    /// rolled by up to `c_rr g` times its rolling mass, like static friction.
    fn pair_motion(&self, phase: [Phase; 2], motion: [((f64, f64), f64); 2]) -> Option<(f64, f64)> {
        let at_rest =
            |i: usize| !matches!(phase[i], Phase::Sliding { .. }) && self.state[i].v == 0.0;
        let hold = self.groove.rolling_resistance * self.groove.g;
        // Force on ball i (besides the push) if the pair accelerates in direction `dir`.
        let force = |i: usize, dir: f64| {
            let ((a, _), m) = motion[i];
            if at_rest(i) { -dir * hold * m } else { a * m }
        };
        let total = motion[0].1 + motion[1].1;
        let mut shared = (force(0, 0.0) + force(1, 0.0)) / total;
        if shared != 0.0 && (at_rest(0) || at_rest(1)) {
            let dir = shared.signum();
            let resisted = (force(0, dir) + force(1, dir)) / total;
            // Too weak to overcome the resting ball's resistance: the pair stays put.
            shared = if resisted * dir > 0.0 { resisted } else { 0.0 };
        }
        let dir = shared.signum();
        // The push follows from whichever ball's force is known (not a static one).
        let push = match (at_rest(0), at_rest(1)) {
            (true, true) => 0.0,
            (false, _) => force(0, dir) - motion[0].1 * shared,
            (true, false) => motion[1].1 * shared - force(1, dir),
        };
        // Balls that would move alike on their own (both rolling, equal decelerations)
        // need no push; the difference above is then rounding, of either sign. Decide it
        // against the forces at play: within the tolerance they move as one, unpressed.
        let scale = force(0, dir).abs() + force(1, dir).abs();
        if push.abs() <= ZERO_PUSH * scale {
            Some((shared, 0.0))
        } else {
            (push > 0.0).then_some((shared, push))
        }
    }
}
