//! Impact series: detecting the geometric series of ever shorter impact cycles
//! (physics.md), summing it to its accumulation point, and ending chatter that has
//! become vanishingly weak.

use super::Engine;
use crate::physics::model::{BallState, Phase};
use crate::physics::solution::{EventKind, Ledger, Who};

/// Impacts closing slower than this fraction of the scene's largest speed are no longer
/// resolved one by one: the balls are taken to touch (perfectly inelastic, losing
/// ~1e-18 of the energy scale). Without it an elastic ball pushed by a rolling one
/// would chatter forever at a fixed, vanishing amplitude.
const CHATTER_SPEED: f64 = 1e-9;

/// Successive impact cycles whose time and speed ratios agree this well are taken as
/// the geometric series of physics.md, which is then summed.
const GEOMETRIC_AGREEMENT: f64 = 1e-9;

/// The series is summed once what remains of it is this short against the time so far…
const REMAINDER_NEGLIGIBLE: f64 = 1e-9;
/// …or after this many cycles confirmed it, bridging the rest (see
/// [`Segment::bridge`](crate::physics::solution::Segment::bridge)). Only cycle ratios
/// within ~1e-2 of 1 (b within ~1e-3 of 2R) need that many.
const CYCLES_BEFORE_SUMMING: usize = 5000;

/// An impact as the series detector needs it.
#[derive(Clone, Copy, Debug)]
pub(super) struct ImpactRecord {
    /// Time since the previous impact.
    pub(super) cycle: f64,
    /// Closing speed just before.
    pub(super) closing: f64,
    /// Everything right after, for summing the series.
    pub(super) state: [BallState; 2],
    pub(super) angle: [f64; 2],
    pub(super) ledger: Ledger,
}

impl Engine {
    fn kinetic(&self, state: &[BallState; 2]) -> f64 {
        (0..2)
            .map(|i| {
                let (t, r) = self.groove.energy(self.mass[i], state[i]);
                t + r
            })
            .sum()
    }

    /// After an impact: if the last impact cycles form a geometric series, sum it and
    /// jump to its accumulation point; if impacts have become vanishingly weak, end them.
    pub(super) fn check_series(&mut self) {
        let n = self.history.len();
        let last = self.history[n - 1];
        if n >= 2 && last.closing <= CHATTER_SPEED * self.speed_scale {
            self.finish_series(0.0, last.state, last.angle, last.ledger);
            return;
        }
        if n < 4 {
            return;
        }
        let [h2, h1, h0] = [self.history[n - 3], self.history[n - 2], last];
        let ratio = h0.cycle / h1.cycle;
        let previous = h1.cycle / h2.cycle;
        let speed_ratio = h0.closing / h1.closing;
        let geometric = ratio < 1.0
            && (ratio - previous).abs() <= GEOMETRIC_AGREEMENT * ratio
            && (speed_ratio - ratio).abs() <= GEOMETRIC_AGREEMENT * ratio;
        if !geometric {
            self.geometric_cycles = 0;
            return;
        }
        self.geometric_cycles += 1;
        let remaining = h0.cycle * ratio / (1.0 - ratio);
        let negligible = remaining <= REMAINDER_NEGLIGIBLE * self.t.abs().max(h0.cycle);
        if !(negligible || self.geometric_cycles >= CYCLES_BEFORE_SUMMING) {
            return;
        }
        // Aitken: every quantity changes by a geometric series of ratio `ratio`
        // from one impact to the next, so its limit is z_n + (z_n − z_{n−1}) ρ/(1 − ρ).
        let f = ratio / (1.0 - ratio);
        let limit = |now: f64, before: f64| now + (now - before) * f;
        let state: [BallState; 2] = std::array::from_fn(|i| BallState {
            x: limit(h0.state[i].x, h1.state[i].x),
            v: limit(h0.state[i].v, h1.state[i].v),
            u: limit(h0.state[i].u, h1.state[i].u),
        });
        let angle = std::array::from_fn(|i| limit(h0.angle[i], h1.angle[i]));
        let ledger = Ledger {
            friction: limit(h0.ledger.friction, h1.ledger.friction),
            impacts: limit(h0.ledger.impacts, h1.ledger.impacts),
            rolling_resistance: limit(h0.ledger.rolling_resistance, h1.ledger.rolling_resistance),
        };
        self.finish_series(remaining, state, angle, ledger);
    }

