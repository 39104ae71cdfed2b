//! Impact series: detecting the geometric series of ever shorter impact cycles
//! (physics.md), summing it to its accumulation point, and ending chatter that has
//! become vanishingly weak.

use super::{Engine, ImpactRecord};
use crate::physics::model::{BallState, Phase};
use crate::physics::solution::{EventKind, Ledger, SeriesSum, Who};

/// Impacts closing slower than this fraction of the scene's largest speed are no longer
/// resolved one by one: the balls are taken to touch (perfectly inelastic, losing
/// ~1e-18 of the energy scale). Without it an elastic ball pushed by a rolling one
/// would chatter forever at a fixed, vanishing amplitude.
const CHATTER_SPEED: f64 = 1e-9;

/// Successive impact cycles whose time and speed ratios agree this well are taken as
/// the geometric series of physics.md, which is then summed.
const GEOMETRIC_AGREEMENT: f64 = 1e-9;

/// The series is summed once what remains of it is this short against the time so far,
/// or after the engine's cycle budget (`CYCLES_BEFORE_SUMMING`) confirmed it.
const REMAINDER_NEGLIGIBLE: f64 = 1e-9;

impl Engine {
    pub(super) fn kinetic(&self, state: &[BallState; 2]) -> f64 {
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
            self.finish_series(0.0, last.state, last.angle, last.ledger, false);
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
        if !(negligible || self.geometric_cycles >= self.cycle_budget) {
            return;
        }
        // The last geometric_cycles + 2 cycles are geometric; the first impact of the
        // history has no cycle before it.
        if !self.sum_tail(self.geometric_cycles.min(n - 2), !negligible) {
            self.geometric_cycles = 0;
        }
    }

    /// Sums the rest of a geometric series of impacts from its last `m` cycles and
    /// jumps to the accumulation point, or, where rolling resistance would stop a ball
    /// inside the tail, sums only the cycles before that stop and jumps to the impact
    /// that ends them (a partial tail, see [`Engine::cycles_before_a_stop`]).
    /// Everything is taken over m cycles, not one: their ratio q = ρ^m is the quotient
    /// of two cycle times, and 1 − q keeps its digits where 1 − ρ (b near 2R:
    /// 1 − ρ ≈ 5k²) would lose them to rounding. Returns false if nothing was summed.
    ///
    /// The sums. In a geometric series every speed, spin, cycle time, arrival velocity
    /// and the clock at the impacts goes as `z_n = z_∞ + C ρ^n`. Over the last m cycles
    /// z changed by `Δ = z_n − z_{n−m} = C ρ^n (1 − 1/q)`, so (Aitken)
    ///
    /// ```text
    /// z_{n+N} = z_n + Δ q/(1 − q) (1 − ρ^N),      ρ^N = exp(N ln q / m),
    /// ```
    ///
    /// the whole tail for N → ∞ (1 − ρ^N = 1). Places and spin angles grow by the
    /// limit rate `w` times the time plus the swing about it (speeds ∝ ρ^n over times
    /// ∝ ρ^n: ratio ρ²), so `y = x − w t` goes as `y_∞ − D ρ^{2n}` and
    ///
    /// ```text
    /// x_{n+N} = x_n + w T_N + (Δx − w Δt) q²/(1 − q²) (1 − ρ^{2N}),
    /// T_N = Δt q/(1 − q) (1 − ρ^N),   1 − ρ^{2N} = (1 − ρ^N)(1 + ρ^N),
    /// ```
    ///
    /// with Δt the time the last m cycles took.
    fn sum_tail(&mut self, m: usize, by_budget: bool) -> bool {
        let n = self.history.len();
        let (h0, hm) = (self.history[n - 1], self.history[n - 1 - m]);
        let q = h0.cycle / hm.cycle;
        let f = q / (1.0 - q);
        let limit = |now: f64, before: f64| now + (now - before) * f;
        // How much of the tail to take: 1 − ρ^N, 1 for all of it.
        let ln_rho = (q - 1.0).ln_1p() / m as f64;
        let (summed, part) = match self.cycles_before_a_stop(&h0, &hm, f, ln_rho) {
            None => (None, 1.0),
            Some(to_stop) => {
                // Two cycles short of the one that would cross the stop: the
                // prediction carries the series' rounding, and the last cycles before
                // the stop are resolved one by one, the stop among them.
                let cycles = to_stop.floor() - 2.0;
                if cycles.is_nan() || cycles < 1.0 {
                    return false;
                }
                (Some(cycles as usize), -(cycles * ln_rho).exp_m1())
            }
        };
        let ahead = |now: f64, before: f64| now + (now - before) * f * part;
        let span: f64 = self.history[n - m..].iter().map(|h| h.cycle).sum();
        let remaining = span * f * part;
        let speed: [f64; 2] = std::array::from_fn(|i| ahead(h0.state[i].v, hm.state[i].v));
        let spin: [f64; 2] = std::array::from_fn(|i| ahead(h0.state[i].u, hm.state[i].u));
        // The limit rates places and angles move with (the whole tail's limit).
        let [ml, mr] = self.mass;
        let shared = (ml * limit(h0.state[0].v, hm.state[0].v)
            + mr * limit(h0.state[1].v, hm.state[1].v))
            / (ml + mr);
        let f2 = q * q / (1.0 - q * q) * part * (2.0 - part);
        let place = |now: f64, before: f64, rate: f64| {
            now + rate * remaining + ((now - before) - rate * span) * f2
        };
        // The balls touch at every impact, so the place to sum is their contact point;
        // summing each centre would also sum their rounding drift, ~1/(1 − ρ) times.
        let contact = |h: &ImpactRecord| 0.5 * (h.state[0].x + h.state[1].x);
        let touch = place(contact(&h0), contact(&hm), shared);
        let r = self.groove.k * self.radius;
        // The whole tail ends in its limit; a partial one just before the impact that
        // ends its summed cycles, which is then resolved (a bridge ending in the
        // separating speeds after it would close the gap below zero on the way).
        let velocity = |i: usize| match summed {
            None => speed[i],
            Some(_) => ahead(h0.arrival[i].0, hm.arrival[i].0),
        };
        let state: [BallState; 2] = std::array::from_fn(|i| BallState {
            x: touch + if i == 0 { -self.radius } else { self.radius },
            v: velocity(i),
            u: spin[i],
        });
        let angle = std::array::from_fn(|i| {
            let rate = limit(h0.state[i].u, hm.state[i].u) / r;
            place(h0.angle[i], hm.angle[i], rate)
        });
        let ledger = Ledger {
            friction: ahead(h0.ledger.friction, hm.ledger.friction),
            impacts: ahead(h0.ledger.impacts, hm.ledger.impacts),
            rolling_resistance: ahead(h0.ledger.rolling_resistance, hm.ledger.rolling_resistance),
        };
        // A limit with more kinetic energy than the pair has now (beyond rounding) is no
        // limit of this series: its cycles only looked geometric (rolling resistance
        // changes the speeds over a long tail). The impacts are then resolved on.
        let kinetic_now = self.kinetic(&self.state);
        let scale = kinetic_now + self.ledger.total();
        if self.kinetic(&state) > kinetic_now + 1e-9 * scale {
            return false;
        }
        // Recorded only once the tail is taken: a refused tail is resolved on, and the
        // solution must not describe a sum that never happened.
        let ratio = (h0.cycle / self.history[n - 2].cycle).min(1.0);
        let from = self.t;
        match summed {
            None => self.finish_series(remaining, state, angle, ledger, by_budget),
            Some(_) => {
                let arriving = [h0.arrival[0].1, h0.arrival[1].1];
                let cycle = h0.cycle * (1.0 - part);
                self.skip_cycles(remaining, state, angle, ledger, (arriving, cycle));
            }
        }
        self.series.push(SeriesSum {
            from,
            to: self.t,
            cycles: m,
            ratio,
            by_budget,
            // The impact at `to` is resolved, the ones before it summed.
            impacts: summed.map(|n| n - 1),
        });
        true
    }

