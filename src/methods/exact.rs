//! The exact event-driven engine behind the methods' one signature: its "steps" are
//! its segments (one polynomial piece from event to event), reported at each segment
//! start, and its events are the engine's.

use super::run::{Integrator, Observer, Run, RunEnd, Stall};
use super::system::Y;
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{Snapshot, Solution};

/// The engine as a method. It solves the scene itself, from the same run-up state
/// that [`start_state`](super::start_state) gives every method (its `y0` is not read).
pub(super) struct Exact;

/// The exact engine's solution of `scene` over `span`: the one way the methods and
/// the comparison call the engine (so that a test can count the solves).
pub fn exact_solution(scene: &Scene, span: &Span) -> Solution {
    #[cfg(test)]
    solves::note(scene);
    engine::solve(scene, span)
}

/// A snapshot as the methods' state vector.
pub fn state(s: Snapshot) -> Y {
    [
        s.left.x, s.left.v, s.left.u, s.right.x, s.right.v, s.right.u,
    ]
}

impl Integrator for Exact {
    fn integrate(&self, run: &Run, obs: &mut dyn Observer) -> RunEnd {
        let (t0, t1) = (run.t0, run.t1);
        let span = Span {
            t_start: t0,
            t_end: Some(t1),
        };
        let sol = exact_solution(&run.model.scene, &span);
        let mut out = RunEnd {
            stalled: sol.truncated.then_some(Stall::EventBudget),
            ..RunEnd::at_start(t0, state(sol.at(t0)))
        };
        let starts = sol.segments.iter().map(|seg| seg.t0.max(t0));
        for t in std::iter::once(t0).chain(starts.filter(|&t| t > t0 && t < t1)) {
            out.steps += 1;
            if !obs.step(t, &state(sol.at(t))) {
                out.aborted = true;
                return out;
            }
        }
        for e in sol.visible_events() {
            obs.event(*e);
        }
        out.t = t1;
        out.y = state(sol.at(t1));
        obs.step(t1, &out.y);
        out
    }
}

/// Test-only: which scenes [`exact_solution`] solved, to count a scene's solves
/// (tests run in parallel: each counts its own scene's).
#[cfg(test)]
pub(crate) mod solves {
    use crate::physics::scene::Scene;
    use std::sync::Mutex;

    static SOLVED: Mutex<Vec<Scene>> = Mutex::new(Vec::new());

    pub(super) fn note(scene: &Scene) {
        SOLVED
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(*scene);
    }

    /// How many times `scene` was solved so far.
    pub(crate) fn of(scene: &Scene) -> usize {
        let solved = SOLVED.lock().unwrap_or_else(|e| e.into_inner());
        solved.iter().filter(|s| *s == scene).count()
    }
}
