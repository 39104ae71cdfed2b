//! Time-stepping methods for the same 1-D model, to weigh against the exact engine:
//! one signature ([`integrate`]), one result type ([`RunEnd`]), the right-hand side
//! kept apart from the methods, each method in its own file.
//!
//! Impacts, for the fixed-step methods (`euler`, `symplectic-euler`, `rk4`), are
//! found the way game engines find them: after a step, if the balls overlap while
//! closing, Newton's law is applied as an impulse at the end of that step and the
//! overlap is removed by moving both centres apart in inverse proportion to their
//! masses. `rk45` locates impacts and slip reversals on its dense output; `moreau`
//! treats impacts and friction as set-valued laws at the velocity level.

mod fixed;
mod grid;
mod moreau;
mod rk45;
mod system;

use crate::physics::scene::Scene;

pub use system::{
    Friction, Method, Model, Observer, RunEnd, Settings, Y, ball, collide, gap, resolve_overlap,
    rhs,
};

/// Runs `method` from the state `y0` at `t0` (the rolling run-up is integrated too)
/// to `t1`, reporting to `obs`.
pub fn integrate(
    method: Method,
    m: &Model,
    y0: Y,
    t0: f64,
    t1: f64,
    s: &Settings,
    obs: &mut dyn Observer,
) -> RunEnd {
    match method {
        Method::Exact => exact(m, t0, t1, obs),
        Method::Euler | Method::SymplecticEuler | Method::Rk4 => {
            fixed::integrate(method, m, y0, t0, t1, s, obs)
        }
        Method::Rk45 => rk45::integrate(m, y0, t0, t1, s, obs),
        Method::Moreau => moreau::integrate(m, y0, t0, t1, s, obs),
    }
}

/// The exact engine behind the same signature: its "steps" are its segments (one
/// polynomial piece from event to event), reported at each segment start, and its
/// events are the engine's. It solves the scene itself, from the same run-up state
/// that [`start_state`] gives every method.
fn exact(m: &Model, t0: f64, t1: f64, obs: &mut dyn Observer) -> RunEnd {
    let span = crate::physics::scene::Span {
        t_start: t0,
        t_end: Some(t1),
    };
    let sol = crate::physics::engine::solve(&m.scene, &span);
    let state = |s: crate::physics::solution::Snapshot| -> Y {
        [
            s.left.x, s.left.v, s.left.u, s.right.x, s.right.v, s.right.u,
        ]
    };
    let mut out = RunEnd {
        steps: 0,
        rhs_evals: 0,
        stalled: sol
            .truncated
            .then(|| "the event budget ended the run early".to_string()),
        aborted: false,
        t: t0,
        y: state(sol.at(t0)),
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

/// The state at `t_start` that rolls into the first impact at t = 0: the exact
/// run-up, shared by every method so that they all start alike.
pub fn start_state(scene: &Scene, t_start: f64) -> Y {
    let sol = crate::physics::engine::solve(
        scene,
        &crate::physics::scene::Span {
            t_start,
            t_end: None,
        },
    );
    let s = sol.at(t_start);
    [
        s.left.x, s.left.v, s.left.u, s.right.x, s.right.v, s.right.u,
    ]
}