    /// Where rolling resistance would stop a ball inside the tail: the number of
    /// cycles `j` (fractional) after which the velocity a ball arrives at an impact
    /// with, rolling, would reach zero, if its limit lies beyond zero. Rolling
    /// resistance acts against a rolling ball's velocity and holds it once it is at
    /// rest, so its cycles cannot carry it through zero: the series holds only until
    /// then. With `a_{n+j} = a_n + (a_∞ − a_n)(1 − ρ^j)`, `a_{n+j} = 0` at
    /// `1 − ρ^j = a_n / (a_n − a_∞)`, i.e. `j = m ln(1 − a_n/(a_n − a_∞)) / ln q`.
    fn cycles_before_a_stop(
        &self,
        last: &ImpactRecord,
        before: &ImpactRecord,
        f: f64,
        ln_rho: f64,
    ) -> Option<f64> {
        if self.groove.rolling_resistance == 0.0 {
            return None;
        }
        let tiny = self.eps_v * 1e3;
        (0..2)
            .filter_map(|i| {
                let (a, phase) = last.arrival[i];
                let a_inf = a + (a - before.arrival[i].0) * f;
                let stops = !matches!(phase, Phase::Sliding { .. })
                    && a * a_inf < 0.0
                    && a_inf.abs() > tiny;
                stops.then(|| (-a / (a - a_inf)).ln_1p() / ln_rho)
            })
            .reduce(f64::min)
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
        averaged: bool,
    ) {
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
        self.bridge_to(remaining, state, angle, estimate, averaged);
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
        self.geometric_cycles = 0;
        // The impact just recorded is the last one resolved; its event already exists.
        // Whether the pair now presses is recorded by the caller, after this event.
        self.settle();
        self.record(&[(kind, Who::Both)]);
    }

