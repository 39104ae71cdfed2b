//! What the time-stepping methods share beyond the model: running on a fixed time grid,
//! and seeing impacts and rolling as a time-stepping method sees them.

use super::run::{Observer, Run, RunEnd, Stall};
use super::system::{Y, ball};
use crate::physics::solution::{Event, EventKind, Who};

/// One step of a fixed-grid method: the new state, right-hand-side evaluations, and
/// whether an impact happened in it.
pub(crate) struct GridStep {
    pub y: Y,
    pub rhs_evals: usize,
    pub impact: bool,
}

/// Makes `run` with a fixed-step method on the grid `t0 + i h` (the last step lands on `t1`, with
/// no drift), reporting steps and events; refuses up front a run beyond the budget.
pub(crate) fn run_grid(
    run: &Run,
    roll_threshold: f64,
    obs: &mut dyn Observer,
    mut step: impl FnMut(&Y, f64) -> GridStep,
) -> RunEnd {
    let (y0, t0, t1, s) = (run.y0, run.t0, run.t1, run.settings);
    let h = s.step;
    let n = ((t1 - t0) / h).ceil() as usize;
    let mut out = RunEnd::at_start(t0, y0);
    if n > s.max_steps {
        out.stalled = Some(Stall::OverBudget {
            needed: n,
            budget: s.max_steps,
        });
        return out;
    }
    let mut tracker = EventTracker::new(roll_threshold);
    if !obs.step(t0, &y0) {
        out.aborted = true;
        return out;
    }
    tracker.step(t0, &y0, obs);
    for i in 1..=n {
        let t = if i == n { t1 } else { t0 + i as f64 * h };
        let next = step(&out.y, t - out.t);
        out.y = next.y;
        out.rhs_evals += next.rhs_evals;
        out.steps += 1;
        out.t = t;
        if next.impact {
            tracker.impact(t, &out.y, obs);
        }
        tracker.step(t, &out.y, obs);
        if !obs.step(t, &out.y) {
            out.aborted = true;
            break;
        }
    }
    out
}

/// Reports "rolling" once per ball after each impact, as a time-stepping method can
/// see it: the slip changes sign (Coulomb friction), or falls below `threshold` (the
/// regularised law, whose slip decays without crossing zero).
#[derive(Clone, Debug, Default)]
pub(crate) struct EventTracker {
    rolled: [bool; 2],
    last: Option<(f64, Y)>,
    threshold: f64,
}

impl EventTracker {
    pub(crate) fn new(threshold: f64) -> EventTracker {
        EventTracker {
            threshold,
            ..EventTracker::default()
        }
    }

    pub(crate) fn impact(&mut self, t: f64, y: &Y, obs: &mut dyn Observer) {
        self.rolled = [false; 2];
        obs.event(event(t, y, EventKind::Collision, Who::Both));
    }

    pub(crate) fn step(&mut self, t: f64, y: &Y, obs: &mut dyn Observer) {
        if let Some((t0, y0)) = self.last {
            for i in 0..2 {
                let s0 = y0[3 * i + 1] - y0[3 * i + 2];
                let s1 = y[3 * i + 1] - y[3 * i + 2];
                let crossed = s0 * s1 < 0.0 || (s1 == 0.0 && s0 != 0.0);
                let settled = s0.abs() > self.threshold && s1.abs() <= self.threshold;
                if !self.rolled[i] && t0 >= 0.0 && (crossed || settled) {
                    // Linear interpolation of the crossing inside the step.
                    let target = if crossed {
                        0.0
                    } else {
                        self.threshold * s0.signum()
                    };
                    let f = (s0 - target) / (s0 - s1);
                    let tc = t0 + f * (t - t0);
                    let yc: Y = std::array::from_fn(|j| y0[j] + f * (y[j] - y0[j]));
                    self.rolled[i] = true;
                    obs.event(event(tc, &yc, EventKind::Rolling, Who::ball(i)));
                }
            }
        }
        self.last = Some((t, *y));
    }
}

pub(crate) fn event(t: f64, y: &Y, kind: EventKind, who: Who) -> Event {
    Event {
        t,
        kind,
        ball: who,
        left: ball(y, 0),
        right: ball(y, 1),
    }
}
