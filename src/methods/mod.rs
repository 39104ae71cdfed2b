//! Time-stepping methods for the same 1-D model, to weigh against the exact engine:
//! one signature ([`Integrator`] over a [`Run`]), one result type ([`RunEnd`]), the
//! right-hand side kept apart from the methods, each method in its own file.
//!
//! Impacts, for the fixed-step methods (`euler`, `symplectic-euler`, `rk4`), are
//! found the way game engines find them: after a step, if the balls overlap while
//! closing, Newton's law is applied as an impulse at the end of that step and the
//! overlap is removed by moving both centres apart in inverse proportion to their
//! masses. `rk45` locates impacts and slip reversals on its dense output; `moreau`
//! treats impacts and friction as set-valued laws at the velocity level.

mod exact;
mod fixed;
mod grid;
mod moreau;
mod rk45;
mod run;
mod system;

use crate::physics::scene::{Scene, Span};

#[cfg(test)]
pub(crate) use exact::solves;
pub use exact::{exact_solution, state};
pub use run::{Integrator, Observer, Run, RunEnd, Stall};
pub use system::{Friction, Method, Model, Settings, Y, ball, collide, gap, resolve_overlap, rhs};

impl Method {
    /// The method itself: what makes its runs.
    pub fn integrator(self) -> &'static dyn Integrator {
        match self {
            Method::Exact => &exact::Exact,
            Method::Euler => &fixed::Fixed::Euler,
            Method::SymplecticEuler => &fixed::Fixed::SymplecticEuler,
            Method::Rk4 => &fixed::Fixed::Rk4,
            Method::Rk45 => &rk45::Rk45,
            Method::Moreau => &moreau::Moreau,
        }
    }

    /// Makes `run` with this method, reporting to `obs`.
    pub fn integrate(self, run: &Run, obs: &mut dyn Observer) -> RunEnd {
        self.integrator().integrate(run, obs)
    }
}

/// The state at `t_start` that rolls into the first impact at t = 0: the exact
/// run-up, shared by every method so that they all start alike. (Where the exact
/// solution over a span from `t_start` is at hand, its state there is the same.)
pub fn start_state(scene: &Scene, t_start: f64) -> Y {
    let span = Span {
        t_start,
        t_end: None,
    };
    state(exact_solution(scene, &span).at(t_start))
}