    /// Ends a series of impacts at `remaining` seconds from now in the limit `state`:
    /// the balls touch and share one speed. The time in between is a bridge segment.
    /// `estimate` is the extrapolated ledger; only its split is used, the total comes
    /// from energy conservation so that the books balance exactly.
    fn finish_series(
        &mut self,
        remaining: f64,
        mut state: [BallState; 2],
        angle: [f64; 2],
        estimate: Ledger,
    ) {
        let energy_now = self.kinetic(&self.state) + self.ledger.total();
        let [ml, mr] = self.mass;
        let v = (ml * state[0].v + mr * state[1].v) / (ml + mr);
        // The extrapolated limit is exact to rounding, which near zero means ~1e-9 of
        // the scale: snap what is that small.
        let tiny = self.eps_v * 1e3;
        let v = if v.abs() <= tiny { 0.0 } else { v };
        for s in state.iter_mut() {
            s.v = v;
            if (s.u - v).abs() <= tiny {
                s.u = v;
            }
        }
        if remaining > 0.0 {
            // The bridge stands for infinitely many ever smaller cycles: velocities
            // and spins go linearly to their limits (the real ones oscillate about
            // that by less than they did in the last resolved cycle).
            let now = self.state;
            self.accel = std::array::from_fn(|i| {
                (
                    (state[i].v - now[i].v) / remaining,
                    (state[i].u - now[i].u) / remaining,
                )
            });
            for i in 0..2 {
                state[i].x = now[i].x + 0.5 * (now[i].v + state[i].v) * remaining;
            }
        }
        let lost = energy_now - self.kinetic(&state);
        let ledger = split_losses(&self.ledger, &estimate, lost);
        if remaining > 0.0 {
            self.push_segment(self.t + remaining);
            self.segments.last_mut().expect("just pushed").bridge = Some(ledger);
            self.t += remaining;
        }
        self.state = state;
        self.angle = angle;
        self.ledger = ledger;
        self.gap = 0.0;
        self.push = 0.0;
        self.set_phases_from_state();
        self.state[1].v = self.state[0].v;
        self.accumulation = Some(self.t);
        let at_rest = self.phase.iter().all(|p| *p == Phase::Resting);
        let kind = if at_rest {
            EventKind::ZenoRest
        } else {
            EventKind::ZenoContact
        };
        self.history.clear();
        // The impact just recorded is the last one resolved; its event already exists.
        // Whether the pair now presses is recorded by the caller, after this event.
        self.settle();
        self.record(&[(kind, Who::Both)]);
    }
}

/// The ledger after losing `lost` joules in all since the start, split like the
/// growth from `now` to `estimate` (into impacts if the estimate shows none).
fn split_losses(now: &Ledger, estimate: &Ledger, lost: f64) -> Ledger {
    let grow = |a: f64, b: f64| (b - a).max(0.0);
    let parts = [
        grow(now.friction, estimate.friction),
        grow(now.impacts, estimate.impacts),
        grow(now.rolling_resistance, estimate.rolling_resistance),
    ];
    let extra = lost - now.total();
    let sum: f64 = parts.iter().sum();
    let share = |i: usize| {
        if sum > 0.0 {
            parts[i] / sum
        } else {
            f64::from(i == 1)
        }
    };
    Ledger {
        friction: now.friction + extra * share(0),
        impacts: now.impacts + extra * share(1),
        rolling_resistance: now.rolling_resistance + extra * share(2),
    }
}