    /// Jumps over the summed cycles of a partial tail through a bridge of cycle
    /// averages to `state`, the balls arriving at the impact that ends them (`last`:
    /// their phases then, and the cycle before it), and resolves that impact; the
    /// impacts after it are resolved one by one again, the series detector starting
    /// afresh (the cycles before the jump are not their neighbours).
    fn skip_cycles(
        &mut self,
        remaining: f64,
        state: [BallState; 2],
        angle: [f64; 2],
        estimate: Ledger,
        last: ([Phase; 2], f64),
    ) {
        self.bridge_to(remaining, state, angle, estimate, true);
        let (arriving, cycle) = last;
        self.phase = arriving;
        self.history.clear();
        self.geometric_cycles = 0;
        self.since_impact = cycle;
        self.collide();
        self.settle();
        self.record(&[(EventKind::Collision, Who::Both)]);
    }

    /// Moves the run `remaining` seconds on to `state` (the balls touching) through a
    /// bridge segment (unless `remaining` is too short to move the clock), booking
    /// what the pair lost on the way split like `estimate`.
    fn bridge_to(
        &mut self,
        remaining: f64,
        mut state: [BallState; 2],
        mut angle: [f64; 2],
        estimate: Ledger,
        averaged: bool,
    ) {
        let energy_now = self.kinetic(&self.state) + self.ledger.total();
        // A remainder too short to move the clock is no bridge.
        let remaining = if self.t + remaining > self.t {
            remaining
        } else {
            0.0
        };
        if remaining > 0.0 {
            self.start_bridge(remaining, &mut state, &mut angle, averaged);
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
        self.together = false;
    }

    /// Sets the state and accelerations of the bridge over the last `remaining`
    /// seconds of a series to the limit `state` (whose places a short bridge sets, and
    /// whose spin `angle` an averaged one may).
    fn start_bridge(
        &mut self,
        remaining: f64,
        state: &mut [BallState; 2],
        angle: &mut [f64; 2],
        averaged: bool,
    ) {
        // The bridge stands for infinitely many ever smaller cycles, each a scaled
        // copy of the last: cycle times and speeds shrink by the same ratio, so the
        // spins fall linearly in time to their limits. A long bridge (`averaged`)
        // moves with the cycle averages (the real velocities swing about them, each
        // bounce less than the last resolved one), from the last impact's places to
        // the summed limit places, ending at the limit velocity. A negligible one
        // just goes on linearly from the last impact.
        let now = self.state;
        let mut speeds = [now[0].v, now[1].v];
        for i in 0..2 {
            let start = if averaged {
                // A cycle's mean velocity lies between the speeds the ball swings
                // between; the bound also keeps rounding in the places (where the
                // bridge moves the balls by less than that) from making a speed.
                let (lo, hi) = (now[i].v.min(state[i].v), now[i].v.max(state[i].v));
                (2.0 * (state[i].x - now[i].x) / remaining - state[i].v).clamp(lo, hi)
            } else {
                state[i].x = now[i].x + 0.5 * (now[i].v + state[i].v) * remaining;
                now[i].v
            };
            speeds[i] = start;
        }
        let spins = if averaged {
            self.bridge_spins(&now, speeds, state)
        } else {
            [now[0].u, now[1].u]
        };
        let r = self.groove.k * self.radius;
        for i in 0..2 {
            self.state[i].v = speeds[i];
            self.state[i].u = spins[i];
            self.accel[i] = (
                (state[i].v - speeds[i]) / remaining,
                (state[i].u - spins[i]) / remaining,
            );
            if spins[i] != now[i].u {
                // The spin angle goes on from the bridge, not from the summed limit.
                angle[i] = self.angle[i] + 0.5 * (spins[i] + state[i].u) * remaining / r;
            }
        }
    }

    /// The spins an averaged bridge starts with beside its mean speeds `speeds`: the
    /// impact's, unless the pair would then hold more kinetic energy than it has at the
    /// impact. A cycle trades spin for speed, so its mean speeds belong with spins
    /// already part way to their limits: the spins then start as far toward their
    /// limits (the same fraction for both) as it takes for the bridge to gain nothing.
    fn bridge_spins(
        &self,
        now: &[BallState; 2],
        speeds: [f64; 2],
        limit: &[BallState; 2],
    ) -> [f64; 2] {
        let spins = |f: f64| -> [f64; 2] {
            std::array::from_fn(|i| now[i].u + f * (limit[i].u - now[i].u))
        };
        let kinetic = |f: f64| {
            let s = spins(f);
            self.kinetic(&std::array::from_fn(|i| BallState {
                x: now[i].x,
                v: speeds[i],
                u: s[i],
            }))
        };
        let budget = self.kinetic(now);
        if kinetic(0.0) <= budget {
            return spins(0.0);
        }
        // Bisection on the fraction, keeping a fraction that fits (if even the limits
        // do not pay for the mean speeds, the spins start there).
        let (mut gains, mut fits) = (0.0, 1.0);
        for _ in 0..64 {
            let mid = 0.5 * (gains + fits);
            if kinetic(mid) <= budget {
                fits = mid;
            } else {
                gains = mid;
            }
        }
        spins(fits)
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
